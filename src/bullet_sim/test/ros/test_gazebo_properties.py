#!/usr/bin/python3
"""set_link_properties, set_joint_properties, the light services and the physics parameters
(gazebo_ros's dynamic_reconfigure server on /gazebo) of bullet_sim_node. The simulation is
paused and stepped; expected values are worked out by hand from the masses, inertias,
torques and the world file (fixtures/lit.world)."""
import time

import dynamic_reconfigure.client
import rospy
import rostest
from gazebo_msgs.msg import ODEJointProperties
from geometry_msgs.msg import Point, Pose, Vector3, Wrench
from std_msgs.msg import ColorRGBA

from gazebo_api_client import BOX_URDF, ROTOR_URDF, GazeboServiceTest, yaw_pose

NAN = float("nan")
TEST_MODELS = ("box", "rotor", "capped")

# A base with a cap joined by a fixed joint: one rigid body of two links.
CAPPED_URDF = """<robot name="capped">
  <link name="base">
    <inertial><mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
  <joint name="cap_joint" type="fixed"><parent link="base"/><child link="cap"/>
    <origin xyz="0 0 0.15"/></joint>
  <link name="cap">
    <inertial><mass value="0.1"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial>
  </link>
</robot>"""

# gazebo_ros's cfg/Physics.cfg: name, type, minimum, maximum.
GAZEBO_ROS_PHYSICS_PARAMETERS = [
    ("time_step", "double", 0, 10), ("max_update_rate", "double", 0, 1000),
    ("gravity_x", "double", -100, 100), ("gravity_y", "double", -100, 100),
    ("gravity_z", "double", -100, 100), ("auto_disable_bodies", "bool", False, True),
    ("sor_pgs_precon_iters", "int", 0, 10000), ("sor_pgs_iters", "int", 0, 10000),
    ("sor_pgs_w", "double", 0, 5), ("sor_pgs_rms_error_tol", "double", -1, 10000),
    ("cfm", "double", 0, 10), ("erp", "double", 0, 10),
    ("contact_surface_layer", "double", 0, 10),
    ("contact_max_correcting_vel", "double", 0, 10000000),
    ("max_contacts", "int", 0, 10000000),
]


def colour(r, g, b, a=1.0):
    return ColorRGBA(r, g, b, a)


class GazeboProperties(GazeboServiceTest):
    NODE_NAME = "gazebo_properties_test"
    TEST_MODELS = TEST_MODELS

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.physics = dynamic_reconfigure.client.Client("/gazebo", timeout=60)

    def set_link(self, link, mass, inertia, gravity=True, com=(0, 0, 0)):
        ixx, iyy, izz, ixy, ixz, iyz = inertia
        com_pose = Pose()
        com_pose.position = Point(*com)
        com_pose.orientation.w = 1
        return self.call("set_link_properties", link, com_pose, gravity, mass,
                         ixx, ixy, ixz, iyy, iyz, izz)

    def wrench(self, body, force, torque, duration_s):
        return self.ok("apply_body_wrench", body, "", Point(),
                       Wrench(force=Vector3(*force), torque=Vector3(*torque)),
                       rospy.Time(0), rospy.Duration(duration_s))

    # ---------------------------------------------------------------- links ----

    def test_link_mass_inertia_and_gravity(self):
        self.ok("spawn_urdf_model", "box", BOX_URDF, "", yaw_pose(0, 0, 5), "")
        props = self.ok("get_link_properties", "box::body")
        self.assertEqual((props.mass, props.izz, props.gravity_mode), (0.5, 0.01, True))
        response = self.set_link("box::body", 2.0, (0.04, 0.04, 0.04, 0, 0, 0), gravity=False)
        self.assertTrue(response.success, response.status_message)
        props = self.ok("get_link_properties", "box::body")
        self.assertEqual((props.mass, props.ixx, props.izz, props.gravity_mode),
                         (2.0, 0.04, 0.04, False))
        # Without gravity it floats: 0.5 s of 9.8 m/s^2 would drop it 1.225 m.
        self.ok("step_simulation", 500)
        state = self.ok("get_model_state", "box", "")
        self.assertAlmostEqual(state.pose.position.z, 5.0, delta=1e-9)
        # 1 N for 0.5 s on 2 kg: 0.25 m/s (1 m/s on the 0.5 kg of the URDF);
        # 0.02 N m for 0.5 s about z on izz 0.04: 0.25 rad/s.
        self.wrench("box::body", (1, 0, 0), (0, 0, 0.02), 0.5)
        self.ok("step_simulation", 600)
        twist = self.ok("get_model_state", "box", "").twist
        self.assertAlmostEqual(twist.linear.x, 1.0 * 0.5 / 2.0, delta=1e-6)
        self.assertAlmostEqual(twist.angular.z, 0.02 * 0.5 / 0.04, delta=1e-6)
        # reset_simulation keeps the properties, as Gazebo does.
        self.call("reset_simulation")
        self.assertEqual(self.ok("get_link_properties", "box::body").mass, 2.0)
        self.ok("step_simulation", 200)
        self.assertAlmostEqual(self.ok("get_model_state", "box", "").pose.position.z, 5.0,
                               delta=1e-9)
        # Gravity back on: falling 0.2 s gives 1.96 m/s down.
        self.assertTrue(self.set_link("box::body", 2.0, (0.04, 0.04, 0.04, 0, 0, 0)).success)
        self.ok("step_simulation", 200)
        self.assertAlmostEqual(self.ok("get_model_state", "box", "").twist.linear.z,
                               -9.8 * 0.2, delta=1e-6)

    def test_link_requests_that_cannot_be_honoured(self):
        self.ok("spawn_urdf_model", "box", BOX_URDF, "", yaw_pose(0, 0, 5), "")
        self.ok("spawn_urdf_model", "capped", CAPPED_URDF, "", yaw_pose(3, 0, 5), "")
        inertia = (0.01, 0.01, 0.01, 0, 0, 0)
        for args, fragment in (
                (("box::nothing", 1.0, inertia), "'box::nothing'"),
                (("box", 1.0, inertia), "'box'"),
                (("box::body", 0.0, inertia), "mass 0 must be > 0"),
                (("box::body", NAN, inertia), "mass nan"),
                (("box::body", 1.0, inertia, True, (0.1, 0, 0)), "com.position (0.1, 0, 0)"),
                (("box::body", 1.0, (0.01, 0.01, 0.01, 0.005, 0, 0)), "not diagonal"),
                (("box::body", 1.0, (0.01, 0.01, -0.01, 0, 0, 0)), "must all be > 0"),
                (("capped::cap", 1.0, (0.001,) * 3 + (0, 0, 0)), "with 'base'"),
                (("capped::base", 1.0, inertia, False), "gravity_mode")):
            response = self.set_link(*args)
            self.assertFalse(response.success, "accepted %s" % (args,))
            self.assertIn(fragment, response.status_message)
        # Nothing was changed by the refused requests.
        props = self.ok("get_link_properties", "box::body")
        self.assertEqual((props.mass, props.ixx, props.gravity_mode), (0.5, 0.01, True))
        self.assertTrue(self.ok("get_link_properties", "capped::base").gravity_mode)

    # --------------------------------------------------------------- joints ----

    def spawn_floating_rotor(self):
        """The rotor (base izz 0.2, wheel izz 0.02 on the continuous joint 'spin') in the
        air, without gravity: only the joint's torques turn it."""
        self.physics.update_configuration({"gravity_z": 0.0})
        self.addCleanup(self.physics.update_configuration, {"gravity_z": -9.8})
        self.ok("spawn_urdf_model", "rotor", ROTOR_URDF, "", yaw_pose(0, 5, 5), "")

    def effort(self, joint, effort, duration_s=-1):
        self.ok("apply_joint_effort", joint, effort, rospy.Time(0), rospy.Duration(duration_s))

    def test_joint_damping(self):
        self.spawn_floating_rotor()
        self.ok("set_joint_properties", "rotor::spin", ODEJointProperties(damping=[0.1]))
        # Effort E against damping c: the relative rate settles at E / c = 0.1 rad/s, with the
        # time constant 1 / (c (1/Iw + 1/Ib)) = 0.18 s (without damping: 2 s of E gives
        # E t (1/Iw + 1/Ib) = 1.1 rad/s).
        self.effort("rotor::spin", 0.01)
        self.ok("step_simulation", 2000)
        self.assertAlmostEqual(self.ok("get_joint_properties", "spin").rate[0], 0.01 / 0.1,
                               delta=1e-3)

    def test_joint_limits_and_motor(self):
        self.spawn_floating_rotor()
        self.ok("set_joint_properties", "rotor::spin",
                ODEJointProperties(loStop=[-0.5], hiStop=[0.5]))
        # Free, 0.01 N m for 1 s would turn it (1/2) E t^2 (1/Iw + 1/Ib) = 0.275 rad; for 2 s,
        # 1.1 rad: the stop at 0.5 holds it.
        self.effort("rotor::spin", 0.01)
        self.ok("step_simulation", 2000)
        position = self.ok("get_joint_properties", "spin").position[0]
        self.assertGreater(position, 0.45)
        self.assertLess(position, 0.52)
        self.call("clear_joint_forces", "spin")
        # The motor (vel, fmax) turns it back at -0.2 rad/s.
        self.ok("set_joint_properties", "spin", ODEJointProperties(vel=[-0.2], fmax=[10.0]))
        self.ok("step_simulation", 500)
        self.assertAlmostEqual(self.ok("get_joint_properties", "spin").rate[0], -0.2, delta=1e-3)

    def test_joint_requests_that_cannot_be_honoured(self):
        self.ok("spawn_urdf_model", "rotor", ROTOR_URDF, "", yaw_pose(0, 5, 5), "")
        for joint, config, fragment in (
                ("nope", ODEJointProperties(damping=[1.0]), "'nope'"),
                ("spin", ODEJointProperties(damping=[1.0, 2.0]), "damping has 2 values"),
                ("spin", ODEJointProperties(fudge_factor=[1.0]), "fudge_factor"),
                ("spin", ODEJointProperties(vel=[1.0]), "vel and fmax"),
                ("spin", ODEJointProperties(erp=[2.0]), "erp 2 must be in [0, 1]"),
                ("spin", ODEJointProperties(damping=[-1.0]), "damping -1"),
                ("spin", ODEJointProperties(hiStop=[1.0]), "hiStop given alone")):
            self.fails("set_joint_properties", fragment, joint, config)

    # --------------------------------------------------------------- lights ----

    def test_lights(self):
        sun = self.ok("get_light_properties", "sun")  # as lit.world writes it
        self.assertAlmostEqual(sun.diffuse.r, 0.8, places=6)
        self.assertAlmostEqual(sun.diffuse.a, 1.0, places=6)
        self.assertEqual((sun.attenuation_constant, sun.attenuation_linear,
                          sun.attenuation_quadratic), (0.9, 0.01, 0.001))
        lamp = self.ok("get_light_properties", "lamp")
        self.assertEqual((lamp.diffuse.r, lamp.diffuse.g, lamp.diffuse.b), (1.0, 0.5, 0.25))
        pose = yaw_pose(4, 5, 6)
        self.ok("set_light_properties", "lamp", False, colour(0.125, 0.25, 0.5),
                colour(0.5, 0.5, 0.5), 1.0, 0.0, 0.5, Vector3(0, 0, -1), pose)
        lamp = self.ok("get_light_properties", "lamp")
        self.assertEqual((lamp.diffuse.r, lamp.diffuse.g, lamp.diffuse.b), (0.125, 0.25, 0.5))
        self.assertEqual((lamp.attenuation_constant, lamp.attenuation_linear,
                          lamp.attenuation_quadratic), (1.0, 0.0, 0.5))
        self.fails("set_light_properties", "'nolight'", "nolight", False, colour(1, 1, 1),
                   colour(1, 1, 1), 1.0, 0.0, 0.0, Vector3(0, 0, -1), pose)
        self.fails("set_light_properties", "diffuse.g", "lamp", False, colour(1, NAN, 1),
                   colour(1, 1, 1), 1.0, 0.0, 0.0, Vector3(0, 0, -1), pose)
        self.fails("set_light_properties", "direction (0, 0, 0)", "sun", False, colour(1, 1, 1),
                   colour(1, 1, 1), 1.0, 0.0, 0.0, Vector3(0, 0, 0), pose)
        self.ok("delete_light", "lamp")
        self.fails("get_light_properties", "'lamp'", "lamp")
        self.fails("delete_light", "'lamp'", "lamp")
        self.ok("get_light_properties", "sun")

    # -------------------------------------------------------------- physics ----

    def test_physics_parameters_follow_the_physics(self):
        descriptions = self.physics.get_parameter_descriptions()
        self.assertEqual([(d["name"], d["type"], d["min"], d["max"]) for d in descriptions],
                         GAZEBO_ROS_PHYSICS_PARAMETERS)
        # At start: the world's step, the real-time factor 1 (1000 updates/s), gravity.
        config = self.physics.get_configuration(timeout=30)
        self.assertEqual((config["time_step"], config["max_update_rate"], config["gravity_z"]),
                         (0.001, 1000.0, -9.8))
        self.assertEqual((config["sor_pgs_iters"], config["max_contacts"]), (10, 4))
        try:
            # A change through dynamic_reconfigure is what get_physics_properties answers;
            # a field without a Bullet equivalent snaps back.
            config = self.physics.update_configuration(
                {"time_step": 0.002, "max_update_rate": 500.0, "gravity_z": -5.0,
                 "sor_pgs_iters": 30, "max_contacts": 100})
            self.assertEqual((config["time_step"], config["gravity_z"], config["sor_pgs_iters"],
                              config["max_contacts"]), (0.002, -5.0, 30, 4))
            props = self.ok("get_physics_properties")
            self.assertEqual((props.time_step, props.max_update_rate, props.gravity.z),
                             (0.002, 500.0, -5.0))
            self.assertEqual((props.ode_config.sor_pgs_iters, props.ode_config.max_contacts),
                             (30, 4))
            # Falling 0.2 s (100 steps of 2 ms) under 5 m/s^2.
            self.ok("spawn_urdf_model", "box", BOX_URDF, "", yaw_pose(0, 0, 5), "")
            self.ok("step_simulation", 100)
            self.assertAlmostEqual(self.ok("get_model_state", "box", "").twist.linear.z,
                                   -1.0, delta=1e-6)
            # set_physics_properties shows in the parameters.
            ode = props.ode_config
            self.ok("set_physics_properties", 0.001, 1000.0, Vector3(0, 0, -9.8), ode)
            end = time.monotonic() + 30  # wall time: sim time stands still while paused
            while self.physics.get_configuration(timeout=30)["time_step"] != 0.001:
                self.assertLess(time.monotonic(), end, "parameter_updates kept 0.002")
                time.sleep(0.01)
            config = self.physics.get_configuration(timeout=30)
            self.assertEqual((config["gravity_z"], config["max_update_rate"]), (-9.8, 1000.0))
        finally:
            props = self.ok("get_physics_properties")
            props.ode_config.sor_pgs_iters = 10
            self.ok("set_physics_properties", 0.001, 1000.0, Vector3(0, 0, -9.8),
                    props.ode_config)


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "gazebo_properties", GazeboProperties)
