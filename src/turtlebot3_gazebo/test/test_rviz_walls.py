#!/usr/bin/python3
"""RViz with the round-track config draws the world: at the screen pixel where each wall of
the world file projects (computed here from the config's Orbit view, the render window's
place on the screen and the wall's pose), the view shows the wall's cardboard colour
(0.57 0.417 0.25, under any shading), and the track's middle shows ground, not wall."""
import math
import os
import sys
import unittest
import xml.etree.ElementTree as ET

import numpy as np
import rospkg
import rospy
import rostest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rviz_gui  # noqa: E402
from mobility_testing import images, x11  # noqa: E402
from mobility_testing.waiting import Timeout, wait_for  # noqa: E402

WALL_RGB = (0.57, 0.417, 0.25)
SEARCH_PX = 3


def walls(world_file):
    """(name, centre x, y, z, yaw, length, height) of every wall_* model of the world file."""
    found = []
    for model in ET.parse(world_file).getroot().iter('model'):
        if not model.get('name').startswith('wall_'):
            continue
        x, y, z, _, _, yaw = (float(v) for v in model.findtext('pose').split())
        _, length, height = (float(v) for v in
                             model.find('link/visual/geometry/box/size').text.split())
        found.append((model.get('name'), x, y, z, yaw, length, height))
    return found


def sample_points(wall):
    """Three points just under the wall's top edge: a quarter from each end and its centre.
    RViz lights a scene along its view direction, so a wall face that the view sees from
    the side away from the light is black; the top face is lit from any view above."""
    _, x, y, z, yaw, length, height = wall
    along = np.array([-math.sin(yaw), math.cos(yaw), 0.0])
    top = np.array([x, y, z + 0.5 * height - 0.005])
    return [top + f * length * along for f in (-0.25, 0.0, 0.25)]


class RvizWalls(unittest.TestCase):
    def test_walls_show_where_they_project(self):
        world = os.path.join(rospkg.RosPack().get_path('turtlebot3_gazebo'), 'worlds',
                             'roundTrack.world')
        wall_list = walls(world)
        self.assertEqual(len(wall_list), 21)
        window = rviz_gui.rviz_window()
        area, view = rviz_gui.view_area(window)
        path = rospy.get_param('~screenshot', '/tmp/roundTrack_rviz_walls.png')
        missing = {}

        def all_walls_drawn():
            mask = images.shade_mask(x11.screenshot_array('root', path), WALL_RGB)
            missing.clear()
            for wall in wall_list:
                for point in sample_points(wall):
                    px, py = (int(round(v)) for v in view.project(point, area))
                    patch = mask[py - SEARCH_PX:py + SEARCH_PX + 1,
                                 px - SEARCH_PX:px + SEARCH_PX + 1]
                    if not patch.any():
                        missing.setdefault(wall[0], []).append((px, py))
            return not missing

        try:
            wait_for(all_walls_drawn, rviz_gui.TIMEOUT_S, 'every wall in the RViz view',
                     poll_s=1.0)
        except Timeout as err:
            self.fail(f'{err}: no wall colour near {missing}; screenshot {path}')
        # The track's middle (the view's focal point) is ground.
        screen = x11.screenshot_array('root', path)
        cx, cy = (int(round(v)) for v in view.project(view.focal, area))
        self.assertFalse(images.shade_mask(screen[cy - 5:cy + 6, cx - 5:cx + 6], WALL_RGB).any())


if __name__ == '__main__':
    rospy.init_node('rviz_walls_check')
    rostest.rosrun('turtlebot3_gazebo', 'rviz_walls', RvizWalls, sys.argv)
