#!/usr/bin/python3
"""The real graph window: draws the running system, follows new nodes by itself
(auto-refresh), switches modes from the keyboard; screenshots are measured."""
import os
import subprocess
import sys
import unittest

import rostest

from mobility_testing import images, x11
from mobility_testing.waiting import wait_for

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from system_wait import wait_for_connections  # noqa: E402

NODE_BLUE = (0xcf, 0xe2, 0xf3)
TOPIC_YELLOW = (0xff, 0xf2, 0xcc)


class GraphWindowTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        wait_for_connections([('/talker', '/chatter'), ('/relay', '/relayed')],
                             [('/listener', '/relayed')])
        cls.window = x11.wait_window('^Node Graph$', timeout_s=60)
        cls.shot_dir = os.environ.get('SCREENSHOT_DIR') or os.environ.get('ROS_HOME', '/tmp')

    def colours(self, name):
        shot = x11.screenshot_array(self.window, os.path.join(self.shot_dir, name))
        return (images.count_colour(shot, NODE_BLUE, 6),
                images.count_colour(shot, TOPIC_YELLOW, 6))

    def test_draws_follows_and_switches_mode(self):
        blue, yellow = wait_for(lambda: all(c > 500 for c in self.colours('graph_a.png'))
                                and self.colours('graph_a.png'), 30,
                                'node and topic shapes in the window')
        late = subprocess.Popen(['rosrun', 'mobility_graph', 'fixture_node.py',
                                 '__name:=late', '--pub', '/late_topic', '--sub', '/relayed'])
        self.addCleanup(late.wait)
        self.addCleanup(late.terminate)
        wait_for(lambda: self.colours('graph_view.png')[1] > yellow * 1.2, 30,
                 f'more topic colour than {yellow} px once /late_topic exists')
        x11.key(self.window, 'ctrl+1')
        wait_for(lambda: self.colours('graph_c.png')[1] == 0, 15,
                 'no topic boxes in nodes-only mode')
        x11.key(self.window, 'ctrl+2')
        wait_for(lambda: self.colours('graph_d.png')[1] > yellow, 15,
                 'topic boxes back in nodes/topics mode')


if __name__ == '__main__':
    rostest.rosrun('mobility_graph', 'graph_window', GraphWindowTest, sys.argv)
