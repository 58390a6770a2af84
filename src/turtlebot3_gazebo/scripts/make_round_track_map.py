#!/usr/bin/python3
"""Writes maps/roundTrack.pgm and maps/roundTrack.yaml from worlds/roundTrack.world.

The ground-truth map of the round track for map_server (0.05 m cells, the walls occupied,
everything else free). Rerun it after changing the world. Usage:
  make_round_track_map.py [WORLD_FILE [MAP_YAML]]
"""
import os
import sys

import occupancy_grid
import world_obstacles

PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main(argv):
    world = argv[1] if len(argv) > 1 else os.path.join(PACKAGE, 'worlds', 'roundTrack.world')
    target = argv[2] if len(argv) > 2 else os.path.join(PACKAGE, 'maps', 'roundTrack.yaml')
    try:
        footprints = world_obstacles.read_footprints(world)
    except world_obstacles.WorldError as error:
        sys.stderr.write('make_round_track_map: %s\n' % error)
        return 1
    grid = occupancy_grid.rasterise(footprints)
    pgm = occupancy_grid.write_map(grid, target)
    rows, columns = grid.occupied.shape
    print('%s: %d x %d cells of %.2f m, %d occupied, from %d shapes'
          % (pgm, columns, rows, grid.resolution, grid.occupied.sum(), len(footprints)))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
