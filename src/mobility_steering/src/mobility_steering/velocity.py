"""The velocity command edited by the steering window: two clamped values and their ranges."""
from dataclasses import dataclass

LINEAR_UP = 'linear_up'
LINEAR_DOWN = 'linear_down'
ANGULAR_UP = 'angular_up'
ANGULAR_DOWN = 'angular_down'
LINEAR_ZERO = 'linear_zero'
ANGULAR_ZERO = 'angular_zero'
STOP = 'stop'

#: Keyboard shortcuts of the steering window (Qt key text, lower case) and their actions.
KEY_ACTIONS = {
    'w': LINEAR_UP,
    's': LINEAR_DOWN,
    'a': ANGULAR_UP,
    'd': ANGULAR_DOWN,
    'x': LINEAR_ZERO,
    'z': ANGULAR_ZERO,
    'space': STOP,
}

#: Values are kept on a 1e-3 grid (mm/s, mrad/s): the sliders are integer widgets.
RESOLUTION = 1e-3


def snap(value):
    """Rounds a velocity to the command grid so repeated steps do not drift."""
    return round(round(value / RESOLUTION) * RESOLUTION, 6)


@dataclass(frozen=True)
class Range:
    """A closed interval [minimum, maximum] of a velocity."""
    minimum: float
    maximum: float

    def __post_init__(self):
        if not self.minimum < self.maximum:
            raise ValueError(f'minimum {self.minimum} must be below maximum {self.maximum}')

    def clamp(self, value):
        return min(max(value, self.minimum), self.maximum)


class SteeringState:
    """Linear (m/s) and angular (rad/s) velocity, each clamped to its editable range."""

    def __init__(self, linear_range, angular_range, linear_step_mps, angular_step_radps):
        if linear_step_mps <= 0 or angular_step_radps <= 0:
            raise ValueError(f'steps must be positive, got {linear_step_mps} and '
                             f'{angular_step_radps}')
        self.linear_range = linear_range
        self.angular_range = angular_range
        self.linear_step_mps = linear_step_mps
        self.angular_step_radps = angular_step_radps
        self.linear_mps = 0.0
        self.angular_radps = 0.0

    @property
    def moving(self):
        return self.linear_mps != 0.0 or self.angular_radps != 0.0

    def set_linear(self, value_mps):
        self.linear_mps = snap(self.linear_range.clamp(value_mps))

    def set_angular(self, value_radps):
        self.angular_radps = snap(self.angular_range.clamp(value_radps))

    def set_linear_range(self, new_range):
        self.linear_range = new_range
        self.set_linear(self.linear_mps)

    def set_angular_range(self, new_range):
        self.angular_range = new_range
        self.set_angular(self.angular_radps)

    def apply(self, action):
        """Applies one of the action constants (a key press or a button)."""
        if action == LINEAR_UP:
            self.set_linear(self.linear_mps + self.linear_step_mps)
        elif action == LINEAR_DOWN:
            self.set_linear(self.linear_mps - self.linear_step_mps)
        elif action == ANGULAR_UP:
            self.set_angular(self.angular_radps + self.angular_step_radps)
        elif action == ANGULAR_DOWN:
            self.set_angular(self.angular_radps - self.angular_step_radps)
        elif action == LINEAR_ZERO:
            self.set_linear(0.0)
        elif action == ANGULAR_ZERO:
            self.set_angular(0.0)
        elif action == STOP:
            self.set_linear(0.0)
            self.set_angular(0.0)
        else:
            raise ValueError(f'unknown steering action {action!r}')
