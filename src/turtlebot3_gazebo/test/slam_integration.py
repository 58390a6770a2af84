#!/usr/bin/python3
"""gmapping along one lap of the round track (rostest node of slam_integration.test).

The Burger is driven round the track by cmd_vel, as with teleop, along the lanes' middle
(steered from its true pose, so that the lap is the same every run); then gmapping's map
must match the true walls: its occupied cells (value >= 65, map_saver's threshold) lie
within 0.10 m of a wall for at least 90 % of the walls' length, and at least 80 % of them
lie that close to a wall (a bound on stray cells and on a map that slid along a lane). The robot never touches a wall. Figures go to ~figures_file;
the map is saved with map_saver beside it.
"""
import json
import math
import os
import subprocess
import time
import unittest

import numpy as np
import rospy
import rostest
from nav_msgs.msg import OccupancyGrid

import sim_truth
from sim_truth import navigation_figures

# The lanes' middle, from the spawn pose north, east along the top, south, west and back.
LAP = [(-0.13, 1.9), (0.45, 2.75), (0.97, 2.65), (1.64, 1.9), (2.1, 1.72), (3.9, 1.72),
       (4.6, 1.0), (4.6, -0.7), (4.3, -1.5), (3.6, -2.05), (2.8, -2.14), (0.3, -2.14),
       (-0.13, -1.6), (-0.13, 0.0)]
REACHED_M = 0.25
SPEED_MPS = 0.15
TURN_RADPS = 0.8  # gentle turns, as a person drives
LAP_TIMEOUT_SIM_S = 400.0
TOLERANCE_M = 0.10
FIGURES = {}


def steer(pose, target):
    heading = math.atan2(target[1] - pose[1], target[0] - pose[0])
    error = math.atan2(math.sin(heading - pose[2]), math.cos(heading - pose[2]))
    return SPEED_MPS * max(0.0, math.cos(error)) ** 2, max(-TURN_RADPS, min(TURN_RADPS, 2.5 * error))


def occupied_cells(grid):
    data = np.array(grid.data, dtype=np.int16).reshape(grid.info.height, grid.info.width)
    rows, columns = np.nonzero(data >= 65)
    r, o = grid.info.resolution, grid.info.origin.position
    return np.column_stack([o.x + (columns + 0.5) * r, o.y + (rows + 0.5) * r])


class TestSlam(unittest.TestCase):
    def setUp(self):
        rospy.init_node('slam_integration')
        self.truth = sim_truth.Truth()
        self.driver = sim_truth.Driver()
        self.maps = []
        rospy.Subscriber('/map', OccupancyGrid, self.maps.append, queue_size=1)
        end = time.monotonic() + 60
        while self.truth.get() is None or rospy.get_time() < 1.0:
            self.assertLess(time.monotonic(), end, 'no true pose or sim time')
            time.sleep(0.05)

    def drive_lap(self):
        rate = rospy.Rate(20)
        start = rospy.get_time()
        for target in LAP:
            while math.hypot(target[0] - self.truth.get()[0],
                             target[1] - self.truth.get()[1]) > REACHED_M:
                self.assertLess(rospy.get_time() - start, LAP_TIMEOUT_SIM_S, 'lap too slow')
                self.driver.send(*steer(self.truth.get(), target))
                rate.sleep()
        self.driver.stop()

    def test_a_lap_maps_the_walls(self):
        start_sim, start_wall = rospy.get_time(), time.monotonic()
        self.drive_lap()
        lap_end = rospy.get_time()
        FIGURES['lap'] = {'sim_s': round(lap_end - start_sim, 1),
                          'wall_s': round(time.monotonic() - start_wall, 1),
                          'min_clearance_m': round(self.truth.min_clearance_m, 3)}
        end = time.monotonic() + 60
        while not self.maps or self.maps[-1].header.stamp.to_sec() < lap_end:
            self.assertLess(time.monotonic(), end, 'no map after the lap')
            time.sleep(0.1)
        cells = occupied_cells(self.maps[-1])
        precision, coverage = navigation_figures.map_against_walls(
            cells, sim_truth.WALLS, TOLERANCE_M)
        FIGURES['map'] = {'occupied_cells': len(cells),
                          'cells_within_0_10_m_of_a_wall': round(precision, 3),
                          'wall_length_with_a_cell_within_0_10_m': round(coverage, 3)}
        figures_file = rospy.get_param('~figures_file')
        with open(figures_file, 'w') as f:
            json.dump(FIGURES, f, indent=1)
        subprocess.run(['rosrun', 'map_server', 'map_saver', '-f',
                        os.path.splitext(figures_file)[0] + '_map'], timeout=60)
        self.assertGreater(self.truth.min_clearance_m, 0.0, 'touched a wall')
        self.assertGreaterEqual(coverage, 0.90, FIGURES)
        self.assertGreaterEqual(precision, 0.80, FIGURES)


if __name__ == '__main__':
    rostest.rosrun('turtlebot3_gazebo', 'slam_integration', TestSlam)
