#!/usr/bin/python3
"""A private Xvfb server: the X server picks a free display number itself (-displayfd), so
that servers started at the same time never race for one. GUI tests find their windows by
name with xdotool: two tests on one display could click each other's windows, so each test
worker has its own.

-noreset: by default an X server resets when its last client disconnects, and a client that
connects during the reset is refused ("could not connect to display"): a test that closes
one window and opens the next, or polls with xdotool, would then fail at random."""
import os
import subprocess

SCREEN = '1920x1200x24'


class DisplayError(RuntimeError):
    """Xvfb did not start."""


class Display:
    def __init__(self, log_path=os.devnull):
        self.process = None
        self.name = None
        self.log_path = log_path

    def start(self):
        """Starts Xvfb and returns its display name (':N') once it accepts clients."""
        read_fd, write_fd = os.pipe()
        try:
            with open(self.log_path, 'w') as log:
                self.process = subprocess.Popen(
                    ['Xvfb', '-displayfd', str(write_fd), '-screen', '0', SCREEN, '-nolisten',
                     'tcp', '-noreset'], pass_fds=(write_fd,), stdout=log,
                    stderr=subprocess.STDOUT, start_new_session=True)
        finally:
            os.close(write_fd)
        with os.fdopen(read_fd) as pipe:
            number = pipe.readline().strip()
        if not number.isdigit():
            self.stop()
            raise DisplayError(f'Xvfb -displayfd wrote {number!r} instead of a display number')
        self.name = ':' + number
        return self.name

    def stop(self):
        if self.process is None:
            return
        self.process.terminate()
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        self.process = None
