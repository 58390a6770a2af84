#!/usr/bin/python3
"""The Kinect of test/fixtures/depth_camera_robot.urdf in the namespace kinect_ns: its five
topics at 10 Hz of sim time, frames under the tf_prefix, Gazebo's encodings and point
fields, the panel ahead at its distance; and nothing published while nobody subscribes
(roscpp numbers every publish() call in header.seq, subscribed or not, so a gap in seq
would show a frame made for nobody)."""
import math
import struct
import unittest

import rospy
import rostest
from sensor_msgs.msg import CameraInfo, Image, PointCloud2

from gazebo_api_client import Latest, connect, simulator_connections, wait_for, yaw_pose

NS = "/kinect_ns/kinect/"
TOPICS = {"rgb/image_raw": Image, "rgb/camera_info": CameraInfo,
          "depth/image_raw": Image, "depth/camera_info": CameraInfo,
          "depth/points": PointCloud2}
FRAME_ID = "kinect_ns/camera_depth_optical_frame"
WIDTH, HEIGHT, HFOV = 160, 120, 1.0472
STEPS_PER_FRAME = 100          # 10 Hz at the 1 ms physics step
PANEL_FACE_M = 1.95            # the panel's centre 2 m ahead, 0.1 m thick, 1 m high:
                               # its top edge (0.5 m above the lens) at row 24.5
PANEL_URDF = """<robot name="panel"><link name="panel">
  <inertial><origin xyz="0 0 0.5"/><mass value="20"/>
    <inertia ixx="5" ixy="0" ixz="0" iyy="2" iyz="0" izz="5"/></inertial>
  <visual><origin xyz="0 0 0.5"/><geometry><box size="0.1 3 1"/></geometry></visual>
  <collision><origin xyz="0 0 0.5"/><geometry><box size="0.1 3 1"/></geometry></collision>
</link></robot>"""


def node_connections(topic):
    return simulator_connections(topic, "/depth_camera_test")


class DepthCamera(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("depth_camera_test")
        cls.gz = connect()
        urdf = rospy.get_param("/depth_robot_description")
        response = cls.gz["spawn_urdf_model"]("depth_bot", urdf, "kinect_ns", yaw_pose(0, 0), "")
        assert response.success, response.status_message
        response = cls.gz["spawn_urdf_model"]("panel", PANEL_URDF, "", yaw_pose(2, 0), "")
        assert response.success, response.status_message
        cls.step(300)  # settle on the ground

    @classmethod
    def step(cls, steps):
        response = cls.gz["step_simulation"](steps)
        assert response.success, response.status_message

    def collect(self, topics, frames):
        """Subscribes to `topics`, steps `frames` update periods, unsubscribes."""
        subs = {t: Latest(NS + t, TOPICS[t]) for t in topics}
        for t, sub in subs.items():
            sub.wait_connected()
            wait_for(lambda: node_connections(NS + t), "the simulator to see the subscriber")
        # A frame at a time, as a lockstep client would: the publishers keep only the
        # newest cloud, which a burst of frames faster than the wire would replace.
        for frame in range(1, frames + 1):
            self.step(STEPS_PER_FRAME)
            for t, sub in subs.items():
                wait_for(lambda: sub.count() >= frame, "%d messages on %s" % (frame, t))
        for sub in subs.values():
            sub.sub.unregister()
        return {t: sub.messages for t, sub in subs.items()}

    def test_topics_at_the_update_rate_with_frames_and_encodings(self):
        got = self.collect(list(TOPICS), 10)
        for topic, messages in got.items():
            self.assertEqual(len(messages), 10, topic)
            stamps = [m.header.stamp.to_sec() for m in messages]
            for a, b in zip(stamps, stamps[1:]):
                self.assertAlmostEqual(b - a, 0.1, places=6, msg=topic)
            for m in messages:
                self.assertEqual(m.header.frame_id, FRAME_ID, topic)
        self.assertEqual(got["rgb/image_raw"][0].encoding, "rgb8")
        depth = got["depth/image_raw"][-1]
        self.assertEqual((depth.encoding, depth.width, depth.height, depth.step),
                         ("32FC1", WIDTH, HEIGHT, 4 * WIDTH))
        fx = (WIDTH / 2) / math.tan(HFOV / 2)
        for info in (got["rgb/camera_info"][0], got["depth/camera_info"][0]):
            self.assertAlmostEqual(info.K[0], fx, places=6)
            self.assertEqual((info.K[2], info.K[5]), (WIDTH / 2, HEIGHT / 2))

        centre = struct.unpack_from("<f", depth.data, 4 * (HEIGHT // 2 * WIDTH + WIDTH // 2))[0]
        self.assertAlmostEqual(centre, PANEL_FACE_M, delta=0.01)
        for row, hit in ((22, False), (27, True)):
            value = struct.unpack_from("<f", depth.data, 4 * (row * WIDTH + WIDTH // 2))[0]
            self.assertEqual(not math.isnan(value), hit, "row %d: %f" % (row, value))

        cloud = got["depth/points"][-1]
        self.assertEqual([(f.name, f.offset, f.datatype) for f in cloud.fields],
                         [("x", 0, 7), ("y", 4, 7), ("z", 8, 7), ("rgb", 16, 7)])
        self.assertEqual((cloud.width, cloud.height, cloud.point_step, cloud.row_step),
                         (WIDTH, HEIGHT, 32, 32 * WIDTH))
        self.assertFalse(cloud.is_dense)
        point = struct.unpack_from("<fff", cloud.data, 32 * (HEIGHT // 2 * WIDTH + WIDTH // 2))
        self.assertAlmostEqual(point[0], 0.0, delta=1e-6)
        self.assertAlmostEqual(point[1], 0.0, delta=1e-6)
        self.assertAlmostEqual(point[2], centre, delta=1e-6)
        # The cloud's colours are the same frame's image (the cloud is made on the node's
        # publishing thread from its own copy of the frame).
        image = got["rgb/image_raw"][-1]
        self.assertEqual(image.header.stamp, cloud.header.stamp)
        for row, col in ((HEIGHT // 2, WIDTH // 2), (HEIGHT - 1, 0), (0, WIDTH - 1)):
            i = row * WIDTH + col
            self.assertEqual(bytes(cloud.data[32 * i + 16:32 * i + 19]),
                             bytes(image.data[3 * i:3 * i + 3]), "row %d col %d" % (row, col))

    def test_a_cloud_watched_alone_has_the_frame_colours(self):
        # Nobody watches the colour image: the node hands the frame's own bytes to the cloud
        # instead of a copy. The robot and the panel stand still and nothing is noisy, so
        # the next frame, watched with its image, has the same colours at every pixel.
        alone = self.collect(["depth/points"], 2)["depth/points"][-1]
        got = self.collect(["depth/points", "rgb/image_raw"], 1)
        image = got["rgb/image_raw"][-1]
        self.assertEqual(image.header.stamp, got["depth/points"][-1].header.stamp)
        self.assertGreater(got["depth/points"][-1].header.stamp, alone.header.stamp)
        cloud_colours = bytes(b for i in range(WIDTH * HEIGHT)
                              for b in alone.data[32 * i + 16:32 * i + 19])
        self.assertEqual(cloud_colours, bytes(image.data))
        # Not a blank frame: the panel ahead and what lies around it differ.
        pixels = {cloud_colours[k:k + 3] for k in range(0, len(cloud_colours), 3)}
        self.assertGreater(len(pixels), 1)

    def test_nothing_is_made_while_nobody_subscribes(self):
        watched = ["depth/image_raw", "depth/points", "rgb/image_raw"]
        before = self.collect(watched, 3)
        for t in watched:
            wait_for(lambda: not node_connections(NS + t), "the simulator to drop " + t)
        self.step(5 * STEPS_PER_FRAME)  # five frames fall due unwatched
        after = self.collect(watched, 2)
        for t in watched:
            last_seq = before[t][-1].header.seq
            self.assertEqual(after[t][0].header.seq, last_seq + 1, t)
            gap = after[t][0].header.stamp.to_sec() - before[t][-1].header.stamp.to_sec()
            self.assertAlmostEqual(gap, 0.6, places=6, msg=t)


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "depth_camera", DepthCamera)
