import unittest

from mobility_steering import velocity
from mobility_steering.velocity import Range, SteeringState


def burger_state():
    return SteeringState(Range(-0.22, 0.22), Range(-2.84, 2.84), 0.02, 0.2)


class VelocityTest(unittest.TestCase):
    def test_starts_at_rest(self):
        state = burger_state()
        self.assertEqual((state.linear_mps, state.angular_radps), (0.0, 0.0))
        self.assertFalse(state.moving)

    def test_w_steps_up_and_clamps_at_max(self):
        state = burger_state()
        state.apply(velocity.KEY_ACTIONS['w'])
        self.assertEqual(state.linear_mps, 0.02)
        for _ in range(20):
            state.apply(velocity.LINEAR_UP)
        self.assertEqual(state.linear_mps, 0.22)

    def test_repeated_steps_do_not_drift(self):
        state = burger_state()
        for _ in range(7):
            state.apply(velocity.LINEAR_UP)
        for _ in range(7):
            state.apply(velocity.LINEAR_DOWN)
        self.assertEqual(state.linear_mps, 0.0)

    def test_a_turns_left_d_turns_right(self):
        state = burger_state()
        state.apply(velocity.KEY_ACTIONS['a'])
        self.assertEqual(state.angular_radps, 0.2)
        for _ in range(3):
            state.apply(velocity.KEY_ACTIONS['d'])
        self.assertEqual(state.angular_radps, -0.4)

    def test_zero_keys_and_stop(self):
        state = burger_state()
        state.apply(velocity.LINEAR_UP)
        state.apply(velocity.ANGULAR_UP)
        state.apply(velocity.KEY_ACTIONS['x'])
        self.assertEqual((state.linear_mps, state.angular_radps), (0.0, 0.2))
        state.apply(velocity.LINEAR_UP)
        state.apply(velocity.KEY_ACTIONS['z'])
        self.assertEqual((state.linear_mps, state.angular_radps), (0.02, 0.0))
        state.apply(velocity.ANGULAR_UP)
        state.apply(velocity.KEY_ACTIONS['space'])
        self.assertFalse(state.moving)

    def test_narrowing_a_range_clamps_the_value(self):
        state = burger_state()
        state.set_linear(0.2)
        state.set_linear_range(Range(-0.1, 0.1))
        self.assertEqual(state.linear_mps, 0.1)

    def test_range_rejects_inverted_limits(self):
        with self.assertRaisesRegex(ValueError, 'minimum 0.5 must be below maximum 0.1'):
            Range(0.5, 0.1)

    def test_unknown_action_is_named(self):
        with self.assertRaisesRegex(ValueError, "'jump'"):
            burger_state().apply('jump')
