"""Tests of the screenshot colour helpers on images made here."""
import os
import subprocess
import tempfile
import unittest

import numpy as np

from mobility_testing.images import count_colour, load_png, parse_ppm


class ImagesTest(unittest.TestCase):
    def test_parse_ppm_reads_pixels_in_row_order(self):
        data = b'P6\n# comment\n2 1\n255\n' + bytes([255, 0, 0, 0, 0, 255])
        image = parse_ppm(data)
        self.assertEqual(image.shape, (1, 2, 3))
        self.assertEqual(image[0, 0].tolist(), [255, 0, 0])
        self.assertEqual(image[0, 1].tolist(), [0, 0, 255])

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


if __name__ == '__main__':
    unittest.main()
