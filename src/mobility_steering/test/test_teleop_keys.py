import unittest

from mobility_steering.teleop_keys import HELP, MOVE_KEYS, TeleopState


def state():
    return TeleopState(0.1, 1.0, 0.22, 2.84)


class TeleopKeysTest(unittest.TestCase):
    def test_i_drives_forward_at_speed(self):
        s = state()
        self.assertEqual(s.handle_key('i'), 'move')
        self.assertEqual(s.command(), (0.1, 0.0))

    def test_diagonals_and_reverse(self):
        s = state()
        expected = {'u': (0.1, 1.0), 'o': (0.1, -1.0), 'j': (0.0, 1.0), 'l': (0.0, -1.0),
                    ',': (-0.1, 0.0), '.': (-0.1, 1.0), 'm': (-0.1, -1.0)}
        for key, command in expected.items():
            s.handle_key(key)
            self.assertEqual(s.command(), command, key)
        self.assertEqual(set(MOVE_KEYS), set(expected) | {'i'})

    def test_any_other_key_stops(self):
        s = state()
        s.handle_key('i')
        self.assertEqual(s.handle_key('k'), 'stop')
        self.assertEqual(s.command(), (0.0, 0.0))
        s.handle_key('i')
        s.handle_key('7')
        self.assertEqual(s.command(), (0.0, 0.0))

    def test_speed_keys_scale_and_keep_direction(self):
        s = state()
        s.handle_key('i')
        self.assertEqual(s.handle_key('w'), 'speed')
        self.assertAlmostEqual(s.command()[0], 0.11)
        s.handle_key('c')
        self.assertAlmostEqual(s.turn_radps, 0.9)
        s.handle_key('z')
        self.assertAlmostEqual(s.speed_mps, 0.099)
        self.assertAlmostEqual(s.turn_radps, 0.81)

    def test_speeds_are_clamped_to_the_burger_limits(self):
        s = state()
        for _ in range(50):
            s.handle_key('q')
        self.assertEqual((s.speed_mps, s.turn_radps), (0.22, 2.84))

    def test_start_speed_above_limit_is_clamped(self):
        self.assertEqual(TeleopState(1.0, 5.0, 0.22, 2.84).command(), (0.0, 0.0))
        self.assertEqual(TeleopState(1.0, 5.0, 0.22, 2.84).speed_mps, 0.22)

    def test_help_lists_the_layout(self):
        self.assertIn('u    i    o', HELP)
