#!/usr/bin/python3
"""maps/roundTrack.{pgm,yaml} against the round track's wall table of the design notes.

The table is typed here as the design notes give it (centre x, y, yaw, length; walls
0.015 m thick, their length along the wall's local y axis), independently of the world
generator: every wall's centre and both ends lie in occupied cells, points 0.15 m to either
side of every wall are free, no occupied cell lies off the walls, and map_server's
resolution and origin are right. The files in maps/ are what the generator writes.
"""
import math
import os
import sys
import tempfile
import unittest

PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(PACKAGE, 'scripts'))
import make_round_track_map  # noqa: E402
import occupancy_grid  # noqa: E402
import world_obstacles  # noqa: E402

WALLS = [
    (1.53496, 2.894504, 0.736056, 1.0), (2.04294, 2.386858, 0.881268, 0.5),
    (3.72582, 2.23758, 1.57177, 3.0), (0.196982, 3.258921, 1.57467, 2.0),
    (5.21431, 0.73692, -0.000378, 3.0), (3.8664, -2.46629, -1.1525, 0.5),
    (5.13135, -0.99504, -0.334721, 0.5), (4.92558, -1.45102, -0.501603, 0.5),
    (4.2862, -2.20397, -0.858577, 0.5), (3.41064, -2.6531, 1.9485, 0.5),
    (-0.80941, 0.25461, 0, 6.0), (4.63833, -1.85451, 2.40733, 0.5),
    (1.1918, -2.74499, 1.5735, 4.0), (0.54193, 0.34703, 0, 3.8),
    (0.87641, 1.88745, 0.736056, 1.0), (1.4037, 1.35442, 0.881268, 0.5),
    (2.78265, 1.19568, 1.57177, 2.4), (3.98336, 0.09495, -0.000378, 2.2),
    (1.89949, -1.53786, 1.5735, 2.7), (3.43608, -1.41841, 2.08925, 0.5),
    (3.79555, -1.15857, -0.858577, 0.5),
]
THICKNESS_M = 0.015
RESOLUTION_M = 0.05


def along(wall, s, offset=0.0):
    """The point s metres along the wall from its centre, offset metres to its side."""
    x, y, yaw, _ = wall
    direction = (-math.sin(yaw), math.cos(yaw))  # the box's local y axis
    normal = (math.cos(yaw), math.sin(yaw))
    return (x + s * direction[0] + offset * normal[0], y + s * direction[1] + offset * normal[1])


def distance_to_wall(point, wall):
    x, y, yaw, length = wall
    dx, dy = point[0] - x, point[1] - y
    s = max(-length / 2, min(length / 2, -dx * math.sin(yaw) + dy * math.cos(yaw)))
    ex, ey = along(wall, s)
    return math.hypot(point[0] - ex, point[1] - ey)


def read_pgm(path):
    with open(path, 'rb') as f:
        data = f.read()
    magic, size, maxval, pixels = data.split(b'\n', 3)
    columns, rows = (int(v) for v in size.split())
    return magic, columns, rows, int(maxval), pixels


class TestRoundTrackMap(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.yaml = os.path.join(PACKAGE, 'maps', 'roundTrack.yaml')
        with open(cls.yaml) as f:
            cls.fields = dict(line.split(': ', 1) for line in f.read().splitlines())
        magic, columns, rows, maxval, pixels = read_pgm(os.path.join(PACKAGE, 'maps',
                                                                     cls.fields['image']))
        cls.header = (magic, maxval, len(pixels))
        cls.columns, cls.rows, cls.pixels = columns, rows, pixels
        cls.origin = [float(v) for v in cls.fields['origin'].strip('[]').split(',')]

    def value_at(self, x, y):
        column = int(math.floor((x - self.origin[0]) / RESOLUTION_M))
        row_from_bottom = int(math.floor((y - self.origin[1]) / RESOLUTION_M))
        self.assertTrue(0 <= column < self.columns and 0 <= row_from_bottom < self.rows,
                        'point %.3f, %.3f outside the map' % (x, y))
        return self.pixels[(self.rows - 1 - row_from_bottom) * self.columns + column]

    def test_map_server_fields(self):
        self.assertEqual(self.header, (b'P5', 255, self.columns * self.rows))
        self.assertEqual(float(self.fields['resolution']), RESOLUTION_M)
        self.assertEqual(self.fields['negate'], '0')
        self.assertEqual(float(self.fields['occupied_thresh']), 0.65)
        self.assertEqual(float(self.fields['free_thresh']), 0.196)
        self.assertEqual(self.origin[2], 0.0)
        self.assertEqual(set(self.pixels), {occupancy_grid.FREE, occupancy_grid.OCCUPIED})

    def test_the_map_covers_every_wall_with_free_space_around(self):
        ends = [along(w, s * (w[3] / 2)) for w in WALLS for s in (-1, 1)]
        xs, ys = [p[0] for p in ends], [p[1] for p in ends]
        self.assertLess(self.origin[0], min(xs) - 0.3)
        self.assertLess(self.origin[1], min(ys) - 0.3)
        self.assertGreater(self.origin[0] + self.columns * RESOLUTION_M, max(xs) + 0.3)
        self.assertGreater(self.origin[1] + self.rows * RESOLUTION_M, max(ys) + 0.3)
        for v in self.origin[:2]:
            self.assertAlmostEqual(v / RESOLUTION_M, round(v / RESOLUTION_M), places=6)

    def test_every_wall_centre_and_end_is_occupied(self):
        for i, wall in enumerate(WALLS):
            for s in (-wall[3] / 2 + 0.005, 0.0, wall[3] / 2 - 0.005):
                point = along(wall, s)
                self.assertEqual(self.value_at(*point), occupancy_grid.OCCUPIED,
                                 'wall %d at %.3f, %.3f' % (i, point[0], point[1]))

    def test_cells_0_15_m_off_the_walls_are_free(self):
        checked = 0
        for wall in WALLS:
            for k in range(11):
                for side in (-0.15, 0.15):
                    point = along(wall, (k / 10.0 - 0.5) * wall[3], side)
                    if min(distance_to_wall(point, w) for w in WALLS) < 0.149:
                        continue  # near a corner another wall is closer
                    checked += 1
                    self.assertEqual(self.value_at(*point), occupancy_grid.FREE,
                                     'point %.3f, %.3f' % point)
        self.assertGreater(checked, 350)
        self.assertEqual(self.value_at(0.0, 0.0), occupancy_grid.FREE)  # the spawn point

    def test_no_occupied_cell_lies_off_the_walls(self):
        reach = RESOLUTION_M / math.sqrt(2) + THICKNESS_M / 2 + 1e-6
        occupied = 0
        for index, value in enumerate(self.pixels):
            if value != occupancy_grid.OCCUPIED:
                continue
            occupied += 1
            row_from_bottom = self.rows - 1 - index // self.columns
            centre = (self.origin[0] + (index % self.columns + 0.5) * RESOLUTION_M,
                      self.origin[1] + (row_from_bottom + 0.5) * RESOLUTION_M)
            self.assertLessEqual(min(distance_to_wall(centre, w) for w in WALLS), reach,
                                 'cell at %.3f, %.3f' % centre)
        total_length_cells = sum(w[3] for w in WALLS) / RESOLUTION_M
        self.assertGreater(occupied, total_length_cells)

    def test_the_files_are_what_the_generator_writes(self):
        with tempfile.TemporaryDirectory() as tmp:
            target = os.path.join(tmp, 'roundTrack.yaml')
            world = os.path.join(PACKAGE, 'worlds', 'roundTrack.world')
            self.assertEqual(make_round_track_map.main(['make', world, target]), 0)
            for name in ('roundTrack.yaml', 'roundTrack.pgm'):
                with open(os.path.join(tmp, name), 'rb') as new, \
                        open(os.path.join(PACKAGE, 'maps', name), 'rb') as old:
                    self.assertEqual(new.read(), old.read(), name)


class TestWorldErrors(unittest.TestCase):
    """Worlds the map cannot be drawn from: one fixture per failure, the message asserted."""

    def check(self, fixture, message):
        path = os.path.join(PACKAGE, 'test', 'map_worlds', fixture)
        with self.assertRaises(world_obstacles.WorldError) as caught:
            world_obstacles.read_footprints(path)
        self.assertEqual(str(caught.exception), path + message)

    def test_an_include(self):
        self.check('include.world', " world 'w' <include> 'model://papptown_track': "
                   "includes are not expanded; list the models")

    def test_a_mesh(self):
        self.check('mesh.world', " world 'w' model 'cone' link 'link' collision 'c' "
                   "<geometry>: <mesh> cannot be mapped (box, cylinder, sphere, plane)")

    def test_a_bad_size(self):
        self.check('bad_size.world', " world 'w' model 'wall' link 'link' collision 'c' "
                   "<box><size>: '0.015 wide 0.5' is not 3 numbers")

    def test_a_tilted_wall(self):
        self.check('tilted.world', " world 'w' model 'wall' <pose>: roll 0.3, pitch 0: "
                   "only upright shapes can be mapped")

    def test_shapes_of_a_nested_and_rotated_model_and_of_no_static_one(self):
        path = os.path.join(PACKAGE, 'test', 'map_worlds', 'nested.world')
        shapes = world_obstacles.read_footprints(path)
        self.assertEqual([s.name for s in shapes], ['outer::base', 'inner::post'])
        post = shapes[1]
        # inner at (1, 0) in outer, outer at (2, 3) turned by pi/2: the post at (2, 4)
        self.assertAlmostEqual(post.x, 2.0)
        self.assertAlmostEqual(post.y, 4.0)
        self.assertAlmostEqual(post.radius, 0.1)


if __name__ == '__main__':
    unittest.main()
