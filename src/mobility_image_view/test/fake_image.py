"""A stand-in for sensor_msgs/Image with the same fields (tests need no ROS)."""
import collections
import struct

FakeImage = collections.namedtuple('FakeImage', 'encoding width height step is_bigendian data')


def packed(encoding, width, height, values, fmt, is_bigendian=0, padding=0):
    """An image whose rows hold `values` (row-major) packed with struct format `fmt`,
    each row followed by `padding` zero bytes."""
    order = '>' if is_bigendian else '<'
    per_row = len(values) // height
    rows = [struct.pack(order + fmt * per_row, *values[r * per_row:(r + 1) * per_row])
            + bytes(padding) for r in range(height)]
    step = len(rows[0])
    return FakeImage(encoding, width, height, step, is_bigendian, b''.join(rows))
