#!/usr/bin/python3
"""roundTrack_obstacles.launch: the world's included models are listed where the world file
puts them, the Burger's lidar sees the traffic cone (a triangle mesh) ahead at the distance
its geometry gives, and driving into a cardboard box shoves it but cannot push it (the
Burger's tyres have mu 0.1)."""
import math
import time
import unittest

import rospy
import rostest
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import GetModelState, GetWorldProperties, SetModelState
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan
from std_srvs.srv import Empty

# worlds/roundTrack_obstacles.world (scripts/make_playground_models.py): cone_1 at (0, 1.2),
# box_1 at (-0.3, 2.3). The cone's radius at the lidar's height (0.182 m above the ground):
# a cone of radius 0.08 m from z 0.02 to its apex at 0.30 m.
CONE_XY = (0.0, 1.2)
CONE_RADIUS_AT_LIDAR_M = 0.08 * (0.30 - 0.182) / (0.30 - 0.02)
LIDAR_BEHIND_BASE_M = 0.032  # base_scan sits 0.032 m behind base_footprint
BOX_XY = (-0.3, 2.3)


class RoundTrackObstacles(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_round_track_obstacles')
        for name in ('get_world_properties', 'get_model_state', 'set_model_state',
                     'unpause_physics'):
            rospy.wait_for_service('/gazebo/' + name, 60)
        cls.world = rospy.ServiceProxy('/gazebo/get_world_properties', GetWorldProperties)
        cls.state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
        cls.set_state = rospy.ServiceProxy('/gazebo/set_model_state', SetModelState)
        deadline = time.monotonic() + 60  # paused: sim time stands still
        while 'turtlebot3_burger' not in cls.world().model_names:  # spawn_model's work
            if time.monotonic() > deadline:
                raise AssertionError('spawn_model never spawned turtlebot3_burger')
            time.sleep(0.05)
        rospy.ServiceProxy('/gazebo/unpause_physics', Empty)()

    def test_1_included_models_stand_where_the_world_puts_them(self):
        names = self.world().model_names
        for name in ('papptown_track', 'ground_plane', 'cone_1', 'cone_2', 'box_1', 'box_2'):
            self.assertIn(name, names)
        cone = self.state('cone_1', 'world').pose.position
        self.assertAlmostEqual(cone.x, CONE_XY[0], places=6)
        self.assertAlmostEqual(cone.y, CONE_XY[1], places=6)
        box = self.state('box_1', 'world').pose.position
        self.assertAlmostEqual(box.x, BOX_XY[0], delta=0.005)
        self.assertAlmostEqual(box.y, BOX_XY[1], delta=0.005)
        self.assertAlmostEqual(box.z, 0.0, delta=0.005)  # resting on the ground

    def test_2_the_lidar_sees_the_meshed_cone(self):
        robot = self.state('turtlebot3_burger', 'world').pose.position
        scan = rospy.wait_for_message('/scan', LaserScan, 30)
        # Facing +y from (0, 0): the front ray meets the cone's surface at its lidar-height
        # radius in front of its axis.
        expected = (CONE_XY[1] - (robot.y - LIDAR_BEHIND_BASE_M) - CONE_RADIUS_AT_LIDAR_M)
        self.assertAlmostEqual(scan.ranges[0], expected, delta=0.03)

    def test_3_the_burger_shoves_a_cardboard_box_it_cannot_push(self):
        # Put the Burger 0.5 m below box_1 facing +y, then drive into the box for 6 s: it
        # meets the box after about 2.2 s (0.31 m from its base's front to the box).
        place = ModelState(model_name='turtlebot3_burger', reference_frame='world')
        place.pose.position.x, place.pose.position.y = BOX_XY[0], BOX_XY[1] - 0.5
        place.pose.orientation.z = math.sin(math.pi / 4)
        place.pose.orientation.w = math.cos(math.pi / 4)
        self.assertTrue(self.set_state(place).success)
        before = self.state('box_1', 'world').pose.position
        cmd = rospy.Publisher('/cmd_vel', Twist, queue_size=1)
        forward = Twist()
        forward.linear.x = 0.15
        start = rospy.Time.now().to_sec()
        at_4s = None
        while rospy.Time.now().to_sec() - start < 6.0:
            cmd.publish(forward)
            rospy.sleep(0.1)
            if at_4s is None and rospy.Time.now().to_sec() - start >= 4.0:
                at_4s = self.state('box_1', 'world').pose.position
        pushing = self.state('turtlebot3_burger', 'world').twist.linear
        cmd.publish(Twist())
        after = self.state('box_1', 'world').pose.position
        # The box (0.5 kg, mu 0.5; the ground's is more) needs 0.5 * 0.5 * 9.8 = 2.45 N to
        # slide; the Burger's tyres (mu 0.1) push with at most 0.1 g times the load on them,
        # under 1.03 N for its 1.044 kg (bullet_sim README, "Friction and drive"). As in
        # Gazebo, it cannot push the box, only shove it as it hits: at 0.15 m/s robot and box
        # go on together at 0.15 * 1.044 / 1.544 = 0.101 m/s, slowed by the box's 2.45 N less
        # the tyres' 0.86 N (the caster sliding) over 1.544 kg, 1.03 m/s^2: they stop
        # 0.101^2 / (2 * 1.03) = 5 mm on (bullet_sim: 4.5 mm). Then the robot stands, its tyres
        # slipping, and the box stays where it is but for Bullet's creep under a steady load
        # (0.75 mm/s here; ODE's model has none): within 1 mm/s from the hit on.
        self.assertLess(math.hypot(pushing.x, pushing.y), 0.005)
        self.assertGreater(after.y - before.y, 0.003)
        self.assertLess(after.y - before.y, 0.005 + 0.001 * (6.0 - 2.2))
        self.assertAlmostEqual(after.y, at_4s.y, delta=0.001 * 2.0)
        self.assertAlmostEqual(after.x, before.x, delta=0.003)


if __name__ == '__main__':
    rostest.rosrun('turtlebot3_gazebo', 'round_track_obstacles', RoundTrackObstacles)
