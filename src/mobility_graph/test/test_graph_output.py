#!/usr/bin/python3
"""Runs `graph_view --output` against a running publisher/subscriber system and reads
the written files back."""
import os
import subprocess
import sys
import tempfile
import unittest

import rostest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from svg_graph import read_svg_graph, read_svg_labels  # noqa: E402
from system_wait import wait_for_connections  # noqa: E402

PUBLICATIONS = [('/talker', '/chatter'), ('/relay', '/relayed')]
SUBSCRIPTIONS = [('/relay', '/chatter'), ('/listener', '/chatter'), ('/listener', '/relayed')]


def graph_view(*args):
    return subprocess.run(['rosrun', 'mobility_graph', 'graph_view', *args],
                          capture_output=True, text=True, timeout=60)


class GraphOutputTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        wait_for_connections(PUBLICATIONS, SUBSCRIPTIONS)

    def setUp(self):
        tmp = tempfile.TemporaryDirectory()
        self.addCleanup(tmp.cleanup)
        self.dir = tmp.name

    def write(self, name, *args):
        path = os.path.join(self.dir, name)
        result = graph_view('--output', path, *args)
        self.assertEqual(result.returncode, 0, result.stderr)
        return path

    def test_all_mode_edges_follow_the_data(self):
        vertices, edges = read_svg_graph(self.write('x.svg', '--mode', 'all'))
        self.assertEqual(vertices, {'n:/talker', 'n:/relay', 'n:/listener',
                                    't:/chatter', 't:/relayed'})
        expected = {('n:' + n, 't:' + t) for n, t in PUBLICATIONS}
        expected |= {('t:' + t, 'n:' + n) for n, t in SUBSCRIPTIONS}
        self.assertEqual(edges, expected)

    def test_nodes_mode_labels_edges_with_topics(self):
        path = self.write('nodes.svg', '--mode', 'nodes')
        vertices, edges = read_svg_graph(path)
        self.assertEqual(vertices, {'n:/talker', 'n:/relay', 'n:/listener'})
        self.assertEqual(edges, {('n:/talker', 'n:/relay'), ('n:/talker', 'n:/listener'),
                                 ('n:/relay', 'n:/listener')})
        self.assertLessEqual({'/chatter', '/relayed', '/talker'}, read_svg_labels(path))

    def test_debug_items_hidden_unless_asked(self):
        vertices, _ = read_svg_graph(self.write('debug.svg', '--mode', 'all',
                                                '--show-debug'))
        self.assertIn('t:/rosout', vertices)  # every node logs there; rostest has no rosout
        hidden, _ = read_svg_graph(self.write('plain.svg', '--mode', 'all'))
        self.assertFalse({v for v in hidden if 'rosout' in v})

    def test_filter(self):
        vertices, edges = read_svg_graph(self.write('f.svg', '--mode', 'all',
                                                    '--filter', '^/relayed$'))
        self.assertEqual(edges, {('n:/relay', 't:/relayed'), ('t:/relayed', 'n:/listener')})
        self.assertEqual(len(vertices), 3)

    def test_png_and_dot(self):
        with open(self.write('x.png'), 'rb') as png:
            self.assertEqual(png.read(8), b'\x89PNG\r\n\x1a\n')
        with open(self.write('x.dot', '--mode', 'all')) as dot:
            self.assertIn('"n:/talker" -> "t:/chatter";', dot.read())

    def test_errors_are_explained(self):
        bad = graph_view('--output', os.path.join(self.dir, 'x.gif'))
        self.assertEqual(bad.returncode, 2)
        self.assertIn("'", bad.stderr)
        self.assertIn('.dot, .svg, .png', bad.stderr)
        env = dict(os.environ, ROS_MASTER_URI='http://127.0.0.1:1')
        down = subprocess.run(['rosrun', 'mobility_graph', 'graph_view', '--output',
                               os.path.join(self.dir, 'y.svg')], env=env,
                              capture_output=True, text=True, timeout=60)
        self.assertEqual(down.returncode, 1)
        self.assertIn('cannot reach the ROS master at http://127.0.0.1:1', down.stderr)


if __name__ == '__main__':
    rostest.rosrun('mobility_graph', 'graph_output_svg', GraphOutputTest, sys.argv)
