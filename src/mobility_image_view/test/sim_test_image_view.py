#!/usr/bin/python3
"""GUI test with the simulator: the viewer shows the Burger's camera picture (the brown
round-track walls) and "save frame" writes a PNG equal to a received camera frame."""
import collections
import os
import sys
import tempfile
import threading
import unittest

import numpy as np
import rospy
import rostest
from sensor_msgs.msg import Image

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from viewer_process import ViewerProcess  # noqa: E402

from mobility_image_view.conversion import to_display_rgb  # noqa: E402
from mobility_image_view.status import parse_status_line  # noqa: E402
from mobility_testing import images, waiting, x11  # noqa: E402

TOPIC = '/camera/image_raw'
# Wall diffuse colour 0.57 0.417 0.25: shading scales all three channels alike, so a lit
# wall keeps g/r = 0.73 and b/r = 0.44.
WALL_G_OVER_R, WALL_B_OVER_R = 0.417 / 0.57, 0.25 / 0.57


def wall_mask(pixels):
    """Pixels with the walls' colour ratios at any brightness above dark."""
    def predicate(r, g, b):
        rf = r.astype(np.float64)
        return ((r > 40) & (np.abs(g - WALL_G_OVER_R * rf) < 0.06 * rf + 3)
                & (np.abs(b - WALL_B_OVER_R * rf) < 0.06 * rf + 3))
    return images.hue_mask(pixels, predicate)


class CameraRecorder:
    """Keeps the last few camera frames as RGB arrays."""

    def __init__(self, keep=10):
        self._frames = collections.deque(maxlen=keep)
        self._lock = threading.Lock()
        self._subscriber = rospy.Subscriber(TOPIC, Image, self._on_image, queue_size=5,
                                            buff_size=2 ** 24)

    def _on_image(self, message):
        with self._lock:
            self._frames.append(to_display_rgb(message))

    def frames(self):
        with self._lock:
            return list(self._frames)


class ImageViewSimTest(unittest.TestCase):
    def test_window_shows_the_camera_and_saves_a_received_frame(self):
        rospy.init_node('image_view_sim_test')
        recorder = CameraRecorder()
        tmp = tempfile.TemporaryDirectory(prefix='image_view_sim_')
        self.addCleanup(tmp.cleanup)
        proc = ViewerProcess(['rosrun', 'rqt_image_view', 'rqt_image_view', TOPIC,
                              f'_save_dir:={tmp.name}', '_print_status:=true'])
        self.addCleanup(proc.stop)
        window = proc.wait_window('^Image View - /camera/image_raw$', timeout_s=60)
        line = proc.wait_line(lambda l: parse_status_line(l)['rate_hz'] != 'none', 60,
                              'camera frames in the viewer', prefix='status: ')
        fields = parse_status_line(line)
        self.assertEqual((fields['encoding'], fields['size']), ('rgb8', '640x480'))

        frame = recorder.frames()[-1]
        self.assertGreater(wall_mask(frame).mean(), 0.02, 'the camera itself sees no wall')
        shot_dir = os.environ.get('SCREENSHOT_DIR') or tmp.name
        shot = x11.screenshot_array(window, os.path.join(shot_dir, 'image_view_sim.png'))
        # The 800x640 window fits the 640x480 picture at about 1.2x: the walls' share of the
        # window is the frame's share scaled by the picture's share of the window.
        self.assertGreater(wall_mask(shot).sum(), 0.5 * wall_mask(frame).sum())

        x11.key(window, 'ctrl+s')
        saved = proc.wait_line(lambda _l: True, 10, 'the saved frame', prefix='saved: ')
        pixels = images.load_png(saved[len('saved: '):])
        # The test's own subscriber may get that frame a moment after the viewer did.
        waiting.wait_for(lambda: any(np.array_equal(pixels, f) for f in recorder.frames()), 5,
                         'a received camera frame equal to the saved PNG')


if __name__ == '__main__':
    rostest.rosrun('mobility_image_view', 'image_view_sim', ImageViewSimTest)
