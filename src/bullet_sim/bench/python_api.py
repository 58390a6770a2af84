#!/usr/bin/python3
"""The engine's rate through the Python module: one Burger on the round track, driving a
circle, its lidar cut to 24 rays and read every 0.2 s of sim (200 physics steps of 1 ms).

    source devel/setup.bash
    python3 src/bullet_sim/bench/python_api.py [--seconds 60] [--threads 1] [--parallel 2]

Prints physics steps per second of wall time (the real-time factor, and steps per second
of the process's CPU time, which other load on the machine changes less) three ways: 200
steps per call (step(200)), one step per call (step() 200 times: the cost of a call), and
with --parallel N, N simulations stepped by N Python threads at once (the GIL is released
while stepping), their steps summed.
"""
import argparse
import os
import re
import subprocess
import sys
import threading
import time

import bullet_sim

HERE = os.path.dirname(os.path.abspath(__file__))
WORKSPACE = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
STEPS_PER_READ = 200  # 0.2 s of 1 ms steps: the LDS's 5 Hz


def burger_urdf(rays):
    """The workspace's Burger (xacro output) with `rays` lidar samples instead of 360."""
    xacro = os.path.join(WORKSPACE, 'src', 'xacro', 'xacro')
    path = os.path.join(WORKSPACE, 'turtlebot3_description', 'urdf',
                        'turtlebot3_burger.urdf.xacro')
    env = dict(os.environ, ROS_PACKAGE_PATH=WORKSPACE)
    text = subprocess.run([sys.executable, xacro, path], env=env, check=True,
                          capture_output=True, text=True).stdout
    text, n = re.subn(r'<samples>\s*360\s*</samples>', '<samples>%d</samples>' % rays, text)
    if n != 1:
        sys.exit('the Burger URDF has no <samples>360</samples> to change')
    return text


def make_sim(world, robot, threads, seed=1):
    sim = bullet_sim.Simulation(world, physics_step=0.001, seed=seed, threads=threads)
    sim.spawn('burger', robot, (0.0, 0.0, 0.0, 1.5675))
    sim.set_cmd_vel('burger', 0.1, 0.3)
    return sim


def run(sim, reads, per_call):
    """Steps `reads` x 200 steps, reading the scan after each 200; returns the checksum of
    the ranges (so that nothing is optimised away) and the number of rays."""
    total, rays = 0.0, 0
    for _ in range(reads):
        if per_call == STEPS_PER_READ:
            sim.step(STEPS_PER_READ)
        else:
            for _ in range(STEPS_PER_READ):
                sim.step()
        ranges = sim.read_scan('burger').ranges
        rays = len(ranges)
        total += float(ranges[ranges < 10].sum())
    return total, rays


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--seconds', type=float, default=60.0, help='sim seconds per run')
    parser.add_argument('--threads', type=int, default=1,
                        help='physics threads of each Simulation (0 = the machine\'s)')
    parser.add_argument('--parallel', type=int, default=0,
                        help='also run this many simulations on as many Python threads')
    parser.add_argument('--rays', type=int, default=24)
    args = parser.parse_args()

    world = bullet_sim.World.from_file(
        os.path.join(WORKSPACE, 'src', 'turtlebot3_gazebo', 'worlds', 'roundTrack.world'))
    robot = bullet_sim.Robot.from_urdf(burger_urdf(args.rays))
    reads = max(1, int(round(args.seconds / (STEPS_PER_READ * 0.001))))
    steps = reads * STEPS_PER_READ

    run(make_sim(world, robot, args.threads), 25, STEPS_PER_READ)  # warm-up: 5 s of sim
    for per_call, label in ((STEPS_PER_READ, 'step(200)'), (1, 'step() x 200')):
        sim = make_sim(world, robot, args.threads)
        start, start_cpu = time.perf_counter(), time.process_time()
        _, rays = run(sim, reads, per_call)
        wall = time.perf_counter() - start
        cpu = time.process_time() - start_cpu
        pose = sim.model_pose('burger')
        print('%-13s %d steps, %d scans of %d rays: %.0f steps/s, real-time factor %.1f; '
              '%.0f steps per CPU second (robot at x %.2f y %.2f)'
              % (label, steps, reads, rays, steps / wall, steps * 0.001 / wall, steps / cpu,
                 pose.x, pose.y))

    if args.parallel > 0:
        sims = [make_sim(world, robot, args.threads, seed=i + 1) for i in range(args.parallel)]
        workers = [threading.Thread(target=run, args=(s, reads, STEPS_PER_READ)) for s in sims]
        start, start_cpu = time.perf_counter(), time.process_time()
        for w in workers:
            w.start()
        for w in workers:
            w.join()
        wall = time.perf_counter() - start
        cpu = time.process_time() - start_cpu
        print('%d threads     %d steps each: %.0f steps/s together (%.0f per simulation), '
              '%.2f cores busy' % (args.parallel, steps, args.parallel * steps / wall,
                                   steps / wall, cpu / wall))


if __name__ == '__main__':
    main()
