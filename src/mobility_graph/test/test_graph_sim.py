#!/usr/bin/python3
"""`graph_view --output` on the running simulation names the simulator node and its
topics with the right directions."""
import os
import subprocess
import sys
import tempfile
import unittest

import rostest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg_graph import read_svg_graph  # noqa: E402
from system_wait import wait_for_connections  # noqa: E402

SIM = '/gazebo'  # bullet_sim_node, started by gazebo_ros's gzserver as node gazebo
RSP = '/robot_state_publisher'


class GraphSimTest(unittest.TestCase):
    def test_simulator_topics_and_directions(self):
        wait_for_connections([(SIM, '/scan'), (SIM, '/joint_states'), (SIM, '/odom')],
                             [(SIM, '/cmd_vel'), (RSP, '/joint_states')], timeout_s=90)
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, 'sim.svg')
            result = subprocess.run(['rosrun', 'mobility_graph', 'graph_view', '--mode', 'all',
                                     '--output', path], capture_output=True, text=True,
                                    timeout=60)
            self.assertEqual(result.returncode, 0, result.stderr)
            vertices, edges = read_svg_graph(path)
        self.assertLessEqual({'n:' + SIM, 'n:' + RSP, 't:/cmd_vel', 't:/scan',
                              't:/joint_states'}, vertices)
        self.assertLessEqual({('n:' + SIM, 't:/scan'), ('n:' + SIM, 't:/joint_states'),
                              ('t:/cmd_vel', 'n:' + SIM), ('t:/joint_states', 'n:' + RSP)},
                             edges)
        self.assertNotIn(('t:/scan', 'n:' + SIM), edges)


if __name__ == '__main__':
    rostest.rosrun('mobility_graph', 'graph_of_simulation', GraphSimTest, sys.argv)
