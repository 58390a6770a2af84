"""Raw keyboard input from a terminal, with the terminal's settings always restored."""
import os
import select
import signal
import termios
import tty

CTRL_C = '\x03'


class NotATerminal(RuntimeError):
    """The input is not a terminal (e.g. a pipe), so single keys cannot be read."""


class RawTerminal:
    """Context manager: puts fd in raw mode and restores the saved settings on exit.

    Raw mode delivers Ctrl-C as a character (CTRL_C) rather than a signal, so the caller
    leaves its loop normally; SIGTERM and SIGHUP also restore the settings before exiting."""

    def __init__(self, fd):
        if not os.isatty(fd):
            raise NotATerminal('teleop_keyboard reads single keys and needs a terminal '
                               '(stdin is not a tty)')
        self.fd = fd
        self._saved = None
        self._old_handlers = {}

    def __enter__(self):
        self._saved = termios.tcgetattr(self.fd)
        for sig in (signal.SIGTERM, signal.SIGHUP):
            self._old_handlers[sig] = signal.signal(sig, self._on_signal)
        tty.setraw(self.fd)
        return self

    def __exit__(self, *exc):
        self.restore()
        for sig, handler in self._old_handlers.items():
            signal.signal(sig, handler)
        return False

    def restore(self):
        if self._saved is not None:
            termios.tcsetattr(self.fd, termios.TCSADRAIN, self._saved)

    def _on_signal(self, signum, _frame):
        self.restore()
        raise SystemExit(128 + signum)

    def read_key(self, timeout_s):
        """One character, or None when none arrives within timeout_s seconds."""
        ready, _, _ = select.select([self.fd], [], [], max(0.0, timeout_s))
        if not ready:
            return None
        data = os.read(self.fd, 1)
        return data.decode('latin-1') if data else CTRL_C
