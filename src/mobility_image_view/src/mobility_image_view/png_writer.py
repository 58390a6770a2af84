"""A small PNG encoder (8- and 16-bit grey, RGB and RGBA), so saved frames keep every bit."""
import os
import struct
import zlib

import numpy as np

# channels -> PNG colour type
_COLOUR_TYPES = {1: 0, 3: 2, 4: 6}


def _chunk(kind, payload):
    body = kind + payload
    return struct.pack('>I', len(payload)) + body + struct.pack('>I', zlib.crc32(body))


def encode_png(pixels):
    """PNG file bytes of an (H, W), (H, W, 3) or (H, W, 4) uint8 or uint16 array."""
    pixels = np.asarray(pixels)
    if pixels.dtype not in (np.uint8, np.uint16):
        raise ValueError(f'PNG pixels must be uint8 or uint16, not {pixels.dtype}')
    channels = 1 if pixels.ndim == 2 else pixels.shape[2]
    if pixels.ndim not in (2, 3) or channels not in _COLOUR_TYPES:
        raise ValueError(f'PNG pixels must be (H, W), (H, W, 3) or (H, W, 4), '
                         f'not {pixels.shape}')
    height, width = pixels.shape[:2]
    bit_depth = 8 * pixels.dtype.itemsize
    rows = pixels.astype(pixels.dtype.newbyteorder('>')).reshape(height, -1).view(np.uint8)
    # Each row starts with filter type 0 (none).
    raw = np.hstack([np.zeros((height, 1), dtype=np.uint8), rows]).tobytes()
    header = struct.pack('>IIBBBBB', width, height, bit_depth, _COLOUR_TYPES[channels], 0, 0, 0)
    return (b'\x89PNG\r\n\x1a\n' + _chunk(b'IHDR', header) +
            _chunk(b'IDAT', zlib.compress(raw, 6)) + _chunk(b'IEND', b''))


def write_png(path, pixels):
    """Writes pixels as a PNG file; readers never see a half-written file."""
    data = encode_png(pixels)
    partial = f'{path}.partial'
    with open(partial, 'wb') as out:
        out.write(data)
    os.replace(partial, path)
