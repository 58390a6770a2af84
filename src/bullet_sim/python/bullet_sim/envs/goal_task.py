"""TurtleBot3 goal reaching as ROBOTIS's DQN stages (turtlebot3_machine_learning, ROS 1)
define it: the observation, the actions, the rewards of stage 1 and the goal rules.

Pure functions of the readings: the environments (turtlebot3.py) feed them from the
simulation.
"""

from __future__ import annotations

import math
from typing import Optional, Sequence, Tuple

import numpy as np

LINEAR_SPEED = 0.15        #: m/s, every action
MAX_ANGULAR_SPEED = 1.5    #: rad/s, the outermost discrete actions
ACTIONS = 5                #: discrete actions
COLLISION_RANGE = 0.13     #: m: a reading below it (and above 0) is a collision
GOAL_RADIUS = 0.2          #: m: closer to the goal than this reaches it
SCAN_SAMPLES = 24          #: rays of the lidar, as the DQN's robot description sets them
SCAN_MAX = 3.5             #: m: what a ray that hits nothing reads
COLLISION_REWARD = -200.0
GOAL_REWARD = 200.0


def angular_speed(action: int, actions: int = ACTIONS,
                  max_angular: float = MAX_ANGULAR_SPEED) -> float:
    """The discrete action's yaw rate: ((actions - 1) / 2 - action) * max_angular / 2, so
    action 0 turns left fastest (1.5 rad/s), action 2 goes straight, action 4 turns right."""
    if not 0 <= action < actions:
        raise ValueError(f'action {action} is not one of 0..{actions - 1}')
    return ((actions - 1) / 2 - action) * max_angular * 0.5


def heading_to(goal: Sequence[float], x: float, y: float, yaw: float) -> float:
    """The goal's bearing from the robot's heading (rad, left positive), in [-pi, pi]."""
    h = math.atan2(goal[1] - y, goal[0] - x) - yaw
    if h > math.pi:
        h -= 2 * math.pi
    elif h < -math.pi:
        h += 2 * math.pi
    return h


def scan_state(ranges: np.ndarray, range_max: float = SCAN_MAX) -> np.ndarray:
    """The scan as the state holds it: a ray that hit nothing (+inf) reads range_max, NaN
    reads 0."""
    r = np.array(ranges, dtype=np.float64)
    r[np.isinf(r)] = range_max
    r[np.isnan(r)] = 0.0
    return r


def collided(state_ranges: np.ndarray, collision_range: float = COLLISION_RANGE) -> bool:
    """A reading closer than the collision range (and above 0, which a NaN became)."""
    m = float(np.min(state_ranges)) if len(state_ranges) else math.inf
    return 0 < m < collision_range


def yaw_reward(heading: float, angle_offset: float) -> float:
    """ROBOTIS's triangle wave of the heading: 1 when the turn's direction (heading +
    angle_offset) points at the goal, -1 when it points away, linear between. For discrete
    action i of 5 the offset is -pi/4 + i pi/8."""
    angle = angle_offset + heading + math.pi / 2
    return 1 - 4 * math.fabs(0.5 - math.modf(0.25 + 0.5 * angle % (2 * math.pi) / math.pi)[0])


def discrete_offset(action: int, actions: int = ACTIONS) -> float:
    return -math.pi / 4 + math.pi / 8 * action * (4 / (actions - 1))


def continuous_offset(angular: float, max_angular: float = MAX_ANGULAR_SPEED) -> float:
    """The continuous action's offset, the discrete one's line through its 5 points:
    +1.5 rad/s (action 0) -> -pi/4, 0 -> 0, -1.5 rad/s (action 4) -> +pi/4."""
    return -math.pi / 4 * angular / max_angular


def step_reward(heading: float, distance: float, start_distance: float,
                angle_offset: float) -> float:
    """Stage 1's reward of a step that neither collides nor reaches the goal:
    round(5 yaw_reward, 2) * 2 ** (distance / start_distance)."""
    rate = 2 ** (distance / start_distance) if start_distance > 0 else 1.0
    return round(yaw_reward(heading, angle_offset) * 5, 2) * rate


# ROBOTIS's goal positions (respawnGoal.py): stages 1-3 draw x and y in -1.2..1.2 by 0.1,
# away from the obstacles of stage 2 and 3 and from the centre, and at least 1 m from the
# last goal in x or y; stage 4 picks from a list.
_STAGE_OBSTACLES = ((0.6, 0.6), (0.6, -0.6), (-0.6, 0.6), (-0.6, -0.6), (0.0, 0.0))
_STAGE4_GOALS = ((0.6, 0), (1.9, -0.5), (0.5, -1.9), (0.2, 1.5), (-0.8, -0.9), (-1, 1),
                 (-1.9, 1.1), (0.5, -1.5), (2, 1.5), (0.5, 1.8), (0, -1), (-0.1, 1.6),
                 (-2, -0.8))
STAGE_FIRST_GOAL = (0.6, 0.0)


def stage_goal(rng: np.random.Generator, stage: int,
               last: Optional[Tuple[float, float]]) -> Tuple[float, float]:
    """A goal drawn by ROBOTIS's rules for stage 1-4 with `rng`, `last` the previous goal."""
    if stage == 4:
        while True:
            g = _STAGE4_GOALS[int(rng.integers(0, len(_STAGE4_GOALS)))]
            if last is None or (abs(g[0] - last[0]) > 1e-9 or abs(g[1] - last[1]) > 1e-9):
                return float(g[0]), float(g[1])
    while True:
        x = int(rng.integers(-12, 13)) / 10.0
        y = int(rng.integers(-12, 13)) / 10.0
        if any(abs(x - ox) <= 0.4 and abs(y - oy) <= 0.4 for ox, oy in _STAGE_OBSTACLES):
            continue
        if last is not None and abs(x - last[0]) < 1 and abs(y - last[1]) < 1:
            continue
        return x, y
