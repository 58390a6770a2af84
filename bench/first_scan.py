#!/usr/bin/python3
"""Launch to first /scan: wall time from starting
`roslaunch turtlebot3_gazebo roundTrack_simulation.launch gui:=false` until a subscriber in
this process has its first laser scan, either with the master started by roslaunch
(`own-master`) or with a master already running (`running-master`). rospy is imported before
the clock starts. Then, after 5 s of simulation at real time, reads bullet_sim_node's
resident memory. Prints both, the simulator's part (from its process start to the first
scan) and the launch time last, after a timeline of when each stage was first seen
(polling the master every 5 ms): the master up, the robot description set (xacro done),
the simulator's process started (roslaunch started gzserver, which becomes bullet_sim_node;
from /proc, to 10 ms), the simulator registered with the master (its roscpp started), the
simulator's spawn service up (world loaded), spawn_model registered, the robot's /scan
advertised (robot spawned), the first scan received.

Usage: first_scan.py own-master|running-master   (BENCH_ROS_PORT, default 11462)
"""
import os
import sys
import threading
import time

import ros_bench


MILESTONES = (
    ("master up", lambda m: m.is_online()),
    ("robot_description set (xacro ran)", lambda m: m.hasParam("/robot_description")),
    ("simulator registered (its roscpp started)", lambda m: "/gazebo" in nodes_of(m)),
    ("/gazebo/spawn_urdf_model up (node started, world loaded)",
     lambda m: bool(m.lookupService("/gazebo/spawn_urdf_model"))),
    ("spawn_model registered", lambda m: "/spawn_urdf" in nodes_of(m)),
    ("/scan advertised (robot spawned)",
     lambda m: any(topic == "/scan" for topic, _ in m.getSystemState()[0])),
)


def nodes_of(master):
    publishers, subscribers, services = master.getSystemState()
    return {node for _, nodes in publishers + subscribers + services for node in nodes}


PROCESS_STARTED = "simulator process started (gzserver, then bullet_sim_node)"


def started_after(pid, boot_start_s):
    """When process `pid` started, in seconds after `boot_start_s` (CLOCK_BOOTTIME), to the
    10 ms of /proc's clock ticks."""
    with open("/proc/%d/stat" % pid) as stat:
        ticks = int(stat.read().rsplit(")", 1)[1].split()[19])
    return ticks / os.sysconf("SC_CLK_TCK") - boot_start_s


def watch(master, start, seen, done):
    """Records when each milestone is first true, polling the master until `done` is set."""
    pending = list(MILESTONES)
    while pending and not done.is_set():
        for milestone in list(pending):
            try:
                reached = milestone[1](master)
            except Exception:  # master not up yet, or a lookup of something not there
                reached = False
            if reached:
                seen[milestone[0]] = time.monotonic() - start
                pending.remove(milestone)
        time.sleep(0.005)


def main():
    mode = sys.argv[1]
    if mode not in ("own-master", "running-master"):
        sys.exit("usage: first_scan.py own-master|running-master")
    port = int(os.environ.get("BENCH_ROS_PORT", "11462"))
    env = ros_bench.ros_env(port)
    env["ROS_HOME"] = os.path.join(os.environ.get("TMPDIR", "/tmp"), "bench_first_scan_ros_home")
    ros_bench.adopt_env(env)
    import rosgraph
    import rospy
    from sensor_msgs.msg import LaserScan
    master = rosgraph.Master("/bench_first_scan")
    got_scan = threading.Event()
    with ros_bench.Processes() as procs:
        if mode == "running-master":
            ros_bench.start_master(procs, env, port)
        elif ros_bench.master_up(env):
            sys.exit("a ROS master already runs on port %d" % port)
        seen, done = {}, threading.Event()
        start = time.monotonic()
        boot_start = time.clock_gettime(time.CLOCK_BOOTTIME)
        watcher = threading.Thread(target=watch, args=(rosgraph.Master("/bench_first_scan_watch"),
                                                         start, seen, done), daemon=True)
        watcher.start()
        launch = procs.start(["roslaunch", "-p", str(port), "turtlebot3_gazebo",
                              "roundTrack_simulation.launch", "gui:=false"], env)
        ros_bench.wait_for(master.is_online, "the launch's master", poll_s=0.005)
        rospy.init_node("bench_first_scan", anonymous=True, disable_signals=True)
        rospy.Subscriber("/scan", LaserScan, lambda _: got_scan.set(), queue_size=1)
        if not got_scan.wait(timeout=60):
            sys.exit("no /scan within 60 s of the launch")
        launch_s = time.monotonic() - start
        done.set()
        watcher.join()
        time.sleep(5.0)
        node = ros_bench.process_named(ros_bench.descendants(launch.pid), "bullet_sim_node")
        if node is None:
            sys.exit("bullet_sim_node is not running under roslaunch")
        seen[PROCESS_STARTED] = started_after(node, boot_start)
        memory_mb = ros_bench.resident_mb(node)
        rospy.signal_shutdown("measured")
    stages = [MILESTONES[0][0], MILESTONES[1][0], PROCESS_STARTED] + [m[0] for m in MILESTONES[2:]]
    for name in stages:
        print("  %6s s  %s" % ("%.3f" % seen[name] if name in seen else "-", name))
    print("  %6.3f s  first /scan received" % launch_s)
    print("bullet_sim_node resident memory %.1f MB" % memory_mb)
    print("simulator process start to first /scan (%s) %.3f s"
          % (mode, launch_s - seen[PROCESS_STARTED]))
    print("launch to first /scan (%s) %.3f s" % (mode, launch_s))


if __name__ == "__main__":
    main()
