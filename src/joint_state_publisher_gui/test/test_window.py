"""The window's widgets without an X server (Qt's offscreen platform): rows,
typed values, Center, Randomize, the filter, the no-joints message, the layout report."""
import math
import os
import random
import unittest

os.environ['QT_QPA_PLATFORM'] = 'offscreen'

from PyQt5.QtWidgets import QApplication  # noqa: E402

from joint_sliders.joint_model import JointModel  # noqa: E402
from joint_sliders.layout_report import describe  # noqa: E402
from joint_sliders.slider_scale import SLIDER_STEPS  # noqa: E402
from joint_sliders.urdf_joints import parse_joints  # noqa: E402
from joint_sliders.window import NO_JOINTS_TEXT, JointWindow  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
APP = QApplication.instance() or QApplication([])


def window_for(fixture, seed=5):
    with open(os.path.join(HERE, 'urdf', fixture), encoding='utf-8') as f:
        name, specs = parse_joints(f.read())
    window = JointWindow(JointModel(specs), name, random.Random(seed))
    window.show()
    APP.processEvents()
    return window


class WindowTest(unittest.TestCase):

    def setUp(self):
        self.window = window_for('arm_minimal.urdf')
        self.rows = {row.joint.name: row for row in self.window.rows}

    def tearDown(self):
        self.window.close()

    def test_rows_units_and_title(self):
        self.assertEqual(list(self.rows), ['shoulder', 'lift', 'finger_left', 'wrist_roll'])
        self.assertEqual(self.rows['lift'].value_box.suffix(), ' m')
        self.assertEqual(self.rows['shoulder'].value_box.suffix(), ' rad')
        self.assertEqual(self.window.windowTitle(), 'Joint State Publisher - test_arm')
        self.assertFalse(self.window.message.isVisible())

    def test_slider_step_sets_model(self):
        self.rows['wrist_roll'].slider.setValue(SLIDER_STEPS // 4)
        self.assertAlmostEqual(self.window.model.position('wrist_roll'), -math.pi / 2)
        self.assertAlmostEqual(self.rows['wrist_roll'].value_box.value(), -math.pi / 2,
                               places=3)

    def test_typed_value_sets_model_and_slider(self):
        self.rows['shoulder'].value_box.setValue(1.0)
        self.assertEqual(self.window.model.position('shoulder'), 1.0)
        self.assertEqual(self.rows['shoulder'].slider.value(),
                         round(SLIDER_STEPS * (1.0 + 1.5) / 3.5))

    def test_randomize_then_center(self):
        self.window.randomize_button.click()
        rng = random.Random(5)
        for row in self.window.rows:
            self.assertEqual(row.joint.position, rng.uniform(row.joint.lower, row.joint.upper))
        self.window.center_button.click()
        self.assertEqual(self.rows['shoulder'].slider.value(),
                         round(SLIDER_STEPS * 1.5 / 3.5))
        self.assertEqual(self.rows['wrist_roll'].slider.value(), SLIDER_STEPS // 2)
        self.assertAlmostEqual(self.rows['lift'].value_box.value(), 0.2)

    def test_filter(self):
        self.window.filter_edit.setText('FINGER')
        self.assertEqual([r.joint.name for r in self.window.rows if r.isVisible()],
                         ['finger_left'])
        self.window.filter_edit.clear()
        self.assertTrue(all(r.isVisible() for r in self.window.rows))

    def test_layout_report_places_handle_inside_groove(self):
        layout = describe(self.window)
        for entry in layout['rows']:
            groove, handle = entry['slider']['groove'], entry['slider']['handle']
            self.assertGreaterEqual(handle['x'], groove['x'])
            self.assertLessEqual(handle['x'] + handle['w'], groove['x'] + groove['w'])
            self.assertLessEqual(groove['x'] + groove['w'], layout['size']['w'])


class NoJointsWindowTest(unittest.TestCase):

    def test_message_and_disabled_buttons(self):
        window = window_for('fixed_only.urdf')
        self.addCleanup(window.close)
        self.assertEqual(window.rows, [])
        self.assertTrue(window.message.isVisible())
        self.assertEqual(window.message.text(), NO_JOINTS_TEXT)
        self.assertFalse(window.center_button.isEnabled())
        self.assertEqual(describe(window)['message'], NO_JOINTS_TEXT)
