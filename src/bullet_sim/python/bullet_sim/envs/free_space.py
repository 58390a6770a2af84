"""Where a round robot fits in a world, found by casting rays through it.

FreeSpace flood-fills a grid from a start point: a cell is free when nothing crosses the
disc of radius `clearance` around its centre (8 rays from the centre out to the circle and
the 16 sides of a polygon inscribed in it hit nothing: a thing that reaches into the disc
crosses one of them, unless it lies wholly within the disc or within the 2 % of the radius
between the polygon and the circle), and it is reachable when a chain of free neighbours
joins it to the start. The rays are Simulation.cast_rays, so whatever the
world is made of (boxes, cylinders, meshes, the world's static models and its movable ones
where they stand) counts. Goals are then drawn among reachable cells in sight of the start.
"""

from __future__ import annotations

import math
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

_SPOKES = np.array([(math.cos(k * math.pi / 4), math.sin(k * math.pi / 4), 0.0)
                    for k in range(8)])
_RING = np.array([(math.cos(k * math.pi / 8), math.sin(k * math.pi / 8), 0.0)
                  for k in range(17)])
#: Unit-radius segments (start, end) tested around a cell's centre: spokes, then ring sides.
_SEGMENT_STARTS = np.vstack([np.zeros((8, 3)), _RING[:-1]])
_SEGMENT_ENDS = np.vstack([_SPOKES, _RING[1:]])


class FreeSpace:
    """The free cells reachable from `start` (x, y) in the simulation's world as it is now.

    clearance: the robot's radius plus a margin (m); resolution: the grid's cell size (m);
    height: the height of the rays above z = 0 (m), between the floor and the top of the
    lowest obstacle that counts; max_extent: how far from the start (m, in x and in y) the
    fill goes, for worlds that are open on a side.
    """

    def __init__(self, sim, start: Sequence[float], *, clearance: float = 0.2,
                 resolution: float = 0.05, height: float = 0.1, max_extent: float = 10.0):
        if not (clearance > 0 and resolution > 0 and max_extent > 0):
            raise ValueError('FreeSpace: clearance, resolution and max_extent must be > 0, '
                             f'got {clearance}, {resolution}, {max_extent}')
        self.clearance = float(clearance)
        self.resolution = float(resolution)
        self.height = float(height)
        self._origin = np.array(start[:2], dtype=float)
        limit = int(math.ceil(max_extent / resolution))
        free: Dict[Tuple[int, int], bool] = {}
        seen = {(0, 0)}
        frontier: List[Tuple[int, int]] = [(0, 0)]
        reached: List[Tuple[int, int]] = []
        while frontier:
            ok = self._free_cells(sim, frontier)
            layer = []
            for cell, is_free in zip(frontier, ok):
                free[cell] = is_free
                if not is_free:
                    continue
                reached.append(cell)
                i, j = cell
                for n in ((i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)):
                    if n not in seen and abs(n[0]) <= limit and abs(n[1]) <= limit:
                        seen.add(n)
                        layer.append(n)
            frontier = layer
        if not reached:
            raise ValueError(f'FreeSpace: the start ({start[0]:.3f}, {start[1]:.3f}) has an '
                             f'obstacle within {clearance} m')
        self.cells = np.array([self._centre(c) for c in reached])
        """Centres (x, y) of the reachable free cells, in the order the fill reached them."""
        self.open = bool(any(abs(i) == limit or abs(j) == limit for i, j in reached))
        """Whether the fill reached max_extent: the start is not enclosed."""

    def _centre(self, cell: Tuple[int, int]) -> Tuple[float, float]:
        return (self._origin[0] + cell[0] * self.resolution,
                self._origin[1] + cell[1] * self.resolution)

    def _free_cells(self, sim, cells: List[Tuple[int, int]]) -> List[bool]:
        centres = np.array([(*self._centre(c), self.height) for c in cells])
        n = len(_SEGMENT_STARTS)
        at = np.repeat(centres, n, axis=0)
        starts = at + np.tile(_SEGMENT_STARTS * self.clearance, (len(cells), 1))
        ends = at + np.tile(_SEGMENT_ENDS * self.clearance, (len(cells), 1))
        hits = np.asarray(sim.cast_rays(starts, ends)).reshape(len(cells), n)
        return list(np.all(np.isinf(hits), axis=1))

    def in_sight(self, sim, start: Sequence[float], ends: np.ndarray, half_width: float,
                 ignored_robot: str = '') -> np.ndarray:
        """For each end (x, y), whether a corridor `2 half_width` wide from `start` to it is
        clear: three rays, along its axis and its edges, hit nothing (but robot
        `ignored_robot`, the one that stands there)."""
        ends = np.asarray(ends, dtype=float).reshape(-1, 2)
        s = np.asarray(start[:2], dtype=float)
        d = ends - s
        lengths = np.linalg.norm(d, axis=1)
        normal = np.zeros_like(d)
        nz = lengths > 0
        normal[nz] = np.stack([-d[nz, 1], d[nz, 0]], axis=1) / lengths[nz, None]
        starts, stops = [], []
        for offset in (0.0, half_width, -half_width):
            starts.append(s + offset * normal)
            stops.append(ends + offset * normal)
        z = np.full((len(ends) * 3, 1), self.height)
        a = np.hstack([np.concatenate(starts), z])
        b = np.hstack([np.concatenate(stops), z])
        hits = np.asarray(sim.cast_rays(a, b, ignored_robot)).reshape(3, len(ends))
        return np.all(np.isinf(hits), axis=0)

    def sample_goal(self, sim, rng: np.random.Generator, start: Sequence[float],
                    distance: Tuple[float, float], half_width: float,
                    ignored_robot: str = '', batch: int = 64) -> Optional[Tuple[float, float]]:
        """A reachable cell's centre at a distance within `distance` of `start` and in sight
        of it (robot `ignored_robot` not in the way), drawn with `rng`; None when there is
        none."""
        s = np.asarray(start[:2], dtype=float)
        dist = np.linalg.norm(self.cells - s, axis=1)
        candidates = self.cells[(dist >= distance[0]) & (dist <= distance[1])]
        if len(candidates) == 0:
            return None
        order = rng.permutation(len(candidates))
        for k in range(0, len(order), batch):
            chunk = candidates[order[k:k + batch]]
            ok = np.flatnonzero(self.in_sight(sim, s, chunk, half_width, ignored_robot))
            if len(ok):
                x, y = chunk[ok[0]]
                return float(x), float(y)
        return None
