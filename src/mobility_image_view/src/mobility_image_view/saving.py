"""What "save frame" writes: the received pixels, as a PNG can hold them."""
import collections

import numpy as np

from mobility_image_view.conversion import grey_8bit, raw_pixels
from mobility_image_view.png_writer import write_png

SavedFrame = collections.namedtuple('SavedFrame', 'pixels exact')


def png_pixels(image):
    """The array to store for a frame and whether it equals the received values.

    Colour frames are stored as RGB(A), mono8 as 8-bit grey and 16-bit frames as
    16-bit grey, all exactly; 32FC1 has no PNG form, so its 8-bit view is stored."""
    pixels = raw_pixels(image)
    encoding = image.encoding
    if encoding in ('bgr8', 'bgra8'):
        order = [2, 1, 0] if encoding == 'bgr8' else [2, 1, 0, 3]
        return SavedFrame(np.ascontiguousarray(pixels[:, :, order]), True)
    if encoding == '32FC1':
        return SavedFrame(grey_8bit(image, pixels), False)
    return SavedFrame(pixels, True)


def save_frame(image, path):
    """Writes the frame to path as PNG; returns True when the pixels are exact."""
    saved = png_pixels(image)
    write_png(path, saved.pixels)
    return saved.exact


def frame_file_name(topic, sequence):
    """A file name for the n-th saved frame of a topic, e.g. camera_image_raw_0003.png."""
    stem = topic.strip('/').replace('/', '_') or 'image'
    return f'{stem}_{sequence:04d}.png'
