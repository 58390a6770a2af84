#!/usr/bin/env python3
"""Trains a policy for bullet_sim/TurtleBot3Goal-v0 with Stable-Baselines3 (PPO or DQN) and
measures its success rate as it learns.

Needs `make learning` (torch and Stable-Baselines3 in build/learning_venv):

    source devel/setup.bash
    build/learning_venv/bin/python src/bullet_sim/scripts/train_turtlebot3.py \\
        --algo ppo --target 0.9 --out build/train_ppo

Every --eval-every environment steps the deterministic policy runs --eval-episodes episodes
(seeds 10000.., the same ones each time) and their success rate (goal reached before a
collision or the 500-action limit) is written to progress.csv with the wall time, the time
spent evaluating and the training's environment steps per second (evaluation left out);
training stops once the rate reaches --target. The learning curve is
drawn into learning_curve.png and the model saved as model.zip.
"""

import argparse
import csv
import os
import sys
import time

import gymnasium as gym
import numpy as np


def make_env(rank, seed, physics_step):
    def thunk():
        import bullet_sim.envs  # noqa: F401  (registers the ids in this process)
        env = gym.make('bullet_sim/TurtleBot3Goal-v0', physics_step=physics_step)
        env.reset(seed=seed + rank)
        return env
    return thunk


def evaluate(model, env, episodes, seed0):
    successes, returns, lengths = 0, [], []
    for i in range(episodes):
        obs, _ = env.reset(seed=seed0 + i)
        done, total, n = False, 0.0, 0
        while not done:
            action, _ = model.predict(obs, deterministic=True)
            obs, reward, terminated, truncated, info = env.step(action)
            total += reward
            n += 1
            done = terminated or truncated
        successes += bool(info.get('is_success'))
        returns.append(total)
        lengths.append(n)
    return successes / episodes, float(np.mean(returns)), float(np.mean(lengths))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    p.add_argument('--algo', choices=('ppo', 'dqn'), default='ppo')
    p.add_argument('--timesteps', type=int, default=1_000_000, help='at most this many')
    p.add_argument('--n-envs', type=int, default=2, help='environments in subprocesses')
    p.add_argument('--seed', type=int, default=0)
    p.add_argument('--physics-step', type=float, default=0.001)
    p.add_argument('--eval-every', type=int, default=20_000)
    p.add_argument('--eval-episodes', type=int, default=100)
    p.add_argument('--target', type=float, default=0.9, help='stop at this success rate')
    p.add_argument('--out', default='build/train_turtlebot3')
    args = p.parse_args(argv)

    import torch
    from stable_baselines3 import DQN, PPO
    from stable_baselines3.common.callbacks import BaseCallback
    from stable_baselines3.common.vec_env import DummyVecEnv, SubprocVecEnv
    import bullet_sim.envs  # noqa: F401

    torch.set_num_threads(1)
    os.makedirs(args.out, exist_ok=True)
    fns = [make_env(i, args.seed, args.physics_step) for i in range(args.n_envs)]
    venv = SubprocVecEnv(fns) if args.n_envs > 1 else DummyVecEnv(fns)
    venv.seed(args.seed)
    eval_env = gym.make('bullet_sim/TurtleBot3Goal-v0', physics_step=args.physics_step)
    if args.algo == 'ppo':
        model = PPO('MlpPolicy', venv, n_steps=1024, batch_size=256, n_epochs=10,
                    learning_rate=3e-4, gamma=0.99, gae_lambda=0.95, ent_coef=0.005,
                    seed=args.seed, verbose=0, device='cpu')
    else:
        model = DQN('MlpPolicy', venv, learning_rate=2.5e-4, buffer_size=200_000,
                    learning_starts=5_000, batch_size=64, gamma=0.99, train_freq=4,
                    target_update_interval=2_000, exploration_fraction=0.2,
                    exploration_final_eps=0.05, seed=args.seed, verbose=0, device='cpu',
                    policy_kwargs={'net_arch': [64, 64]})

    log_path = os.path.join(args.out, 'progress.csv')
    start = time.time()

    class Progress(BaseCallback):
        def __init__(self):
            super().__init__()
            self.next_eval = args.eval_every
            self.rows = []
            self.eval_s = 0.0

        def _on_training_start(self):
            self.record()  # the untrained policy

        def _on_step(self):
            if self.num_timesteps < self.next_eval:
                return True
            self.next_eval += args.eval_every
            return self.record() < args.target

        def record(self):
            t0 = time.time()
            rate, ret, length = evaluate(self.model, eval_env, args.eval_episodes, 10_000)
            self.eval_s += time.time() - t0
            wall = time.time() - start
            train = wall - self.eval_s
            row = {'env_steps': self.num_timesteps, 'wall_s': round(wall, 1),
                   'eval_s': round(self.eval_s, 1), 'train_s': round(train, 1),
                   'train_steps_per_s': round(self.num_timesteps / max(train, 1e-9), 1),
                   'success_rate': rate, 'mean_return': round(ret, 2),
                   'mean_length': round(length, 1)}
            self.rows.append(row)
            with open(log_path, 'w', newline='') as f:
                w = csv.DictWriter(f, fieldnames=list(row))
                w.writeheader()
                w.writerows(self.rows)
            print(' '.join(f'{k}={v}' for k, v in row.items()), flush=True)
            return rate

    progress = Progress()
    model.learn(total_timesteps=args.timesteps, callback=progress)
    model.save(os.path.join(args.out, 'model.zip'))
    venv.close()
    if progress.rows:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        steps = [r['env_steps'] for r in progress.rows]
        fig, ax = plt.subplots(figsize=(6, 3.2), dpi=100)
        ax.plot(steps, [100 * r['success_rate'] for r in progress.rows], marker='o')
        ax.axhline(100 * args.target, color='grey', linestyle='--', linewidth=1)
        ax.set_xlabel('environment steps (0.2 s each)')
        ax.set_ylabel('success rate, %')
        ax.set_ylim(0, 100)
        ax.set_title(f'{args.algo.upper()} on bullet_sim/TurtleBot3Goal-v0 (round track)')
        ax.grid(True, alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, 'learning_curve.png'))
    last = progress.rows[-1] if progress.rows else {}
    print(f'done: {last}')
    return 0 if last.get('success_rate', 0) >= args.target else 1


if __name__ == '__main__':
    sys.exit(main())
