"""A ground-truth occupancy grid from obstacle footprints, in map_server's file format.

A cell is occupied when an obstacle's footprint touches it (so a 15 mm wall still shows as
a line of 5 cm cells) and free otherwise; the grid covers the obstacles with a margin and
its origin lies on the resolution's lattice. Files: a binary PGM (0 occupied, 254 free)
and map_server's YAML (origin = lower-left corner of the lower-left cell).
"""
import collections
import math
import os

import numpy as np

from world_obstacles import Circle, Rectangle

FREE = 254
OCCUPIED = 0

Grid = collections.namedtuple('Grid', 'origin_x origin_y resolution occupied')
"""occupied: bool array [row, column], row 0 at origin_y (the bottom of the map)."""


def _extent(footprint):
    if isinstance(footprint, Circle):
        return footprint.radius, footprint.radius
    c, s = abs(math.cos(footprint.yaw)), abs(math.sin(footprint.yaw))
    hx, hy = footprint.size_x / 2, footprint.size_y / 2
    return c * hx + s * hy, s * hx + c * hy


def _rectangle_touches(rect, cx, cy, half):
    """Separating-axis test of the rectangle against square cells centred at cx, cy."""
    ux, uy = math.cos(rect.yaw), math.sin(rect.yaw)
    hx, hy = rect.size_x / 2, rect.size_y / 2
    ex, ey = _extent(rect)
    touches = (np.abs(cx - rect.x) <= ex + half) & (np.abs(cy - rect.y) <= ey + half)
    cell_reach = half * (abs(ux) + abs(uy))
    along_u = (cx - rect.x) * ux + (cy - rect.y) * uy
    along_v = -(cx - rect.x) * uy + (cy - rect.y) * ux
    return touches & (np.abs(along_u) <= hx + cell_reach) & (np.abs(along_v) <= hy + cell_reach)


def _circle_touches(circle, cx, cy, half):
    dx = np.maximum(np.abs(cx - circle.x) - half, 0.0)
    dy = np.maximum(np.abs(cy - circle.y) - half, 0.0)
    return dx * dx + dy * dy <= circle.radius * circle.radius


def rasterise(footprints, resolution_m=0.05, margin_m=0.5):
    """The grid of the footprints: margin_m of free space around them on every side."""
    if not footprints:
        raise ValueError('no obstacles to map')
    lows, highs = [], []
    for f in footprints:
        ex, ey = _extent(f)
        lows.append((f.x - ex, f.y - ey))
        highs.append((f.x + ex, f.y + ey))
    low = np.floor((np.min(lows, axis=0) - margin_m) / resolution_m) * resolution_m
    high = np.max(highs, axis=0) + margin_m
    columns, rows = np.ceil((high - low) / resolution_m).astype(int)
    cx = low[0] + (np.arange(columns) + 0.5) * resolution_m
    cy = low[1] + (np.arange(rows) + 0.5) * resolution_m
    cx, cy = np.meshgrid(cx, cy)
    occupied = np.zeros((rows, columns), dtype=bool)
    for f in footprints:
        touches = _circle_touches if isinstance(f, Circle) else _rectangle_touches
        occupied |= touches(f, cx, cy, resolution_m / 2)
    return Grid(float(low[0]), float(low[1]), resolution_m, occupied)


def cell_of(grid, x, y):
    """(row, column) of the cell holding the point x, y."""
    return (int(math.floor((y - grid.origin_y) / grid.resolution)),
            int(math.floor((x - grid.origin_x) / grid.resolution)))


def pgm_bytes(grid):
    """The binary PGM of the grid, top row (largest y) first, as map_server reads it."""
    rows, columns = grid.occupied.shape
    pixels = np.where(grid.occupied[::-1], OCCUPIED, FREE).astype(np.uint8)
    return b'P5\n%d %d\n255\n' % (columns, rows) + pixels.tobytes()


def yaml_text(grid, image_name):
    return ('image: %s\nresolution: %.3f\norigin: [%.3f, %.3f, 0.0]\nnegate: 0\n'
            'occupied_thresh: 0.65\nfree_thresh: 0.196\n'
            % (image_name, grid.resolution, grid.origin_x, grid.origin_y))


def write_map(grid, yaml_path):
    """Writes yaml_path and the PGM beside it (same name, .pgm)."""
    pgm_path = os.path.splitext(yaml_path)[0] + '.pgm'
    with open(pgm_path, 'wb') as f:
        f.write(pgm_bytes(grid))
    with open(yaml_path, 'w') as f:
        f.write(yaml_text(grid, os.path.basename(pgm_path)))
    return pgm_path
