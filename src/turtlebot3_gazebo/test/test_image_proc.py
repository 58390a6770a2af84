#!/usr/bin/python3
"""Debian's image_proc rectifies: the camera stage of the AutoRace chapter.

Debian 12 and 13 ship image_proc's node in ros-image-proc but its nodelet descriptions
(/usr/share/image_proc/nodelet_plugins.xml) and the library's unversioned name in
libimage-proc-dev: without that package the node loads no nodelet ("Failed to load nodelet
[/camera/image_proc_debayer]") and nothing is rectified. deps/apt-packages.txt has both.

image_proc is started as ROBOTIS's intrinsic_camera_calibration.launch starts it; it is fed a
64 x 48 image whose grey level is 4 x its column, with barrel distortion k1 = -0.2 (fx = fy =
50, cx = 32, cy = 24). A rectified pixel (u, v) shows the raw image at the distorted point:
x = (u - cx) / fx, y = (v - cy) / fy, r^2 = x^2 + y^2, u_raw = fx x (1 + k1 r^2) + cx, so its
grey level is 4 u_raw (worked out below by hand for three pixels).
"""
import os
import signal
import subprocess
import sys
import time
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..',
                                'mobility_testing', 'src'))
from mobility_testing.ports import free_port  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
WIDTH, HEIGHT, F, CX, CY, K1 = 64, 48, 50.0, 32.0, 24.0, -0.2
# (u, v) -> grey level, by hand: (60, 24): x = 0.56, r^2 = 0.3136, u_raw = 50 * 0.56 *
# 0.93728 + 32 = 58.244 -> 232.98; (60, 44): x = 0.56, y = 0.4, r^2 = 0.4736, u_raw = 50 *
# 0.56 * 0.90528 + 32 = 57.348 -> 229.39; (10, 10): x = -0.44, y = -0.28, r^2 = 0.272,
# u_raw = 50 * -0.44 * 0.9456 + 32 = 11.197 -> 44.79
EXPECTED = {(60, 24): 232.98, (60, 44): 229.39, (10, 10): 44.79}


class TestImageProc(unittest.TestCase):
    def setUp(self):
        self.port = free_port()
        env = dict(os.environ, ROS_MASTER_URI='http://localhost:%d' % self.port,
                   PATH='/usr/bin:/bin:' + os.environ.get('PATH', ''))
        self.launch = subprocess.Popen(
            ['roslaunch', '-p', str(self.port),
             os.path.join(HERE, 'autorace', 'image_proc.launch')],
            env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        os.environ['ROS_MASTER_URI'] = env['ROS_MASTER_URI']

    def tearDown(self):
        os.killpg(self.launch.pid, signal.SIGINT)
        try:
            self.launch.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(self.launch.pid, signal.SIGKILL)
            self.launch.wait()

    def test_image_rect_color_is_the_undistorted_image(self):
        import rospy
        from sensor_msgs.msg import CameraInfo, Image
        end = time.monotonic() + 60
        while time.monotonic() < end:  # the launch's master
            try:
                rospy.init_node('image_proc_check', disable_signals=True)
                break
            except Exception:
                time.sleep(0.5)
        rectified = []
        rospy.Subscriber('/camera/image_rect_color', Image, rectified.append, queue_size=1)
        image_pub = rospy.Publisher('/camera/image_raw', Image, queue_size=1)
        info_pub = rospy.Publisher('/camera/camera_info', CameraInfo, queue_size=1)
        grey = np.tile((4 * np.arange(WIDTH)).astype(np.uint8), (HEIGHT, 1))
        image = Image(height=HEIGHT, width=WIDTH, encoding='rgb8', step=3 * WIDTH,
                      data=np.repeat(grey[:, :, None], 3, axis=2).tobytes())
        info = CameraInfo(height=HEIGHT, width=WIDTH, distortion_model='plumb_bob',
                          D=[K1, 0, 0, 0, 0], K=[F, 0, CX, 0, F, CY, 0, 0, 1],
                          R=[1, 0, 0, 0, 1, 0, 0, 0, 1], P=[F, 0, CX, 0, 0, F, CY, 0, 0, 0, 1, 0])
        end = time.monotonic() + 60
        while not rectified and time.monotonic() < end:
            stamp = rospy.Time.now()
            image.header.stamp = info.header.stamp = stamp
            image.header.frame_id = info.header.frame_id = 'camera'
            image_pub.publish(image)
            info_pub.publish(info)
            time.sleep(0.2)
        rospy.signal_shutdown('done')
        self.assertTrue(rectified, 'no /camera/image_rect_color from image_proc in 60 s: its '
                        'nodelets did not load (Debian: install libimage-proc-dev, which has '
                        '/usr/share/image_proc/nodelet_plugins.xml)')
        out = np.frombuffer(rectified[0].data, np.uint8).reshape(HEIGHT, WIDTH, 3)
        for (u, v), grey_level in EXPECTED.items():
            self.assertLessEqual(abs(float(out[v, u, 0]) - grey_level), 1.5,
                                 'pixel (%d, %d): %d, undistorted %.2f, raw %d'
                                 % (u, v, out[v, u, 0], grey_level, 4 * u))
            self.assertGreater(abs(4 * u - grey_level), 3)  # it differs from the raw image


if __name__ == '__main__':
    unittest.main()
