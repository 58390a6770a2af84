"""PNG files of frames (8- and 16-bit grey, RGB and RGBA) through OpenCV, so saved frames
keep every bit."""
import os

import cv2
import numpy as np

# channels -> OpenCV's channel order for an RGB(A) array
_TO_OPENCV = {1: None, 3: cv2.COLOR_RGB2BGR, 4: cv2.COLOR_RGBA2BGRA}


def encode_png(pixels):
    """PNG file bytes of an (H, W), (H, W, 3) or (H, W, 4) uint8 or uint16 array."""
    pixels = np.asarray(pixels)
    if pixels.dtype not in (np.uint8, np.uint16):
        raise ValueError(f'PNG pixels must be uint8 or uint16, not {pixels.dtype}')
    channels = 1 if pixels.ndim == 2 else pixels.shape[2]
    if pixels.ndim not in (2, 3) or channels not in _TO_OPENCV:
        raise ValueError(f'PNG pixels must be (H, W), (H, W, 3) or (H, W, 4), '
                         f'not {pixels.shape}')
    if _TO_OPENCV[channels] is not None:
        pixels = cv2.cvtColor(pixels, _TO_OPENCV[channels])
    ok, data = cv2.imencode('.png', pixels)
    if not ok:
        raise ValueError(f'OpenCV could not encode a {pixels.shape} {pixels.dtype} PNG')
    return data.tobytes()


def write_png(path, pixels):
    """Writes pixels as a PNG file; readers never see a half-written file."""
    data = encode_png(pixels)
    partial = f'{path}.partial'
    with open(partial, 'wb') as out:
        out.write(data)
    os.replace(partial, path)
