"""Frame rate measurement, image topic listing and the status text."""
import unittest

from mobility_image_view import status, topics
from mobility_image_view.rate import RateMeter


class RateMeterTest(unittest.TestCase):
    def test_ten_hz(self):
        meter = RateMeter(window_s=2.0)
        for k in range(11):
            meter.tick(100.0 + 0.1 * k)
        self.assertAlmostEqual(meter.rate_hz(101.0), 10.0)

    def test_only_the_window_counts(self):
        meter = RateMeter(window_s=2.0)
        for k in range(10):             # 1 Hz for 10 s ...
            meter.tick(float(k))
        for k in range(1, 21):          # ... then 20 Hz for 1 s
            meter.tick(9.0 + 0.05 * k)
        # window [8, 10]: arrivals at 8, 9 and 20 at 9.05..10.0 -> 21 intervals over 2 s
        self.assertAlmostEqual(meter.rate_hz(10.0), 10.5)

    def test_no_rate_before_two_frames_or_after_the_stream_stops(self):
        meter = RateMeter(window_s=2.0)
        self.assertIsNone(meter.rate_hz(0.0))
        meter.tick(0.0)
        self.assertIsNone(meter.rate_hz(0.5))
        meter.tick(0.5)
        self.assertAlmostEqual(meter.rate_hz(0.5), 2.0)
        self.assertIsNone(meter.rate_hz(3.0))

    def test_reset_forgets(self):
        meter = RateMeter()
        meter.tick(0.0)
        meter.tick(0.1)
        meter.reset()
        self.assertIsNone(meter.rate_hz(0.1))

    def test_bad_window(self):
        with self.assertRaisesRegex(ValueError, 'rate window must be positive, got 0'):
            RateMeter(window_s=0)


class FakeMaster:
    def __init__(self, published=None, error=None):
        self.published, self.error = published, error

    def getPublishedTopics(self, subgraph):
        assert subgraph == ''
        if self.error:
            raise self.error
        return self.published


class TopicsTest(unittest.TestCase):
    PUBLISHED = [['/rosout', 'rosgraph_msgs/Log'], ['/camera/image_raw', 'sensor_msgs/Image'],
                 ['/camera/camera_info', 'sensor_msgs/CameraInfo'],
                 ['/depth/image', 'sensor_msgs/Image'],
                 ['/camera/image_raw/compressed', 'sensor_msgs/CompressedImage']]

    def test_only_image_topics_sorted(self):
        self.assertEqual(topics.image_topics(self.PUBLISHED), ['/camera/image_raw', '/depth/image'])

    def test_query_master(self):
        self.assertEqual(topics.query_image_topics(FakeMaster(self.PUBLISHED)),
                         ['/camera/image_raw', '/depth/image'])

    def test_master_down_is_a_clear_error(self):
        master = FakeMaster(error=ConnectionRefusedError(111, 'Connection refused'))
        with self.assertRaisesRegex(topics.MasterUnavailable,
                                    'cannot list topics from the ROS master: .*refused'):
            topics.query_image_topics(master)

    def test_selected_topic_not_yet_published_is_offered(self):
        self.assertEqual(topics.choices(['/b'], '/a'), ['/a', '/b'])
        self.assertEqual(topics.choices(['/b'], '/b'), ['/b'])
        self.assertEqual(topics.choices(['/b'], ''), ['/b'])


class StatusTest(unittest.TestCase):
    def test_status_text(self):
        self.assertEqual(status.status_text('/cam', 'rgb8', 640, 480, 29.96),
                         '/cam  640x480 rgb8  30.0 Hz')
        self.assertEqual(status.status_text('/cam', 'rgb8', 640, 480, None),
                         '/cam  640x480 rgb8  no frames')
        self.assertEqual(status.status_text('/cam', '', 0, 0, None), '/cam  waiting for frames')
        self.assertEqual(status.status_text('', '', 0, 0, None), 'no topic selected')

    def test_status_line_round_trip(self):
        line = status.status_line('/cam', '16UC1', 4, 3, 9.996)
        self.assertEqual(line, 'status: topic=/cam encoding=16UC1 size=4x3 rate_hz=10.00')
        self.assertEqual(status.parse_status_line(line),
                         {'topic': '/cam', 'encoding': '16UC1', 'size': '4x3', 'rate_hz': '10.00'})
        self.assertEqual(status.parse_status_line(status.status_line('', '', 0, 0, None)),
                         {'topic': 'none', 'encoding': 'none', 'size': '0x0', 'rate_hz': 'none'})

    def test_parse_rejects_other_lines(self):
        with self.assertRaisesRegex(ValueError, "not a status line: 'saved: x'"):
            status.parse_status_line('saved: x')


if __name__ == '__main__':
    unittest.main()
