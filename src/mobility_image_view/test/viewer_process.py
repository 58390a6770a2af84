"""Runs the viewer as a child process and collects its stdout lines (for the GUI tests)."""
import signal
import subprocess
import threading

from mobility_testing import x11
from mobility_testing.waiting import wait_for


class ViewerProcess:
    """The viewer started with `command` (a list); its stdout is read on a thread."""

    def __init__(self, command):
        self.command = command
        self._lines = []
        self._lock = threading.Lock()
        self.process = subprocess.Popen(command, stdout=subprocess.PIPE, text=True, bufsize=1)
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self):
        for line in self.process.stdout:
            with self._lock:
                self._lines.append(line.rstrip('\n'))

    def lines(self, prefix=''):
        """Every line printed so far that starts with prefix."""
        with self._lock:
            return [line for line in self._lines if line.startswith(prefix)]

    def wait_line(self, predicate, timeout_s, what, prefix=''):
        """Waits for a line (with prefix) satisfying predicate; returns the newest one."""
        def found():
            self._check_running(what)
            matches = [line for line in self.lines(prefix) if predicate(line)]
            return matches[-1] if matches else None
        return wait_for(found, timeout_s, what)

    def _check_running(self, what):
        if self.process.poll() is not None:
            raise AssertionError(f'viewer exited with {self.process.returncode} '
                                 f'while waiting for {what}')

    def wait_window(self, title_regex, timeout_s):
        """Waits for the viewer's window (failing at once if the viewer exits); its id."""
        x11.require_display()
        what = f'a window titled /{title_regex}/'

        def found():
            self._check_running(what)
            return (x11.find_windows(title_regex) or [None])[0]
        return wait_for(found, timeout_s, what)

    def stop(self):
        """Asks the viewer to quit (SIGINT), kills it if it does not; returns its exit code."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self._reader.join(timeout=5)
        return self.process.returncode
