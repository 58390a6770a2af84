"""The TurtleBot3 Burger goal-reaching environments (Gymnasium).

ROBOTIS's DQN task (goal_task.py) on a bullet_sim world: the round track of the Mobility
training by default, ROBOTIS's stage worlds of turtlebot3_simulations when a clone is on
ROS_PACKAGE_PATH, or any SDF world file. No ROS runs: the simulation is bullet_sim's core,
stepped 0.2 s (the lidar's period) per action.
"""

from __future__ import annotations

import math
import os
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET
from typing import Any, Dict, List, Optional, Sequence, Tuple

import gymnasium as gym
import numpy as np
from gymnasium import spaces

import bullet_sim
from bullet_sim.envs import goal_task as task
from bullet_sim.envs.free_space import FreeSpace

ROBOT = 'turtlebot3_burger'
#: The Burger's reach from base_footprint (m): the back corners of its base's collision box,
#: (-0.102, +-0.07) m, are 0.124 m away.
ROBOT_RADIUS = 0.124
#: Bound of the goal distance observed in ROBOTIS's stage worlds (m): their arenas are
#: at most 5 m across.
STAGE_MAX_DISTANCE = 10.0

# Worlds by short name: (package, path in it, how goals are drawn, the robot's spawn).
_WORLDS = {
    'roundTrack': ('turtlebot3_gazebo', 'worlds/roundTrack.world', 'free', (0.0, 0.0, 1.5675)),
    'stage_1': ('turtlebot3_gazebo', 'worlds/turtlebot3_stage_1.world', 1, (0.0, 0.0, 0.0)),
    'stage_2': ('turtlebot3_gazebo', 'worlds/turtlebot3_stage_2.world', 2, (0.0, 0.0, 0.0)),
    'stage_3': ('turtlebot3_gazebo', 'worlds/turtlebot3_stage_3.world', 3, (0.0, 0.0, 0.0)),
    'stage_4': ('turtlebot3_gazebo', 'worlds/turtlebot3_stage_4.world', 4, (-0.7, 0.0, 0.0)),
}


def find_packages(name: str) -> List[str]:
    """The folders of ROS package `name` on ROS_PACKAGE_PATH, in its order (rospack takes
    the first; an overlay's clone and this workspace may both have one of a name)."""
    found = []
    for root in os.environ.get('ROS_PACKAGE_PATH', '').split(os.pathsep):
        if not root or not os.path.isdir(root):
            continue
        for dirpath, dirnames, filenames in os.walk(root):
            if 'CATKIN_IGNORE' in filenames:
                dirnames[:] = []
                continue
            if 'package.xml' in filenames:
                dirnames[:] = []
                try:
                    if ET.parse(os.path.join(dirpath, 'package.xml')).findtext('name') == name:
                        found.append(dirpath)
                except ET.ParseError:
                    pass
                continue
            dirnames[:] = [d for d in dirnames if not d.startswith('.')]
    return found


def find_package(name: str) -> Optional[str]:
    """The folder of ROS package `name` as rospack finds it (the first on ROS_PACKAGE_PATH),
    None when it is not there."""
    found = find_packages(name)
    return found[0] if found else None


def _model_paths(packages: List[str]) -> List[str]:
    """GAZEBO_MODEL_PATH, then the `models` folders the packages export to gazebo_ros
    (<gazebo_ros gazebo_model_path="${prefix}/models"/>), as gazebo_ros adds them."""
    paths = [p for p in os.environ.get('GAZEBO_MODEL_PATH', '').split(os.pathsep) if p]
    for pkg in packages:
        try:
            exports = ET.parse(os.path.join(pkg, 'package.xml')).findall('export/gazebo_ros')
        except ET.ParseError:
            continue
        for export in exports:
            if export.get('gazebo_model_path'):
                paths.append(export.get('gazebo_model_path').replace('${prefix}', pkg))
    return paths


def world_file(world: str) -> Tuple[str, Any, Tuple[float, float, float]]:
    """(path, goal rule, spawn x y yaw) of a world given by short name or path."""
    if world in _WORLDS:
        package, rel, rule, spawn = _WORLDS[world]
        for root in find_packages(package):
            path = os.path.join(root, rel)
            if os.path.isfile(path):
                return path, rule, spawn
        # our turtlebot3_gazebo has the round track; ROBOTIS's has the stages
        raise FileNotFoundError(
            f"world '{world}': no {rel} in a package '{package}' on ROS_PACKAGE_PATH "
            '(source devel/setup.bash; the stage worlds need a clone of ROBOTIS\'s '
            'turtlebot3_simulations on it)')
    if not os.path.isfile(world):
        raise FileNotFoundError(f"world '{world}': neither a known name "
                                f'({", ".join(_WORLDS)}) nor a file')
    return world, 'free', (0.0, 0.0, 0.0)


_URDF_CACHE: Dict[Tuple[str, int], str] = {}
_FREE_SPACE_CACHE: Dict[Tuple[str, float, float], FreeSpace] = {}


def burger_urdf(scan_samples: int = task.SCAN_SAMPLES) -> str:
    """The Burger's URDF from turtlebot3_description's xacro, its lidar set to
    `scan_samples` rays over 0..2 pi as ROBOTIS's machine-learning description does."""
    key = ('burger', scan_samples)
    if key in _URDF_CACHE:
        return _URDF_CACHE[key]
    pkg = find_package('turtlebot3_description')
    if pkg is None:
        raise FileNotFoundError('turtlebot3_description is not on ROS_PACKAGE_PATH '
                                '(source devel/setup.bash)')
    xacro = shutil.which('xacro')
    if xacro is None:
        raise FileNotFoundError('no xacro command on PATH (source devel/setup.bash)')
    path = os.path.join(pkg, 'urdf', 'turtlebot3_burger.urdf.xacro')
    out = subprocess.run([xacro, path], check=True, capture_output=True, text=True).stdout
    root = ET.fromstring(out)
    lidar = None
    for sensor in root.iter('sensor'):
        if sensor.get('type') == 'ray':
            lidar = sensor
    if lidar is None:
        raise ValueError(f'{path}: the Burger has no ray sensor')
    samples = lidar.find('ray/scan/horizontal/samples')
    samples.text = str(int(scan_samples))
    urdf = ET.tostring(root, encoding='unicode')
    _URDF_CACHE[key] = urdf
    return urdf


class TurtleBot3GoalEnv(gym.Env):
    """Drive a TurtleBot3 Burger to a goal: ROBOTIS's DQN task (stage 1's rewards).

    Observation (float32): the lidar's `scan_samples` ranges (a ray that hits nothing reads
    3.5 m), the goal's bearing from the heading (rad, left positive) and its distance (m).
    Actions: 5 yaw rates (1.5, 0.75, 0, -0.75, -1.5 rad/s) at 0.15 m/s, or with
    `continuous` one number in [-1, 1] for a yaw rate of 1.5 times it (rad/s); each held
    for `control_period` s of sim time (the lidar's period, 0.2 s: 200 physics steps of
    `physics_step`, 1 ms as in the TurtleBot3 worlds; 5 ms runs 4x faster and drifts by a
    few cm over 60 actions from the 1 ms path).
    Rewards: +200 on reaching the goal (closer than 0.2 m), -200 on a collision (a reading
    below 0.13 m, or a body 1 cm into an obstacle), else ROBOTIS's stage-1 shaping.
    The episode ends at the goal (`goals_per_episode` > 1: a new goal is drawn, as ROBOTIS's
    loop does, until that many are reached) or on a collision; it is truncated after
    `max_episode_steps` actions (500, ROBOTIS's limit) by the TimeLimit of gymnasium.make.

    world: 'roundTrack', 'stage_1' .. 'stage_4' or a world file. Start and goal: on the
    round track and other worlds, the robot starts at a random free place and heading and
    the goal is a free place `goal_distance` away in sight; on the stage worlds the robot
    starts at ROBOTIS's spawn and goals follow ROBOTIS's rules: (0.6, 0) first, kept across
    episodes until reached, then drawn away from the obstacles and the last goal.
    """

    metadata = {'render_modes': ['rgb_array'], 'render_fps': 5}

    def __init__(self, world: str = 'roundTrack', *, continuous: bool = False,
                 goal_distance: Tuple[float, float] = (0.5, 2.0),
                 goals_per_episode: int = 1, control_period: float = 0.2,
                 physics_step: float = 0.001, scan_samples: int = task.SCAN_SAMPLES,
                 render_mode: Optional[str] = None):
        if render_mode is not None and render_mode not in self.metadata['render_modes']:
            raise ValueError(f'render_mode {render_mode!r}: not one of '
                             f'{self.metadata["render_modes"]}')
        steps = control_period / physics_step
        if not (physics_step > 0 and steps >= 1 and abs(steps - round(steps)) < 1e-9):
            raise ValueError(f'control_period {control_period} s is not a whole number of '
                             f'physics steps of {physics_step} s')
        if not 0 < goal_distance[0] <= goal_distance[1]:
            raise ValueError(f'goal_distance {goal_distance}: needs 0 < min <= max')
        if goals_per_episode < 1:
            raise ValueError(f'goals_per_episode {goals_per_episode}: needs >= 1')
        self.render_mode = render_mode
        self.continuous = bool(continuous)
        self.goal_distance = (float(goal_distance[0]), float(goal_distance[1]))
        self.goals_per_episode = int(goals_per_episode)
        self.physics_step = float(physics_step)
        self.steps_per_action = int(round(steps))
        self.world_path, self._goal_rule, self._spawn = world_file(world)
        self._world = bullet_sim.World.from_file(
            self.world_path, model_paths=_model_paths(find_packages('turtlebot3_gazebo')))
        self._robot = bullet_sim.Robot.from_urdf(burger_urdf(scan_samples), 'turtlebot3_burger')
        self.scan_samples = int(scan_samples)

        self._sim: Optional[bullet_sim.Simulation] = None
        self._free: Optional[FreeSpace] = None
        if self._goal_rule == 'free':
            # the free space, found once per world in a simulation of the world alone
            x, y, _ = self._spawn
            key = (os.path.realpath(self.world_path), x, y)
            if key not in _FREE_SPACE_CACHE:
                probe = bullet_sim.Simulation(self._world, physics_step=self.physics_step,
                                              seed=0, threads=1)
                _FREE_SPACE_CACHE[key] = FreeSpace(probe, (x, y), clearance=ROBOT_RADIUS + 0.1)
            self._free = _FREE_SPACE_CACHE[key]
            if self._free.open:
                raise ValueError(f'{self.world_path}: the spawn ({x}, {y}) is not enclosed '
                                 'within 10 m: goals need a bounded world')
            lo, hi = self._free.cells.min(axis=0), self._free.cells.max(axis=0)
            self.max_distance = float(np.hypot(*(hi - lo))) + 2 * self._free.clearance
        else:
            self.max_distance = STAGE_MAX_DISTANCE
        self.observation_space = spaces.Box(
            low=np.array([0.0] * self.scan_samples + [-math.pi, 0.0], dtype=np.float32),
            high=np.array([task.SCAN_MAX] * self.scan_samples + [math.pi, self.max_distance],
                          dtype=np.float32),
            dtype=np.float32)
        if self.continuous:
            # normalised: -1..1 is -1.5..1.5 rad/s
            self.action_space = spaces.Box(-1.0, 1.0, shape=(1,), dtype=np.float32)
        else:
            self.action_space = spaces.Discrete(task.ACTIONS)

        self._goal: Tuple[float, float] = task.STAGE_FIRST_GOAL
        self._start_distance = 1.0
        self._goals_reached = 0
        self._episodes = 0

    # -- the simulation --------------------------------------------------------------

    def _build(self, seed: int) -> None:
        """A new simulation whose sensor noise is seeded from `seed`."""
        sim = bullet_sim.Simulation(self._world, physics_step=self.physics_step,
                                    seed=int(seed), threads=1)
        x, y, yaw = self._spawn
        sim.spawn(ROBOT, self._robot, pose=(x, y, 0.0, yaw))
        self._sim = sim

    @property
    def simulation(self) -> bullet_sim.Simulation:
        """The bullet_sim.Simulation the robot runs in (after the first reset)."""
        if self._sim is None:
            raise RuntimeError('call reset() first')
        return self._sim

    @property
    def goal(self) -> Tuple[float, float]:
        return self._goal

    def _observe(self) -> Tuple[np.ndarray, Dict[str, Any]]:
        scan = self._sim.read_scan(ROBOT)
        ranges = task.scan_state(scan.ranges, task.SCAN_MAX)
        pose = self._sim.model_pose(ROBOT)
        heading = task.heading_to(self._goal, pose.x, pose.y, pose.yaw)
        distance = math.hypot(self._goal[0] - pose.x, self._goal[1] - pose.y)
        obs = np.concatenate([ranges, [heading, distance]]).astype(np.float32)
        info = {'goal': self._goal, 'distance': distance, 'heading': heading,
                'pose': (pose.x, pose.y, pose.yaw), 'sim_time': self._sim.time}
        return obs, info

    def _new_goal(self, x: float, y: float) -> Tuple[float, float]:
        if self._goal_rule == 'free':
            goal = self._free.sample_goal(self._sim, self.np_random, (x, y), self.goal_distance,
                                          half_width=ROBOT_RADIUS, ignored_robot=ROBOT)
            if goal is None:
                raise RuntimeError(f'{self.world_path}: no goal {self.goal_distance} m from '
                                   f'({x:.2f}, {y:.2f}) in sight')
            return goal
        return task.stage_goal(self.np_random, int(self._goal_rule), self._goal)

    # -- gymnasium.Env ---------------------------------------------------------------

    def reset(self, *, seed: Optional[int] = None,
              options: Optional[Dict[str, Any]] = None):
        """A new episode. With `seed`: the simulation is built anew, its sensor noise and
        the start and goal draws seeded from it, so that the same seed and actions give the
        same episode to the bit. Without: the simulation is reset (time 0) and draws go on.
        options: 'start' (x, y, yaw) and 'goal' (x, y) put them where given."""
        super().reset(seed=seed)
        options = options or {}
        if seed is not None or self._sim is None:
            self._build(int(self.np_random.integers(0, 2 ** 63)))
        else:
            self._sim.reset()
        if 'start' in options:
            x, y, yaw = (float(v) for v in options['start'])
        elif self._goal_rule == 'free':
            x, y = self._free.cells[int(self.np_random.integers(0, len(self._free.cells)))]
            yaw = float(self.np_random.uniform(-math.pi, math.pi))
        else:
            x, y, yaw = self._spawn
        self._sim.set_model_state(ROBOT, (float(x), float(y), 0.0, float(yaw)))
        if 'goal' in options:
            self._goal = (float(options['goal'][0]), float(options['goal'][1]))
        elif self._goal_rule == 'free':
            self._goal = self._new_goal(float(x), float(y))
        elif seed is not None or not self._episodes:
            # ROBOTIS's first goal of a run; then it stays until reached
            self._goal = task.STAGE_FIRST_GOAL
        elif self._goals_reached:
            self._goal = self._new_goal(float(x), float(y))
        self._episodes += 1
        self._sim.set_cmd_vel(ROBOT, 0.0, 0.0)
        self._goals_reached = 0
        obs, info = self._observe()
        self._start_distance = info['distance']
        info['is_success'] = False
        return obs, info

    def step(self, action):
        if self._sim is None:
            raise RuntimeError('call reset() before step()')
        if self.continuous:
            a = np.asarray(action, dtype=np.float64).reshape(-1)
            if a.shape != (1,) or not np.isfinite(a[0]):
                raise ValueError(f'action {action!r}: one finite yaw rate expected')
            angular = float(np.clip(a[0], -1.0, 1.0)) * task.MAX_ANGULAR_SPEED
            offset = task.continuous_offset(angular)
        else:
            angular = task.angular_speed(int(action))
            offset = task.discrete_offset(int(action))
        self._sim.set_cmd_vel(ROBOT, task.LINEAR_SPEED, angular)
        self._sim.step(self.steps_per_action)
        obs, info = self._observe()
        ranges = obs[:self.scan_samples]
        condition = self._sim.condition(ROBOT)
        collision = task.collided(ranges) or condition.in_wall or condition.tipped_over
        reached = info['distance'] < task.GOAL_RADIUS
        terminated = False
        if collision:
            reward = task.COLLISION_REWARD
            terminated = True
        elif reached:
            reward = task.GOAL_REWARD
            self._goals_reached += 1
            if self._goals_reached >= self.goals_per_episode:
                terminated = True
            else:
                pose = info['pose']
                self._goal = self._new_goal(pose[0], pose[1])
                obs, info = self._observe()
                self._start_distance = info['distance']
        else:
            reward = task.step_reward(info['heading'], info['distance'],
                                      self._start_distance, offset)
        if terminated:
            self._sim.set_cmd_vel(ROBOT, 0.0, 0.0)
        info['collision'] = bool(collision)
        info['is_success'] = bool(reached and not collision)
        info['goals_reached'] = self._goals_reached
        return obs, float(reward), terminated, False, info

    def render(self):
        if self.render_mode == 'rgb_array':
            return self.simulation.read_camera(ROBOT)
        return None
