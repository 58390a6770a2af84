#!/usr/bin/python3
"""The ground-truth reader and ray caster that the upstream-world tests rely on, checked
on files written here and on distances worked out by hand."""
import math
import os
import shutil
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gazebo_truth  # noqa: E402

# A wall 100 x 10 x 200 inches, standing on z = 0, tagged Y_UP as TurtleBot3's wall.dae is.
WALL_DAE = '''<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
 <asset><unit name="inch" meter="0.0254"/><up_axis>Y_UP</up_axis></asset>
 <library_geometries><geometry id="g"><mesh>
  <source id="p"><float_array id="pa" count="24">
   0 0 0  100 0 0  100 10 0  0 10 0  0 0 200  100 0 200  100 10 200  0 10 200
  </float_array><technique_common><accessor source="#pa" count="8" stride="3"/>
  </technique_common></source>
  <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
  <triangles count="12"><input semantic="VERTEX" source="#v" offset="0"/>
   <p>0 2 1 0 3 2 4 5 6 4 6 7 0 1 5 0 5 4 1 2 6 1 6 5 2 3 7 2 7 6 3 0 4 3 4 7</p>
  </triangles></mesh></geometry></library_geometries>
 <library_visual_scenes><visual_scene id="s"><node><instance_geometry url="#g"/></node>
 </visual_scene></library_visual_scenes>
 <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
'''


class GazeboTruth(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix='gazebo_truth_')
        self.addCleanup(shutil.rmtree, self.dir, ignore_errors=True)

    def write(self, name, text):
        path = os.path.join(self.dir, name)
        with open(path, 'w') as f:
            f.write(text)
        return path

    def test_collada_unit_applied_and_up_axis_ignored(self):
        tris = gazebo_truth.collada_triangles(self.write('wall.dae', WALL_DAE))
        self.assertEqual(tris.shape, (12, 3, 3))
        points = tris.reshape(-1, 3)
        np.testing.assert_allclose(points.min(axis=0), [0, 0, 0], atol=1e-12)
        np.testing.assert_allclose(points.max(axis=0), [2.54, 0.254, 5.08], atol=1e-12)

    def test_rays_meet_a_meshed_wall_a_box_and_a_cylinder_where_geometry_says(self):
        self.write('wall.dae', WALL_DAE)
        world = self.write('w.world', '''<sdf version="1.6"><world name="w">
          <model name="m"><static>1</static><link name="l">
            <collision name="wall"><pose>2 -0.06 0 0 0 0</pose><geometry><mesh>
              <uri>wall.dae</uri><scale>0.5 0.5 0.5</scale></mesh></geometry></collision>
            <collision name="box"><pose>-3 0 0.5 0 0 0.7853981634</pose><geometry>
              <box><size>1 1 1</size></box></geometry></collision>
            <collision name="post"><pose>0 2 0.5 0 0 0</pose><geometry>
              <cylinder><radius>0.25</radius><length>1</length></cylinder></geometry></collision>
          </link></model></world></sdf>''')
        shapes = gazebo_truth.world_shapes(world, [])
        self.assertEqual(len(shapes), 3)
        origin = np.array([0.0, 0.0, 0.2])
        # Wall: from (2, -0.06) 1.27 m along x, 0.127 m thick (y -0.06 .. 0.067): it is
        # met from the origin along +x at x = 2.
        self.assertAlmostEqual(gazebo_truth.cast(shapes, origin, np.array([1.0, 0, 0])), 2.0)
        # A box turned 45 degrees, centre 3 m away along -x: its corner at 3 - sqrt(0.5).
        self.assertAlmostEqual(gazebo_truth.cast(shapes, origin, np.array([-1.0, 0, 0])),
                               3 - math.sqrt(0.5))
        self.assertAlmostEqual(gazebo_truth.cast(shapes, origin, np.array([0, 1.0, 0])), 1.75)
        self.assertEqual(gazebo_truth.cast(shapes, origin, np.array([0, -1.0, 0])), math.inf)
        # Above the 1 m box and post, below the 2.54 m wall.
        high = np.array([0.0, 0.0, 1.2])
        self.assertEqual(gazebo_truth.cast(shapes, high, np.array([0, 1.0, 0])), math.inf)

    def test_lidar_rays_start_at_range_min_and_beyond_range_max_read_inf(self):
        world = self.write('w.world', '''<sdf version="1.6"><world name="w">
          <model name="m"><static>1</static><link name="l">
            <collision name="near"><pose>0.1 0 0 0 0 0</pose><geometry>
              <box><size>0.02 0.02 1</size></box></geometry></collision>
          </link></model></world></sdf>''')
        shapes = gazebo_truth.world_shapes(world, [])
        ranges = gazebo_truth.lidar_ranges(shapes, 0, 0, 0, 0, samples=4,
                                           angle_max=1.5 * math.pi)
        self.assertEqual(ranges, [math.inf] * 4)  # the post stands inside range_min

    def test_a_textured_plane_seen_from_above_is_a_map(self):
        texture = np.zeros((2, 2, 3), np.uint8)
        texture[0, 0] = (255, 0, 0)    # top left: -x, +y
        texture[1, 1] = (0, 0, 255)    # bottom right: +x, -y
        T_camera = gazebo_truth.pose_matrix('0 0 0.9 0 1.5707963268 0')  # looking down
        image, hit = gazebo_truth.textured_plane_view(T_camera, math.pi / 2, 40, 40,
                                                      np.eye(4), (2.0, 2.0), texture)
        self.assertTrue(hit.all())
        # Looking down with the camera's up along +x: image top is +x, image left is +y.
        np.testing.assert_array_equal(image[30, 10], (255, 0, 0))   # -x, +y
        np.testing.assert_array_equal(image[10, 30], (0, 0, 255))   # +x, -y


if __name__ == '__main__':
    unittest.main()
