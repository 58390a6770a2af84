#!/usr/bin/python3
"""Range (libgazebo_ros_range.so), block laser (libgazebo_ros_block_laser.so) and bumper
(libgazebo_ros_bumper.so) topics of test/fixtures/cone_contact_robot.urdf in the namespace
cube_ns: message types, frames under the tf_prefix, rates in sim time, and what they read of
a panel whose face is 0.9 m ahead of the sensors and of the ground the 2 kg cube rests on."""
import math
import unittest

import rospy
import rostest
from gazebo_msgs.msg import ContactsState
from sensor_msgs.msg import PointCloud, Range

from gazebo_api_client import Latest, connect, simulator_connections, wait_for, yaw_pose

NS = "/cube_ns/"
PANEL_URDF = """<robot name="panel"><link name="panel">
  <inertial><origin xyz="0 0 0.5"/><mass value="20"/>
    <inertia ixx="5" ixy="0" ixz="0" iyy="2" iyz="0" izz="5"/></inertial>
  <collision><origin xyz="0 0 0.5"/><geometry><box size="0.1 3 1"/></geometry></collision>
</link></robot>"""
STEPS = 1000  # one second of sim time at the 1 ms physics step


class ConeContactSensors(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("cone_contact_sensors_test")
        cls.gz = connect()
        urdf = rospy.get_param("/cube_description")
        response = cls.gz["spawn_urdf_model"]("cube", urdf, "cube_ns", yaw_pose(0, 0, 0.1), "")
        assert response.success, response.status_message
        # The panel's face (x 1.05 - 0.05) is 0.9 m ahead of the sensors at x 0.1.
        response = cls.gz["spawn_urdf_model"]("panel", PANEL_URDF, "", yaw_pose(1.05, 0), "")
        assert response.success, response.status_message
        cls.step(500)  # settle on the ground

    @classmethod
    def step(cls, steps):
        response = cls.gz["step_simulation"](steps)
        assert response.success, response.status_message

    def collect(self, topic, msg_type, expected):
        sub = Latest(NS + topic, msg_type)
        sub.wait_connected()
        wait_for(lambda: simulator_connections(NS + topic, "/cone_contact_sensors_test"),
                 "the simulator to see the subscriber")
        self.step(STEPS)
        wait_for(lambda: sub.count() >= expected, "%d messages on %s" % (expected, topic))
        sub.sub.unregister()
        self.assertEqual(len(sub.messages), expected, topic)
        stamps = [m.header.stamp.to_sec() for m in sub.messages]
        for a, b in zip(stamps, stamps[1:]):
            self.assertAlmostEqual(b - a, 1.0 / expected, places=6, msg=topic)
        return sub.messages

    def test_range_at_10_hz_reads_the_panel(self):
        for msg in self.collect("sonar", Range, 10):
            self.assertEqual(msg.header.frame_id, "cube_ns/sonar_link")
            self.assertEqual(msg.radiation_type, Range.ULTRASOUND)
            self.assertAlmostEqual(msg.field_of_view, 0.4, places=6)
            self.assertAlmostEqual(msg.min_range, 0.02, places=6)
            self.assertAlmostEqual(msg.max_range, 2.0, places=6)
            self.assertAlmostEqual(msg.range, 0.9, delta=0.002)

    def test_block_laser_at_5_hz_puts_points_on_the_panel(self):
        # 4 x 3 rays at yaw -0.3, -0.1, 0.1, 0.3 and pitch -0.1, 0, 0.1 meet the plane
        # x = 0.9 of the sensor frame at 0.9 / (cos pitch cos yaw); as Gazebo's plugin does,
        # each point takes its ray's range along the direction half way to the next ray
        # (the last: its own): yaw -0.2, 0, 0.2, 0.3 and pitch -0.05, 0.05, 0.1.
        ray_yaws, ray_pitches = (-0.3, -0.1, 0.1, 0.3), (-0.1, 0.0, 0.1)
        yaws, pitches = (-0.2, 0.0, 0.2, 0.3), (-0.05, 0.05, 0.1)
        for msg in self.collect("block", PointCloud, 5):
            self.assertEqual(msg.header.frame_id, "cube_ns/block_frame")
            self.assertEqual(len(msg.points), 12)
            self.assertEqual(len(msg.channels), 1)
            self.assertEqual(len(msg.channels[0].values), 12)
            for j, pitch in enumerate(pitches):
                for i, yaw in enumerate(yaws):
                    p = msg.points[j * 4 + i]
                    r = 0.9 / (math.cos(ray_pitches[j]) * math.cos(ray_yaws[i]))
                    self.assertAlmostEqual(p.x, r * math.cos(pitch) * math.cos(yaw), delta=0.002)
                    self.assertAlmostEqual(p.y, r * math.cos(pitch) * math.sin(yaw), delta=0.002)
                    self.assertAlmostEqual(p.z, r * math.sin(pitch), delta=0.002)

    def test_bumper_at_20_hz_carries_the_cubes_weight(self):
        for msg in self.collect("bumps", ContactsState, 20):
            self.assertEqual(msg.header.frame_id, "cube_ns/world")
            self.assertEqual(len(msg.states), 1)
            state = msg.states[0]
            self.assertEqual(state.collision1_name, "cube::base_link::base_link_collision")
            self.assertEqual(state.collision2_name, "ground_plane::link::collision")
            self.assertAlmostEqual(state.total_wrench.force.z, 2 * 9.8, delta=0.05)
            self.assertGreaterEqual(len(state.contact_positions), 3)
            for normal in state.contact_normals:
                self.assertAlmostEqual(normal.z, 1.0, places=6)

    def test_nothing_is_published_while_nobody_subscribes(self):
        subs = {t: Latest(NS + t, m) for t, m in
                (("sonar", Range), ("block", PointCloud), ("bumps", ContactsState))}
        for sub in subs.values():
            sub.wait_connected()
        seqs = {}
        for topic, sub in subs.items():
            wait_for(lambda: simulator_connections(NS + topic, "/cone_contact_sensors_test"),
                     "the simulator to see the subscriber")
        self.step(200)
        # 0.2 s of sim time holds 2 sonar readings (10 Hz), 1 block laser cloud (5 Hz) and 4
        # bumper states (20 Hz): all of them, delivered, before the last one's number is read
        expected = {"sonar": 2, "block": 1, "bumps": 4}
        for topic, sub in subs.items():
            wait_for(lambda: sub.count() >= expected[topic],
                     "%d messages on %s" % (expected[topic], topic))
            seqs[topic] = sub.last().header.seq
            sub.sub.unregister()
        for topic in subs:
            wait_for(lambda: not simulator_connections(NS + topic, "/cone_contact_sensors_test"),
                     "the simulator to see the subscriber go")
        self.step(STEPS)
        subs = {t: Latest(NS + t, m) for t, m in
                (("sonar", Range), ("block", PointCloud), ("bumps", ContactsState))}
        for topic, sub in subs.items():
            sub.wait_connected()
            wait_for(lambda: simulator_connections(NS + topic, "/cone_contact_sensors_test"),
                     "the simulator to see the subscriber")
        self.step(200)
        for topic, sub in subs.items():
            wait_for(lambda: sub.count() >= 1, "a message on " + topic)
            # roscpp numbers every publish() call: none in the second unsubscribed.
            self.assertEqual(sub.messages[0].header.seq, seqs[topic] + 1, topic)


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "cone_contact_sensors", ConeContactSensors)
