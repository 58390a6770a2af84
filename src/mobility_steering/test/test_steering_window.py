"""The steering widget without ROS, on Qt's offscreen platform (no X server needed)."""
import os
import unittest

os.environ.setdefault('QT_QPA_PLATFORM', 'offscreen')
from PyQt5 import QtWidgets  # noqa: E402

from mobility_steering.steering_window import SteeringWindow  # noqa: E402
from mobility_steering.velocity import Range, SteeringState  # noqa: E402

APP = QtWidgets.QApplication.instance() or QtWidgets.QApplication([])


def make_window():
    state = SteeringState(Range(-0.22, 0.22), Range(-2.84, 2.84), 0.02, 0.2)
    return SteeringWindow(state, '/cmd_vel')


class SteeringWindowTest(unittest.TestCase):
    def test_sliders_span_the_limits_in_milli_units(self):
        window = make_window()
        self.assertEqual((window.linear_slider.minimum(), window.linear_slider.maximum()),
                         (-220, 220))
        self.assertEqual((window.angular_slider.minimum(), window.angular_slider.maximum()),
                         (-2840, 2840))

    def test_slider_sets_the_command(self):
        window = make_window()
        window.linear_slider.setValue(150)
        window.angular_slider.setValue(-1000)
        self.assertEqual((window.state.linear_mps, window.state.angular_radps), (0.15, -1.0))
        self.assertEqual(window.linear_value.text(), '+0.150 m/s')

    def test_editing_max_narrows_slider_and_clamps(self):
        window = make_window()
        window.linear_slider.setValue(200)
        window.vx_max_box.setValue(0.1)
        self.assertEqual(window.linear_slider.maximum(), 100)
        self.assertEqual(window.state.linear_mps, 0.1)

    def test_inverted_limits_are_refused_with_a_message(self):
        window = make_window()
        window.vw_min_box.setValue(3.0)
        self.assertEqual(window.state.angular_range, Range(-2.84, 2.84))
        self.assertIn('limits not applied', window.status_label.text())

    def test_stop_button_zeroes_both(self):
        window = make_window()
        window.linear_slider.setValue(100)
        window.angular_slider.setValue(500)
        window.stop_button.click()
        self.assertFalse(window.state.moving)
        self.assertEqual(window.angular_slider.value(), 0)

    def test_topic_edit_is_announced(self):
        window = make_window()
        topics = []
        window.topic_changed.connect(topics.append)
        window.topic_edit.setText(' /robot/cmd_vel ')
        window.topic_edit.editingFinished.emit()
        self.assertEqual(topics, ['/robot/cmd_vel'])
