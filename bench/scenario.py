"""The round-track benchmark scenario shared by the peer scripts (MuJoCo, PyBullet), and the
sanity checks that keep a broken peer from flattering bullet_sim: a peer whose walls are
misplaced or whose robot does not drive fails here instead of reporting a fast run.

Pure Python (no simulator imports), so bench/test_scenario.py tests it on its own.
"""
import math
import xml.etree.ElementTree as ET

STEP_S = 0.001                      # 1 kHz physics, as the world's max_step_size
SPAWN_YAW_RAD = 1.5675              # west lane, facing +y (DESIGN.md)
CMD_LINEAR_MPS, CMD_ANGULAR_RADPS = 0.1, 0.3   # bench/sim_rtf.sh's latched command
WHEEL_SEPARATION_M, WHEEL_RADIUS_M = 0.160, 0.033
WHEEL_ACCEL_MPS2, WHEEL_TORQUE_NM = 1.0, 10.0  # the Burger's diff-drive plugin
RAY_COUNT, RAY_MIN_M, RAY_MAX_M = 360, 0.12, 3.5
LIDAR_PERIOD_STEPS = 200            # 5 Hz
IMU_PERIOD_STEPS = 5                # 200 Hz
ODOM_PERIOD_STEPS = 33              # 30 Hz: odometry, joint states, link poses for tf
WALL_COUNT = 21

# Lidar ranges at the spawn pose, by hand from the DESIGN.md wall table.
# base_scan sits at (-0.032, 0, 0.182) in base_footprint; with yaw 1.5675 (cos 0.0032963,
# sin 0.9999946) it is at world x = -0.032 * 0.0032963 = -0.0001055, y = -0.0320.
# Ray 90 (+90 deg) points along yaw + pi/2: direction (-0.9999946, 0.0032963). It meets
# wall_10 (x -0.80941, yaw 0, 0.015 thick: inner face x = -0.80191) after
# (0.80191 - 0.0001055) / 0.9999946 = 0.80181 m, at y -0.029 (the wall spans y -2.75..3.25).
# Ray 270 (-90 deg), direction (0.9999946, -0.0032963), meets wall_13 (x 0.54193: inner face
# x = 0.53443) after (0.53443 + 0.0001055) / 0.9999946 = 0.53454 m (wall spans y -1.55..2.25).
SPAWN_LEFT_RANGE_M = 0.80181
SPAWN_RIGHT_RANGE_M = 0.53454
RANGE_TOLERANCE_M = 0.01


class SanityError(RuntimeError):
    """A peer's run does not match the scenario: its figures must not be reported."""


def wheel_speeds_radps(linear_mps, angular_radps):
    """Left and right wheel speeds of the diff drive for a body twist."""
    half = angular_radps * WHEEL_SEPARATION_M / 2.0
    return ((linear_mps - half) / WHEEL_RADIUS_M, (linear_mps + half) / WHEEL_RADIUS_M)


def ramp(current, target, max_delta):
    """One diff-drive update: moves `current` towards `target` by at most `max_delta`."""
    return current + max(-max_delta, min(max_delta, target - current))


def ray_angles_rad():
    """Ray angles in the lidar frame, 0 along +x, counter-clockwise."""
    return [2.0 * math.pi * i / RAY_COUNT for i in range(RAY_COUNT)]


def read_world(world_file):
    """The static boxes of the SDF world: (name, (x, y, z, yaw), (sx, sy, sz), rgba, collides)."""
    boxes = []
    for model in ET.parse(world_file).getroot().iter("model"):
        pose = [float(v) for v in model.find("pose").text.split()] if model.find("pose") \
            is not None else [0.0] * 6
        collision = model.find("link/collision/geometry/box/size")
        visual = model.find("link/visual/geometry/box/size")
        size = collision if collision is not None else visual
        if size is None:
            continue
        diffuse = model.find("link/visual/material/diffuse")
        rgba = [float(v) for v in diffuse.text.split()] if diffuse is not None else [1, 1, 1, 1]
        boxes.append((model.get("name"), (pose[0], pose[1], pose[2], pose[5]),
                      tuple(float(v) for v in size.text.split()), rgba, collision is not None))
    walls = [b for b in boxes if b[4]]
    if len(walls) != WALL_COUNT:
        raise SanityError("%s: %d walls, the round track has %d" % (world_file, len(walls),
                                                                  WALL_COUNT))
    return boxes


def check_spawn_scan(ranges, who):
    """Raises unless rays 90 and 270 of the first scan see the lane's walls by hand."""
    for index, expected in ((90, SPAWN_LEFT_RANGE_M), (270, SPAWN_RIGHT_RANGE_M)):
        got = ranges[index]
        if not abs(got - expected) <= RANGE_TOLERANCE_M:
            raise SanityError("%s: lidar ray %d at the spawn pose reads %.4f m, the wall table "
                              "gives %.4f m" % (who, index, got, expected))


class Track:
    """Path length and heading change of the robot, sampled at the odometry rate."""

    def __init__(self):
        self.length_m = 0.0
        self.turned_rad = 0.0
        self.last = None

    def add(self, x, y, yaw):
        if self.last is not None:
            self.length_m += math.hypot(x - self.last[0], y - self.last[1])
            self.turned_rad += math.remainder(yaw - self.last[2], 2.0 * math.pi)
        self.last = (x, y, yaw)

    def check(self, sim_s, who):
        """Raises unless the robot drove the command's arc: v*t and w*t within 15 %."""
        want_m, want_rad = CMD_LINEAR_MPS * sim_s, CMD_ANGULAR_RADPS * sim_s
        if not (0.85 * want_m <= self.length_m <= 1.15 * want_m
                and 0.85 * want_rad <= self.turned_rad <= 1.15 * want_rad):
            raise SanityError("%s: the robot drove %.2f m and turned %.2f rad in %.1f s; the "
                              "command gives %.2f m and %.2f rad" % (
                                  who, self.length_m, self.turned_rad, sim_s, want_m, want_rad))


TEXTURED_SHADES = 40   # fewest shades of wall and of floor in a frame of the textured track


def check_textured_frame(pixels, who):
    """Raises unless a frame of textured_world.py's round track, (r, g, b) pixels, shows its
    images: at least TEXTURED_SHADES shades among its wall (brown) pixels and among its floor
    (grey) pixels, where the plain track's lit flat faces show a handful of each."""
    walls, floors = set(), set()
    for r, g, b in pixels:
        if r > b + 15 and g > b:
            walls.add((r, g, b))
        elif abs(r - b) < 10 and r > 40:
            floors.add((r, g, b))
    if len(walls) < TEXTURED_SHADES or len(floors) < TEXTURED_SHADES:
        raise SanityError("%s: the textured frame shows %d shades of wall and %d of floor, "
                          "fewer than %d: its textures were not drawn" % (
                              who, len(walls), len(floors), TEXTURED_SHADES))


def yaw_of_quaternion(w, x, y, z):
    """Heading (rotation about world z) of a unit quaternion."""
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def wall_segments(world_file):
    """Centre lines of the colliding walls as ((x0, y0), (x1, y1), half_thickness)."""
    segments = []
    for _, (x, y, _, yaw), size, _, collides in read_world(world_file):
        if collides:
            # The box's long side is its y size; the wall's yaw turns it in the plane.
            half = size[1] / 2
            dx, dy = -math.sin(yaw) * half, math.cos(yaw) * half
            segments.append(((x - dx, y - dy), (x + dx, y + dy), size[0] / 2))
    return segments


def distance_to_segment(point, segment):
    (x0, y0), (x1, y1), half_thickness = segment
    vx, vy = x1 - x0, y1 - y0
    t = max(0.0, min(1.0, ((point[0] - x0) * vx + (point[1] - y0) * vy) / (vx * vx + vy * vy)))
    return math.hypot(point[0] - x0 - t * vx, point[1] - y0 - t * vy) - half_thickness


CIRCLE_RADIUS_M = CMD_LINEAR_MPS / CMD_ANGULAR_RADPS
ROBOT_REACH_M = 0.13   # farthest point of the Burger's footprint from base_footprint


def circle_starts(world_file, count, cell_m=0.05):
    """Start poses (x, y, yaw) for `count` Burgers that each drive the command's circle inside
    the track without touching a wall or another robot's circle. The first is the spawn pose;
    the others are circle centres found by flood-filling the track from it (so none is outside
    the outer walls), taken in order of distance from the spawn."""
    segments = wall_segments(world_file)
    xs = [c for s in segments for c in (s[0][0], s[1][0])]
    ys = [c for s in segments for c in (s[0][1], s[1][1])]
    clear = CIRCLE_RADIUS_M + ROBOT_REACH_M
    # A counter-clockwise circle's centre is on the robot's left.
    spawn_centre = (-CIRCLE_RADIUS_M * math.sin(SPAWN_YAW_RAD),
                    CIRCLE_RADIUS_M * math.cos(SPAWN_YAW_RAD))
    start = (round(spawn_centre[0] / cell_m), round(spawn_centre[1] / cell_m))
    seen, frontier, inside = {start}, [start], []
    while frontier:
        cell = frontier.pop()
        point = (cell[0] * cell_m, cell[1] * cell_m)
        inside.append(point)
        for nx, ny in ((cell[0] + 1, cell[1]), (cell[0] - 1, cell[1]),
                       (cell[0], cell[1] + 1), (cell[0], cell[1] - 1)):
            p = (nx * cell_m, ny * cell_m)
            if (nx, ny) in seen or not (min(xs) < p[0] < max(xs) and min(ys) < p[1] < max(ys)):
                continue
            seen.add((nx, ny))
            if min(distance_to_segment(p, s) for s in segments) > cell_m:
                frontier.append((nx, ny))
    centres = [spawn_centre]
    for point in sorted(inside, key=lambda q: math.hypot(q[0] - spawn_centre[0],
                                                         q[1] - spawn_centre[1])):
        if len(centres) == count:
            break
        if min(distance_to_segment(point, s) for s in segments) >= clear and all(
                math.hypot(point[0] - c[0], point[1] - c[1]) >= 2 * clear for c in centres):
            centres.append(point)
    if len(centres) < count:
        raise SanityError("%s: room for %d driving circles, not %d" % (world_file, len(centres),
                                                                     count))
    # On a counter-clockwise circle the robot faces +y where it is east of the centre.
    poses = [(0.0, 0.0, SPAWN_YAW_RAD)]
    poses += [(cx + CIRCLE_RADIUS_M, cy, math.pi / 2) for cx, cy in centres[1:]]
    return poses


def write_circle_starts(world_file, count, path):
    """Writes circle_starts(world_file, count) to `path`, an "x y yaw" line per robot (the
    poses file of bullet_sim_bench and multi_robot.py); returns `path`."""
    with open(path, "w") as f:
        for x, y, yaw in circle_starts(world_file, count):
            f.write("%r %r %r\n" % (x, y, yaw))
    return path
