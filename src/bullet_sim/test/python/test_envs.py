"""The Gymnasium environments: ROBOTIS's task rules by hand, the free space of the round
track against its wall table, driving to a goal and into a wall with the step counts worked
out from the speed, Gymnasium's checker, determinism and the vector environment."""

import math

import numpy as np
import pytest

gym = pytest.importorskip('gymnasium', reason='gymnasium is not installed (make setup)')

import bullet_sim  # noqa: E402
from bullet_sim.envs import goal_task as task  # noqa: E402
from bullet_sim.envs.free_space import FreeSpace  # noqa: E402
from bullet_sim.envs.turtlebot3 import TurtleBot3GoalEnv, find_package  # noqa: E402
from bullet_sim.envs.vector import TurtleBot3GoalVectorEnv  # noqa: E402

# The round track's walls (DESIGN.md): centre x, y, yaw, length; 0.015 m thick, the length
# along the wall's local y axis.
WALLS = [
    (1.53496, 2.894504, 0.736056, 1.0), (2.04294, 2.386858, 0.881268, 0.5),
    (3.72582, 2.23758, 1.57177, 3.0), (0.196982, 3.258921, 1.57467, 2.0),
    (5.21431, 0.73692, -0.000378, 3.0), (3.8664, -2.46629, -1.1525, 0.5),
    (5.13135, -0.99504, -0.334721, 0.5), (4.92558, -1.45102, -0.501603, 0.5),
    (4.2862, -2.20397, -0.858577, 0.5), (3.41064, -2.6531, 1.9485, 0.5),
    (-0.80941, 0.25461, 0, 6.0), (4.63833, -1.85451, 2.40733, 0.5),
    (1.1918, -2.74499, 1.5735, 4.0), (0.54193, 0.34703, 0, 3.8),
    (0.87641, 1.88745, 0.736056, 1.0), (1.4037, 1.35442, 0.881268, 0.5),
    (2.78265, 1.19568, 1.57177, 2.4), (3.98336, 0.09495, -0.000378, 2.2),
    (1.89949, -1.53786, 1.5735, 2.7), (3.43608, -1.41841, 2.08925, 0.5),
    (3.79555, -1.15857, -0.858577, 0.5)]
HALF_THICKNESS = 0.0075


def distance_to_walls(points):
    """Distance (m) from each point (x, y) to the nearest wall box, in the plane."""
    p = np.asarray(points, dtype=float)
    best = np.full(len(p), np.inf)
    for cx, cy, yaw, length in WALLS:
        ux, uy = -math.sin(yaw), math.cos(yaw)   # the wall's local y: its length
        dx, dy = p[:, 0] - cx, p[:, 1] - cy
        along = np.abs(dx * ux + dy * uy) - length / 2
        across = np.abs(dx * uy - dy * ux) - HALF_THICKNESS
        d = np.hypot(np.maximum(along, 0), np.maximum(across, 0))
        best = np.minimum(best, d)
    return best


# ---------------------------------------------------------------- the task's rules ----

def test_discrete_actions_are_robotis_yaw_rates():
    assert [task.angular_speed(a) for a in range(5)] == [1.5, 0.75, 0.0, -0.75, -1.5]
    with pytest.raises(ValueError, match='action 5'):
        task.angular_speed(5)


def test_yaw_reward_is_a_triangle_wave_of_the_turn_direction():
    # straight on (offset 0): 1 facing the goal, -1 facing away, 0 at a right angle
    assert task.yaw_reward(0.0, 0.0) == pytest.approx(1.0)
    assert task.yaw_reward(math.pi, 0.0) == pytest.approx(-1.0)
    assert task.yaw_reward(math.pi / 2, 0.0) == pytest.approx(0.0, abs=1e-12)
    assert task.yaw_reward(-math.pi / 4, 0.0) == pytest.approx(0.5)
    # action 0 turns left fastest: offset -pi/4, best with the goal 45 degrees to the left
    assert task.discrete_offset(0) == pytest.approx(-math.pi / 4)
    assert task.yaw_reward(math.pi / 4, task.discrete_offset(0)) == pytest.approx(1.0)
    assert task.discrete_offset(4) == pytest.approx(math.pi / 4)
    # the continuous offset goes through the discrete actions' points
    for a in range(5):
        assert task.continuous_offset(task.angular_speed(a)) == \
            pytest.approx(task.discrete_offset(a))


def test_step_reward_rounds_then_scales_by_the_distance_rate():
    # heading 0, straight: round(5 * 1, 2) * 2 ** (0.5 / 1.0)
    assert task.step_reward(0.0, 0.5, 1.0, 0.0) == pytest.approx(5 * 2 ** 0.5)
    # yaw reward 0.5 -> 2.5, at the start distance: * 2
    assert task.step_reward(-math.pi / 4, 1.0, 1.0, 0.0) == pytest.approx(5.0)


def test_scan_state_and_collision():
    r = task.scan_state(np.array([np.inf, np.nan, 1.0, 0.2], dtype=np.float32))
    assert list(r) == [3.5, 0.0, 1.0, pytest.approx(0.2)]
    assert not task.collided(r)          # the NaN's 0 does not count
    assert task.collided(np.array([3.5, 0.129]))
    assert not task.collided(np.array([3.5, 0.13]))


def test_stage_goals_follow_robotis_rules():
    rng = np.random.default_rng(3)
    last = task.STAGE_FIRST_GOAL
    for _ in range(200):
        g = task.stage_goal(rng, 1, last)
        assert g[0] * 10 == pytest.approx(round(g[0] * 10)) and abs(g[0]) <= 1.2
        assert abs(g[1]) <= 1.2
        for ox, oy in ((0.6, 0.6), (0.6, -0.6), (-0.6, 0.6), (-0.6, -0.6), (0, 0)):
            assert not (abs(g[0] - ox) <= 0.4 and abs(g[1] - oy) <= 0.4)
        assert abs(g[0] - last[0]) >= 1 or abs(g[1] - last[1]) >= 1
        last = g


# ------------------------------------------------------------------- free space ----

@pytest.fixture(scope='module')
def track_env():
    env = TurtleBot3GoalEnv()
    env.reset(seed=0)
    yield env
    env.close()


def test_round_track_free_space_against_the_wall_table(track_env):
    free = track_env._free
    assert not free.open
    d = distance_to_walls(free.cells)
    # every free cell centre keeps the clearance from every wall, give or take the gap
    # between the circle and the 16-gon inscribed in it: clearance (1 - cos 11.25 deg)
    assert d.min() >= free.clearance * math.cos(math.pi / 16) - 1e-6
    # the same lattice (spacing `resolution` through the spawn) flood-filled by hand from
    # the spawn over points at least `clearance` from every wall: the corridor, and no
    # point outside it
    res = free.resolution
    ii, jj = np.meshgrid(np.arange(-30, 131), np.arange(-80, 91), indexing='ij')
    pts = np.stack([ii.ravel() * res, jj.ravel() * res], axis=1)
    ok = (distance_to_walls(pts) >= free.clearance).reshape(ii.shape)
    seen = np.zeros_like(ok)
    todo = [(30, 80)]
    seen[30, 80] = True
    while todo:
        i, j = todo.pop()
        for a, b in ((i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)):
            if 0 <= a < ok.shape[0] and 0 <= b < ok.shape[1] and ok[a, b] and not seen[a, b]:
                seen[a, b] = True
                todo.append((a, b))
    by_hand = {(int(i), int(j)) for i, j in zip(ii[seen], jj[seen])}
    by_rays = {(int(round(x / res)), int(round(y / res))) for x, y in free.cells}
    assert by_hand <= by_rays
    # the rays' extra cells are those whose disc a wall's end enters by less than the gap
    assert len(by_rays - by_hand) <= 0.03 * len(by_hand)
    assert 10.0 < len(by_rays) * res ** 2 < 17.7   # the corridor, less its edges


def test_goals_are_free_in_reach_and_in_sight(track_env):
    env = track_env
    for seed in range(20):
        obs, info = env.reset(seed=seed)
        x, y, _ = info['pose']
        gx, gy = info['goal']
        d = math.hypot(gx - x, gy - y)
        assert env.goal_distance[0] - 1e-9 <= d <= env.goal_distance[1] + 1e-9
        assert info['distance'] == pytest.approx(d, abs=1e-3)
        assert distance_to_walls([(gx, gy)])[0] >= 0.2
        # the segment start-goal crosses no wall: sampled every 1 cm
        t = np.linspace(0, 1, int(d / 0.01) + 2)
        seg = np.stack([x + t * (gx - x), y + t * (gy - y)], axis=1)
        assert distance_to_walls(seg).min() > 0.1


# ------------------------------------------------------------- driving the robot ----

# The west lane: x between the west wall (-0.817) and the inner wall (0.534): its middle,
# facing +y (north), the lane free for 2 m and more.
LANE_X = (-0.80941 + 0.54193) / 2 - 0.0  # -0.134


def test_straight_to_a_goal_ahead():
    env = TurtleBot3GoalEnv()
    obs, info = env.reset(seed=1, options={'start': (LANE_X, 0.0, math.pi / 2),
                                           'goal': (LANE_X, 1.0)})
    assert obs.shape == (26,) and obs.dtype == np.float32
    assert obs[24] == pytest.approx(0.0, abs=1e-3) and obs[25] == pytest.approx(1.0, abs=1e-3)
    # at 0.15 m/s, 0.03 m per action: the goal (0.2 m radius) after (1.0 - 0.2) / 0.03 = 26.7
    # actions, give or take one for the wheels' start
    rewards = []
    for k in range(1, 40):
        obs, reward, terminated, truncated, info = env.step(2)
        rewards.append(reward)
        if terminated:
            break
    assert info['is_success'] and not info['collision']
    assert 26 <= k <= 29
    assert rewards[-1] == task.GOAL_REWARD
    # heading stays ~0: each shaping reward is 5 * 2 ** (distance / 1.0)
    d = 1.0 - 0.03 * 10
    assert rewards[9] == pytest.approx(5 * 2 ** d, rel=0.03)
    # the lidar's 24 rays: ray 0 looks ahead (north: 3.5 m, nothing within range), rays 6
    # and 18 (15.65 deg apart: 6 * 0.2732 = 1.639 rad) nearly at the side walls
    env.close()


def test_into_a_wall_is_a_collision():
    env = TurtleBot3GoalEnv()
    # facing west, the west wall's face at x = -0.80941 + 0.0075 = -0.802; the base at
    # x0 = -0.3 is 0.502 m from it; the lidar sits 0.032 m behind the base, so it reads
    # below 0.13 m once the base is within 0.098 m: after (0.502 - 0.098) / 0.03 = 13.5
    # actions
    obs, info = env.reset(seed=2, options={'start': (-0.3, 0.0, math.pi),
                                           'goal': (0.2, 1.0)})
    assert obs[0] == pytest.approx(0.502 + 0.032, abs=0.04)   # ray 0, noise 0.01 m
    for k in range(1, 30):
        obs, reward, terminated, truncated, info = env.step(2)
        if terminated:
            break
    assert info['collision'] and not info['is_success']
    assert reward == task.COLLISION_REWARD
    assert 13 <= k <= 16
    env.close()


# ------------------------------------------------------------- gymnasium contract ----

def test_check_env_passes():
    from gymnasium.utils.env_checker import check_env
    for continuous in (False, True):
        env = TurtleBot3GoalEnv(continuous=continuous)
        check_env(env, skip_render_check=True)
        env.close()


def test_registered_ids_make_the_envs():
    import bullet_sim.envs  # noqa: F401
    env = gym.make('bullet_sim/TurtleBot3Goal-v0')
    assert env.spec.max_episode_steps == 500
    assert isinstance(env.action_space, gym.spaces.Discrete)
    env.close()
    env = gym.make('bullet_sim/TurtleBot3GoalContinuous-v0')
    assert env.action_space.shape == (1,)
    env.close()


def run_episode(env, seed, actions):
    out = [env.reset(seed=seed)[0]]
    for a in actions:
        obs, r, term, trunc, _ = env.step(a)
        out.append(obs)
        out.append(np.array([r, term, trunc], dtype=np.float64))
        if term or trunc:
            out.append(env.reset()[0])
    return np.concatenate([np.ravel(o).astype(np.float64) for o in out])


def test_same_seed_same_episode_to_the_bit():
    actions = np.random.default_rng(0).integers(0, 5, 80)
    a = run_episode(TurtleBot3GoalEnv(), 11, actions)
    b = run_episode(TurtleBot3GoalEnv(), 11, actions)
    c = run_episode(TurtleBot3GoalEnv(), 12, actions)
    assert a.tobytes() == b.tobytes()
    assert a.shape != c.shape or a.tobytes() != c.tobytes()


def test_reset_without_seed_keeps_the_simulation():
    env = TurtleBot3GoalEnv()
    env.reset(seed=5)
    sim = env.simulation
    env.step(2)
    assert sim.time == pytest.approx(0.2)
    env.reset()
    assert env.simulation is sim and sim.time == 0.0


def test_vector_env_equals_single_envs():
    n = 3
    actions = np.random.default_rng(1).integers(0, 5, (60, n))
    vec = TurtleBot3GoalVectorEnv(n, threads=2, max_episode_steps=25)
    singles = [gym.wrappers.TimeLimit(TurtleBot3GoalEnv(), 25) for _ in range(n)]
    obs, _ = vec.reset(seed=40)
    single_obs = [s.reset(seed=40 + i)[0] for i, s in enumerate(singles)]
    assert np.array_equal(obs, np.stack(single_obs))
    done = [False] * n
    for step_actions in actions:
        obs, rew, term, trunc, info = vec.step(step_actions)
        for i, s in enumerate(singles):
            if done[i]:
                o, _ = s.reset()
                r, te, tr = 0.0, False, False
            else:
                o, r, te, tr, _ = s.step(step_actions[i])
            done[i] = te or tr
            assert np.array_equal(obs[i], o), f'env {i}'
            assert rew[i] == r and term[i] == te and trunc[i] == tr
    vec.close()


def test_continuous_actions_match_the_discrete_ones_at_their_points():
    # 1, 0.5, 0, -0.5, -1 are 1.5, 0.75, 0, -0.75, -1.5 rad/s: discrete actions 0..4
    start = {'start': (LANE_X, -1.0, math.pi / 2), 'goal': (LANE_X, 1.5)}
    d, c = TurtleBot3GoalEnv(), TurtleBot3GoalEnv(continuous=True)
    od, _ = d.reset(seed=4, options=start)
    oc, _ = c.reset(seed=4, options=start)
    for k, a in enumerate([2, 0, 4, 1, 3, 2]):
        od, rd, *_ = d.step(a)
        oc, rc, *_ = c.step(np.array([1.0 - 0.5 * a], dtype=np.float32))
        assert od.tobytes() == oc.tobytes(), f'action {k}'
        assert rd == rc
    # 1 is 1.5 rad/s: once the wheels have reached their speeds (the outer one needs
    # (0.15 + 1.5 * 0.08) m/s / 1 m/s^2 = 0.27 s at the description's wheelAcceleration),
    # each action turns the heading by 1.5 * 0.2 = 0.3 rad
    env = TurtleBot3GoalEnv(continuous=True)
    env.reset(seed=4, options=start)
    yaws = [env.step(np.array([1.0], dtype=np.float32))[4]['pose'][2] for _ in range(4)]
    for k in (2, 3):
        assert yaws[k] - yaws[k - 1] == pytest.approx(0.3, abs=0.003)


# ------------------------------------------------ ROBOTIS's stage worlds (a clone) ----

def _stage_worlds():
    from bullet_sim.envs.turtlebot3 import find_packages
    import os
    for pkg in find_packages('turtlebot3_gazebo'):
        if os.path.isfile(os.path.join(pkg, 'worlds', 'turtlebot3_stage_1.world')):
            return pkg
    return None


needs_stages = pytest.mark.skipif(
    _stage_worlds() is None,
    reason="ROBOTIS's turtlebot3_simulations (its turtlebot3_gazebo with the stage worlds) "
           'is not on ROS_PACKAGE_PATH')


@needs_stages
@pytest.mark.parametrize('stage', [1, 2, 3, 4])
def test_stage_worlds_pass_the_checker_with_robotis_spawn_and_first_goal(stage):
    from gymnasium.utils.env_checker import check_env
    env = TurtleBot3GoalEnv(world=f'stage_{stage}')
    obs, info = env.reset(seed=0)
    assert info['goal'] == task.STAGE_FIRST_GOAL
    assert info['pose'][:2] == pytest.approx((-0.7 if stage == 4 else 0.0, 0.0), abs=1e-3)
    check_env(env, skip_render_check=True)


@needs_stages
def test_stage_1_straight_to_the_first_goal():
    # from the spawn (0, 0) facing +x, the first goal (0.6, 0) is 0.6 m ahead: reached
    # after (0.6 - 0.2) / 0.03 = 13.3 actions, give or take one for the wheels' start
    env = TurtleBot3GoalEnv(world='stage_1')
    obs, info = env.reset(seed=0)
    assert obs[24] == pytest.approx(0.0, abs=1e-3) and obs[25] == pytest.approx(0.6, abs=1e-3)
    for k in range(1, 30):
        obs, reward, terminated, truncated, info = env.step(2)
        if terminated:
            break
    assert info['is_success'] and 13 <= k <= 16
    # the goal stays after a collision-free reset only when it was not reached: reached
    # here, the next episode draws a new one by ROBOTIS's rules
    env.reset()
    g = env.goal
    assert abs(g[0] - 0.6) >= 1 or abs(g[1]) >= 1
