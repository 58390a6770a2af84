#!/usr/bin/python3
"""The camera plugins of test/ros/fixtures/camera_plugins.world, stepped by hand: the
triggered camera (libgazebo_ros_triggered_camera.so) subscribes to trig/image_trigger and
publishes one frame per std_msgs/Empty, none otherwise; the multicamera
(libgazebo_ros_multicamera.so) publishes stereo/camera/left and /right at 5 Hz with equal
stamps, the right camera_info's P[3] = -fx * 0.07; the R16G16B16 camera publishes rgb16."""
import math
import unittest

import rosgraph
import rospy
import rostest
from sensor_msgs.msg import CameraInfo, Image
from std_msgs.msg import Empty

from gazebo_api_client import Latest, connect, simulator_connections, wait_for

WIDTH, HFOV = 32, 1.0


def connected(sub, topic):
    sub.wait_connected()
    wait_for(lambda: simulator_connections(topic, "/camera_plugins_test"),
             "the simulator to see the subscriber of " + topic)


class CameraPlugins(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("camera_plugins_test")
        cls.gz = connect()

    def step(self, steps):
        response = self.gz["step_simulation"](steps)
        self.assertTrue(response.success, response.status_message)

    def test_triggered_camera_publishes_one_frame_per_trigger(self):
        _, subscribers, _ = rosgraph.Master("/camera_plugins_test").getSystemState()
        trigger_subscribers = dict(subscribers).get("/trig/image_trigger", [])
        self.assertEqual(trigger_subscribers, ["/bullet_sim"])
        images = Latest("/trig/image_raw", Image)
        connected(images, "/trig/image_raw")
        self.step(500)  # five periods of its 10 Hz update rate
        self.assertEqual(images.count(), 0)
        trigger = rospy.Publisher("/trig/image_trigger", Empty, queue_size=10)
        wait_for(lambda: trigger.get_num_connections() > 0, "the simulator's trigger subscriber")
        trigger.publish(Empty())
        trigger.publish(Empty())
        for _ in range(200):
            if images.count() >= 2:
                break
            self.step(1)
        wait_for(lambda: images.count() >= 2, "two triggered frames")
        self.step(500)
        self.assertEqual(images.count(), 2)

    def test_multicamera_left_and_right_share_stamps(self):
        left = Latest("/stereo/camera/left/image_raw", Image)
        right = Latest("/stereo/camera/right/image_raw", Image)
        info = Latest("/stereo/camera/right/camera_info", CameraInfo)
        for sub, topic in ((left, "/stereo/camera/left/image_raw"),
                           (right, "/stereo/camera/right/image_raw"),
                           (info, "/stereo/camera/right/camera_info")):
            connected(sub, topic)
        self.step(400)  # two periods of 5 Hz
        wait_for(lambda: left.count() >= 2 and right.count() >= 2 and info.count() >= 2,
                 "two stereo frames")
        self.assertEqual([m.header.stamp for m in left.messages],
                         [m.header.stamp for m in right.messages])
        self.assertEqual(left.last().header.frame_id, "left_optical")
        fx = (WIDTH / 2) / math.tan(HFOV / 2)
        self.assertAlmostEqual(info.last().P[0], fx, places=9)
        self.assertAlmostEqual(info.last().P[3], -fx * 0.07, places=9)

    def test_sixteen_bit_camera_publishes_rgb16(self):
        images = Latest("/cam16/image_raw", Image)
        connected(images, "/cam16/image_raw")
        self.step(100)
        wait_for(lambda: images.count() >= 1, "a 16-bit frame")
        image = images.last()
        self.assertEqual(image.encoding, "rgb16")
        self.assertEqual(image.step, 6 * WIDTH)
        self.assertEqual(len(image.data), 6 * WIDTH * 24)


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "camera_plugins", CameraPlugins)
