"""Private X servers for the test workers: started at the same time, each gets a display
of its own that accepts clients, and stopping one leaves the other serving."""
import os
import subprocess
import sys
import threading

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from xvfb_display import Display  # noqa: E402


def screen_size(name):
    return subprocess.run(['xdotool', 'getdisplaygeometry'], env=dict(os.environ, DISPLAY=name),
                          capture_output=True, text=True, timeout=10).stdout.split()


def test_servers_started_together_get_displays_of_their_own(tmp_path):
    folder = str(tmp_path)
    displays = [Display(os.path.join(folder, 'x%d.log' % i)) for i in range(3)]
    names = []
    starters = [threading.Thread(target=lambda d=d: names.append(d.start())) for d in displays]
    try:
        for starter in starters:
            starter.start()
        for starter in starters:
            starter.join(timeout=30)
        assert len(set(names)) == 3, names
        for name in names:
            assert screen_size(name) == ['1920', '1200']
        displays[0].stop()
        assert screen_size(displays[1].name) == ['1920', '1200']
    finally:
        for display in displays:
            display.stop()


def test_the_server_does_not_reset_when_its_last_client_leaves():
    # A reset would drop the root window's properties and refuse the next client meanwhile.
    display = Display()
    try:
        env = dict(os.environ, DISPLAY=display.start())
        subprocess.run(['xprop', '-root', '-f', 'MOBILITY_TEST', '8s', '-set', 'MOBILITY_TEST',
                        'kept'], env=env, check=True, timeout=10)
        read = subprocess.run(['xprop', '-root', 'MOBILITY_TEST'], env=env, capture_output=True,
                              text=True, timeout=10)
        assert read.stdout.strip() == 'MOBILITY_TEST(STRING) = "kept"', read.stderr
    finally:
        display.stop()
