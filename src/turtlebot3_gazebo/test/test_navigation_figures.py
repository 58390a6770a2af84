#!/usr/bin/python3
"""navigation_figures against cases computed by hand and against the round track's own
ground-truth map (which must match its walls fully) and that map shifted by 0.2 m."""
import math
import os
import sys
import unittest

import numpy as np

PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(PACKAGE, 'scripts'))
import navigation_figures as nf  # noqa: E402
import occupancy_grid  # noqa: E402
import world_obstacles  # noqa: E402

WALL = world_obstacles.Rectangle('w', 1.0, 0.0, 0.0, 0.015, 2.0)  # along y at x = 1


class TestFigures(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.walls = world_obstacles.read_footprints(
            os.path.join(PACKAGE, 'worlds', 'roundTrack.world'))

    def test_clearance_of_the_outline(self):
        # facing the wall (+x): the body's front at 0.038 m, wall surface at 1 - 0.0075
        self.assertAlmostEqual(nf.clearance_m(0.5, 0.0, 0.0, [WALL]), 0.9925 - 0.538, places=6)
        # side on: a wheel's outer face 0.089 m from the centre
        self.assertAlmostEqual(nf.clearance_m(0.5, 0.0, math.pi / 2, [WALL]),
                               0.9925 - 0.589, places=6)
        self.assertLess(nf.clearance_m(0.98, 0.0, 0.0, [WALL]), 0.0)
        # beyond the wall's end the nearest point is its end
        self.assertAlmostEqual(nf.clearance_m(1.0, 1.5, math.pi / 2, [WALL]),
                               0.5 - 0.102 - 0.0075, places=6)

    def test_the_spawn_pose_is_clear_of_the_walls(self):
        self.assertGreater(nf.clearance_m(0.0, 0.0, 1.5675, self.walls), 0.4)

    def test_pose_error(self):
        d, a = nf.pose_error((1.0, 1.0, math.pi - 0.05), (1.3, 1.4, -math.pi + 0.05))
        self.assertAlmostEqual(d, 0.5)
        self.assertAlmostEqual(a, 0.1)

    def test_the_true_map_matches_the_walls_and_a_shifted_one_does_not(self):
        grid = occupancy_grid.rasterise(self.walls)
        rows, columns = np.nonzero(grid.occupied)
        cells = np.column_stack([grid.origin_x + (columns + 0.5) * grid.resolution,
                                 grid.origin_y + (rows + 0.5) * grid.resolution])
        precision, coverage = nf.map_against_walls(cells, self.walls)
        self.assertEqual((precision, coverage), (1.0, 1.0))
        precision, coverage = nf.map_against_walls(cells + [0.2, 0.0], self.walls)
        self.assertLess(precision, 0.6)
        self.assertLess(coverage, 0.6)
        self.assertEqual(nf.map_against_walls([], self.walls), (0.0, 0.0))


if __name__ == '__main__':
    unittest.main()
