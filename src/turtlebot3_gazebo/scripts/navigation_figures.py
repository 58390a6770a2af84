"""Figures of a navigation run against the world's true geometry (no ROS in here).

- clearance_m: how far the Burger's outline at a pose keeps from the nearest wall (negative:
  the outline cuts into it);
- pose_error: distance and heading difference between an estimate and the true pose;
- map_against_walls: how well an occupancy grid (e.g. gmapping's) matches the true walls:
  the share of its occupied cells within a tolerance of a wall, and the share of the walls'
  length that has an occupied cell within that tolerance.
Walls are world_obstacles.Rectangle footprints (a thin box: its long side is the wall).
"""
import math

import numpy as np

# The Burger's collision outline in base_footprint: the body box 0.140 m square centred
# 0.032 m behind the origin, and the wheels (r 0.033, 0.018 wide) at y = +/-0.08.
OUTLINE_X_M = (-0.102, 0.038)
OUTLINE_Y_M = (-0.089, 0.089)
OUTLINE_STEP_M = 0.005


def _outline_points():
    (x0, x1), (y0, y1) = OUTLINE_X_M, OUTLINE_Y_M
    nx = int(math.ceil((x1 - x0) / OUTLINE_STEP_M)) + 1
    ny = int(math.ceil((y1 - y0) / OUTLINE_STEP_M)) + 1
    xs, ys = np.linspace(x0, x1, nx), np.linspace(y0, y1, ny)
    return np.vstack([np.column_stack([xs, np.full(nx, y0)]), np.column_stack([xs, np.full(nx, y1)]),
                      np.column_stack([np.full(ny, x0), ys]), np.column_stack([np.full(ny, x1), ys])])


_OUTLINE = _outline_points()


def _segments(walls):
    """Centre-line end points and half thickness of each wall (the long side of the box)."""
    rows = []
    for w in walls:
        c, s = math.cos(w.yaw), math.sin(w.yaw)
        if w.size_y >= w.size_x:
            half, along, thick = w.size_y / 2, (-s, c), w.size_x / 2
        else:
            half, along, thick = w.size_x / 2, (c, s), w.size_y / 2
        rows.append((w.x - half * along[0], w.y - half * along[1],
                     w.x + half * along[0], w.y + half * along[1], thick))
    return np.array(rows)


def distance_to_walls(points, walls):
    """For each point (N x 2), the distance to the nearest wall's surface."""
    seg = _segments(walls)
    p = np.asarray(points, dtype=float)[:, None, :]
    a, b = seg[None, :, 0:2], seg[None, :, 2:4]
    ab = b - a
    t = np.clip(np.sum((p - a) * ab, axis=2) / np.sum(ab * ab, axis=2), 0.0, 1.0)
    nearest = a + t[:, :, None] * ab
    return np.min(np.linalg.norm(p - nearest, axis=2) - seg[None, :, 4], axis=1)


def clearance_m(x, y, yaw, walls):
    """Smallest distance from the Burger's outline at (x, y, yaw) to a wall's surface."""
    c, s = math.cos(yaw), math.sin(yaw)
    points = np.column_stack([x + c * _OUTLINE[:, 0] - s * _OUTLINE[:, 1],
                              y + s * _OUTLINE[:, 0] + c * _OUTLINE[:, 1]])
    return float(np.min(distance_to_walls(points, walls)))


def pose_error(estimate, truth):
    """(distance m, |heading difference| rad) of two (x, y, yaw) poses."""
    heading = math.atan2(math.sin(estimate[2] - truth[2]), math.cos(estimate[2] - truth[2]))
    return math.hypot(estimate[0] - truth[0], estimate[1] - truth[1]), abs(heading)


def map_against_walls(occupied_xy, walls, tolerance_m=0.10, step_m=0.02):
    """(share of occupied cells within tolerance of a wall, share of wall length with an
    occupied cell within tolerance); occupied_xy are the cells' centres (N x 2)."""
    cells = np.asarray(occupied_xy, dtype=float).reshape(-1, 2)
    if not len(cells):
        return 0.0, 0.0
    near = distance_to_walls(cells, walls) <= tolerance_m
    samples = []
    for x0, y0, x1, y1, _ in _segments(walls):
        n = max(2, int(math.ceil(math.hypot(x1 - x0, y1 - y0) / step_m)) + 1)
        samples.append(np.column_stack([np.linspace(x0, x1, n), np.linspace(y0, y1, n)]))
    samples = np.vstack(samples)
    covered = np.zeros(len(samples), dtype=bool)
    for start in range(0, len(cells), 2000):
        chunk = cells[start:start + 2000]
        d = np.linalg.norm(samples[:, None, :] - chunk[None, :, :], axis=2)
        covered |= np.min(d, axis=1) <= tolerance_m
    return float(np.mean(near)), float(np.mean(covered))
