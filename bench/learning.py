#!/usr/bin/python3
"""bench/learning.py: agent steps per second of the TurtleBot3 goal environment
(bullet_sim.envs.TurtleBot3GoalEnv: 24-ray scan, 0.2 s control period, random actions, a
reset whenever an episode ends) against the Gazebo way (5 agent steps per second at
real-time factor 1) and a MuJoCo Gymnasium environment (Ant-v5) on the same machine.

Medians of N rounds (default 3), each figure measured in a process of its own:
  single   one environment in one thread, physics_step 1 ms and 5 ms: steps/s and steps
           per CPU second (time.process_time of the process); then the median cost of
           100 resets and of 20 seeded ones (which build the simulation anew)
  vector   TurtleBot3GoalVectorEnv with 1, 2, 4 simulations in one process (threads =
           min(N, cores)): total agent steps/s
  ray      2 Ray workers through bullet_sim.batch (build/learning_venv's Python; skipped
           without it): total agent steps over the wall time of the batch, actor start-up
           included, and the workers' own steps/s
  ros      the Gazebo way measured once: roslaunch turtlebot3_gazebo
           roundTrack_simulation.launch gui:=false (master on BENCH_PORT_BASE, default 11470),
           an agent sending a random action on /cmd_vel each time a /scan arrives, 10 s
  mujoco   gymnasium.make('Ant-v5') on MuJoCo 4.0.0 (build/bench_venv, `scripts/setup.sh
           --bench`): steps/s and steps per CPU second
Ends with the target line: >= 1000 agent steps/s per core (200x Gazebo's 5/s) at 1 ms and at
5 ms physics steps, and the load average (the machine's cores are shared).

Usage: bench/learning.py [--rounds N] [--seconds S] [--ros-seconds S]  (needs `make build`)
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ros_bench  # noqa: E402

ROOT = ros_bench.ROOT
LEARNING_PYTHON = os.path.join(ROOT, "build/learning_venv/bin/python")
BENCH_PYTHON = os.path.join(ROOT, "build/bench_venv/bin/python")
GAZEBO_WAY = 5.0  # agent steps/s at real-time factor 1: one scan per action, scans at 5 Hz
TARGET = 1000.0   # agent steps/s per core


# ---------------------------------------------------------------- the measured parts ----

def timed_loop(env, seconds, vector=False):
    """Random actions for `seconds` of wall time after 20 warm-up steps; (steps, wall, cpu)."""
    env.action_space.seed(0)

    def step():
        _, _, term, trunc, _ = env.step(env.action_space.sample())
        if not vector and (term or trunc):
            env.reset()
    for _ in range(20):
        step()
    n, w0, c0 = 0, time.perf_counter(), time.process_time()
    while True:
        for _ in range(10):
            step()
        n += 10
        wall = time.perf_counter() - w0
        if wall >= seconds:
            return n, wall, time.process_time() - c0


def part_single(physics_step, seconds):
    import gymnasium as gym
    import bullet_sim.envs  # noqa: F401
    env = gym.make("bullet_sim/TurtleBot3Goal-v0", physics_step=physics_step)
    env.reset(seed=0)
    n, wall, cpu = timed_loop(env, seconds)
    # the cost of a reset: the simulation's own (time 0, a new start and goal), and one with
    # a seed, which builds the simulation anew
    plain, seeded = [], []
    for k in range(100):
        t0 = time.perf_counter()
        env.reset()
        plain.append(time.perf_counter() - t0)
    for k in range(20):
        t0 = time.perf_counter()
        env.reset(seed=k)
        seeded.append(time.perf_counter() - t0)
    return {"steps_per_s": n / wall, "steps_per_cpu_s": n / cpu,
            "reset_ms": 1000 * statistics.median(plain),
            "seeded_reset_ms": 1000 * statistics.median(seeded)}


def part_vector(num, seconds):
    from bullet_sim.envs import TurtleBot3GoalVectorEnv
    env = TurtleBot3GoalVectorEnv(num)
    env.reset(seed=list(range(num)))
    n, wall, cpu = timed_loop(env, seconds, vector=True)
    return {"steps_per_s": n * num / wall, "steps_per_cpu_s": n * num / cpu,
            "threads": env.threads}


def part_ray(workers, seconds):
    import ray
    from bullet_sim import batch
    ray.init(runtime_env={"env_vars": batch.worker_env_vars()}, log_to_driver=False,
             include_dashboard=False)
    # warm-up: the workers' imports and the free space of the track, then the timed batch
    # of enough random episodes (about 20 actions each) for `seconds` per worker
    batch.run(range(workers), workers=workers)
    episodes = max(workers, int(seconds * workers * 300 / 20))
    t0 = time.perf_counter()
    results = batch.run(range(1000, 1000 + episodes), workers=workers)
    wall = time.perf_counter() - t0
    ray.shutdown()
    steps = sum(r["length"] for r in results)
    return {"steps_per_s": steps / wall,
            "worker_steps_per_s": statistics.median(r["steps_per_s"] for r in results),
            "nodes": len({r["node_id"] for r in results}), "pids": len({r["pid"] for r in results})}


def part_mujoco(seconds):
    import gymnasium as gym
    import mujoco
    env = gym.make("Ant-v5")
    env.reset(seed=0)
    n, wall, cpu = timed_loop(env, seconds)
    return {"steps_per_s": n / wall, "steps_per_cpu_s": n / cpu, "dt": env.unwrapped.dt,
            "mujoco": mujoco.__version__, "gymnasium": gym.__version__}


def part_ros(seconds):
    """The Gazebo way, measured: the round-track launch at real-time factor 1 (no GUI), an
    agent that sends a random action on /cmd_vel each time a /scan arrives; agent steps/s
    over `seconds` of wall time after the first scan."""
    import random
    import threading
    import rospy
    from geometry_msgs.msg import Twist
    from sensor_msgs.msg import LaserScan
    env = dict(os.environ)
    with ros_bench.Processes() as procs:
        ros_bench.start_master(procs, env, int(env["ROS_MASTER_URI"].rsplit(":", 1)[1]))
        procs.start(["roslaunch", "turtlebot3_gazebo", "roundTrack_simulation.launch",
                     "gui:=false"], env)
        rospy.init_node("bench_learning_agent", anonymous=True, disable_signals=True)
        pub = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
        scans, lock = [], threading.Condition()

        def on_scan(_):
            with lock:
                scans.append(time.perf_counter())
                lock.notify()
        rospy.Subscriber("/scan", LaserScan, on_scan, queue_size=1)
        rng = random.Random(0)
        with lock:
            if not lock.wait_for(lambda: scans, timeout=90):
                raise RuntimeError("no /scan within 90 s of the launch")
        n, seen, t0 = 0, len(scans), time.perf_counter()
        while time.perf_counter() - t0 < seconds:
            with lock:  # an action per scan, as an agent waiting for its observation does
                if not lock.wait_for(lambda: len(scans) > seen, timeout=5):
                    raise RuntimeError("/scan stopped")
                seen = len(scans)
            cmd = Twist()
            cmd.linear.x, cmd.angular.z = 0.15, rng.choice([1.5, 0.75, 0.0, -0.75, -1.5])
            pub.publish(cmd)
            n += 1
        wall = time.perf_counter() - t0
        rospy.signal_shutdown("done")
    return {"steps_per_s": n / wall}


PARTS = {"single": lambda a, s: part_single(float(a), s),
         "vector": lambda a, s: part_vector(int(a), s),
         "ray": lambda a, s: part_ray(int(a), s),
         "mujoco": lambda a, s: part_mujoco(s),
         "ros": lambda a, s: part_ros(s)}


# ---------------------------------------------------------------- the driver ----

def measure(python, env, part, arg, seconds, timeout=300):
    out = subprocess.run([python, os.path.abspath(__file__), "--part", part, str(arg),
                          "--seconds", str(seconds)], env=env, capture_output=True, text=True,
                         timeout=timeout)
    for line in out.stdout.splitlines():
        if line.startswith("RESULT "):
            return json.loads(line[7:])
    raise RuntimeError("%s %s failed:\n%s" % (part, arg, out.stderr[-3000:]))


def med(results, key):
    values = [r[key] for r in results]
    return statistics.median(values), min(values), max(values)


def fmt(values, digits=0):
    m, lo, hi = values
    return "%.*f (%.*f-%.*f)" % (digits, m, digits, lo, digits, hi)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--seconds", type=float, default=3.0, help="timed wall seconds per figure")
    p.add_argument("--ros-seconds", type=float, default=10.0,
                   help="the Gazebo way through ROS, measured once (0: derived only)")
    p.add_argument("--part", nargs=2, help=argparse.SUPPRESS)
    a = p.parse_args()
    if a.part:
        print("RESULT " + json.dumps(PARTS[a.part[0]](a.part[1], a.seconds)), flush=True)
        return

    env = ros_bench.ros_env(int(os.environ.get("BENCH_PORT_BASE", "11470")))
    plain_env = {k: v for k, v in os.environ.items()
                 if k not in ("PYTHONPATH", "LD_LIBRARY_PATH")}  # the bench venv's NumPy
    cores = os.cpu_count() or 1
    have_ray = os.access(LEARNING_PYTHON, os.X_OK)
    have_mujoco = subprocess.run([BENCH_PYTHON, "-c", "import gymnasium, mujoco"], env=plain_env,
                                 capture_output=True).returncode == 0 \
        if os.access(BENCH_PYTHON, os.X_OK) else False
    runs = [("single_1ms", sys.executable, env, "single", 0.001),
            ("single_5ms", sys.executable, env, "single", 0.005)]
    runs += [("vector_%d" % n, sys.executable, env, "vector", n) for n in (1, 2, 4)]
    if have_ray:
        runs.append(("ray_2", LEARNING_PYTHON, env, "ray", 2))
    if have_mujoco:
        runs.append(("mujoco", BENCH_PYTHON, plain_env, "mujoco", 0))
    results = {name: [] for name, *_ in runs}
    load_before = ros_bench.load_average()
    ros = None
    if a.ros_seconds > 0:
        ros = measure(sys.executable, env, "ros", 0, a.ros_seconds)["steps_per_s"]
        print("ros %.3f" % ros, flush=True)
    for r in range(a.rounds):
        order = runs if r % 2 == 0 else list(reversed(runs))
        for name, python, penv, part, arg in order:
            results[name].append(measure(python, penv, part, arg, a.seconds))
            print("round %d %s %s" % (r + 1, name, json.dumps(results[name][-1])), flush=True)
    load_after = ros_bench.load_average()

    s1, s5 = med(results["single_1ms"], "steps_per_s"), med(results["single_5ms"], "steps_per_s")
    c1 = med(results["single_1ms"], "steps_per_cpu_s")
    c5 = med(results["single_5ms"], "steps_per_cpu_s")
    print()
    print("## TurtleBot3 goal environment: agent steps per second (24-ray scan, 0.2 s control "
          "period), medians of %d rounds (range)" % a.rounds)
    print()
    print("| figure | steps/s | steps per CPU s |")
    print("|---|---|---|")
    print("| one env, one thread, physics 1 ms (200 steps per action) | %s | %s |"
          % (fmt(s1), fmt(c1)))
    print("| one env, one thread, physics 5 ms (40 steps per action) | %s | %s |"
          % (fmt(s5), fmt(c5)))
    print("| reset (the simulation's own, a new start and goal) / with a seed (the simulation "
          "built anew), physics 1 ms | %s ms / %s ms | |"
          % (fmt(med(results["single_1ms"], "reset_ms"), 2),
             fmt(med(results["single_1ms"], "seeded_reset_ms"), 2)))
    for n in (1, 2, 4):
        v = results["vector_%d" % n]
        print("| vector env, %d simulations, %d threads, physics 1 ms | %s | %s |"
              % (n, v[0]["threads"], fmt(med(v, "steps_per_s")), fmt(med(v, "steps_per_cpu_s"))))
    if have_ray:
        v = results["ray_2"]
        print("| 2 Ray workers (bullet_sim.batch), physics 1 ms, start-up included | %s | "
              "workers' own: %s steps/s each |"
              % (fmt(med(v, "steps_per_s")), fmt(med(v, "worker_steps_per_s"))))
    else:
        print("| 2 Ray workers | skipped: make learning | |")
    print("| the Gazebo way: ROS at real-time factor 1, an action per 5 Hz scan (derived) "
          "| %.0f | |" % GAZEBO_WAY)
    if ros is not None:
        print("| the same measured: roundTrack_simulation.launch gui:=false, an agent sending "
              "/cmd_vel on each /scan, %.0f s | %.2f | |" % (a.ros_seconds, ros))
    if have_mujoco:
        v = results["mujoco"]
        print("| MuJoCo %s, gymnasium %s Ant-v5 (%.2f s per step, 5 physics steps, no lidar) "
              "| %s | %s |" % (v[0]["mujoco"], v[0]["gymnasium"], v[0]["dt"],
                              fmt(med(v, "steps_per_s")), fmt(med(v, "steps_per_cpu_s"))))
    else:
        print("| MuJoCo Ant-v5 | skipped: scripts/setup.sh --bench | |")
    print()
    print("ours / Gazebo way: 1 ms %.0fx, 5 ms %.0fx" % (s1[0] / GAZEBO_WAY, s5[0] / GAZEBO_WAY))
    if have_mujoco:
        m = med(results["mujoco"], "steps_per_s")[0]
        mc = med(results["mujoco"], "steps_per_cpu_s")[0]
        print("ours / MuJoCo Ant-v5: steps/s 1 ms %.2f, 5 ms %.2f; per CPU s 1 ms %.2f, "
              "5 ms %.2f" % (s1[0] / m, s5[0] / m, c1[0] / mc, c5[0] / mc))
    print("target >= %.0f agent steps/s per core (per CPU second): 1 ms %s (%.0f), "
          "5 ms %s (%.0f)" % (TARGET, "met" if c1[0] >= TARGET else "not met", c1[0],
                              "met" if c5[0] >= TARGET else "not met", c5[0]))
    print("cores=%d loadavg before %s, after %s" % (cores, load_before, load_after))


if __name__ == "__main__":
    main()
