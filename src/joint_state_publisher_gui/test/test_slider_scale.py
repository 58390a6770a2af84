"""Slider steps <-> joint positions."""
import math
import unittest

from joint_sliders.slider_scale import SLIDER_STEPS, from_step, to_step


class SliderScaleTest(unittest.TestCase):

    def test_steps_are_ints_at_the_ends_and_middle(self):
        for position, step in ((-math.pi, 0), (0.0, SLIDER_STEPS // 2), (math.pi, SLIDER_STEPS)):
            value = to_step(position, -math.pi, math.pi)
            self.assertIsInstance(value, int)
            self.assertEqual(value, step)

    def test_middle_step_is_exactly_the_middle(self):
        self.assertEqual(from_step(SLIDER_STEPS // 2, -math.pi, math.pi), 0.0)
        self.assertEqual(from_step(SLIDER_STEPS // 2, 0.1, 0.3), 0.2)

    def test_quarter_step(self):
        self.assertAlmostEqual(from_step(SLIDER_STEPS // 4, -1.0, 1.0), -0.5)

    def test_round_trip_within_one_step(self):
        lower, upper = -1.5, 2.0
        for position in (-1.5, -0.3333, 0.0, 1.234, 2.0):
            back = from_step(to_step(position, lower, upper), lower, upper)
            self.assertLessEqual(abs(back - position), (upper - lower) / SLIDER_STEPS)

    def test_out_of_range_is_clamped(self):
        self.assertEqual(to_step(5.0, -1.0, 1.0), SLIDER_STEPS)
        self.assertEqual(to_step(-5.0, -1.0, 1.0), 0)

    def test_empty_range(self):
        self.assertEqual(to_step(0.2, 0.2, 0.2), 0)
        self.assertEqual(from_step(123, 0.2, 0.2), 0.2)
