"""Reading screenshots and measuring colours in them."""
import subprocess

import numpy as np


def load_png(path):
    """Returns an image file as an (H, W, 3) uint8 RGB array (via ImageMagick's convert)."""
    out = subprocess.run(['/usr/bin/convert', path, '-depth', '8', 'ppm:-'], check=True,
                         capture_output=True).stdout
    return parse_ppm(out)


def parse_ppm(data):
    """Parses a binary PPM (P6, maxval 255) into an (H, W, 3) uint8 array."""
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b'#':
            pos = data.index(b'\n', pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    if fields[0] != b'P6' or int(fields[3]) != 255:
        raise ValueError(f'not an 8-bit binary PPM: {fields!r}')
    width, height = int(fields[1]), int(fields[2])
    pixels = np.frombuffer(data, dtype=np.uint8, count=width * height * 3, offset=pos + 1)
    return pixels.reshape(height, width, 3)


def colour_mask(image, rgb, tolerance=30):
    """Boolean mask of pixels whose every channel is within tolerance of rgb."""
    diff = np.abs(image.astype(np.int16) - np.array(rgb, dtype=np.int16))
    return np.all(diff <= tolerance, axis=2)


def count_colour(image, rgb, tolerance=30):
    """Number of pixels within tolerance of rgb."""
    return int(colour_mask(image, rgb, tolerance).sum())


def hue_mask(image, predicate):
    """Mask of pixels for which predicate(r, g, b) (int arrays) is true."""
    r, g, b = (image[..., i].astype(np.int32) for i in range(3))
    return predicate(r, g, b)
