"""The round track painted with textures, for the camera benchmark: the world file with its
ground plane and walls wearing OGRE material scripts, as Gazebo worlds paint theirs (one
texture_unit per material), and the PNG images the scripts name, written into a folder of
their own. bullet_sim reads the scripts; mjcf_builder hands MuJoCo the same image files as
2D textures. The ground's image repeats every FLOOR_TILE_M metres in both, and keeps the
floor grey; the walls' brick image keeps them brown, so that a frame's sanity check by hue
holds for the plain track and the textured one alike.

  textured_world.py WORLD OUT_DIR     writes OUT_DIR/roundTrack_textured.world, prints its path
"""
import os
import random
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

FLOOR_TILE_M = 1.0
GROUND_SIZE_M = 100.0   # the round track's ground plane: <size>100 100</size>
IMAGE_SIZE = 256
FLOOR_IMAGE = "bench_floor.png"
WALL_IMAGE = "bench_wall.png"
FLOOR_MATERIAL = "Bench/Floor"
WALL_MATERIAL = "Bench/Wall"
WORLD_NAME = "roundTrack_textured.world"


def png_bytes(width, height, rgb_rows):
    """An 8-bit RGB PNG of `rgb_rows` (height rows of width * 3 bytes each)."""
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    raw = b"".join(b"\x00" + bytes(row) for row in rgb_rows)
    return (b"\x89PNG\r\n\x1a\n"
            + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def floor_rows(size=IMAGE_SIZE, seed=7):
    """Grey asphalt: every texel grey (r = g = b), 70 to 170, seeded noise."""
    rng = random.Random(seed)
    rows = []
    for _ in range(size):
        row = bytearray()
        for _ in range(size):
            v = rng.randint(70, 170)
            row += bytes((v, v, v))
        rows.append(row)
    return rows


def wall_rows(size=IMAGE_SIZE, seed=11):
    """Brown bricks in a running bond, 8 courses of 4 bricks, lighter mortar lines between:
    every texel has red above blue by more than 15 and green above blue."""
    rng = random.Random(seed)
    course, brick = size // 8, size // 4
    shades = [(rng.randint(130, 170), rng.randint(85, 110), rng.randint(40, 60))
              for _ in range(8 * 5)]
    rows = []
    for y in range(size):
        row = bytearray()
        level = y // course
        shift = brick // 2 if level % 2 else 0
        for x in range(size):
            index = (x + shift) // brick
            if y % course < 3 or (x + shift) % brick < 3:
                row += bytes((190, 170, 130))  # mortar
            else:
                row += bytes(shades[level * 5 + index])
        rows.append(row)
    return rows


def material_script(floor_scale):
    unit = "      texture_unit\n      {\n        texture %s\n%s      }\n"
    return ("material %s\n{\n  technique\n  {\n    pass\n    {\n%s    }\n  }\n}\n\n"
            "material %s\n{\n  technique\n  {\n    pass\n    {\n%s    }\n  }\n}\n" % (
                FLOOR_MATERIAL, unit % (FLOOR_IMAGE, "        scale %g %g\n" % (
                    floor_scale, floor_scale)),
                WALL_MATERIAL, unit % (WALL_IMAGE, "")))


def paint(material, out_dir, name):
    """Adds a <script> naming `name` in out_dir's scripts and textures to `material`."""
    script = ET.SubElement(material, "script")
    for folder in ("scripts", "textures"):
        ET.SubElement(script, "uri").text = "file://" + os.path.join(out_dir, "materials", folder)
    ET.SubElement(script, "name").text = name


def write(world_file, out_dir):
    """Writes the textured world, its material script and images; returns the world's path."""
    out_dir = os.path.abspath(out_dir)
    for folder in ("scripts", "textures"):
        os.makedirs(os.path.join(out_dir, "materials", folder), exist_ok=True)
    textures = os.path.join(out_dir, "materials", "textures")
    with open(os.path.join(textures, FLOOR_IMAGE), "wb") as f:
        f.write(png_bytes(IMAGE_SIZE, IMAGE_SIZE, floor_rows()))
    with open(os.path.join(textures, WALL_IMAGE), "wb") as f:
        f.write(png_bytes(IMAGE_SIZE, IMAGE_SIZE, wall_rows()))
    # OGRE scales texture coordinates about the image's centre: on the plane, whose image
    # spans its whole size once, a scale of tile / size repeats it every tile.
    with open(os.path.join(out_dir, "materials", "scripts", "bench.material"), "w") as f:
        f.write(material_script(FLOOR_TILE_M / GROUND_SIZE_M))
    tree = ET.parse(world_file)
    painted = {FLOOR_MATERIAL: 0, WALL_MATERIAL: 0}
    for model in tree.getroot().iter("model"):
        name = model.get("name")
        material = model.find("link/visual/material")
        if material is None:
            continue
        if name == "ground_plane":
            paint(material, out_dir, FLOOR_MATERIAL)
            painted[FLOOR_MATERIAL] += 1
        elif name.startswith("wall_"):
            paint(material, out_dir, WALL_MATERIAL)
            painted[WALL_MATERIAL] += 1
    if painted[FLOOR_MATERIAL] != 1 or painted[WALL_MATERIAL] == 0:
        raise ValueError("%s: no ground_plane or wall_* visual to paint (%s)" % (world_file,
                                                                               painted))
    path = os.path.join(out_dir, WORLD_NAME)
    tree.write(path, xml_declaration=True, encoding="unicode")
    return path


def texture_files(out_dir):
    """The floor's and the walls' image files that write() put in out_dir."""
    textures = os.path.join(os.path.abspath(out_dir), "materials", "textures")
    return os.path.join(textures, FLOOR_IMAGE), os.path.join(textures, WALL_IMAGE)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: textured_world.py WORLD OUT_DIR")
    print(write(sys.argv[1], sys.argv[2]))
