#!/usr/bin/python3
"""/camera/image_raw and /camera/camera_info of the simulated Burger on the round track:
the configured rate in sim time, the image format and frame, K from the fov, and the
cardboard walls in the picture."""
import math
import threading
import unittest

import rospy
import rostest
from sensor_msgs.msg import CameraInfo, Image

FRAMES = 61                    # 60 intervals: 2 s of sim time at 30 Hz
RATE_HZ = 30.0
WIDTH, HEIGHT, HFOV = 640, 480, 1.5707
FRAME_ID = "camera_optical_link"
WALL_RGB = (0.57, 0.417, 0.25)  # the walls' diffuse colour


def is_wall(r, g, b):
    """Cardboard under any light: channel ratios as in the wall colour."""
    if r < 20:
        return False
    return (abs(g / r - WALL_RGB[1] / WALL_RGB[0]) < 0.06 and
            abs(b / r - WALL_RGB[2] / WALL_RGB[0]) < 0.06)


class Collector:
    def __init__(self, topic, msg_type, count):
        self.count = count
        self.messages = []
        self.done = threading.Event()
        self.sub = rospy.Subscriber(topic, msg_type, self.on_message, queue_size=200,
                                    buff_size=1 << 26)

    def on_message(self, msg):
        if len(self.messages) < self.count:
            self.messages.append(msg)
        if len(self.messages) >= self.count:
            self.done.set()

    def wait(self, timeout_s):
        ok = self.done.wait(timeout_s)
        self.sub.unregister()
        return ok


class Camera(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("camera_test")
        info = Collector("/camera/camera_info", CameraInfo, 1)
        images = Collector("/camera/image_raw", Image, FRAMES)
        cls.info_ok = info.wait(60)
        cls.images_ok = images.wait(60)
        cls.info = info.messages[0] if info.messages else None
        cls.images = images.messages

    def test_rate_in_sim_time(self):
        self.assertTrue(self.images_ok, "got %d of %d images" % (len(self.images), FRAMES))
        stamps = [m.header.stamp.to_sec() for m in self.images]
        intervals = [b - a for a, b in zip(stamps, stamps[1:])]
        rate = len(intervals) / (stamps[-1] - stamps[0])
        print("camera rate %.2f Hz from stamps, intervals %.4f..%.4f s" %
              (rate, min(intervals), max(intervals)))
        self.assertAlmostEqual(rate, RATE_HZ, delta=0.1 * RATE_HZ)
        # Never faster than configured; a frame a loaded machine drops only lowers the mean.
        self.assertGreater(min(intervals), 0.9 / RATE_HZ)
        self.assertAlmostEqual(sorted(intervals)[len(intervals) // 2], 1 / RATE_HZ,
                               delta=0.1 / RATE_HZ)

    def test_image_format(self):
        self.assertTrue(self.images)
        for msg in self.images[:3]:
            self.assertEqual((msg.width, msg.height), (WIDTH, HEIGHT))
            self.assertEqual(msg.encoding, "rgb8")
            self.assertEqual(msg.step, 3 * WIDTH)
            self.assertEqual(len(msg.data), 3 * WIDTH * HEIGHT)
            self.assertEqual(msg.header.frame_id, FRAME_ID)

    def test_camera_info_from_fov(self):
        self.assertTrue(self.info_ok, "no camera_info")
        f = (WIDTH / 2) / math.tan(HFOV / 2)
        expected_k = [f, 0, WIDTH / 2, 0, f, HEIGHT / 2, 0, 0, 1]
        expected_p = [f, 0, WIDTH / 2, 0, 0, f, HEIGHT / 2, 0, 0, 0, 1, 0]
        for got, want in zip(self.info.K, expected_k):
            self.assertAlmostEqual(got, want, places=6)
        for got, want in zip(self.info.P, expected_p):
            self.assertAlmostEqual(got, want, places=6)
        self.assertEqual(list(self.info.D), [0.0] * len(self.info.D))
        self.assertEqual((self.info.width, self.info.height), (WIDTH, HEIGHT))
        self.assertEqual(self.info.header.frame_id, FRAME_ID)

    def test_walls_in_picture(self):
        self.assertTrue(self.images)
        data = self.images[-1].data
        wall = sum(1 for i in range(0, len(data), 3 * 7)
                   if is_wall(data[i], data[i + 1], data[i + 2]))
        sampled = len(data) // (3 * 7)
        print("wall-coloured pixels: %.1f %% of the image" % (100.0 * wall / sampled))
        self.assertGreater(wall, 0.05 * sampled)


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "camera", Camera)
