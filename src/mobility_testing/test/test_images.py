"""Tests of the screenshot colour helpers on images made here."""
import os
import subprocess
import tempfile
import unittest

import numpy as np

from mobility_testing.images import count_colour, load_png, save_png


class ImagesTest(unittest.TestCase):
    def test_save_png_keeps_rgb_order(self):
        image = np.array([[[255, 0, 0], [0, 0, 255]]], dtype=np.uint8)
        with tempfile.TemporaryDirectory() as tmp:
            path = save_png(image, os.path.join(tmp, 'two.png'))
            # ImageMagick reads the file as a third party: red first, then blue.
            rgb = subprocess.run(['/usr/bin/convert', path, '-depth', '8', 'rgb:-'],
                                 check=True, capture_output=True).stdout
        self.assertEqual(list(rgb), [255, 0, 0, 0, 0, 255])

    def test_load_png_and_count_colour(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, 'half.png')
            subprocess.run(['/usr/bin/convert', '-size', '10x4', 'xc:rgb(255,107,10)',
                            '-fill', 'rgb(0,0,0)', '-draw', 'rectangle 0,0 4,3', path],
                           check=True)
            image = load_png(path)
        self.assertEqual(image.shape, (4, 10, 3))
        self.assertEqual(count_colour(image, (255, 107, 10), tolerance=2), 20)
        self.assertEqual(count_colour(image, (0, 0, 0), tolerance=2), 20)
        self.assertEqual(int(np.sum(image[:, 5:] == [255, 107, 10]) // 3), 20)


class ColourClassTest(unittest.TestCase):
    def test_classes_of_lit_colours(self):
        from mobility_testing.images import count_class
        image = np.array([[[230, 97, 9], [200, 10, 12], [5, 5, 5], [48, 48, 48]]], dtype=np.uint8)
        self.assertEqual(count_class(image, 'orange'), 1)
        self.assertEqual(count_class(image, 'red'), 1)
        self.assertEqual(count_class(image, 'black'), 1)
        self.assertEqual(count_class(image, 'white'), 0)

    def test_region_of_background(self):
        from mobility_testing.images import region_of_colour
        image = np.full((20, 30, 3), 239, dtype=np.uint8)
        image[5:15, 10:25] = 48
        image[8, 12] = 255
        self.assertEqual(region_of_colour(image, (48, 48, 48)), (5, 15, 10, 25))
        self.assertIsNone(region_of_colour(image, (1, 2, 3)))


class UrdfModelTest(unittest.TestCase):
    def test_rpy_matrix_follows_urdf_convention(self):
        from mobility_testing.urdf_model import rpy_matrix
        # yaw 90 deg maps x to y; roll 90 deg maps y to z
        np.testing.assert_allclose(rpy_matrix(0, 0, np.pi / 2) @ [1, 0, 0], [0, 1, 0], atol=1e-12)
        np.testing.assert_allclose(rpy_matrix(np.pi / 2, 0, 0) @ [0, 1, 0], [0, 0, 1], atol=1e-12)
        # fixed axes: roll applied first, then yaw
        np.testing.assert_allclose(rpy_matrix(np.pi / 2, 0, np.pi / 2) @ [0, 1, 0],
                                   [0, 0, 1], atol=1e-12)

    def test_structure_readers(self):
        from mobility_testing.urdf_model import joints, links, roots
        text = ('<robot name="r"><link name="a"/><link name="b"/><link name="c"/>'
                '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>'
                '</robot>')
        self.assertEqual(links(text), {'a', 'b', 'c'})
        self.assertEqual(joints(text), {'j': ('fixed', 'a', 'b')})
        self.assertEqual(roots(text), {'a', 'c'})


if __name__ == '__main__':
    unittest.main()
