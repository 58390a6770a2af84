"""Key bindings of the terminal teleop (the layout of teleop_twist_keyboard).

   u    i    o        q/z  both speeds +-10 %
   j    k    l        w/x  linear speed +-10 %
   m    ,    .        e/c  angular speed +-10 %
Any other key stops. Speeds are clamped to the configured limits (the Burger's)."""

#: key -> (linear direction, angular direction)
MOVE_KEYS = {
    'i': (1, 0), 'o': (1, -1), 'j': (0, 1), 'l': (0, -1),
    'u': (1, 1), ',': (-1, 0), '.': (-1, 1), 'm': (-1, -1),
}

#: key -> (linear speed factor, angular speed factor)
SPEED_KEYS = {
    'q': (1.1, 1.1), 'z': (0.9, 0.9),
    'w': (1.1, 1.0), 'x': (0.9, 1.0),
    'e': (1.0, 1.1), 'c': (1.0, 0.9),
}

HELP = __doc__.split('\n\n', 1)[1].strip()


class TeleopState:
    """Current direction and speeds; `command()` is the (linear, angular) to publish."""

    def __init__(self, speed_mps, turn_radps, speed_limit_mps, turn_limit_radps):
        self.speed_limit_mps = speed_limit_mps
        self.turn_limit_radps = turn_limit_radps
        self.speed_mps = min(speed_mps, speed_limit_mps)
        self.turn_radps = min(turn_radps, turn_limit_radps)
        self.linear_dir = 0
        self.angular_dir = 0

    def handle_key(self, key):
        """Applies one key; returns 'move', 'speed' or 'stop'."""
        if key in MOVE_KEYS:
            self.linear_dir, self.angular_dir = MOVE_KEYS[key]
            return 'move'
        if key in SPEED_KEYS:
            linear_factor, angular_factor = SPEED_KEYS[key]
            self.speed_mps = min(self.speed_mps * linear_factor, self.speed_limit_mps)
            self.turn_radps = min(self.turn_radps * angular_factor, self.turn_limit_radps)
            return 'speed'
        self.linear_dir, self.angular_dir = 0, 0
        return 'stop'

    def command(self):
        return self.linear_dir * self.speed_mps, self.angular_dir * self.turn_radps

    def status(self):
        return f'speed {self.speed_mps:.3f} m/s  turn {self.turn_radps:.3f} rad/s'
