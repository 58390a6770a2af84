#!/usr/bin/python3
"""N Burgers on the round track in one bullet_sim_node, every topic of every robot subscribed
(bullet_sim's bench_rate_listener), each driving the command's circle in its own part of the track
(scenario.circle_starts), as fast as possible. The first robot comes from robot_description
at the spawn pose; robots 2..N are added through /gazebo/spawn_urdf_model
(gazebo_msgs/SpawnModel) under the namespaces tb3_2..tb3_N. Checks that every robot drives at
the command's twist and every topic arrived at its rate, then prints the real-time factor
last.

Usage: multi_robot.py LISTENER_BINARY ROBOTS SIM_SECONDS   (BENCH_ROS_PORT, default 11461)
"""
import os
import subprocess
import sys
import tempfile
import time

import ros_bench
import scenario

RATES_HZ = {"odom": 30.0, "scan": 5.0, "imu": 200.0, "joint_states": 30.0}
WARMUP_S = 1.0


def namespaces(count):
    return ["/"] + ["tb3_%d" % k for k in range(2, count + 1)]


def spawn_others(env, urdf_file, poses):
    """Spawns robots 2..N at `poses[1:]` and gives each the circle command, latched."""
    ros_bench.adopt_env(env)
    import math
    import rospy
    from gazebo_msgs.srv import SpawnModel
    from geometry_msgs.msg import Pose, Twist
    rospy.init_node("bench_multi_robot", anonymous=True, disable_signals=True)
    rospy.wait_for_service("/gazebo/spawn_urdf_model", timeout=30)
    spawn = rospy.ServiceProxy("/gazebo/spawn_urdf_model", SpawnModel)
    with open(urdf_file) as f:
        urdf = f.read()
    command = Twist()
    command.linear.x, command.angular.z = scenario.CMD_LINEAR_MPS, scenario.CMD_ANGULAR_RADPS
    publishers = []
    for ns, (x, y, yaw) in zip(namespaces(len(poses)), poses):
        if ns != "/":
            pose = Pose()
            pose.position.x, pose.position.y = x, y
            pose.orientation.z, pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
            result = spawn(model_name=ns, model_xml=urdf, robot_namespace=ns,
                           initial_pose=pose, reference_frame="world")
            if not result.success:
                raise RuntimeError("spawning %s: %s" % (ns, result.status_message))
        publisher = rospy.Publisher(("/" if ns == "/" else "/%s/" % ns) + "cmd_vel", Twist,
                                    queue_size=1, latch=True)
        publisher.publish(command)
        publishers.append(publisher)
    for publisher in publishers:
        ros_bench.wait_for(lambda: publisher.get_num_connections() > 0,
                           "the node subscribing to %s" % publisher.resolved_name)
    time.sleep(0.5)  # the latched commands reach the node
    return publishers


def check_driving(count):
    """Raises unless every robot moves at the command's twist (a robot at rest sleeps and
    would cost nothing, flattering the figure)."""
    import math
    import rospy
    import rosservice
    state_type = rosservice.get_service_class_by_name("/gazebo/get_model_state")
    get_state = rospy.ServiceProxy("/gazebo/get_model_state", state_type)
    for ns in namespaces(count):
        name = "turtlebot3_burger" if ns == "/" else ns
        twist = get_state(model_name=name, relative_entity_name="world").twist
        speed = math.hypot(twist.linear.x, twist.linear.y)
        if not (abs(speed - scenario.CMD_LINEAR_MPS) < 0.03
                and abs(twist.angular.z - scenario.CMD_ANGULAR_RADPS) < 0.1):
            raise scenario.SanityError("%s moves at %.3f m/s, %.3f rad/s; the command is "
                                       "%.1f m/s, %.1f rad/s" % (
                                           name, speed, twist.angular.z, scenario.CMD_LINEAR_MPS,
                                           scenario.CMD_ANGULAR_RADPS))


def check_rates(output, count):
    """Raises unless every robot's topics (and /tf for all) came at their rates."""
    rates = {line.split()[0]: float(line.split()[1]) for line in output.splitlines()
             if line.startswith("/") and "Hz" in line}
    expected = {"/tf": 30.0 * count}
    for ns in namespaces(count):
        prefix = "/" if ns == "/" else "/%s/" % ns
        expected.update({prefix + topic: hz for topic, hz in RATES_HZ.items()})
    for topic, hz in expected.items():
        if not abs(rates.get(topic, 0.0) - hz) <= 0.1 * hz:
            raise scenario.SanityError("%s came at %.1f Hz (sim time), not %.0f Hz"
                                       % (topic, rates.get(topic, 0.0), hz))


def main():
    listener, count, sim_s = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
    port = int(os.environ.get("BENCH_ROS_PORT", "11461"))
    env = ros_bench.ros_env(port)
    poses = scenario.circle_starts(ros_bench.WORLD, count)
    work = tempfile.mkdtemp()
    with ros_bench.Processes() as procs:
        ros_bench.start_master(procs, env, port)
        urdf_file = ros_bench.burger_urdf(env, os.path.join(work, "burger.urdf"))
        subprocess.run(["rosparam", "set", "robot_description", "-t", urdf_file], env=env,
                       check=True)
        x, y, yaw = poses[0]
        procs.start(["rosrun", "bullet_sim", "bullet_sim_node", "_world_file:=" + ros_bench.WORLD,
                     "_real_time_factor:=0", "_paused:=true", "_robot_name:=turtlebot3_burger",
                     "_spawn_x:=%g" % x,
                     "_spawn_y:=%g" % y, "_spawn_yaw:=%g" % yaw], env)
        spawn_others(env, urdf_file, poses)
        result = subprocess.run([listener, str(WARMUP_S), str(sim_s)] + namespaces(count),
                                env=env, stdout=subprocess.PIPE, universal_newlines=True,
                                timeout=900)
        if result.returncode != 0:
            sys.exit("bench_rate_listener failed (exit %d)" % result.returncode)
        try:
            check_driving(count)
        except scenario.SanityError as error:
            sys.exit("sanity check failed: %s" % error)
    try:
        check_rates(result.stdout, count)
    except scenario.SanityError as error:
        sys.exit("sanity check failed: %s" % error)
    print("%d robots: every topic at its rate" % count)
    print(result.stdout.strip().splitlines()[-1])


if __name__ == "__main__":
    main()
