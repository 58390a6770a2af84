"""Fixtures of the bullet_sim Python module tests: the round-track world and the Burger
(expanded from its xacro with the workspace's xacro, as the core's gtests do)."""
import os
import subprocess
import sys

import pytest

PACKAGE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WORKSPACE = os.path.dirname(os.path.dirname(PACKAGE))
FIXTURES = os.path.join(PACKAGE, 'test', 'fixtures')
ROUND_TRACK = os.path.join(WORKSPACE, 'src', 'turtlebot3_gazebo', 'worlds', 'roundTrack.world')
BURGER_XACRO = os.path.join(WORKSPACE, 'turtlebot3_description', 'urdf',
                            'turtlebot3_burger.urdf.xacro')
SPAWN_YAW = 1.5675  # DESIGN.md: the robot spawns at x 0, y 0, yaw 1.5675


@pytest.fixture(scope='session')
def burger_urdf():
    env = dict(os.environ, ROS_PACKAGE_PATH=WORKSPACE)
    out = subprocess.run([sys.executable, os.path.join(WORKSPACE, 'src', 'xacro', 'xacro'),
                          BURGER_XACRO], env=env, check=True, capture_output=True, text=True)
    assert '<robot' in out.stdout
    return out.stdout


@pytest.fixture(scope='session')
def burger(burger_urdf):
    import bullet_sim
    return bullet_sim.Robot.from_urdf(burger_urdf)


@pytest.fixture(scope='session')
def round_track():
    import bullet_sim
    return bullet_sim.World.from_file(ROUND_TRACK)


@pytest.fixture
def make_sim(round_track, burger):
    """A Simulation of the round track with the Burger at the spawn pose."""
    import bullet_sim

    def make(seed=1, threads=0):
        sim = bullet_sim.Simulation(round_track, physics_step=0.001, seed=seed, threads=threads)
        sim.spawn('burger', burger, (0.0, 0.0, 0.0, SPAWN_YAW))
        return sim
    return make
