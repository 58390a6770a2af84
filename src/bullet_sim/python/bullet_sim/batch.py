"""Episodes of the bullet_sim Gymnasium environments in batches, on Ray.

    from bullet_sim import batch
    results = batch.run(seeds=range(8), workers=2)                 # random actions
    results = batch.run(seeds=[1, 2], actions=[2, 2, 0, 4])        # a fixed action sequence
    results = batch.run(seeds=[1, 2], policy=my_policy)            # obs -> action
    results = batch.run(seeds=[1, 2], use_ray=False)               # in this process

With Ray, `workers` actors each own one environment and run episodes one after another
(Ray's ActorPool hands them out); each episode is reset with its seed, so an episode's
result does not depend on which worker ran it or what it ran before: the same seeds and
actions give the same returns and observations to the bit as in-process.

Where it runs: `ray.init()` (called here unless Ray is already initialised) starts a local
Ray on this machine, or joins the cluster that the environment variable RAY_ADDRESS names
(e.g. RAY_ADDRESS=10.0.0.1:6379, the head's `ray start --head --port=6379`), so the same
script runs on a laptop and on a cluster. Every node must have this workspace built at the
same path as the driver's and its devel/setup.bash sourced in the shell that runs
`ray start`; the driver also passes its own PYTHONPATH, LD_LIBRARY_PATH, ROS_PACKAGE_PATH,
PATH and CMAKE_PREFIX_PATH to the workers (Ray's runtime_env env_vars), so that
`import bullet_sim.envs` in a worker finds the same build.

Imports of bullet_sim.envs, gymnasium and numpy happen in the workers, not at module import:
this module imports without Ray or Gymnasium.
"""

from __future__ import annotations

import os
import socket
import time
from typing import Any, Callable, Dict, Iterable, List, Optional, Sequence

#: The environment variables the workers need to import bullet_sim and find the worlds.
WORKER_ENV_VARS = ('PYTHONPATH', 'LD_LIBRARY_PATH', 'ROS_PACKAGE_PATH', 'PATH',
                   'CMAKE_PREFIX_PATH', 'ROS_ROOT', 'ROS_DISTRO', 'ROS_ETC_DIR')

DEFAULT_ENV_ID = 'bullet_sim/TurtleBot3Goal-v0'


def worker_env_vars() -> Dict[str, str]:
    """This process's values of WORKER_ENV_VARS (those that are set)."""
    return {k: os.environ[k] for k in WORKER_ENV_VARS if k in os.environ}


class EpisodeRunner:
    """One environment (gymnasium.make(env_id, **env_kwargs)) that runs whole episodes.
    Used as is in-process and as the class of the Ray actors."""

    def __init__(self, env_id: str = DEFAULT_ENV_ID, env_kwargs: Optional[Dict[str, Any]] = None,
                 max_episode_steps: Optional[int] = None):
        import gymnasium as gym
        import bullet_sim.envs  # noqa: F401  registers the environments
        kwargs = dict(env_kwargs or {})
        if max_episode_steps is not None:
            kwargs['max_episode_steps'] = int(max_episode_steps)
        self.env = gym.make(env_id, **kwargs)

    def episode(self, seed: int, actions: Optional[Sequence[Any]] = None,
                policy: Optional[Callable[[Any], Any]] = None) -> Dict[str, Any]:
        """One episode reset with `seed`. Actions: `actions[i]` at step i, the episode cut
        (truncated) when they run out; else `policy(obs)`; else random, the action space
        seeded with `seed`. Returns return, length, success, terminated, truncated,
        final_obs, steps_per_s and steps_per_cpu_s (of the steps alone, resets excluded),
        the worker's host, pid and Ray node id (None in-process)."""
        import numpy as np
        if actions is not None and policy is not None:
            raise ValueError('give actions or a policy, not both')
        env = self.env
        obs, info = env.reset(seed=int(seed))
        if actions is None and policy is None:
            env.action_space.seed(int(seed))
        total, length = 0.0, 0
        terminated = truncated = False
        success = False
        wall = cpu = 0.0
        while not (terminated or truncated):
            if actions is not None:
                if length >= len(actions):
                    truncated = True
                    break
                action = actions[length]
            elif policy is not None:
                action = policy(obs)
            else:
                action = env.action_space.sample()
            w0, c0 = time.perf_counter(), time.process_time()
            obs, reward, terminated, truncated, info = env.step(action)
            wall += time.perf_counter() - w0
            cpu += time.process_time() - c0
            total += float(reward)
            length += 1
            success = success or bool(info.get('is_success', False))
        return {
            'seed': int(seed), 'return': total, 'length': length, 'success': success,
            'terminated': bool(terminated), 'truncated': bool(truncated),
            'final_obs': np.asarray(obs).copy(),
            'steps_per_s': length / wall if wall > 0 else float('nan'),
            'steps_per_cpu_s': length / cpu if cpu > 0 else float('nan'),
            'host': socket.gethostname(), 'pid': os.getpid(), 'node_id': _node_id(),
        }


def _node_id() -> Optional[str]:
    try:
        import ray
        if ray.is_initialized():
            return ray.get_runtime_context().get_node_id()
    except ImportError:
        pass
    return None


def run(seeds: Iterable[int], *, actions: Optional[Sequence[Any]] = None,
        policy: Optional[Callable[[Any], Any]] = None, workers: int = 2,
        env_id: str = DEFAULT_ENV_ID, env_kwargs: Optional[Dict[str, Any]] = None,
        max_episode_steps: Optional[int] = None, use_ray: bool = True,
        num_cpus_per_worker: float = 1, runtime_env: Optional[Dict[str, Any]] = None
        ) -> List[Dict[str, Any]]:
    """One episode per seed (see EpisodeRunner.episode), results in the order of `seeds`.

    use_ray: `workers` Ray actors of `num_cpus_per_worker` CPUs each (Ray places them on
    the nodes that have the CPUs free); ray.init() is called if Ray is not initialised
    (RAY_ADDRESS picks the cluster), with `runtime_env` (default: env_vars of
    worker_env_vars()). Else: one environment in this process. `policy` is pickled to the
    workers (cloudpickle: a function, lambda or callable object)."""
    seeds = [int(s) for s in seeds]
    if workers < 1:
        raise ValueError(f'workers {workers}: needs >= 1')
    if not use_ray:
        runner = EpisodeRunner(env_id, env_kwargs, max_episode_steps)
        return [runner.episode(s, actions, policy) for s in seeds]
    import ray
    from ray.util import ActorPool
    if runtime_env is None:
        runtime_env = {'env_vars': worker_env_vars()}
    if not ray.is_initialized():
        ray.init(runtime_env=runtime_env)
    actor = ray.remote(num_cpus=num_cpus_per_worker)(EpisodeRunner).options(
        runtime_env=runtime_env)
    pool = ActorPool([actor.remote(env_id, env_kwargs, max_episode_steps)
                      for _ in range(min(workers, max(1, len(seeds))))])
    return list(pool.map(lambda a, s: a.episode.remote(s, actions, policy), seeds))


def summary(results: Sequence[Dict[str, Any]]) -> str:
    """A line: episodes, mean return and length, success rate, agent steps/s per worker."""
    import statistics
    n = len(results)
    if n == 0:
        return 'episodes=0'
    return (f'episodes={n} return_mean={statistics.fmean(r["return"] for r in results):.2f} '
            f'length_mean={statistics.fmean(r["length"] for r in results):.1f} '
            f'success={sum(r["success"] for r in results) / n:.2f} '
            f'steps_per_s_median={statistics.median(r["steps_per_s"] for r in results):.0f} '
            f'nodes={len({r["node_id"] for r in results})}')


def main(argv: Optional[Sequence[str]] = None) -> None:
    import argparse
    p = argparse.ArgumentParser(
        prog='python3 -m bullet_sim.batch',
        description='Random-action episodes of a bullet_sim environment on Ray workers '
                    '(RAY_ADDRESS=host:port joins a cluster; without it a local Ray starts).')
    p.add_argument('--episodes', type=int, default=8)
    p.add_argument('--workers', type=int, default=2)
    p.add_argument('--seed', type=int, default=0, help='seeds SEED .. SEED+EPISODES-1')
    p.add_argument('--env', default=DEFAULT_ENV_ID)
    p.add_argument('--physics-step', type=float, default=None)
    p.add_argument('--max-episode-steps', type=int, default=None)
    p.add_argument('--no-ray', action='store_true', help='run in this process')
    a = p.parse_args(argv)
    kwargs = {} if a.physics_step is None else {'physics_step': a.physics_step}
    t0 = time.perf_counter()
    results = run(range(a.seed, a.seed + a.episodes), workers=a.workers, env_id=a.env,
                  env_kwargs=kwargs, max_episode_steps=a.max_episode_steps,
                  use_ray=not a.no_ray)
    wall = time.perf_counter() - t0
    for r in results:
        print(f'seed={r["seed"]} return={r["return"]:.2f} length={r["length"]} '
              f'success={r["success"]} steps_per_s={r["steps_per_s"]:.0f} '
              f'host={r["host"]} pid={r["pid"]}')
    steps = sum(r['length'] for r in results)
    print(summary(results) + f' total_steps={steps} wall_s={wall:.1f} '
          f'total_steps_per_s={steps / wall:.0f}')


if __name__ == '__main__':
    main()
