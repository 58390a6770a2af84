"""N goal-reaching environments stepped together on threads, one simulation each.

Each environment is a TurtleBot3GoalEnv with a simulation of its own (robots in separate
worlds cannot touch). bullet_sim releases the GIL while it steps, so the N simulations step
in parallel on up to `threads` threads. The results are those of N single environments
given the same seeds and actions, to the bit, whatever the number of threads.
"""

from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Dict, List, Optional, Sequence, Union

import numpy as np
from gymnasium.vector import VectorEnv
from gymnasium.vector.utils import batch_space

try:  # gymnasium >= 1.1
    from gymnasium.vector import AutoresetMode
    _NEXT_STEP = AutoresetMode.NEXT_STEP
except ImportError:  # pragma: no cover
    _NEXT_STEP = 'NextStep'

from bullet_sim.envs.turtlebot3 import TurtleBot3GoalEnv


class TurtleBot3GoalVectorEnv(VectorEnv):
    """`num_envs` TurtleBot3GoalEnv(**kwargs), autoreset on the step after an episode ends
    (Gymnasium's NEXT_STEP mode: that step's action is ignored and the new episode's first
    observation is returned with reward 0). Infos are Gymnasium's vector infos (a key's
    values in an array, with a '_key' mask)."""

    def __init__(self, num_envs: int, *, threads: Optional[int] = None,
                 max_episode_steps: Optional[int] = 500, **kwargs):
        if num_envs < 1:
            raise ValueError(f'num_envs {num_envs}: needs >= 1')
        self.envs = [TurtleBot3GoalEnv(**kwargs) for _ in range(num_envs)]
        self.num_envs = num_envs
        self.max_episode_steps = max_episode_steps
        self.metadata = dict(TurtleBot3GoalEnv.metadata)
        self.metadata['autoreset_mode'] = _NEXT_STEP
        self.render_mode = self.envs[0].render_mode
        self.single_observation_space = self.envs[0].observation_space
        self.single_action_space = self.envs[0].action_space
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        self.action_space = batch_space(self.single_action_space, num_envs)
        self.threads = max(1, min(num_envs, threads or os.cpu_count() or 1))
        self._pool = ThreadPoolExecutor(self.threads) if self.threads > 1 else None
        self._elapsed = np.zeros(num_envs, dtype=np.int64)
        self._needs_reset = np.zeros(num_envs, dtype=bool)

    def _map(self, fn, items: Sequence[Any]) -> List[Any]:
        if self._pool is None:
            return [fn(i, x) for i, x in enumerate(items)]
        return list(self._pool.map(fn, range(len(items)), items))

    @staticmethod
    def _merge(infos: List[Dict[str, Any]]) -> Dict[str, Any]:
        out: Dict[str, Any] = {}
        n = len(infos)
        for i, info in enumerate(infos):
            for k, v in info.items():
                if k not in out:
                    dtype = type(v) if isinstance(v, (bool, int, float)) else object
                    out[k] = np.zeros(n, dtype=dtype) if dtype is not object else \
                        np.empty(n, dtype=object)
                    out['_' + k] = np.zeros(n, dtype=bool)
                out[k][i] = v
                out['_' + k][i] = True
        return out

    def reset(self, *, seed: Optional[Union[int, Sequence[int]]] = None,
              options: Optional[Dict[str, Any]] = None):
        """Resets every environment; an int seed s seeds environment i with s + i."""
        if seed is None:
            seeds = [None] * self.num_envs
        elif isinstance(seed, int):
            seeds = [seed + i for i in range(self.num_envs)]
        else:
            seeds = list(seed)
            if len(seeds) != self.num_envs:
                raise ValueError(f'{len(seeds)} seeds for {self.num_envs} environments')
        results = self._map(lambda i, s: self.envs[i].reset(seed=s, options=options), seeds)
        self._elapsed[:] = 0
        self._needs_reset[:] = False
        obs = np.stack([r[0] for r in results])
        return obs, self._merge([r[1] for r in results])

    def step(self, actions):
        actions = np.asarray(actions)
        if len(actions) != self.num_envs:
            raise ValueError(f'{len(actions)} actions for {self.num_envs} environments')

        def one(i, action):
            env = self.envs[i]
            if self._needs_reset[i]:
                obs, info = env.reset()
                return obs, 0.0, False, False, info, True
            obs, reward, terminated, truncated, info = env.step(action)
            return obs, reward, terminated, truncated, info, False

        results = self._map(one, list(actions))
        obs = np.stack([r[0] for r in results])
        rewards = np.array([r[1] for r in results], dtype=np.float64)
        terminated = np.array([r[2] for r in results], dtype=bool)
        truncated = np.array([r[3] for r in results], dtype=bool)
        for i, r in enumerate(results):
            self._elapsed[i] = 0 if r[5] else self._elapsed[i] + 1
        if self.max_episode_steps is not None:
            truncated |= (self._elapsed >= self.max_episode_steps) & ~terminated
        self._needs_reset = terminated | truncated
        return obs, rewards, terminated, truncated, self._merge([r[4] for r in results])

    def render(self):
        return tuple(env.render() for env in self.envs)

    def close_extras(self, **kwargs):
        if self._pool is not None:
            self._pool.shutdown(wait=True)
            self._pool = None
