#!/usr/bin/env python3
"""PPO (RLlib) on bullet_sim/TurtleBot3Goal-v0 with M env runners, each a Ray actor with
its own simulation. Needs build/learning_venv (`make learning`) and devel/setup.bash:

    source devel/setup.bash
    build/learning_venv/bin/python src/bullet_sim/scripts/rllib_turtlebot3.py --iterations 50
    build/learning_venv/bin/python src/bullet_sim/scripts/rllib_turtlebot3.py --smoke

`ray.init()` joins the cluster named by RAY_ADDRESS when it is set (every node with this
workspace built at the same path and sourced before `ray start`), else starts a local Ray.
Prints, per iteration, the mean episode return and the env steps sampled.
"""

import argparse
import os
import sys
import time


def make_env(config):
    import gymnasium as gym
    import bullet_sim.envs  # noqa: F401  registers the environments
    kwargs = dict(config or {})
    return gym.make('bullet_sim/TurtleBot3Goal-v0', **kwargs)


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('--iterations', type=int, default=20)
    p.add_argument('--env-runners', type=int, default=2, help='M: Ray actors sampling')
    p.add_argument('--physics-step', type=float, default=0.001)
    p.add_argument('--train-batch', type=int, default=4000, help='env steps per iteration')
    p.add_argument('--smoke', action='store_true',
                   help='2 iterations of 400 steps, episodes cut at 100 actions')
    p.add_argument('--checkpoint', default=None, help='save the algorithm here at the end')
    a = p.parse_args()
    if a.smoke:
        a.iterations, a.train_batch = min(a.iterations, 2), 400

    import ray
    from ray.rllib.algorithms.ppo import PPOConfig
    from ray.tune.registry import register_env
    from bullet_sim.batch import worker_env_vars

    env_config = {'physics_step': a.physics_step}
    if a.smoke:
        env_config['max_episode_steps'] = 100
    ray.init(runtime_env={'env_vars': worker_env_vars()})
    register_env('bullet_sim_turtlebot3_goal', make_env)
    config = (PPOConfig()
              .environment('bullet_sim_turtlebot3_goal', env_config=env_config)
              .env_runners(num_env_runners=a.env_runners, num_envs_per_env_runner=1,
                           num_cpus_per_env_runner=1)
              .training(train_batch_size_per_learner=a.train_batch,
                        minibatch_size=min(128, a.train_batch), num_epochs=4 if a.smoke else 10,
                        lr=3e-4, gamma=0.99)
              .debugging(seed=0))
    algo = config.build_algo()
    try:
        for i in range(1, a.iterations + 1):
            t0 = time.perf_counter()
            result = algo.train()
            dt = time.perf_counter() - t0
            runners = result.get('env_runners', {})
            ret = runners.get('episode_return_mean', float('nan'))
            steps = runners.get('num_env_steps_sampled', 0)
            total = result.get('num_env_steps_sampled_lifetime',
                               runners.get('num_env_steps_sampled_lifetime', 0))
            print(f'iteration {i}: episode_return_mean={ret:.2f} env_steps_sampled={steps} '
                  f'env_steps_total={int(total)} seconds={dt:.1f} steps_per_s={steps / dt:.0f}',
                  flush=True)
        if a.checkpoint:
            print('checkpoint:', algo.save(os.path.abspath(a.checkpoint)))
    finally:
        algo.stop()
        ray.shutdown()
    return 0


if __name__ == '__main__':
    sys.exit(main())
