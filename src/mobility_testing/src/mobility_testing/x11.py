"""Finding, driving and photographing X windows with xdotool and ImageMagick.

Every function uses the X server named by $DISPLAY (under `make test`, its worker's Xvfb)."""
import os
import re
import subprocess

from mobility_testing.images import load_png
from mobility_testing.waiting import wait_for


def require_display():
    """Raises a clear error when no X server is available."""
    if not os.environ.get('DISPLAY'):
        raise RuntimeError('GUI test needs an X server: run it under '
                           'xvfb-run -a -s "-screen 0 1600x1200x24" (make test does)')


def _xdotool(*args, check=True):
    result = subprocess.run(['xdotool', *map(str, args)], capture_output=True, text=True,
                            timeout=20)
    if check and result.returncode != 0:
        raise RuntimeError(f'xdotool {" ".join(map(str, args))} failed: {result.stderr.strip()}')
    return result.stdout.strip()


def find_windows(name_regex):
    """Ids of visible windows whose title matches name_regex (may be empty)."""
    out = _xdotool('search', '--onlyvisible', '--name', name_regex, check=False)
    return [int(w) for w in out.split()]


def wait_window(name_regex, timeout_s=30.0):
    """Waits for a visible window whose title matches, returns its id."""
    require_display()
    return wait_for(lambda: (find_windows(name_regex) or [None])[0], timeout_s,
                    f'a window titled /{name_regex}/')


def geometry(window):
    """(x, y, width, height) of a window on the screen."""
    out = _xdotool('getwindowgeometry', '--shell', window)
    values = dict(line.split('=', 1) for line in out.splitlines() if '=' in line)
    return int(values['X']), int(values['Y']), int(values['WIDTH']), int(values['HEIGHT'])


def activate(window):
    """Raises and focuses a window (Xvfb has no window manager: focus directly)."""
    _xdotool('windowraise', window, check=False)
    _xdotool('windowfocus', '--sync', window, check=False)


def key(window, *keys):
    """Sends key presses (xdotool key names, e.g. 'w', 'space') to a window."""
    activate(window)
    _xdotool('key', '--window', window, '--delay', 30, *keys)


def type_text(window, text):
    """Types text into the focused widget of a window."""
    activate(window)
    _xdotool('type', '--window', window, '--delay', 20, '--', text)


def click(window, x, y, button=1):
    """Clicks at (x, y) relative to the window's top-left corner."""
    activate(window)
    _xdotool('mousemove', '--window', window, x, y)
    _xdotool('click', button)


def drag(window, x0, y0, x1, y1, steps=10):
    """Drags with the left button from (x0, y0) to (x1, y1), window-relative."""
    activate(window)
    _xdotool('mousemove', '--window', window, x0, y0)
    _xdotool('mousedown', 1)
    for i in range(1, steps + 1):
        _xdotool('mousemove', '--window', window,
                 x0 + (x1 - x0) * i // steps, y0 + (y1 - y0) * i // steps)
    _xdotool('mouseup', 1)


def move(window, x, y):
    """Moves a window's top-left corner to (x, y) on the screen."""
    _xdotool('windowmove', '--sync', window, x, y)


def screenshot(window, path):
    """Saves a PNG of a window (or of the whole screen for window='root')."""
    require_display()
    target = 'root' if window == 'root' else str(window)
    subprocess.run(['/usr/bin/import', '-window', target, path], check=True, timeout=30,
                   capture_output=True)
    return path


def screenshot_array(window, path):
    """Screenshot of a window as an (H, W, 3) uint8 array; the PNG is kept at path."""
    return load_png(screenshot(window, path))


def render_areas(window):
    """(x, y, width, height) on the screen of the windows that a renderer created inside
    `window` (RViz's Ogre views: unnamed X windows of another client), largest first.
    RViz's main 3D view is the first; an Image display adds a smaller one."""
    out = subprocess.run(['xwininfo', '-tree', '-id', str(window)], capture_output=True,
                         text=True, timeout=20, check=True).stdout
    # e.g. "0x600004 (has no name): ()  820x755+0+0  +364+62" (size, then absolute corner)
    child = re.compile(r'^0x[0-9a-f]+ \(has no name\): \(\)\s+(\d+)x(\d+)[-+]\d+[-+]\d+'
                       r'\s+\+(-?\d+)\+(-?\d+)$')
    areas = []
    for line in out.splitlines():
        match = child.match(line.strip())
        if match:
            width, height, x, y = (int(v) for v in match.groups())
            areas.append((x, y, width, height))
    return sorted(areas, key=lambda a: a[2] * a[3], reverse=True)
