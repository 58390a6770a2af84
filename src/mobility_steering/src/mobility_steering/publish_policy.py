"""When the steering tools publish: every tick while moving, a short zero tail after a stop.

The tail makes sure the robot hears the stop; the silence after it lets another source
(a teleop, a planner) drive without being overwritten by zeros."""


class PublishPolicy:
    """Decides, once per tick, whether the current command is published."""

    def __init__(self, zero_repeats):
        if zero_repeats < 1:
            raise ValueError(f'zero_repeats must be at least 1, got {zero_repeats}')
        self.zero_repeats = zero_repeats
        self._zeros_left = 0

    def tick(self, moving):
        """True when this tick publishes; `moving` says whether the command is non-zero."""
        if moving:
            self._zeros_left = self.zero_repeats
            return True
        if self._zeros_left > 0:
            self._zeros_left -= 1
            return True
        return False

    def restart(self):
        """Forgets a pending tail (e.g. when the topic changes: the new topic stays quiet)."""
        self._zeros_left = 0
