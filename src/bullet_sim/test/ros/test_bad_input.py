#!/usr/bin/python3
"""bullet_sim_node on bad input: it exits with a non-zero code (not by a signal) and
prints the error naming what is wrong, for each fixture. On good input it runs until
SIGINT and then exits cleanly with code 0."""
import os
import signal
import subprocess
import time
import unittest

import rosgraph
import rospy

import rostest
from gazebo_msgs.srv import SpawnModel
from geometry_msgs.msg import Pose
from roslib.packages import find_node
from rospkg import RosPack

FIXTURES = os.path.join(RosPack().get_path("bullet_sim"), "test", "ros", "fixtures")
CORE_FIXTURES = os.path.join(RosPack().get_path("bullet_sim"), "test", "fixtures")
GOOD_WORLD = os.path.join(FIXTURES, "flat.world")
TIMEOUT_S = 60


def run_node(name, *args):
    """Runs the node to its end; returns (exit code, stdout + stderr)."""
    node = find_node("bullet_sim", "bullet_sim_node")[0]
    result = subprocess.run([node, "__name:=" + name] + list(args), stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, timeout=TIMEOUT_S, text=True)
    return result.returncode, result.stdout


class BadInput(unittest.TestCase):
    def assertFailsWith(self, code, output, *fragments):
        self.assertGreater(code, 0, "exit code %d (negative: killed by a signal)\n%s"
                           % (code, output))
        self.assertIn("FATAL", output)
        for fragment in fragments:
            self.assertIn(fragment, output)

    def test_missing_world_file(self):
        missing = os.path.join(FIXTURES, "no_such.world")
        code, output = run_node("missing_world", "_world_file:=" + missing)
        self.assertFailsWith(code, output, missing, "does not exist")

    def test_world_file_from_the_parameter_server(self):
        # Not on the command line: the node reads ~world_file from the master, then loads.
        missing = os.path.join(FIXTURES, "no_such_param.world")
        rospy.set_param("/param_world/world_file", missing)
        code, output = run_node("param_world")
        self.assertFailsWith(code, output, missing, "does not exist")

    def test_a_bad_parameter_is_reported_while_the_world_loads(self):
        code, output = run_node("bad_rtf", "_world_file:=" + GOOD_WORLD, "_real_time_factor:=-1")
        self.assertEqual(code, 1, output)
        self.assertFailsWith(code, output, "~real_time_factor = -1 is invalid: must be >= 0")
        self.assertNotIn("world ", output.split("FATAL")[0])  # nothing started before it

    def test_malformed_world(self):
        malformed = os.path.join(FIXTURES, "malformed.world")
        code, output = run_node("malformed_world", "_world_file:=" + malformed)
        self.assertFailsWith(code, output, malformed, "invalid SDF")

    def test_urdf_with_two_roots(self):
        code, output = run_node("two_roots", "_world_file:=" + GOOD_WORLD, "_robot_name:=two",
                                "robot_description:=/two_roots_description")
        self.assertFailsWith(code, output, "robot_description", "Two root links")

    def test_urdf_with_a_link_of_two_parents(self):
        # urdfdom hands back a cycle for it, which once overflowed the node's stack.
        code, output = run_node("two_parents", "_world_file:=" + GOOD_WORLD, "_robot_name:=two",
                                "robot_description:=/two_parents_description")
        self.assertEqual(code, 1, output)
        self.assertFailsWith(code, output, "robot_description: link 'arm_a' is the child of "
                             "joints 'base_a' and 'b_to_a'")

    def test_world_with_a_negative_box_size(self):
        world = os.path.join(CORE_FIXTURES, "world_negative_box_size.world")
        code, output = run_node("negative_size", "_world_file:=" + world)
        self.assertEqual(code, 1, output)
        self.assertFailsWith(code, output, world + ": model 'crate' link 'body' collision "
                             "'collision': <box> <size>: '1 -0.5 0.3' must be finite and not "
                             "negative")

    def test_spawning_a_urdf_with_nan_in_an_origin_fails_and_the_node_runs_on(self):
        spawn = "/nan_spawn/spawn_urdf_model"
        process = self.start_until_clock("nan_spawn", "/gazebo/spawn_urdf_model:=" + spawn)
        try:
            rospy.wait_for_service(spawn, timeout=TIMEOUT_S)
            with open(os.path.join(CORE_FIXTURES, "urdf_nan_origin.urdf")) as urdf:
                response = rospy.ServiceProxy(spawn, SpawnModel)("nan_robot", urdf.read(), "",
                                                                 Pose(), "")
            self.assertFalse(response.success)
            message = response.status_message
            self.assertIn("nan_robot: invalid URDF: Unable to parse component [nan]", message)
            self.assertIn("origin element for joint [arm_joint]", message)
            self.assertNotIn("\n", message)
            self.assertIsNone(process.poll(), "the node ended after a bad spawn")
        finally:
            self.interrupt(process)

    def test_missing_robot_description(self):
        code, output = run_node("no_description", "_world_file:=" + GOOD_WORLD,
                                "_robot_name:=burger", "robot_description:=/not_set")
        self.assertFailsWith(code, output, "/not_set", "is not set", "'burger'")

    def test_invalid_model_states_rate(self):
        code, output = run_node("bad_states_rate", "_world_file:=" + GOOD_WORLD,
                                "_model_states_rate:=0.0")
        self.assertFailsWith(code, output, "model_states_rate", "must be > 0 Hz")

    def test_missing_world_parameter(self):
        code, output = run_node("no_world")
        self.assertFailsWith(code, output, "world_file", "is not set")

    def test_invalid_real_time_factor(self):
        code, output = run_node("bad_factor", "_world_file:=" + GOOD_WORLD,
                                "_real_time_factor:=-2.0")
        self.assertFailsWith(code, output, "real_time_factor", "-2")

    def test_starts_without_robot_description_when_no_robot_name(self):
        self.run_until_clock_then_interrupt("no_robot", "robot_description:=/not_set")

    def test_sigint_ends_a_running_node_cleanly(self):
        self.run_until_clock_then_interrupt("interrupted")

    def run_until_clock_then_interrupt(self, name, *args):
        self.interrupt(self.start_until_clock(name, *args))

    def start_until_clock(self, name, *args):
        """Starts the node on the flat world; returns it once it publishes its clock."""
        node = find_node("bullet_sim", "bullet_sim_node")[0]
        clock = "/%s_clock" % name
        process = subprocess.Popen([node, "__name:=" + name, "_world_file:=" + GOOD_WORLD,
                                    "/clock:=" + clock] + list(args),
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        master = rosgraph.Master("/bad_input_test")
        deadline = time.monotonic() + TIMEOUT_S
        while [clock, "rosgraph_msgs/Clock"] not in master.getPublishedTopics(""):
            if process.poll() is not None:
                self.fail("the node ended early: " + process.stdout.read())
            self.assertLess(time.monotonic(), deadline, "the node did not advertise /clock")
            time.sleep(0.05)
        return process

    def interrupt(self, process):
        process.send_signal(signal.SIGINT)
        output, _ = process.communicate(timeout=TIMEOUT_S)
        self.assertEqual(process.returncode, 0, output)
        self.assertNotIn("FATAL", output)


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "bad_input", BadInput)
