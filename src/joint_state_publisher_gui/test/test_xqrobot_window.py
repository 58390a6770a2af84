#!/usr/bin/python3
"""The xqrobot in the real window: four sliders; a drag with xdotool moves the
joint in /joint_states and the wheel in tf; typing a value; the filter field."""
import math
import unittest

import numpy as np
import rospy
import rostest
import tf2_ros

import gui_support as gs
from mobility_testing import x11
from mobility_testing.waiting import wait_for

JOINTS = ['left_wheel_joint', 'right_wheel_joint', 'front_caster_joint', 'back_caster_joint']
AXIS = np.array([0.0, 1.0, 0.0])


def quaternion(transform):
    q = transform.transform.rotation
    return np.array([q.w, q.x, q.y, q.z])


def relative_rotation(q0, q1):
    """(angle, unit axis) of the rotation taking orientation q0 to q1 (w, x, y, z)."""
    w0, v0 = q0[0], -q0[1:]
    w1, v1 = q1[0], q1[1:]
    w = w0 * w1 - v0 @ v1
    v = w0 * v1 + w1 * v0 + np.cross(v0, v1)
    if w < 0.0:
        w, v = -w, -v
    angle = 2.0 * math.atan2(np.linalg.norm(v), w)
    return angle, v / max(np.linalg.norm(v), 1e-12)


class XqrobotWindowTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_xqrobot_window')
        cls.report = rospy.get_param('~layout_report')
        cls.addClassCleanup(gs.remove_layout, cls.report)
        cls.states = gs.JointStateWatcher()
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)
        cls.window = gs.open_window()

    def wheel_rotation(self, link):
        def lookup():
            try:
                return self.tf_buffer.lookup_transform('base_link', link, rospy.Time(0))
            except tf2_ros.TransformException:
                return None
        return quaternion(wait_for(lookup, gs.TIMEOUT_S, f'tf base_link -> {link}'))

    def current_wheel_rotation(self, link, angle_from_rest, rest):
        """Waits until tf shows the wheel turned by angle_from_rest; returns the rotation."""
        def turned():
            angle, axis = relative_rotation(rest, self.wheel_rotation(link))
            return (angle, axis) if abs(angle - abs(angle_from_rest)) < 0.01 else None
        return wait_for(turned, gs.TIMEOUT_S, f'{link} turned by {angle_from_rest:.3f} rad')

    def test_1_four_sliders_at_zero(self):
        layout = gs.wait_layout(self.report, lambda l: len(l['rows']) == 4, 'four slider rows')
        self.assertEqual(sorted(r['name'] for r in layout['rows']), sorted(JOINTS))
        self.assertEqual(layout['message'], '')
        positions = self.states.wait_positions(lambda p: set(p) == set(JOINTS),
                                               'joint_states with the four joints')
        self.assertEqual(positions, {name: 0.0 for name in JOINTS})

    def test_2_drag_moves_joint_and_wheel_tf(self):
        rest = self.wheel_rotation('left_wheel_link')
        rest_right = self.wheel_rotation('right_wheel_link')
        layout = gs.wait_layout(self.report, lambda l: len(l['rows']) == 4, 'slider rows')
        entry = gs.row(layout, 'left_wheel_joint')
        x0, y0 = gs.centre(entry['slider']['handle'])
        drag_px = entry['slider']['groove']['w'] // 4
        expected = drag_px * gs.radians_per_pixel(entry)
        x11.drag(self.window, x0, y0, x0 + drag_px, y0)
        tolerance = 2.0 * gs.radians_per_pixel(entry)
        positions = self.states.wait_positions(
            lambda p: gs.close_to(p['left_wheel_joint'], expected, tolerance),
            f'left_wheel_joint near {expected:.3f} rad')
        for other in JOINTS[1:]:
            self.assertEqual(positions[other], 0.0)
        moved = positions['left_wheel_joint']
        angle, axis = self.current_wheel_rotation('left_wheel_link', moved, rest)
        rospy.loginfo('dragged %d px: expected %.4f rad, published %.4f rad, tf turned %.4f rad',
                      drag_px, expected, moved, angle)
        self.assertAlmostEqual(angle, abs(moved), delta=0.01)
        self.assertAlmostEqual(abs(axis @ AXIS), 1.0, delta=1e-3)
        still, _ = relative_rotation(rest_right, self.wheel_rotation('right_wheel_link'))
        self.assertAlmostEqual(still, 0.0, delta=1e-6)

    def test_3_typed_value_is_published(self):
        layout = gs.wait_layout(self.report, lambda l: len(l['rows']) == 4, 'slider rows')
        box = gs.row(layout, 'right_wheel_joint')['value_box']
        x11.click(self.window, *gs.centre(box))
        x11.key(self.window, 'ctrl+a')
        x11.type_text(self.window, '1.5')
        x11.key(self.window, 'Return')
        self.states.wait_positions(lambda p: abs(p['right_wheel_joint'] - 1.5) < 1e-9,
                                   'right_wheel_joint = 1.5 rad')
        layout = gs.wait_layout(self.report,
                                lambda l: gs.row(l, 'right_wheel_joint')['position'] == 1.5,
                                'the row showing 1.5')
        self.assertEqual(gs.row(layout, 'right_wheel_joint')['value_text'], '1.500 rad')

    def test_4_filter_hides_other_rows(self):
        layout = gs.wait_layout(self.report, lambda l: len(l['rows']) == 4, 'slider rows')
        x11.click(self.window, *gs.centre(layout['widgets']['filter']))
        x11.type_text(self.window, 'CASTER')
        layout = gs.wait_layout(self.report,
                                lambda l: sum(r['visible'] for r in l['rows']) == 2,
                                'two visible rows after filtering')
        self.assertEqual(sorted(r['name'] for r in layout['rows'] if r['visible']),
                         ['back_caster_joint', 'front_caster_joint'])


if __name__ == '__main__':
    rostest.rosrun('joint_state_publisher_gui', 'xqrobot_window', XqrobotWindowTest)
