"""Turning the bytes of a sensor_msgs/Image into pixel arrays.

Works on any object with the message's fields (encoding, width, height, step,
is_bigendian, data), so it needs no ROS. Two views of a frame exist:
- raw_pixels: the received values, shape (H, W) or (H, W, C), native dtype;
- to_display_rgb: an (H, W, 3) uint8 RGB array for the screen. 16UC1 and 32FC1
  are scaled linearly from the smallest to the largest finite value to 0..255
  (NaN and +-inf are drawn black); mono16 is shown by its high byte.
"""
import numpy as np

# encoding -> (element dtype, channels)
ENCODINGS = {
    'rgb8': (np.uint8, 3),
    'bgr8': (np.uint8, 3),
    'rgba8': (np.uint8, 4),
    'bgra8': (np.uint8, 4),
    'mono8': (np.uint8, 1),
    '8UC1': (np.uint8, 1),
    'mono16': (np.uint16, 1),
    '16UC1': (np.uint16, 1),
    '32FC1': (np.float32, 1),
}
SCALED_ENCODINGS = ('16UC1', '32FC1')


class ImageError(ValueError):
    """A frame cannot be shown; the message says why in plain words."""


class UnsupportedEncoding(ImageError):
    """The frame's encoding is not one the viewer can draw."""


def supported_list():
    """The supported encodings as a readable, comma-separated list."""
    return ', '.join(ENCODINGS)


def raw_pixels(image):
    """The received pixel values as a numpy array (rows without their padding).

    Raises UnsupportedEncoding or ImageError (size, step or data length wrong)."""
    if image.encoding not in ENCODINGS:
        raise UnsupportedEncoding(
            f"cannot show encoding '{image.encoding}': supported are {supported_list()}")
    dtype, channels = ENCODINGS[image.encoding]
    dtype = np.dtype(dtype).newbyteorder('>' if image.is_bigendian else '<')
    width, height, step = int(image.width), int(image.height), int(image.step)
    row_bytes = width * channels * dtype.itemsize
    if width <= 0 or height <= 0:
        raise ImageError(f'empty image: {width}x{height}')
    if step < row_bytes:
        raise ImageError(f'step {step} is shorter than a row of {width} {image.encoding} '
                         f'pixels ({row_bytes} bytes)')
    if len(image.data) < step * height:
        raise ImageError(f'data has {len(image.data)} bytes, {height} rows of step {step} '
                         f'need {step * height}')
    rows = np.frombuffer(bytes(image.data), dtype=np.uint8, count=step * height)
    rows = rows.reshape(height, step)[:, :row_bytes]
    pixels = np.ascontiguousarray(rows).view(dtype).astype(dtype.newbyteorder('='))
    shape = (height, width) if channels == 1 else (height, width, channels)
    return pixels.reshape(shape)


def scale_to_8bit(values):
    """Maps the finite values' range [min, max] linearly onto 0..255, rounding half up.

    Non-finite values become 0; if every finite value is the same they all become 0."""
    values = values.astype(np.float64)
    finite = np.isfinite(values)
    out = np.zeros(values.shape, dtype=np.uint8)
    if not finite.any():
        return out
    low, high = values[finite].min(), values[finite].max()
    if high > low:
        scaled = np.floor((values[finite] - low) * (255.0 / (high - low)) + 0.5)
        out[finite] = np.clip(scaled, 0, 255).astype(np.uint8)
    return out


def grey_8bit(image, pixels):
    """The single-channel frame as 8-bit grey (the display rule of its encoding)."""
    if image.encoding in SCALED_ENCODINGS:
        return scale_to_8bit(pixels)
    if image.encoding == 'mono16':
        return (pixels >> 8).astype(np.uint8)
    return pixels


def to_display_rgb(image):
    """An (H, W, 3) uint8 RGB array showing the frame. Raises ImageError subclasses."""
    pixels = raw_pixels(image)
    encoding = image.encoding
    if encoding in ('rgb8', 'rgba8'):
        rgb = pixels[:, :, :3]
    elif encoding in ('bgr8', 'bgra8'):
        rgb = pixels[:, :, 2::-1]
    else:
        rgb = np.repeat(grey_8bit(image, pixels)[:, :, np.newaxis], 3, axis=2)
    return np.ascontiguousarray(rgb)
