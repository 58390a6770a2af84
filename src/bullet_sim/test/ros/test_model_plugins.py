#!/usr/bin/python3
"""libgazebo_ros_p3d.so and libgazebo_ros_force.so through their topics.

A 2 kg box (a cube of 0.2 m) is spawned at (0, 0, 1) in a world without gravity with a p3d
plugin (topic /box/truth, xyzOffset 1 2 3, updateRate 100) and a force plugin (topic
/box/push). A wrench of 4 N along x pushes it for 1 s of sim time: a = F / m = 2 m/s^2,
so the ground truth then reads v = 2 m/s and x = a t^2 / 2 = 1 m, plus the offset.
"""
import time

import rospy
import rostest
from geometry_msgs.msg import Wrench
from nav_msgs.msg import Odometry
from spawned_model_test import TIMEOUT_S, SpawnedModelTest

BOX = """<robot name="box"><link name="body"><inertial><mass value="2"/>
<inertia ixx="0.013333" ixy="0" ixz="0" iyy="0.013333" iyz="0" izz="0.013333"/></inertial>
<collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
<gazebo><plugin name="truth" filename="libgazebo_ros_p3d.so"><bodyName>body</bodyName>
<topicName>truth</topicName><xyzOffset>1 2 3</xyzOffset><updateRate>100</updateRate>
</plugin><plugin name="push" filename="libgazebo_ros_force.so"><bodyName>body</bodyName>
<topicName>push</topicName></plugin></gazebo></robot>"""


class ModelPlugins(SpawnedModelTest):
    node_name = 'model_plugins_test'

    def setUp(self):
        super().setUp()
        self.spawn('box', BOX, 1.0)
        self.truths = []
        self.sub = rospy.Subscriber('/box/truth', Odometry, self.store, queue_size=2000)

    def store(self, msg):
        with self.lock:
            self.truths.append(msg)

    def test_force_pushes_the_box_and_p3d_reports_it(self):
        push = rospy.Publisher('/box/push', Wrench, queue_size=1, latch=True)
        self.wait_for_connection(push)
        self.wait_for_connection(self.sub)
        wrench = Wrench()
        wrench.force.x = 4.0
        push.publish(wrench)
        # The message has arrived when the box moves; from then on, 1 s of pushing.
        self.step_until(1, lambda: self.truths and self.truths[-1].twist.twist.linear.x > 0,
                        'the box never moved')
        with self.lock:
            start = self.truths[-1]
            self.truths = []
        self.step(1000)
        deadline = time.monotonic() + TIMEOUT_S
        while True:  # 100 readings at 100 Hz in 1 s of sim time
            with self.lock:
                if len(self.truths) >= 100:
                    break
            self.assertLess(time.monotonic(), deadline, 'fewer than 100 readings')
            time.sleep(0.02)
        time.sleep(0.2)
        with self.lock:
            truths = list(self.truths)
        self.assertEqual(len(truths), 100)
        last = truths[-1]
        self.assertEqual((last.header.frame_id, last.child_frame_id), ('world', 'body'))
        dt = (last.header.stamp - start.header.stamp).to_sec()
        self.assertAlmostEqual(dt, 1.0, delta=0.011)
        v0 = start.twist.twist.linear.x
        self.assertAlmostEqual(last.twist.twist.linear.x, v0 + 2.0 * dt, delta=0.01)
        x0 = start.pose.pose.position.x
        self.assertAlmostEqual(last.pose.pose.position.x, x0 + v0 * dt + dt * dt, delta=0.01)
        self.assertAlmostEqual(last.pose.pose.position.y, 2.0, delta=1e-6)
        self.assertAlmostEqual(last.pose.pose.position.z, 4.0, delta=1e-6)


if __name__ == '__main__':
    rostest.rosrun('bullet_sim', 'model_plugins', ModelPlugins)
