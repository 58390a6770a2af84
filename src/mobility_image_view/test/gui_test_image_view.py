#!/usr/bin/python3
"""GUI test under X: the viewer shows a published picture, shows its rate, saves it exactly,
lists image topics and names unsupported encodings."""
import os
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np
import rospy
import rostest
from std_msgs.msg import String

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from synthetic_camera import (GREY, HEIGHT, WALL, WALL_H, WALL_W, WALL_X, WALL_Y,  # noqa: E402
                              WIDTH, SyntheticCamera, frame_number, make_frame)
from viewer_process import ViewerProcess  # noqa: E402

from mobility_image_view.status import parse_status_line  # noqa: E402
from mobility_testing import images, waiting, x11  # noqa: E402

RATE_HZ = 10.0


def viewer(*args, package='mobility_image_view', executable='image_view_gui'):
    return ViewerProcess(['rosrun', package, executable, *args, '_print_status:=true'])


def bounding_box(mask, min_count=50):
    """(x0, y0, x1, y1) inclusive of the rows and columns holding over min_count True
    pixels (a drawn picture, not the odd pixel of a widget that happens to match)."""
    xs = np.nonzero(mask.sum(axis=0) > min_count)[0]
    ys = np.nonzero(mask.sum(axis=1) > min_count)[0]
    return xs.min(), ys.min(), xs.max(), ys.max()


class ImageViewGuiTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('image_view_gui_test')
        x11.require_display()

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix='image_view_test_')
        self.addCleanup(self.tmp.cleanup)

    def start(self, proc):
        self.addCleanup(proc.stop)
        return proc

    def shot(self, window, name):
        return x11.screenshot_array(window, os.path.join(self.tmp.name, name))

    def shot_if(self, window, name, condition):
        """[screenshot] if condition(screenshot) holds, else None (for wait_for)."""
        shot = self.shot(window, name)
        return [shot] if condition(shot) else None

    def test_shows_image_rate_and_saves_the_last_frame(self):
        camera = SyntheticCamera('/gui_test/image', RATE_HZ)
        self.addCleanup(camera.stop)
        proc = self.start(viewer('/gui_test/image', f'_save_dir:={self.tmp.name}',
                                 package='rqt_image_view', executable='rqt_image_view'))
        window = proc.wait_window('^Image View - /gui_test/image$', timeout_s=30)

        # Rate: after 3 s of frames the shown rate matches what was published.
        first = proc.wait_line(lambda line: parse_status_line(line)['rate_hz'] != 'none', 20,
                               'a measured rate', prefix='status: ')
        start = time.monotonic()
        waiting.wait_for(lambda: time.monotonic() - start > 3.0, 5, '3 s of frames')
        count_before = len(proc.lines('status: '))
        line = proc.wait_line(lambda _l: len(proc.lines('status: ')) > count_before, 5,
                              'a fresh status line', prefix='status: ')
        fields = parse_status_line(line)
        self.assertEqual(fields['encoding'], 'rgb8', first)
        self.assertEqual(fields['size'], f'{WIDTH}x{HEIGHT}')
        print(f"shown rate {fields['rate_hz']} Hz, published {camera.measured_rate_hz():.2f} Hz")
        self.assertAlmostEqual(float(fields['rate_hz']), camera.measured_rate_hz(), delta=0.3)
        self.assertAlmostEqual(float(fields['rate_hz']), RATE_HZ, delta=0.5)

        # Fit to window: the grey picture is scaled up with its aspect ratio, wall centred.
        shot = self.shot(window, 'fit.png')
        x0, y0, x1, y1 = bounding_box(images.colour_mask(shot, GREY, tolerance=3))
        scale = (x1 - x0 + 1) / WIDTH
        self.assertGreater(scale, 1.5)
        self.assertAlmostEqual((y1 - y0 + 1) / HEIGHT, scale, delta=3.0 / HEIGHT)
        wall = images.colour_mask(shot, WALL, tolerance=6)
        self.assertAlmostEqual(wall.sum() / (WALL_W * WALL_H * scale ** 2), 1.0, delta=0.03)
        wy, wx = np.nonzero(wall)
        self.assertAlmostEqual(wx.mean(), x0 + (WALL_X + WALL_W / 2) * scale, delta=2)
        self.assertAlmostEqual(wy.mean(), y0 + (WALL_Y + WALL_H / 2) * scale, delta=2)

        # 1:1: every image pixel is one screen pixel.
        x11.key(window, 'ctrl+1')
        [shot] = waiting.wait_for(lambda: self.shot_if(window, 'one_to_one.png', lambda s: (
            images.count_colour(s, WALL, 0) == WALL_W * WALL_H)), 10, 'the 1:1 picture')
        wall_x0, wall_y0, _, _ = bounding_box(images.colour_mask(shot, WALL, 0))
        left, top = wall_x0 - WALL_X, wall_y0 - WALL_Y
        shown = shot[top:top + HEIGHT, left:left + WIDTH]
        np.testing.assert_array_equal(shown, make_frame(frame_number(shown)))

        # Save frame (Ctrl+S, into ~save_dir): the PNG equals a frame just published.
        x11.key(window, 'ctrl+s')
        saved = proc.wait_line(lambda _l: True, 10, 'the saved frame', prefix='saved: ')
        sent_by_then = [k for _, k in camera.sent()]
        pixels = images.load_png(saved[len('saved: '):])
        k = frame_number(pixels)
        self.assertIn(k, sent_by_then[-3:])
        np.testing.assert_array_equal(pixels, make_frame(k))
        self.assertEqual(proc.stop(), 0, 'the viewer did not quit cleanly on SIGINT')

    def test_drop_down_lists_image_topics_and_refresh_adds_new_ones(self):
        camera = SyntheticCamera('/gui_test/first', RATE_HZ)
        self.addCleanup(camera.stop)
        chatter = rospy.Publisher('/gui_test/chatter', String, queue_size=1)
        self.addCleanup(chatter.unregister)
        waiting.wait_for(lambda: '/gui_test/chatter' in dict(rospy.get_published_topics()), 10,
                         'the String topic registered')
        proc = self.start(viewer())
        window = proc.wait_window('^Image View$', timeout_s=30)
        topics = proc.wait_line(lambda _l: True, 10, 'the topic list', prefix='topics: ').split()
        self.assertIn('/gui_test/first', topics)
        self.assertNotIn('/gui_test/chatter', topics)

        late = SyntheticCamera('/gui_test/late', RATE_HZ)
        self.addCleanup(late.stop)
        waiting.wait_for(lambda: '/gui_test/late' in dict(rospy.get_published_topics()), 10,
                         'the late image topic registered')
        x11.key(window, 'F5')
        proc.wait_line(lambda line: '/gui_test/late' in line.split(), 10,
                       'the refreshed topic list', prefix='topics: ')

        # Alt+T focuses the drop-down, Down selects its first entry, which is then shown.
        x11.key(window, 'alt+t', 'Down')
        proc.wait_window('^Image View - /gui_test/first$', timeout_s=10)
        proc.wait_line(lambda line: parse_status_line(line)['encoding'] == 'rgb8', 10,
                       'frames of the selected topic', prefix='status: ')

    def test_32fc1_depth_is_scaled_to_grey_with_nan_black(self):
        # 160x120 metres: columns 0-49 at 1 m, 50-99 at 2 m, 100-159 at 3 m, the top 20 rows
        # NaN. Scaled from 1..3 m: 0, 127.5 -> 128 and 255; NaN black.
        depth = np.empty((120, 160), dtype=np.float32)
        depth[:, :50], depth[:, 50:100], depth[:, 100:] = 1.0, 2.0, 3.0
        depth[:20] = np.nan
        expected = np.zeros((120, 160, 3), dtype=np.uint8)
        expected[20:, 50:100], expected[20:, 100:] = 128, 255
        camera = SyntheticCamera('/gui_test/depth', RATE_HZ, encoding='32FC1',
                                 frame=lambda _k: depth)
        self.addCleanup(camera.stop)
        proc = self.start(viewer('/gui_test/depth'))
        window = proc.wait_window('^Image View - /gui_test/depth$', timeout_s=30)
        proc.wait_line(lambda line: parse_status_line(line)['encoding'] == '32FC1', 20,
                       'depth frames', prefix='status: ')
        x11.key(window, 'ctrl+1')
        white = (255, 255, 255)
        [shot] = waiting.wait_for(lambda: self.shot_if(window, 'depth.png', lambda s: (
            images.count_colour(s, white, 0) >= 60 * 100)), 10, 'the 1:1 depth picture')
        x0, y0, _, _ = bounding_box(images.colour_mask(shot, white, 0))
        left, top = x0 - 100, y0 - 20
        np.testing.assert_array_equal(shot[top:top + 120, left:left + 160], expected)

    def test_unsupported_encoding_is_named_plainly(self):
        camera = SyntheticCamera('/gui_test/yuv', RATE_HZ, encoding='yuv422')
        self.addCleanup(camera.stop)
        proc = self.start(viewer('/gui_test/yuv', f'_save_dir:={self.tmp.name}'))
        window = proc.wait_window('^Image View - /gui_test/yuv$', timeout_s=30)
        message = proc.wait_line(lambda line: 'yuv422' in line, 20, 'the encoding message',
                                 prefix='message: ')
        self.assertEqual(message, "message: cannot show encoding 'yuv422': supported are rgb8, "
                                  "bgr8, rgba8, bgra8, mono8, 8UC1, mono16, 16UC1, 32FC1")
        # No picture is drawn (a drawn frame would give over 50000 grey pixels; the
        # widgets' anti-aliased text has a few).
        shot = self.shot(window, 'yuv.png')
        self.assertLess(images.count_colour(shot, GREY, 0), 200)

    def test_bad_save_dir_is_named_and_exits(self):
        result = subprocess.run(['rosrun', 'mobility_image_view', 'image_view_gui',
                                 '_save_dir:=/no/such/dir'], capture_output=True, text=True,
                                timeout=30)
        self.assertEqual(result.returncode, 2)
        self.assertIn('image_view_gui: ~save_dir "/no/such/dir" is not an existing directory',
                      result.stderr)


if __name__ == '__main__':
    rostest.rosrun('mobility_image_view', 'image_view_gui', ImageViewGuiTest)
