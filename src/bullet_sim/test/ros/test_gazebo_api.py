#!/usr/bin/python3
"""Every /gazebo service of bullet_sim_node with a good and a bad request, through
gazebo_msgs clients as scripts written for Gazebo use them. The simulation is paused and
stepped; expected values are worked out by hand from the poses, masses and inertias set
here."""
import math

import rospy
import rostest
from gazebo_msgs.msg import LinkState, LinkStates, ModelState, ModelStates, ODEPhysics
from geometry_msgs.msg import Point, Pose, Twist, Vector3, Wrench
from sensor_msgs.msg import Imu

from gazebo_api_client import (BOX_MASS_KG, BOX_URDF, ROTOR_URDF, SDF_BOX, SDF_STATIC_BOX,
                               GazeboServiceTest, Latest, rotate, simulator_connections,
                               wait_for, yaw_of, yaw_pose)

ROBOT = "burger"
SPAWN_X, SPAWN_Y = 0.5, -0.25
TEST_MODELS = ("a", "b", "c", "d", "rotor")
NAN = float("nan")


class GazeboApi(GazeboServiceTest):
    NODE_NAME = "gazebo_api_test"
    TEST_MODELS = TEST_MODELS

    def spawn_boxes(self):
        """Box a at (1, 2, 3) turned 0.5, box b at (2, 1, 3) turned -0.4 (in the air)."""
        self.ok("spawn_urdf_model", "a", BOX_URDF, "", yaw_pose(1, 2, 3, 0.5), "")
        self.ok("spawn_urdf_model", "b", BOX_URDF, "", yaw_pose(2, 1, 3, -0.4), "world")

    def assertPose(self, pose, x, y, z, yaw, delta=1e-6):
        self.assertAlmostEqual(pose.position.x, x, delta=delta)
        self.assertAlmostEqual(pose.position.y, y, delta=delta)
        self.assertAlmostEqual(pose.position.z, z, delta=delta)
        self.assertAlmostEqual(math.remainder(yaw_of(pose.orientation) - yaw, 2 * math.pi), 0,
                               delta=delta)

    def test_world_properties(self):
        self.spawn_boxes()
        self.ok("step_simulation", 250)
        response = self.ok("get_world_properties")
        self.assertEqual(sorted(response.model_names), ["a", "b", ROBOT, "ground_plane"])
        self.assertAlmostEqual(response.sim_time, 0.25, places=9)

    def test_model_state_relative_to_a_model_and_a_link(self):
        self.spawn_boxes()
        # b seen from a: a's rotation undone on the offset (1, -1, 0); yaw -0.4 - 0.5.
        x, y = rotate(-0.5, 1, -1)
        for frame in ("a", "a::body"):
            response = self.ok("get_model_state", "b", frame)
            self.assertPose(response.pose, x, y, 0, -0.9)
            self.assertEqual(response.header.frame_id, frame)
        self.assertPose(self.ok("get_model_state", "b", "world").pose, 2, 1, 3, -0.4)
        self.fails("get_model_state", "'ghost'", "ghost", "")
        self.fails("get_model_state", "'nowhere'", "b", "nowhere")

    def test_set_model_state_in_another_models_frame(self):
        self.spawn_boxes()
        twist = Twist(linear=Vector3(1, 0, 0))
        self.ok("set_model_state", ModelState("b", yaw_pose(1, 0, 0, 0.2), twist, "a"))
        x, y = rotate(0.5, 1, 0)
        response = self.ok("get_model_state", "b", "")
        self.assertPose(response.pose, 1 + x, 2 + y, 3, 0.7)
        self.assertAlmostEqual(response.twist.linear.x, math.cos(0.5), delta=1e-6)
        self.assertAlmostEqual(response.twist.linear.y, math.sin(0.5), delta=1e-6)
        self.fails("set_model_state", "position.x",
                   ModelState("b", yaw_pose(NAN, 0), Twist(), ""))
        self.fails("set_model_state", "'nowhere'", ModelState("b", Pose(), Twist(), "nowhere"))
        self.fails("set_model_state", "'ghost'", ModelState("ghost", Pose(), Twist(), ""))

    def test_set_model_state_topic(self):
        self.spawn_boxes()
        pub = rospy.Publisher("/gazebo/set_model_state", ModelState, queue_size=10)
        wait_for(lambda: pub.get_num_connections() > 0, "the set_model_state subscriber")
        pub.publish(ModelState("a", yaw_pose(-3, 4, 2, 1.0), Twist(), "world"))
        wait_for(lambda: abs(self.ok("get_model_state", "a", "").pose.position.x + 3) < 1e-6,
                 "model a to move")
        self.assertPose(self.ok("get_model_state", "a", "").pose, -3, 4, 2, 1.0)

    def test_spawn_in_a_models_frame_and_bad_spawns(self):
        self.spawn_boxes()
        self.ok("spawn_urdf_model", "c", BOX_URDF, "", yaw_pose(0, 1, 0, 0.1), "a::body")
        x, y = rotate(0.5, 0, 1)
        self.assertPose(self.ok("get_model_state", "c", "").pose, 1 + x, 2 + y, 3, 0.6)
        self.fails("spawn_urdf_model", "already exists", "c", BOX_URDF, "", Pose(), "")
        self.fails("spawn_urdf_model", "'nowhere'", "d", BOX_URDF, "", Pose(), "nowhere")
        response = self.fails("spawn_urdf_model", "neither URDF", "d", "<robot", "", Pose(), "")
        self.assertIn("not well-formed XML", response.status_message)
        self.assertIn("Line number=1", response.status_message)  # tinyxml2 says where
        self.fails("spawn_urdf_model", "its root element is <html>", "d", "<html/>", "", Pose(),
                   "")
        self.fails("spawn_urdf_model", "initial_pose position.z", "d", BOX_URDF, "",
                   yaw_pose(0, 0, NAN), "")
        bad_static = SDF_STATIC_BOX.replace("<size>0.2 0.2 0.2</size>",
                                            "<size>0.2 nan 0.2</size>")
        response = self.fails("spawn_sdf_model", "0.2 nan 0.2", "d", bad_static, "", Pose(), "")
        self.assertIn("size", response.status_message)
        self.fails("spawn_sdf_model", "neither URDF", "d", "<sdf version='1.6'><model", "",
                   Pose(), "")
        negative_radius = ("<sdf version='1.6'><model name='ball'><link name='body'><collision "
                           "name='shell'><geometry><sphere><radius>-1</radius></sphere></geometry>"
                           "</collision></link></model></sdf>")
        self.fails("spawn_sdf_model", "link 'body' collision 'shell': <sphere> <radius>: '-1'",
                   "d", negative_radius, "", Pose(), "")
        self.fails("spawn_urdf_model", "robot_namespace 'tb3-1'", "d", BOX_URDF, "tb3-1",
                   Pose(), "")
        bad_topic = ROTOR_URDF.replace("</robot>", """<gazebo><plugin name="drive"
            filename="libgazebo_ros_diff_drive.so"><leftJoint>spin</leftJoint>
            <rightJoint>spin</rightJoint><commandTopic>cmd vel</commandTopic></plugin>
            </gazebo></robot>""")
        self.fails("spawn_urdf_model", "cmd vel", "d", bad_topic, "", Pose(), "")
        self.fails("get_model_state", "'d'", "d", "")
        self.ok("spawn_sdf_model", "rotor", ROTOR_URDF, "", yaw_pose(0, 5, 1), "")

    def test_spawn_sdf_model(self):
        # Paused: the cube stays where it is put; its link 0.1 m above the model frame.
        self.ok("spawn_sdf_model", "d", SDF_BOX, "", yaw_pose(2, 3, 0, 0.5), "")
        state = self.ok("get_model_state", "d", "")
        p = state.pose.position
        self.assertAlmostEqual(p.x, 2, places=6)
        self.assertAlmostEqual(p.y, 3, places=6)
        self.assertAlmostEqual(p.z, 0, places=6)
        self.assertAlmostEqual(yaw_of(state.pose.orientation), 0.5, places=6)
        link = self.ok("get_link_state", "d::body", "").link_state.pose.position
        self.assertAlmostEqual(link.z, 0.1, places=6)
        self.assertEqual(self.ok("get_model_properties", "d").body_names, ["body"])

    def test_spawn_static_sdf_model(self):
        # A static model is spawned where it is put, listed, says it is static, and goes
        # with delete_model.
        self.ok("spawn_sdf_model", "s", SDF_STATIC_BOX, "", yaw_pose(2, -3, 0, 0.5), "")
        p = self.ok("get_model_state", "s", "").pose
        self.assertPose(p, 2, -3, 0, 0.5)
        self.assertTrue(self.ok("get_model_properties", "s").is_static)
        self.assertIn("s", self.ok("get_world_properties").model_names)
        self.ok("delete_model", "s")
        self.assertNotIn("s", self.ok("get_world_properties").model_names)
        self.fails("get_model_state", "'s'", "s", "")

    def test_delete_model(self):
        self.spawn_boxes()
        self.ok("delete_model", "a")
        self.fails("delete_model", "'a'", "a")
        self.fails("get_model_state", "'a'", "a", "")

    def test_static_world_models(self):
        # flat.world's ground_plane: listed, at the origin, at rest; it cannot be moved,
        # deleted or spawned over, and it serves as a reference frame.
        self.assertPose(self.ok("get_model_state", "ground_plane", "").pose, 0, 0, 0, 0)
        self.fails("delete_model", "static model of the world file", "ground_plane")
        state = ModelState(model_name="ground_plane", pose=yaw_pose(1, 0))
        self.fails("set_model_state", "cannot be moved", state)
        self.fails("spawn_urdf_model", "already exists", "ground_plane", BOX_URDF, "", Pose(), "")
        robot = self.ok("get_model_state", ROBOT, "ground_plane").pose
        self.assertAlmostEqual(robot.position.x, SPAWN_X, delta=1e-3)

    def test_model_properties(self):
        response = self.ok("get_model_properties", ROBOT)
        for link in ("base_footprint", "base_link", "wheel_left_link", "base_scan", "flag_link"):
            self.assertIn(link, response.body_names)
        self.assertEqual(response.joint_names,
                         ["flag_pole_joint", "wheel_left_joint", "wheel_right_joint"])
        self.assertEqual(response.canonical_body_name, "base_footprint")
        self.assertFalse(response.is_static)
        self.assertTrue(response.geom_names)
        self.fails("get_model_properties", "'ghost'", "ghost")

    def test_link_state_and_properties(self):
        # Straight after a reset the Burger is at its spawn pose: the wheel axle sits
        # 0.08 m left of and 0.010 + 0.023 m above base_footprint, the lidar 0.032 m
        # behind and 0.010 + 0.172 m above it.
        response = self.ok("get_link_state", ROBOT + "::wheel_left_link", ROBOT + "::base_footprint")
        self.assertAlmostEqual(response.link_state.pose.position.x, 0, delta=1e-6)
        self.assertAlmostEqual(response.link_state.pose.position.y, 0.08, delta=1e-6)
        self.assertAlmostEqual(response.link_state.pose.position.z, 0.033, delta=1e-6)
        response = self.ok("get_link_state", ROBOT + "::base_scan", "")
        self.assertPose(response.link_state.pose, SPAWN_X - 0.032, SPAWN_Y, 0.182, 0)
        self.fails("get_link_state", "'wheel_left_link'", "wheel_left_link", "")
        self.fails("get_link_state", "'nowhere'", ROBOT + "::base_scan", "nowhere")
        props = self.ok("get_link_properties", ROBOT + "::base_link")
        self.assertAlmostEqual(props.mass, 0.82573504, places=8)
        self.assertAlmostEqual(props.ixx, 2.2124e-3, places=10)
        self.assertAlmostEqual(props.izz, 2.0064e-3, places=10)
        self.assertTrue(props.gravity_mode)
        self.fails("get_link_properties", "'burger::nothing'", ROBOT + "::nothing")

    def test_set_link_state_service_and_topic(self):
        self.spawn_boxes()
        self.ok("set_link_state", LinkState("a::body", yaw_pose(5, 5, 2, 0.3), Twist(), ""))
        self.assertPose(self.ok("get_model_state", "a", "").pose, 5, 5, 2, 0.3)
        # 1 m ahead of b (turned -0.4).
        self.ok("set_link_state", LinkState("a::body", yaw_pose(1, 0, 0), Twist(), "b"))
        x, y = rotate(-0.4, 1, 0)
        self.assertPose(self.ok("get_model_state", "a", "").pose, 2 + x, 1 + y, 3, -0.4)
        self.fails("set_link_state", "'a'", LinkState("a", Pose(), Twist(), ""))
        twist = Twist(angular=Vector3(0, NAN, 0))
        self.fails("set_link_state", "angular.y", LinkState("a::body", Pose(), twist, ""))
        pub = rospy.Publisher("/gazebo/set_link_state", LinkState, queue_size=10)
        wait_for(lambda: pub.get_num_connections() > 0, "the set_link_state subscriber")
        pub.publish(LinkState("b::body", yaw_pose(-1, -1, 1), Twist(), ""))
        wait_for(lambda: abs(self.ok("get_model_state", "b", "").pose.position.x + 1) < 1e-6,
                 "model b to move")

    def test_joint_properties_and_model_configuration(self):
        self.ok("set_model_configuration", ROBOT, "", ["flag_pole_joint"], [1.0])
        response = self.ok("get_joint_properties", "flag_pole_joint")
        self.assertEqual(response.type, response.CONTINUOUS)
        self.assertAlmostEqual(response.position[0], 1.0, delta=1e-6)
        self.assertAlmostEqual(
            self.ok("get_joint_properties", ROBOT + "::flag_pole_joint").position[0], 1.0,
            delta=1e-6)
        self.fails("get_joint_properties", "'nope'", "nope")
        self.fails("set_model_configuration", "2 joint_names but 1 joint_positions", ROBOT, "",
                   ["flag_pole_joint", "wheel_left_joint"], [0.5])
        self.fails("set_model_configuration", "'nope'", ROBOT, "", ["nope"], [0.5])
        self.fails("set_model_configuration", "'ghost'", "ghost", "", [], [])
        self.fails("set_model_configuration", "not finite", ROBOT, "", ["flag_pole_joint"], [NAN])

    def test_physics_properties(self):
        props = self.ok("get_physics_properties")
        self.assertEqual((props.time_step, props.max_update_rate), (0.001, 1000.0))
        self.assertEqual((props.gravity.x, props.gravity.y, props.gravity.z), (0, 0, -9.8))
        self.assertTrue(props.pause)
        self.spawn_boxes()
        try:
            self.ok("set_physics_properties", 0.002, 500.0, Vector3(0, 0, -1), props.ode_config)
            start = self.ok("step_simulation", 0).sim_time.to_sec()
            self.assertAlmostEqual(self.ok("step_simulation", 100).sim_time.to_sec() - start,
                                   0.2, places=9)
            # Falling for 0.2 s under 1 m/s^2.
            self.assertAlmostEqual(self.ok("get_model_state", "a", "").twist.linear.z, -0.2,
                                   delta=1e-6)
            self.assertEqual(self.ok("get_physics_properties").max_update_rate, 500.0)
        finally:
            self.ok("set_physics_properties", 0.001, 1000.0, Vector3(0, 0, -9.8), ODEPhysics())
        self.fails("set_physics_properties", "time_step", 0.0, 1000.0, Vector3(0, 0, -9.8),
                   props.ode_config)
        self.fails("set_physics_properties", "gravity.z", 0.001, 1000.0, Vector3(0, 0, NAN),
                   props.ode_config)
        # Bullet's solver takes iterations, SOR, ERP and CFM; ODE's other fields are refused.
        changed = self.ok("get_physics_properties").ode_config
        changed.sor_pgs_iters, changed.erp = 50, 0.3
        try:
            self.ok("set_physics_properties", 0.001, 1000.0, Vector3(0, 0, -9.8), changed)
            solver = self.ok("get_physics_properties").ode_config
            self.assertEqual((solver.sor_pgs_iters, solver.erp), (50, 0.3))
        finally:
            self.ok("set_physics_properties", 0.001, 1000.0, Vector3(0, 0, -9.8), props.ode_config)
        changed.max_contacts = 100
        self.fails("set_physics_properties", "ode_config.max_contacts", 0.001, 1000.0,
                   Vector3(0, 0, -9.8), changed)
        changed = props.ode_config
        changed.sor_pgs_iters = 0
        self.fails("set_physics_properties", "iterations 0", 0.001, 1000.0,
                   Vector3(0, 0, -9.8), changed)

    def wrench(self, body, frame, force, duration_s):
        return self.call("apply_body_wrench", body, frame, Point(),
                         Wrench(force=Vector3(*force)), rospy.Time(0),
                         rospy.Duration(duration_s))

    def test_body_wrench(self):
        self.spawn_boxes()
        for name in ("a", "b"):  # high enough not to land within the test's 1 s
            pose = self.ok("get_model_state", name, "").pose
            pose.position.z = 20
            self.ok("set_model_state", ModelState(name, pose, Twist(), ""))
        # 1 N for 0.5 s on 0.5 kg: 1 m/s, along the x axis of b (turned -0.4).
        self.assertTrue(self.wrench("a::body", "b", (1, 0, 0), 0.5).success)
        self.ok("step_simulation", 600)
        twist = self.ok("get_model_state", "a", "").twist
        speed = 1.0 * 0.5 / BOX_MASS_KG
        self.assertAlmostEqual(twist.linear.x, speed * math.cos(-0.4), delta=1e-6)
        self.assertAlmostEqual(twist.linear.y, speed * math.sin(-0.4), delta=1e-6)
        # Until cleared: 0.5 N for 0.2 s on b, then nothing more.
        self.assertTrue(self.wrench("b::body", "", (0, 0.5, 0), -1).success)
        self.ok("step_simulation", 200)
        self.call("clear_body_wrenches", "b::body")
        self.ok("step_simulation", 200)
        self.assertAlmostEqual(self.ok("get_model_state", "b", "").twist.linear.y,
                               0.5 * 0.2 / BOX_MASS_KG, delta=1e-6)
        response = self.wrench("a", "", (1, 0, 0), 1)
        self.assertFalse(response.success)
        self.assertIn("'a'", response.status_message)
        response = self.wrench("a::body", "", (NAN, 0, 0), 1)
        self.assertFalse(response.success)
        self.assertIn("wrench.force.x", response.status_message)
        with self.assertRaises(rospy.ServiceException):
            self.call("clear_body_wrenches", "a::nothing")

    def test_joint_effort(self):
        self.ok("spawn_urdf_model", "rotor", ROTOR_URDF, "", yaw_pose(0, 5, 5), "")
        # Equal and opposite torques on wheel and base: relative rate tau T (1/Iw + 1/Ib).
        response = self.call("apply_joint_effort", "rotor::spin", 0.01, rospy.Time(0),
                             rospy.Duration(0.5))
        self.assertTrue(response.success, response.status_message)
        self.ok("step_simulation", 600)
        rate = self.ok("get_joint_properties", "spin").rate[0]
        self.assertAlmostEqual(rate, 0.01 * 0.5 * (1 / 0.02 + 1 / 0.2), delta=1e-3)
        response = self.call("apply_joint_effort", "spin", 0.01, rospy.Time(0),
                             rospy.Duration(-1))
        self.assertTrue(response.success, response.status_message)
        self.ok("step_simulation", 100)
        self.call("clear_joint_forces", "spin")
        rate = self.ok("get_joint_properties", "spin").rate[0]
        self.ok("step_simulation", 100)
        self.assertAlmostEqual(self.ok("get_joint_properties", "spin").rate[0], rate, delta=1e-3)
        response = self.call("apply_joint_effort", "nope", 1.0, rospy.Time(0), rospy.Duration(1))
        self.assertFalse(response.success)
        self.assertIn("'nope'", response.status_message)
        response = self.call("apply_joint_effort", "spin", NAN, rospy.Time(0), rospy.Duration(1))
        self.assertFalse(response.success)
        with self.assertRaises(rospy.ServiceException):
            self.call("clear_joint_forces", "nope")

    def test_model_and_link_state_topics(self):
        models = Latest("/gazebo/model_states", ModelStates)
        links = Latest("/gazebo/link_states", LinkStates)
        models.wait_connected()
        links.wait_connected()
        self.ok("step_simulation", 1000)  # 1 s of sim time at 100 Hz: 100 messages
        wait_for(lambda: models.count() >= 100 and links.count() >= 100, "100 state messages")
        last = models.last()
        index = last.name.index(ROBOT)
        expected = self.ok("get_model_state", ROBOT, "").pose
        self.assertAlmostEqual(last.pose[index].position.x, expected.position.x, delta=1e-9)
        self.assertIn(ROBOT + "::base_footprint", links.last().name)
        # One more period gives one more message; messages arrive in order, so once it is
        # here any surplus from the first second would be here too.
        self.ok("step_simulation", 10)
        wait_for(lambda: models.count() >= 101, "the message at 1.01 s")
        self.assertEqual(models.count(), 101)

    def test_imu_is_read_only_while_subscribed(self):
        """The Burger's IMU (200 Hz: a reading every 5 steps) is read and published while
        someone subscribes, and not while nobody does. roscpp numbers every publish() in
        header.seq, so the first reading after an unwatched stretch follows the last one
        before it in seq, while its stamp is the stretch later."""
        def watch(steps):
            imu = Latest("/imu", Imu)
            imu.wait_connected()
            wait_for(lambda: simulator_connections("/imu", "/gazebo_api_test"),
                     "the simulator to see the /imu subscriber")
            self.ok("step_simulation", steps)
            wait_for(lambda: imu.count() >= steps // 5, "%d IMU readings" % (steps // 5))
            imu.sub.unregister()
            wait_for(lambda: not simulator_connections("/imu", "/gazebo_api_test"),
                     "the simulator to drop the /imu subscriber")
            return imu.messages

        before = watch(50)
        self.ok("step_simulation", 100)  # 20 readings fall due unwatched
        after = watch(50)
        self.assertEqual((len(before), len(after)), (10, 10))
        for messages in (before, after):
            for a, b in zip(messages, messages[1:]):
                self.assertEqual(b.header.seq, a.header.seq + 1)
                self.assertAlmostEqual((b.header.stamp - a.header.stamp).to_sec(), 0.005,
                                       places=9)
        self.assertEqual(after[0].header.seq, before[-1].header.seq + 1)
        self.assertAlmostEqual((after[0].header.stamp - before[-1].header.stamp).to_sec(),
                               0.105, places=9)


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "gazebo_api", GazeboApi)
