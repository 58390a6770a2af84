"""Measuring the frame rate of a stream from arrival times (time is passed in)."""
import collections


class RateMeter:
    """Frame rate over a sliding window of the most recent arrivals.

    rate_hz(now) is (n - 1) / (last - first) over the arrivals of the last
    window_s seconds, or None when fewer than two frames arrived in that window.
    """

    def __init__(self, window_s=2.0):
        if not window_s > 0:
            raise ValueError(f'rate window must be positive, got {window_s}')
        self.window_s = window_s
        self._times = collections.deque()

    def tick(self, t_s):
        """Records one frame arriving at time t_s (seconds, monotonic)."""
        self._times.append(t_s)
        self._forget_before(t_s - self.window_s)

    def reset(self):
        """Forgets every arrival (a new topic was selected)."""
        self._times.clear()

    def rate_hz(self, now_s):
        """Frames per second at time now_s, or None when there is no recent stream."""
        self._forget_before(now_s - self.window_s)
        if len(self._times) < 2 or self._times[-1] <= self._times[0]:
            return None
        return (len(self._times) - 1) / (self._times[-1] - self._times[0])

    def _forget_before(self, t_s):
        while self._times and self._times[0] < t_s:
            self._times.popleft()
