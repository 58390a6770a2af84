"""Saved PNGs hold the received pixels; checked by decoding them with ImageMagick."""
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fake_image import packed  # noqa: E402
from mobility_image_view.png_writer import encode_png, write_png  # noqa: E402
from mobility_image_view.saving import frame_file_name, png_pixels, save_frame  # noqa: E402
from mobility_testing.images import load_png  # noqa: E402


def decode_with_imagemagick(path, channels, depth):
    """Pixels of a PNG as ImageMagick reads them (raw gray/rgb/rgba samples)."""
    kind = {1: 'gray', 3: 'rgb', 4: 'rgba'}[channels]
    raw = subprocess.run(['/usr/bin/convert', path, '-depth', str(depth), '-endian', 'MSB',
                          f'{kind}:-'],
                         check=True, capture_output=True).stdout
    dtype = np.dtype('>u2') if depth == 16 else np.uint8
    return np.frombuffer(raw, dtype=dtype)


def png_info(path):
    """'WxH depth colourspace' as ImageMagick identifies the file."""
    return subprocess.run(['/usr/bin/identify', '-format', '%wx%h %z %[channels]', path],
                          check=True, capture_output=True, text=True).stdout


class PngWriterTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)

    def roundtrip(self, pixels, channels, depth):
        path = os.path.join(self.tmp.name, 'out.png')
        write_png(path, pixels)
        self.assertFalse(os.path.exists(path + '.partial'))
        return decode_with_imagemagick(path, channels, depth), path

    def test_rgb8(self):
        pixels = np.arange(2 * 3 * 3, dtype=np.uint8).reshape(2, 3, 3) * 7
        decoded, path = self.roundtrip(pixels, 3, 8)
        self.assertEqual(decoded.tolist(), pixels.ravel().tolist())
        self.assertEqual(load_png(path).tolist(), pixels.tolist())

    def test_rgba8(self):
        pixels = np.array([[[1, 2, 3, 4], [250, 251, 252, 253]]], dtype=np.uint8)
        decoded, _ = self.roundtrip(pixels, 4, 8)
        self.assertEqual(decoded.tolist(), [1, 2, 3, 4, 250, 251, 252, 253])

    def test_grey16_keeps_every_bit(self):
        pixels = np.array([[0, 1, 258], [65535, 4096, 12345]], dtype=np.uint16)
        decoded, path = self.roundtrip(pixels, 1, 16)
        self.assertEqual(decoded.tolist(), pixels.ravel().tolist())
        self.assertTrue(png_info(path).startswith('3x2 16'))

    def test_rejects_float_pixels(self):
        with self.assertRaisesRegex(ValueError, 'uint8 or uint16, not float32'):
            encode_png(np.zeros((2, 2), dtype=np.float32))

    def test_rejects_two_channels(self):
        with self.assertRaisesRegex(ValueError, r'not \(2, 2, 2\)'):
            encode_png(np.zeros((2, 2, 2), dtype=np.uint8))


class SaveFrameTest(unittest.TestCase):
    def test_bgr8_saved_as_rgb(self):
        image = packed('bgr8', 1, 1, [64, 106, 145], 'B')
        saved = png_pixels(image)
        self.assertEqual(saved.pixels.tolist(), [[[145, 106, 64]]])
        self.assertTrue(saved.exact)

    def test_16uc1_saved_exactly_as_16_bit(self):
        image = packed('16UC1', 2, 1, [1000, 3000], 'H')
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, 'depth.png')
            self.assertTrue(save_frame(image, path))
            self.assertEqual(decode_with_imagemagick(path, 1, 16).tolist(), [1000, 3000])

    def test_32fc1_saved_as_its_8_bit_view(self):
        image = packed('32FC1', 3, 1, [0.5, math.nan, 2.5], 'f')
        saved = png_pixels(image)
        self.assertFalse(saved.exact)
        self.assertEqual(saved.pixels.tolist(), [[0, 0, 255]])

    def test_file_names(self):
        self.assertEqual(frame_file_name('/camera/image_raw', 3), 'camera_image_raw_0003.png')
        self.assertEqual(frame_file_name('/', 12), 'image_0012.png')


if __name__ == '__main__':
    unittest.main()
