#!/usr/bin/python3
"""Our camera on the textured round track (textured_world.py): bullet_sim_camera_bench on
that world, its last frame saved and checked (walls and floor in view, and their images
drawn: many shades of each, scenario.check_textured_frame); no warning may come (a texture
that could not be read is one). Prints the median frame time last.

Usage: textured_camera.py CAMERA_BENCH URDF TEXTURED_WORLD SIM_SECONDS
"""
import os
import re
import subprocess
import sys
import tempfile

import scenario


def read_ppm(path):
    """(width, height, [(r, g, b), ...]) of a binary PPM (P6, maxval 255)."""
    with open(path, "rb") as f:
        data = f.read()
    header = re.match(rb"P6\s+(\d+)\s+(\d+)\s+255\s", data)
    if not header:
        raise ValueError("%s: not a binary 8-bit PPM" % path)
    width, height = int(header.group(1)), int(header.group(2))
    raster = data[header.end():header.end() + 3 * width * height]
    return width, height, [tuple(raster[i:i + 3]) for i in range(0, len(raster), 3)]


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__.strip().splitlines()[-1])
    camera_bench, urdf, world, sim_seconds = sys.argv[1:]
    with tempfile.TemporaryDirectory() as work:
        frame = os.path.join(work, "frame.ppm")
        out = subprocess.run([camera_bench, "--save-frame", frame, urdf, world, sim_seconds],
                             check=True, stdout=subprocess.PIPE, universal_newlines=True).stdout
        print(out, end="")
        warnings = [line for line in out.splitlines() if line.startswith("warning:")]
        if warnings:
            sys.exit("textured camera: %s" % warnings[0])
        _, _, pixels = read_ppm(frame)
    median = re.search(r"frame render: median ([0-9.]+) ms", out)
    try:
        scenario.check_textured_frame(pixels, "bullet_sim")
    except scenario.SanityError as error:
        sys.exit("sanity check failed: %s" % error)
    print("textured frame render: median %s ms" % median.group(1))


if __name__ == "__main__":
    main()
