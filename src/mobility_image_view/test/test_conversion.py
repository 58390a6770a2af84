"""Display conversion of every supported encoding, against values worked out by hand."""
import math
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fake_image import FakeImage, packed  # noqa: E402
from mobility_image_view.conversion import (ImageError, UnsupportedEncoding,  # noqa: E402
                                            raw_pixels, scale_to_8bit, to_display_rgb)


class ColourEncodingsTest(unittest.TestCase):
    def test_rgb8_keeps_channels(self):
        image = packed('rgb8', 2, 1, [145, 106, 64, 1, 2, 3], 'B')
        self.assertEqual(to_display_rgb(image).tolist(), [[[145, 106, 64], [1, 2, 3]]])

    def test_bgr8_swaps_to_rgb(self):
        image = packed('bgr8', 2, 1, [64, 106, 145, 3, 2, 1], 'B')
        self.assertEqual(to_display_rgb(image).tolist(), [[[145, 106, 64], [1, 2, 3]]])

    def test_rgba8_and_bgra8_drop_alpha(self):
        rgba = packed('rgba8', 1, 1, [10, 20, 30, 40], 'B')
        bgra = packed('bgra8', 1, 1, [30, 20, 10, 40], 'B')
        self.assertEqual(to_display_rgb(rgba).tolist(), [[[10, 20, 30]]])
        self.assertEqual(to_display_rgb(bgra).tolist(), [[[10, 20, 30]]])

    def test_row_padding_is_skipped(self):
        # 2 rgb8 pixels per row = 6 bytes, step 8: the 2 padding bytes are not pixels.
        image = packed('rgb8', 2, 2, list(range(12)), 'B', padding=2)
        self.assertEqual(image.step, 8)
        self.assertEqual(to_display_rgb(image).tolist(),
                         [[[0, 1, 2], [3, 4, 5]], [[6, 7, 8], [9, 10, 11]]])


class GreyEncodingsTest(unittest.TestCase):
    def test_mono8_is_grey(self):
        image = packed('mono8', 3, 1, [0, 128, 255], 'B')
        self.assertEqual(to_display_rgb(image).tolist(),
                         [[[0, 0, 0], [128, 128, 128], [255, 255, 255]]])

    def test_8uc1_is_shown_as_mono8(self):
        image = packed('8UC1', 1, 1, [77], 'B')
        self.assertEqual(to_display_rgb(image).tolist(), [[[77, 77, 77]]])

    def test_mono16_shows_its_high_byte(self):
        image = packed('mono16', 3, 1, [0x0000, 0x80ff, 0xffff], 'H')
        self.assertEqual(to_display_rgb(image)[0, :, 0].tolist(), [0x00, 0x80, 0xff])

    def test_16uc1_scales_min_to_0_and_max_to_255(self):
        # 1000 -> 0, 3000 -> 255, 2000 -> 127.5 rounds up to 128.
        image = packed('16UC1', 2, 2, [1000, 2000, 3000, 1000], 'H')
        self.assertEqual(to_display_rgb(image)[:, :, 0].tolist(), [[0, 128], [255, 0]])
        self.assertEqual(raw_pixels(image).tolist(), [[1000, 2000], [3000, 1000]])

    def test_16uc1_big_endian(self):
        image = packed('16UC1', 2, 1, [0x0102, 0x0201], 'H', is_bigendian=1)
        self.assertEqual(image.data, b'\x01\x02\x02\x01')
        self.assertEqual(raw_pixels(image).tolist(), [[258, 513]])

    def test_32fc1_scales_finite_values_and_draws_nan_inf_black(self):
        values = [math.nan, 0.5, math.inf, 1.5, -math.inf, 2.5]
        image = packed('32FC1', 2, 3, values, 'f')
        grey = to_display_rgb(image)[:, :, 0]
        # finite range 0.5..2.5: 0.5 -> 0, 1.5 -> 127.5 -> 128, 2.5 -> 255; NaN/inf -> 0
        self.assertEqual(grey.tolist(), [[0, 0], [0, 128], [0, 255]])
        self.assertTrue(np.all(to_display_rgb(image)[:, :, 1] == grey))

    def test_32fc1_all_nan_is_black(self):
        image = packed('32FC1', 2, 1, [math.nan, math.nan], 'f')
        self.assertEqual(to_display_rgb(image).sum(), 0)

    def test_constant_depth_is_black(self):
        self.assertEqual(scale_to_8bit(np.array([7.0, 7.0])).tolist(), [0, 0])

    def test_scale_quarters(self):
        values = np.array([0.0, 1.0, 2.0, 3.0, 4.0])
        # 255 * k / 4 = 0, 63.75, 127.5, 191.25, 255 -> rounded half up
        self.assertEqual(scale_to_8bit(values).tolist(), [0, 64, 128, 191, 255])


class BadImageTest(unittest.TestCase):
    def test_unsupported_encoding_says_so_plainly(self):
        image = FakeImage('yuv422', 2, 1, 4, 0, bytes(4))
        with self.assertRaises(UnsupportedEncoding) as caught:
            to_display_rgb(image)
        self.assertIn("cannot show encoding 'yuv422'", str(caught.exception))
        self.assertIn('rgb8', str(caught.exception))
        self.assertIn('32FC1', str(caught.exception))

    def test_short_data_names_sizes(self):
        image = FakeImage('rgb8', 2, 2, 6, 0, bytes(11))
        with self.assertRaisesRegex(ImageError, 'data has 11 bytes, 2 rows of step 6 need 12'):
            to_display_rgb(image)

    def test_short_step(self):
        image = FakeImage('16UC1', 4, 1, 6, 0, bytes(6))
        with self.assertRaisesRegex(ImageError, r'step 6 is shorter .* \(8 bytes\)'):
            to_display_rgb(image)

    def test_empty_image(self):
        with self.assertRaisesRegex(ImageError, 'empty image: 0x0'):
            to_display_rgb(FakeImage('mono8', 0, 0, 0, 0, b''))


if __name__ == '__main__':
    unittest.main()
