"""The graph window without ROS (a fake system state), on Qt's offscreen platform."""
import os
import unittest

os.environ.setdefault('QT_QPA_PLATFORM', 'offscreen')
from PyQt5 import QtWidgets  # noqa: E402

from mobility_graph.graph_model import MODE_ALL, Options, SystemState  # noqa: E402
from mobility_graph.graph_window import GraphWindow  # noqa: E402
from mobility_graph.master_source import MasterUnreachable  # noqa: E402

APP = QtWidgets.QApplication.instance() or QtWidgets.QApplication([])
STATE = SystemState({'/chatter': ('/talker',), '/rosout': ('/talker', '/listener')},
                    {'/chatter': ('/listener',), '/rosout': ('/rosout',)})


class GraphWindowTest(unittest.TestCase):
    def window(self, fetch=lambda: STATE, options=Options(mode=MODE_ALL)):
        window = GraphWindow(fetch, options)
        self.addCleanup(window.close)
        return window

    def status(self, window):
        return window.statusBar().currentMessage()

    def test_counts_in_status_and_svg_in_view(self):
        window = self.window()
        self.assertTrue(self.status(window).startswith('2 nodes, 1 topics, 2 edges'))
        self.assertEqual(len(window.view.scene().items()), 1)

    def test_mode_and_debug_controls_rebuild(self):
        window = self.window()
        window.mode_combo.setCurrentIndex(0)
        self.assertTrue(self.status(window).startswith('2 nodes, 0 topics, 1 edges'))
        window.debug_check.setChecked(False)
        self.assertTrue(self.status(window).startswith('3 nodes, 0 topics, 3 edges'))

    def test_filter_field(self):
        window = self.window()
        window.filter_edit.setText('-listener')
        window.filter_edit.editingFinished.emit()
        self.assertTrue(self.status(window).startswith('1 nodes, 1 topics, 1 edges'))

    def test_master_down_is_shown_not_raised(self):
        def fetch():
            raise MasterUnreachable('cannot reach the ROS master at http://nowhere:11311')
        window = self.window(fetch)
        self.assertIn('cannot reach the ROS master', self.status(window))

    def test_auto_refresh_timer_follows_the_controls(self):
        window = GraphWindow(lambda: STATE, Options(), auto_refresh_s=3.0)
        self.addCleanup(window.close)
        self.assertEqual(window._timer.interval(), 3000)
        window.auto_check.setChecked(False)
        self.assertFalse(window._timer.isActive())
