#!/usr/bin/python3
"""libgazebo_ros_ft_sensor.so and libgazebo_ros_f3d.so through their topics.

A stand (a 50 kg slab lying on the ground) holds a 2 kg bob on a hinge 1 m up, its centre
of mass 0.5 m below the hinge and 0.1 m along x. Gravity is 9.8 m/s^2. The ft_sensor on
the hinge (topic /pendulum/ft, updateRate 100) reads what the bob exerts on the joint in
the bob's frame: force (0, 0, -m g) = (0, 0, -19.6) N and torque about the joint
(0, 0.1 m g, 0) = (0, 1.96, 0) N m. A force plugin pushes the stand down with 10 N
(topic /pendulum/push); the f3d on the stand (topic /pendulum/f3d, frameName base) reads
that push alone, in world axes: not the stand's weight, not the ground's support.
"""
import time

import rospy
import rostest
from geometry_msgs.msg import Wrench, WrenchStamped
from spawned_model_test import TIMEOUT_S, SpawnedModelTest

PENDULUM = """<robot name="pendulum">
<link name="base"><inertial><mass value="50"/>
<inertia ixx="4.2083" ixy="0" ixz="0" iyy="4.2083" iyz="0" izz="8.3333"/></inertial>
<collision><geometry><box size="1 1 0.1"/></geometry></collision></link>
<joint name="hinge" type="continuous"><parent link="base"/><child link="bob"/>
<origin xyz="0 0 1"/><axis xyz="1 0 0"/></joint>
<link name="bob"><inertial><origin xyz="0.1 0 -0.5"/><mass value="2"/>
<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
<gazebo><plugin name="ft" filename="libgazebo_ros_ft_sensor.so"><jointName>hinge</jointName>
<topicName>ft</topicName><updateRate>100</updateRate></plugin>
<plugin name="f3d" filename="libgazebo_ros_f3d.so"><bodyName>base</bodyName>
<topicName>f3d</topicName><frameName>base</frameName></plugin>
<plugin name="push" filename="libgazebo_ros_force.so"><bodyName>base</bodyName>
<topicName>push</topicName></plugin></gazebo></robot>"""


class WrenchPlugins(SpawnedModelTest):
    node_name = 'wrench_plugins_test'

    def setUp(self):
        super().setUp()
        self.spawn('pendulum', PENDULUM, 0.05)
        self.messages = {'ft': [], 'f3d': []}
        self.subs = [rospy.Subscriber('/pendulum/' + topic, WrenchStamped, self.store,
                                      callback_args=topic, queue_size=5000)
                     for topic in self.messages]

    def store(self, msg, topic):
        with self.lock:
            self.messages[topic].append(msg)

    def wait_for(self, topic, count):
        deadline = time.monotonic() + TIMEOUT_S
        while True:
            with self.lock:
                if len(self.messages[topic]) >= count:
                    return
            self.assertLess(time.monotonic(), deadline, 'fewer than %d on %s' % (count, topic))
            time.sleep(0.02)

    def test_ft_sensor_weighs_the_bob_and_f3d_reads_the_push(self):
        push = rospy.Publisher('/pendulum/push', Wrench, queue_size=1, latch=True)
        for topic_object in [push] + self.subs:
            self.wait_for_connection(topic_object)
        wrench = Wrench()
        wrench.force.z = -10.0
        push.publish(wrench)
        # The push has arrived when the f3d reads it; then 1 s of settled readings.
        self.step_until(
            1, lambda: self.messages['f3d'] and self.messages['f3d'][-1].wrench.force.z < 0,
            'the f3d never read the push')
        self.step(500)
        self.wait_for('ft', 50)
        time.sleep(0.2)
        with self.lock:
            self.messages = {'ft': [], 'f3d': []}
        for batch in range(1, 11):  # 100 steps at a time: the f3d sends one per step
            self.step(100)
            self.wait_for('ft', 10 * batch)
            self.wait_for('f3d', 100 * batch)
        time.sleep(0.2)
        with self.lock:
            ft, f3d = list(self.messages['ft']), list(self.messages['f3d'])
        self.assertEqual(len(ft), 100)  # updateRate 100 over 1 s
        self.assertEqual(len(f3d), 1000)  # f3d: every 1 ms step
        last = ft[-1]
        self.assertEqual(last.header.frame_id, 'bob')
        self.assertAlmostEqual((last.header.stamp - ft[0].header.stamp).to_sec(), 0.99,
                               delta=1e-6)
        force, torque = last.wrench.force, last.wrench.torque
        for value, expected in ((force.x, 0), (force.y, 0), (force.z, -19.6),
                                (torque.x, 0), (torque.y, 1.96), (torque.z, 0)):
            self.assertAlmostEqual(value, expected, delta=0.02)
        pushed = f3d[-1]
        self.assertEqual(pushed.header.frame_id, 'base')
        self.assertEqual((pushed.wrench.force.x, pushed.wrench.force.y, pushed.wrench.force.z),
                         (0.0, 0.0, -10.0))
        self.assertEqual((pushed.wrench.torque.x, pushed.wrench.torque.y,
                          pushed.wrench.torque.z), (0.0, 0.0, 0.0))


if __name__ == '__main__':
    rostest.rosrun('bullet_sim', 'wrench_plugins', WrenchPlugins)
