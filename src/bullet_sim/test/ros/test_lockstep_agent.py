#!/usr/bin/python3
"""An agent stepping the Burger on the round track over ROS, as openai_ros agents do.

The step services (step_simulation, step_control) take exactly the steps asked for and
publish every scan that falls due on the way, stamped with its sim time, before they
reply. A seeded sequence of actions, each held for 0.2 s of sim time, is run from
reset_simulation: (a) in lockstep through step_control at real-time factor 1 and (a')
unpaced, which must agree to the bit; (b) the classic loop at real-time factor 1:
unpause, publish the command, wait for the scan stamped at the action's end, pause.

(b) reads each command later than (a): the Burger's diff drive reads its command at 30 Hz,
before the steps k with floor((k - 1) * 0.001 * 30) > floor((k - 2) * 0.001 * 30): steps
1, 35, 68, 101, 135, 168 of every 200-step action (sim times 0, 0.034, 0.067, 0.1, ...
after its start). (a) sets the command before step 1, so it is read at once. In (b) the
simulation runs on until the pause lands, so step 1 of the next action has already read
the old command, and the new one, arriving after unpause, is read before step 35. (c) is
lockstep with that delay: one step with the old command, then the new command and 199
steps. (b) equals (c) to the bit for every action whose commands, so far, all came within
those 34 steps; the test measures each pause's overshoot from get_model_state's stamp and
holds (b) to the bit while it is under half of them (the other half for unpause and
publish), and its poses, read after the pause, to the distance the Burger covers in the
overshoot. With persistent service connections the pauses overshoot by 1 to 12 ms and all
30 actions are held to the bit; at least 10 (2 s of sim) must be, leaving room for a
loaded machine (a new connection per call once stalled a pause 100 ms).
"""
import math
import random
import threading
import time
import unittest

import rospy
import rostest
from bullet_sim.srv import StepSimulation
from gazebo_msgs.srv import (GetModelState, GetPhysicsProperties, SetPhysicsProperties,
                             StepControl)
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
from std_srvs.srv import Empty

ROBOT = "turtlebot3_burger"
STEP_S = 0.001             # roundTrack.world's max_step_size
SCAN_HZ = 5.0              # the Burger's LDS update_rate

ACTION_STEPS = 200         # 0.2 s of sim per action
LINEAR_MPS = 0.15
ANGULARS_RADPS = (-1.5, -0.75, 0.0, 0.75, 1.5)
ACTIONS = 30
SEED = 1268                # the seed of the action sequence
# The second step of an action before which the diff drive reads the command (the first
# is step 1): the first k > 1 with floor((k - 1) * STEP_S * 30 Hz) passing an integer.
FIRST_DRIVE_STEP = 35

def action_sequence():
    rng = random.Random(SEED)
    return [rng.choice(ANGULARS_RADPS) for _ in range(ACTIONS)]

def stamp_ns(stamp):
    return stamp.secs * 1000000000 + stamp.nsecs

def steps_ns(steps):
    """The sim time of step `steps`, to the nanosecond as the node stamps it."""
    return int(round(steps * STEP_S * 1e9))

class Inbox:
    """Messages of one topic by stamp (ns), and a wait for a given stamp."""

    def __init__(self, topic, msg_type):
        self.by_stamp = {}
        self.cond = threading.Condition()
        self.sub = rospy.Subscriber(topic, msg_type, self._on_msg, queue_size=1000)

    def _on_msg(self, msg):
        with self.cond:
            self.by_stamp[stamp_ns(msg.header.stamp)] = msg
            self.cond.notify_all()

    def clear(self):
        with self.cond:
            self.by_stamp = {}

    def wait_for(self, ns, timeout_s=20.0):
        """The message stamped `ns`; in order on the connection, so every earlier one is in."""
        end = time.monotonic() + timeout_s
        with self.cond:
            while ns not in self.by_stamp:
                left = end - time.monotonic()
                if left <= 0:
                    raise AssertionError("no message stamped %d ns (latest: %s)" % (
                        ns, max(self.by_stamp) if self.by_stamp else None))
                self.cond.wait(left)
            return self.by_stamp[ns]

    def stamps(self):
        with self.cond:
            return sorted(self.by_stamp)

def pose_tuple(pose):
    p, q = pose.position, pose.orientation
    return (p.x, p.y, p.z, q.x, q.y, q.z, q.w)

def yaw_of(q):
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))

class LockstepAgent(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("lockstep_agent")
        for name in ("/gazebo/step_control", "/gazebo/step_simulation"):
            rospy.wait_for_service(name, timeout=60)
        cls.step_control = rospy.ServiceProxy("/gazebo/step_control", StepControl)
        cls.step_simulation = rospy.ServiceProxy("/gazebo/step_simulation", StepSimulation)
        # Persistent: one connection each, no master lookup per call in the timed loop.
        cls.pause = rospy.ServiceProxy("/gazebo/pause_physics", Empty, persistent=True)
        cls.unpause = rospy.ServiceProxy("/gazebo/unpause_physics", Empty, persistent=True)
        cls.reset = rospy.ServiceProxy("/gazebo/reset_simulation", Empty)
        cls.get_state = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState,
                                           persistent=True)
        cls.get_physics = rospy.ServiceProxy("/gazebo/get_physics_properties",
                                             GetPhysicsProperties)
        cls.set_physics = rospy.ServiceProxy("/gazebo/set_physics_properties",
                                             SetPhysicsProperties)
        cls.scans = Inbox("/scan", LaserScan)
        cls.odom = Inbox("/odom", Odometry)
        # queue_size None: publish() has written the command to the simulator's socket
        # when it returns, before the step request that follows is even connected.
        cls.cmd_vel = rospy.Publisher("/cmd_vel", Twist, queue_size=None)
        end = time.monotonic() + 30
        while (cls.scans.sub.get_num_connections() == 0 or
               cls.odom.sub.get_num_connections() == 0 or
               cls.cmd_vel.get_num_connections() == 0):
            if time.monotonic() > end:
                raise AssertionError("no connection to the simulator's topics")
            time.sleep(0.01)

    def setUp(self):
        self.pause()
        self.set_real_time_factor(1.0)
        self.restart()

    def restart(self):
        self.reset()
        self.scans.clear()
        self.odom.clear()

    def set_real_time_factor(self, factor):
        """Gazebo's way: max_update_rate = real-time factor / time step (0: unpaced)."""
        now = self.get_physics()
        response = self.set_physics(now.time_step, factor / now.time_step, now.gravity,
                                    now.ode_config)
        self.assertTrue(response.success, response.status_message)
        self.assertAlmostEqual(self.get_physics().max_update_rate * STEP_S, factor)

    def command(self, angular_radps):
        twist = Twist()
        twist.linear.x = LINEAR_MPS
        twist.angular.z = angular_radps
        self.cmd_vel.publish(twist)

    def model_state(self):
        response = self.get_state(ROBOT, "")
        self.assertTrue(response.success, response.status_message)
        return response

    def record(self, end_ns, state):
        scan = self.scans.wait_for(end_ns)
        odom = self.odom.wait_for(end_ns)
        return {"scan": tuple(scan.ranges), "odom": pose_tuple(odom.pose.pose),
                "pose": state.pose, "state_ns": stamp_ns(state.header.stamp)}

    def run_lockstep(self, delay_steps=0):
        """Each action's command set after `delay_steps` steps of the action."""
        trajectory = []
        for i, angular in enumerate(action_sequence()):
            if delay_steps > 0:
                self.assertTrue(self.step_control(delay_steps).success)
            self.command(angular)
            response = self.step_control(ACTION_STEPS - delay_steps)
            self.assertTrue(response.success, response.status_message)
            trajectory.append(self.record(steps_ns(ACTION_STEPS * (i + 1)), self.model_state()))
        return trajectory

    def run_unpause_pause(self):
        trajectory = []
        for i, angular in enumerate(action_sequence()):
            end_ns = steps_ns(ACTION_STEPS * (i + 1))
            self.unpause()
            self.command(angular)
            self.scans.wait_for(end_ns)
            self.pause()
            trajectory.append(self.record(end_ns, self.model_state()))
        return trajectory

    def test_step_publishes_every_due_scan_before_replying(self):
        # From sim time 0 the 5 Hz scan is due at every step k with k * 0.001 * 5 an
        # integer: steps 200, 400, ...; a step call covers the scans of (start, end].
        per_scan = int(round(1 / (SCAN_HZ * STEP_S)))
        calls = [(self.step_simulation, 1000), (self.step_control, 130),
                 (self.step_control, 70), (self.step_simulation, 199), (self.step_control, 1)]
        done = 0
        for call, steps in calls:
            response = call(steps)
            self.assertTrue(response.success, response.status_message)
            if call is self.step_simulation:
                self.assertEqual(stamp_ns(response.sim_time), steps_ns(done + steps))
            expected = [steps_ns(k) for k in range(per_scan, done + steps + 1, per_scan)]
            if expected:
                self.scans.wait_for(expected[-1])
            self.assertEqual(self.scans.stamps(), expected, "after %d steps" % (done + steps))
            done += steps
        self.assertEqual(len(self.scans.stamps()), 7)  # 1400 steps: 0.2, 0.4 .. 1.4 s
        self.assertEqual(stamp_ns(self.model_state().header.stamp), steps_ns(done))

    def test_step_control_zero_unpauses_and_n_pauses(self):
        self.assertTrue(self.step_control(0).success)
        self.assertFalse(self.get_physics().pause)
        self.assertTrue(self.step_control(5).success)
        self.assertTrue(self.get_physics().pause)
        paused_at = stamp_ns(self.model_state().header.stamp)
        self.assertEqual(stamp_ns(self.model_state().header.stamp), paused_at)

    def test_lockstep_and_unpause_pause_loops_agree(self):
        lockstep = self.run_lockstep()
        moved_m = math.hypot(lockstep[-1]["pose"].position.x, lockstep[-1]["pose"].position.y)
        self.assertGreater(moved_m, 0.3)  # it drove: 30 actions of 0.03 m at most each

        self.set_real_time_factor(0.0)
        self.restart()
        unpaced = self.run_lockstep()
        for i, (a, b) in enumerate(zip(lockstep, unpaced)):
            self.assertEqual(a["state_ns"], steps_ns(ACTION_STEPS * (i + 1)))
            self.assertEqual(b["state_ns"], a["state_ns"])
            self.assertEqual(a["scan"], b["scan"], "action %d" % i)
            self.assertEqual(a["odom"], b["odom"], "action %d" % i)
            self.assertEqual(pose_tuple(a["pose"]), pose_tuple(b["pose"]), "action %d" % i)

        self.restart()
        delayed = self.run_lockstep(delay_steps=1)
        self.set_real_time_factor(1.0)
        self.restart()
        start = time.monotonic()
        classic = self.run_unpause_pause()
        wall_s = time.monotonic() - start
        overshoots_ms = [(b["state_ns"] - c["state_ns"]) / 1e6 for b, c in zip(classic, delayed)]
        half_window_ms = (FIRST_DRIVE_STEP - 1) * STEP_S * 1e3 / 2
        exact = 0
        for i, (b, c) in enumerate(zip(classic, delayed)):
            if i > 0 and overshoots_ms[i - 1] >= half_window_ms:
                break
            exact += 1
            self.assertEqual(b["scan"], c["scan"], "action %d" % i)
            self.assertEqual(b["odom"], c["odom"], "action %d" % i)
            # After the action's end it went on for the overshoot: no farther than
            # 0.15 m/s and 1.5 rad/s take it (the ramp only slows a change), 10 % for
            # the wheels' contacts.
            overshoot_s = overshoots_ms[i] / 1e3
            self.assertGreaterEqual(overshoot_s, 0, "action %d" % i)
            drift_m = math.hypot(b["pose"].position.x - c["pose"].position.x,
                                 b["pose"].position.y - c["pose"].position.y)
            self.assertLessEqual(drift_m, 1.1 * LINEAR_MPS * overshoot_s + 1e-6, "action %d" % i)
            turn = abs(math.remainder(yaw_of(b["pose"].orientation) -
                                      yaw_of(c["pose"].orientation), math.tau))
            self.assertLessEqual(turn, 1.1 * max(map(abs, ANGULARS_RADPS)) * overshoot_s + 1e-6,
                                 "action %d" % i)
        self.assertGreaterEqual(exact, 10, "pause overshoots (ms): %s" % overshoots_ms)
        gap_m = math.hypot(delayed[-1]["pose"].position.x - lockstep[-1]["pose"].position.x,
                           delayed[-1]["pose"].position.y - lockstep[-1]["pose"].position.y)
        rospy.loginfo("unpause/pause loop: %.2f s wall for %.1f s sim; pause overshoot %.1f .. "
                      "%.1f ms; %d of %d actions to the bit; delayed commands end %.4f m from "
                      "lockstep", wall_s, ACTIONS * ACTION_STEPS * STEP_S, min(overshoots_ms),
                      max(overshoots_ms), exact, ACTIONS, gap_m)


if __name__ == "__main__":
    rostest.rosrun("bullet_sim", "lockstep_agent", LockstepAgent)
