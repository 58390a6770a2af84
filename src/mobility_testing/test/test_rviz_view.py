"""Orbit-view projection against cases worked out by hand."""
import math
import os
import tempfile
import unittest

import numpy as np

from mobility_testing.images import shade_mask
from mobility_testing.rviz_view import OrbitView

AREA = (100, 50, 800, 600)


class OrbitViewTest(unittest.TestCase):
    def test_focal_point_is_the_centre(self):
        view = OrbitView((2, 1, 0), 10, 0.3, 0.7, 0.785)
        x, y = view.project((2, 1, 0), AREA)
        self.assertAlmostEqual(x, 500)
        self.assertAlmostEqual(y, 350)

    def test_top_down_view_scale(self):
        # Looking straight down from 10 m (pitch just under 90 deg, yaw -90 deg so the
        # screen's right is +x and up is +y): a point 1 m along +x lies
        # 300 px / (10 m * tan(fov / 2)) to the right.
        view = OrbitView((0, 0, 0), 10, -math.pi / 2, math.pi / 2 - 1e-9, math.pi / 2)
        x, y = view.project((1, 0, 0), AREA)
        self.assertAlmostEqual(x, 500 + 30, places=5)
        self.assertAlmostEqual(y, 350, places=5)
        x, y = view.project((0, 2, 0), AREA)
        self.assertAlmostEqual(y, 350 - 60, places=5)

    def test_ground_point_inverts_project(self):
        view = OrbitView((2.2, 0.3, 0), 9.5, 4.4, 0.8, 0.785)
        for point in ((0, 0, 0), (5, -2.5, 0), (-1, 3, 0)):
            pixel = view.project(point, AREA)
            np.testing.assert_allclose(view.ground_point(pixel, AREA), point, atol=1e-9)

    def test_reads_the_view_of_an_rviz_file(self):
        text = ('Visualization Manager:\n  Views:\n    Current:\n      Class: rviz/Orbit\n'
                '      Distance: 4\n      Focal Point: {X: 1, Y: 2, Z: 0}\n'
                '      Pitch: 0.5\n      Yaw: 1\n      Field of View: 0.785\n')
        with tempfile.NamedTemporaryFile('w', suffix='.rviz', delete=False) as f:
            f.write(text)
        try:
            view = OrbitView.from_rviz_config(f.name)
        finally:
            os.unlink(f.name)
        np.testing.assert_allclose(view.focal, (1, 2, 0))
        self.assertAlmostEqual(np.linalg.norm(view.eye - view.focal), 4)


class ShadeMaskTest(unittest.TestCase):
    def test_shades_of_cardboard_and_not_grey_or_orange(self):
        wall = (0.57, 0.417, 0.25)
        image = np.array([[[145, 106, 64], [32, 23, 14], [91, 91, 91], [255, 107, 10],
                           [8, 6, 3]]], dtype=np.uint8)
        self.assertEqual(shade_mask(image, wall)[0].tolist(),
                         [True, True, False, False, False])


if __name__ == '__main__':
    unittest.main()
