"""Gymnasium environments on bullet_sim (needs the `gymnasium` package).

    import gymnasium as gym
    import bullet_sim.envs  # registers them
    env = gym.make('bullet_sim/TurtleBot3Goal-v0')             # 5 discrete actions
    env = gym.make('bullet_sim/TurtleBot3GoalContinuous-v0')   # one yaw rate
    env = gym.make('bullet_sim/TurtleBot3Goal-v0', world='stage_1')
    envs = bullet_sim.envs.TurtleBot3GoalVectorEnv(8)           # 8 in one process

See turtlebot3.py for the task (ROBOTIS's DQN stage 1) and vector.py for N at once.
"""

import gymnasium as gym

from bullet_sim.envs.turtlebot3 import TurtleBot3GoalEnv  # noqa: F401
from bullet_sim.envs.vector import TurtleBot3GoalVectorEnv  # noqa: F401

MAX_EPISODE_STEPS = 500  #: ROBOTIS's limit: an episode ends after 500 actions

for _id, _kwargs in (('bullet_sim/TurtleBot3Goal-v0', {}),
                     ('bullet_sim/TurtleBot3GoalContinuous-v0', {'continuous': True})):
    if _id not in gym.registry:
        gym.register(_id, entry_point='bullet_sim.envs.turtlebot3:TurtleBot3GoalEnv',
                     max_episode_steps=MAX_EPISODE_STEPS, kwargs=_kwargs)

__all__ = ['TurtleBot3GoalEnv', 'TurtleBot3GoalVectorEnv', 'MAX_EPISODE_STEPS']
