#!/usr/bin/python3
"""N Burgers on the round track in one bullet_sim_node, every topic of every robot subscribed
(bullet_sim's bench_rate_listener), each driving the command's circle in its own part of the track
(scenario.circle_starts), as fast as possible. The first robot comes from robot_description
at the spawn pose; robots 2..N are added through /gazebo/spawn_urdf_model
(gazebo_msgs/SpawnModel) under the namespaces tb3_2..tb3_N. Checks that every robot drives at
the command's twist and every topic arrived at its rate, then prints the real-time factor
last.

With --in-process the listener loads the simulator as the bullet_sim/Simulator nodelet into
its own process (bench_rate_listener --simulator), so that every subscription is in-process:
the messages reach it as the objects the simulator made, without serialisation or a socket.

With --depth every Burger's camera is a depth camera (ros_bench.depth_burger_urdf), and its
colour and depth images and point cloud (640 x 480, 30 Hz) are subscribed too; it prints
which share of them arrived (a publisher drops what its subscriber cannot take in time).

With --threads N the simulator steps its physics on N threads (its ~threads parameter;
default: the machine's hardware threads).

Usage: multi_robot.py [--in-process] [--depth] [--threads N] LISTENER_BINARY ROBOTS SIM_SECONDS
       (BENCH_ROS_PORT, default 11461)
"""
import os
import re
import subprocess
import sys
import time

import ros_bench
import scenario

RATES_HZ = {"odom": 30.0, "scan": 5.0, "imu": 200.0, "joint_states": 30.0}
CAMERA_RATES_HZ = {"camera/image_raw": 30.0, "camera/depth/image_raw": 30.0,
                   "camera/points": 30.0}
WARMUP_S = 1.0
# The last line of bench_rate_listener's figures.
FIGURES_END = re.compile(r"^real-time factor [0-9.]+$", re.M)
# bench_rate_listener --simulator: its subscriptions are made.
SUBSCRIBED = re.compile(r"^subscribed$", re.M)


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


def unpause():
    """Starts the in-process simulator once every robot has its command (the listener
    only unpauses a simulator of another process)."""
    import rospy
    from std_srvs.srv import Empty
    rospy.wait_for_service("/gazebo/unpause_physics", timeout=30)
    rospy.ServiceProxy("/gazebo/unpause_physics", Empty)()


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


def check_rates(output, count, depth):
    """Raises unless every robot's topics (and /tf for all) came at their rates. The camera
    topics may come slower: their publishers keep one message and drop the rest when the
    subscriber cannot take them as fast (as Gazebo's camera plugins do); returns how many
    of them arrived, as a fraction of those made (1.0 when all did)."""
    rates = {line.split()[0]: float(line.split()[1]) for line in output.splitlines()
             if line.startswith("/") and "Hz" in line}
    expected, camera = {"/tf": 30.0 * count}, {}
    for ns in namespaces(count):
        prefix = "/" if ns == "/" else "/%s/" % ns
        expected.update({prefix + topic: hz for topic, hz in RATES_HZ.items()})
        if depth:
            camera.update({prefix + topic: hz for topic, hz in CAMERA_RATES_HZ.items()})
    for topic, hz in expected.items():
        if not abs(rates.get(topic, 0.0) - hz) <= 0.1 * hz:
            raise scenario.SanityError("%s came at %.1f Hz (sim time), not %.0f Hz"
                                       % (topic, rates.get(topic, 0.0), hz))
    for topic, hz in camera.items():
        if not 0 < rates.get(topic, 0.0) <= 1.1 * hz:
            raise scenario.SanityError("%s came at %.1f Hz (sim time); it is made at %.0f Hz"
                                       % (topic, rates.get(topic, 0.0), hz))
    if not camera:
        return 1.0
    return min(1.0, sum(rates[t] for t in camera) / sum(camera.values()))


def simulator_parameters(pose, threads=None):
    """bullet_sim_node's private parameters: as fast as possible, paused until the robots
    have their commands and the listener its subscriptions, the first robot from
    robot_description at `pose`; ~threads if given (else the node's default)."""
    x, y, yaw = pose
    parameters = {"world_file": ros_bench.WORLD, "real_time_factor": "0", "paused": "true",
                  "robot_name": "turtlebot3_burger", "spawn_x": "%g" % x, "spawn_y": "%g" % y,
                  "spawn_yaw": "%g" % yaw}
    if threads is not None:
        parameters["threads"] = str(threads)
    return parameters


def main():
    args = sys.argv[1:]
    options, threads = set(), None
    while args and args[0] in ("--in-process", "--depth", "--threads"):
        option = args.pop(0)
        if option == "--threads":
            threads = int(args.pop(0))
        options.add(option)
    in_process, depth = "--in-process" in options, "--depth" in options
    listener, count, sim_s = args[0], int(args[1]), float(args[2])
    port = int(os.environ.get("BENCH_ROS_PORT", "11461"))
    env = ros_bench.ros_env(port)
    poses = scenario.circle_starts(ros_bench.WORLD, count)
    work = ros_bench.work_folder("bench_multi_robot_")
    parameters = simulator_parameters(poses[0], threads)
    listen = ([listener] + (["--camera"] if depth else []) + [str(WARMUP_S), str(sim_s)]
              + namespaces(count))
    with ros_bench.Processes() as procs:
        ros_bench.start_master(procs, env, port)
        urdf_file = ros_bench.burger_urdf(env, os.path.join(work, "burger.urdf"))
        if depth:
            urdf_file = ros_bench.depth_burger_urdf(urdf_file, os.path.join(work, "depth.urdf"))
        subprocess.run(["rosparam", "set", "robot_description", "-t", urdf_file], env=env,
                       check=True)
        if in_process:
            # The nodelet is named /gazebo: its private parameters are /gazebo/...
            for name, value in parameters.items():
                subprocess.run(["rosparam", "set", "/gazebo/" + name, value], env=env,
                               check=True)
            output = open(os.path.join(work, "rates.txt"), "w+")
            listening = procs.start([listener, "--simulator"] + listen[1:], env, stdout=output)

            def printed(line):  # true once the listener printed `line` (or exited)
                return lambda: (listening.poll() is not None
                                or line.search(open(output.name).read()))

            # Spawning while it subscribes would let roscpp link some subscriptions twice.
            ros_bench.wait_for(printed(SUBSCRIBED), "bench_rate_listener's subscriptions",
                               timeout_s=120, poll_s=0.05)
            spawn_others(env, urdf_file, poses)
            unpause()
            # It prints its figures and keeps the simulator running for check_driving.
            # (the simulator's own log lines, in the same output, speak of its real-time
            # factor too: the listener's figures end with a line of its own)
            ros_bench.wait_for(printed(FIGURES_END), "bench_rate_listener's figures",
                               timeout_s=900, poll_s=0.2)
            result = subprocess.CompletedProcess(listening.args, listening.poll() or 0,
                                                 open(output.name).read())
        else:
            procs.start(["rosrun", "bullet_sim", "bullet_sim_node"]
                        + ["_%s:=%s" % item for item in parameters.items()], env)
            spawn_others(env, urdf_file, poses)
            result = subprocess.run(listen, env=env, stdout=subprocess.PIPE,
                                    universal_newlines=True, timeout=900)
        if result.returncode != 0:
            sys.exit("bench_rate_listener failed (exit %d)" % result.returncode)
        try:
            check_driving(count)
        except scenario.SanityError as error:
            sys.exit("sanity check failed: %s" % error)
    try:
        delivered = check_rates(result.stdout, count, depth)
    except scenario.SanityError as error:
        sys.exit("sanity check failed: %s" % error)
    print("%d robots: odometry, scan, IMU, joint states and tf at their rates" % count)
    if depth:
        print("camera images and point clouds delivered: %.0f %% of those made"
              % (100 * delivered))
    print(FIGURES_END.findall(result.stdout)[-1])


if __name__ == "__main__":
    main()
