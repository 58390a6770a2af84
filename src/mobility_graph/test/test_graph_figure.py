#!/usr/bin/python3
"""The node graph window while the steering window and the image viewer run on the
simulation: once the master lists the steering node publishing /cmd_vel and the viewer
subscribed to the camera, the window (auto-refreshing) is photographed; the picture must
hold the graph's node colour (light blue ellipses) beside the topic colour (light yellow)."""
import os
import sys
import time
import unittest

import rosgraph
import rospy
import rostest

from mobility_testing import images, x11
from mobility_testing.waiting import wait_for

NODE_FILL = (207, 226, 243)
TOPIC_FILL = (255, 242, 204)


def node_with(master, kind, topic, prefix):
    pubs, subs, _ = master.getSystemState()
    for name, nodes in (pubs if kind == 'pub' else subs):
        if name == topic and any(n.startswith(prefix) for n in nodes):
            return True
    return False


class GraphFigure(unittest.TestCase):
    def test_graph_of_steering_and_image_view(self):
        master = rosgraph.Master('/graph_figure')
        wait_for(lambda: node_with(master, 'pub', '/cmd_vel', '/robot_steering')
                 and node_with(master, 'sub', '/camera/image_raw', '/image_view'),
                 90, 'the steering and image view nodes at the master')
        graph = x11.wait_window('^Node Graph', 60)
        x11.move(x11.wait_window('^Robot Steering', 60), 1120, 0)
        x11.move(x11.wait_window('^Image View', 60), 1120, 560)
        x11.move(graph, 0, 0)
        time.sleep(3.0)  # two auto-refreshes of the graph after the last node arrived
        path = rospy.get_param('~screenshot')
        os.makedirs(os.path.dirname(path), exist_ok=True)
        x11.screenshot('root', path)
        x, y, width, height = x11.geometry(graph)
        screen = images.load_png(path)
        images.save_png(screen[y:y + height, x:x + width], path)
        picture = images.load_png(path)
        self.assertGreater(images.count_colour(picture, NODE_FILL, 12), 500)
        self.assertGreater(images.count_colour(picture, TOPIC_FILL, 12), 500)


if __name__ == '__main__':
    rospy.init_node('graph_figure_check')
    rostest.rosrun('mobility_graph', 'graph_figure', GraphFigure, sys.argv)
