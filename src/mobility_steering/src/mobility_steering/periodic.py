"""A steady wall-clock tick in its own thread, independent of the Qt event loop."""
import threading
import time


def next_deadline(previous_s, now_s, period_s):
    """The first deadline on the grid previous + k * period (k >= 1) that is after now.

    Keeping the grid (instead of now + period) gives a steady rate without drift; a late
    wake-up skips the missed ticks instead of bursting them."""
    if period_s <= 0:
        raise ValueError(f'period must be positive, got {period_s}')
    missed = max(0, int((now_s - previous_s) // period_s))
    return previous_s + (missed + 1) * period_s


class PeriodicThread:
    """Calls callback() every period_s seconds (monotonic clock) until stop()."""

    def __init__(self, period_s, callback, clock=time.monotonic):
        self._period_s = period_s
        self._callback = callback
        self._clock = clock
        self._stopped = threading.Event()
        self._thread = threading.Thread(target=self._run, name='periodic', daemon=True)

    def start(self):
        self._thread.start()

    def stop(self):
        self._stopped.set()
        if self._thread.is_alive() and self._thread is not threading.current_thread():
            self._thread.join(timeout=2.0)

    def _run(self):
        deadline = self._clock()
        while not self._stopped.is_set():
            self._callback()
            deadline = next_deadline(deadline, self._clock(), self._period_s)
            self._stopped.wait(max(0.0, deadline - self._clock()))
