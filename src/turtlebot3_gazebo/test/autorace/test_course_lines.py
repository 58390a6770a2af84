#!/usr/bin/python3
"""course_lines on a course written here: a 2 m x 1 m plane with a 4 x 2 texture (one white
and one yellow texel), included at (1, 2) turned by 90 degrees; the texels' places worked
out by hand from Gazebo's plane mapping (u from -x to +x, v from +y to -y)."""
import math
import os
import shutil
import sys
import tempfile
import unittest

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import course_lines  # noqa: E402

WORLD = '''<sdf version="1.6"><world name="w">
  <include><uri>model://stripes</uri><pose>1 2 0 0 0 1.5707963267948966</pose></include>
</world></sdf>'''
MODEL = '''<sdf version="1.6"><model name="stripes"><static>true</static>
  <link name="l"><visual name="v"><geometry><plane><normal>%s</normal><size>2 1</size></plane>
  </geometry><material><script><uri>model://stripes/materials/scripts</uri>
  <uri>model://stripes/materials/textures</uri><name>%s</name></script></material></visual>
  </link></model></sdf>'''
MATERIAL = 'material other\n{\n}\nmaterial stripes\n{ technique { pass { texture_unit {\n' \
           '  texture stripes.png\n} } } }\n'


class TestCourseLines(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp(prefix='course_lines_')
        self.addCleanup(shutil.rmtree, self.root)
        self.world = os.path.join(self.root, 'course.world')
        open(self.world, 'w').write(WORLD)
        self.write_model('0 0 1', 'stripes')

    def write_model(self, normal, material):
        model = os.path.join(self.root, 'models', 'stripes')
        for sub in ('scripts', 'textures'):
            os.makedirs(os.path.join(model, 'materials', sub), exist_ok=True)
        open(os.path.join(model, 'model.sdf'), 'w').write(MODEL % (normal, material))
        open(os.path.join(model, 'materials', 'scripts', 'c.material'), 'w').write(MATERIAL)
        texture = np.zeros((2, 4, 3), np.uint8)
        texture[0, 3] = (255, 255, 255)          # white, top right
        texture[1, 0] = (0, 255, 255)            # yellow (BGR), bottom left
        cv2.imwrite(os.path.join(model, 'materials', 'textures', 'stripes.png'), texture)

    def lines(self):
        return course_lines.CourseLines(self.world, [os.path.join(self.root, 'models')],
                                        'model://stripes')

    def test_texels_land_where_the_plane_mapping_puts_them(self):
        lines = self.lines()
        self.assertEqual(lines.texel, (0.5, 0.5))
        # white texel (row 0, col 3): plane x 0.5..1.0, y 0..0.5; turned 90 degrees about
        # (1, 2): world x = 1 - y in 0.5..1.0, y = 2 + x in 2.5..3.0, centre (0.75, 2.75)
        self.assertEqual(lines.texel_at(0.75, 2.75), (0, 3))
        self.assertEqual(lines.distance('white', 0.75, 2.75), 0.0)
        self.assertAlmostEqual(lines.distance('white', 0.75, 3.5), 0.5)
        self.assertAlmostEqual(lines.distance('white', 1.3, 3.4), 0.5)   # 0.3 and 0.4 out
        # yellow texel (row 1, col 0): plane x -1.0..-0.5, y -0.5..0: world x 1.0..1.5,
        # y 1.0..1.5
        self.assertEqual(lines.texel_at(1.25, 1.25), (1, 0))
        self.assertEqual(lines.distance('yellow', 1.25, 1.25), 0.0)
        self.assertAlmostEqual(lines.distance('yellow', 1.25, 0.75), 0.25)
        # the white square (x 0.5..1.0, y 2.5..3.0) from the yellow texel's centre
        self.assertAlmostEqual(lines.distance('white', 1.25, 1.25), math.hypot(0.25, 1.25))

    def test_a_world_without_the_include_says_so(self):
        with self.assertRaisesRegex(course_lines.CourseError, 'course.world: no <include> of '
                                    'model://elsewhere'):
            course_lines.CourseLines(self.world, [os.path.join(self.root, 'models')],
                                     'model://elsewhere')

    def test_a_tilted_plane_is_refused_naming_the_visual(self):
        self.write_model('0 1 0', 'stripes')
        with self.assertRaisesRegex(course_lines.CourseError,
                                    r'model.sdf: <visual name="v">: <normal> \[0.0, 1.0, 0.0\]'):
            self.lines()

    def test_a_material_without_a_texture_is_named(self):
        self.write_model('0 0 1', 'other')
        with self.assertRaisesRegex(course_lines.CourseError, 'material other with a texture '
                                    'not found'):
            self.lines()


if __name__ == '__main__':
    unittest.main()
