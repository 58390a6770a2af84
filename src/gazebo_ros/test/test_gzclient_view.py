#!/usr/bin/python3
"""gzclient's window on a TurtleBot3-style launch (no robot_state_publisher, nothing in TF
publishes `world`) shows no error status: the fixed frame `world` exists in the view, as
Gazebo's window has its world without TF, and nothing is drawn that TF cannot place.

RViz draws an error status (the "Global Status: Error" line, a display's name) in red
(192, 32, 32); with the view as it was, the Displays panel had about 220 such pixels."""
import os
import tempfile
import unittest

import numpy as np
import rospy
import rostest
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import LaserScan

from mobility_testing import x11
from mobility_testing.waiting import wait_for

TIMEOUT_S = 60.0
ERROR_RED = np.array([192, 32, 32])
# Anti-aliased edges of the Marker displays' icons (red balls) come this close to it too.
MOST_STRAY_PIXELS = 20


def error_red_pixels(image, box):
    """Pixels within 8 levels of RViz's error colour inside box (x, y, w, h)."""
    x, y, w, h = box
    part = image[y:y + h, x:x + w].astype(int)
    return int((np.abs(part - ERROR_RED).max(axis=2) <= 8).sum())


class GzclientView(unittest.TestCase):
    def test_no_error_status_on_a_launch_without_robot_state_publisher(self):
        rospy.init_node('gzclient_view_test')
        window = x11.wait_window('RViz', TIMEOUT_S)
        render = wait_for(lambda: (x11.render_areas(window) or [None])[0], TIMEOUT_S,
                          'RViz\'s 3D view')
        wx, wy, _, _ = x11.geometry(window)
        # The docks left of the 3D view: Displays and the Simulation panel.
        docks = (0, render[1] - wy, render[0] - wx, render[3])
        # The Burger's lidar publishes: a LaserScan display of /scan (frame base_scan, with
        # no transform to world) would now be red.
        rospy.wait_for_message('/scan', LaserScan, timeout=TIMEOUT_S)
        start = rospy.wait_for_message('/clock', Clock, timeout=TIMEOUT_S).clock.to_sec()
        counts = []
        with tempfile.TemporaryDirectory(prefix='gzclient_view_') as folder:
            path = os.path.join(folder, 'window.png')
            # Five looks over 2 s of simulated time (RViz redraws at 30 Hz).
            for i in range(5):
                wait_for(lambda: rospy.wait_for_message('/clock', Clock, timeout=TIMEOUT_S)
                         .clock.to_sec() >= start + 0.5 * i, TIMEOUT_S, 'sim time')
                image = x11.screenshot_array(window, path)
                counts.append(error_red_pixels(image, docks))
        self.assertLess(max(counts), MOST_STRAY_PIXELS,
                        'red status in the Displays panel: %s pixels' % counts)


if __name__ == '__main__':
    rostest.rosrun('gazebo_ros', 'gzclient_view', GzclientView)
