"""A test publisher of synthetic sensor_msgs/Image frames at a fixed rate."""
import threading
import time

import numpy as np
import rospy
from sensor_msgs.msg import Image

WIDTH, HEIGHT = 320, 240
GREY = (128, 128, 128)
# The round-track walls' diffuse colour 0.57 0.417 0.25, in 8 bit.
WALL = (145, 106, 64)
WALL_X, WALL_Y, WALL_W, WALL_H = 80, 60, 160, 120


def make_frame(k):
    """Frame k: grey, a wall-coloured rectangle, and k in pixel (0, 0) as (k % 256, k // 256, 0)."""
    pixels = np.empty((HEIGHT, WIDTH, 3), dtype=np.uint8)
    pixels[:, :] = GREY
    pixels[WALL_Y:WALL_Y + WALL_H, WALL_X:WALL_X + WALL_W] = WALL
    pixels[0, 0] = (k % 256, (k // 256) % 256, 0)
    return pixels


def frame_number(pixels):
    """The k that make_frame wrote into pixel (0, 0)."""
    return int(pixels[0, 0, 0]) + 256 * int(pixels[0, 0, 1])


def to_message(pixels, encoding='rgb8'):
    """A sensor_msgs/Image of an array whose rows are the image rows (little-endian)."""
    pixels = np.ascontiguousarray(pixels, dtype=pixels.dtype.newbyteorder('<'))
    message = Image(height=pixels.shape[0], width=pixels.shape[1], encoding=encoding,
                    is_bigendian=0, step=pixels.nbytes // pixels.shape[0])
    message.data = pixels.tobytes()
    message.header.frame_id = 'camera_link'
    return message


class SyntheticCamera:
    """Publishes frame(0), frame(1), ... on topic at rate_hz (wall clock).

    frame(k) is an array (default make_frame) sent with the given encoding."""

    def __init__(self, topic, rate_hz, encoding='rgb8', frame=make_frame):
        self.topic, self.rate_hz, self.encoding = topic, rate_hz, encoding
        self._frame = frame
        self._publisher = rospy.Publisher(topic, Image, queue_size=2)
        self._sent = []   # (monotonic time, k)
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self):
        period = 1.0 / self.rate_hz
        start = time.monotonic()
        k = 0
        while not self._stop.is_set() and not rospy.is_shutdown():
            self._publisher.publish(to_message(self._frame(k), self.encoding))
            with self._lock:
                self._sent.append((time.monotonic(), k))
            k += 1
            self._stop.wait(max(0.0, start + k * period - time.monotonic()))

    def sent(self):
        """(time, k) of every frame published so far."""
        with self._lock:
            return list(self._sent)

    def measured_rate_hz(self, window_s=2.0):
        """The rate actually published over the last window_s seconds."""
        times = [t for t, _ in self.sent() if t >= time.monotonic() - window_s]
        return (len(times) - 1) / (times[-1] - times[0])

    def stop(self):
        self._stop.set()
        self._thread.join(timeout=5)
        self._publisher.unregister()
