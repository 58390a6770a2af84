"""Tests of the textured round track the camera benchmark draws (bench/textured_world.py):
its images read back by OpenCV, its world file against the plain one, and a frame of it
drawn by bullet_sim_camera_bench (needs a built workspace): /usr/bin/python3 -m pytest bench/"""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import cv2
import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ros_bench  # noqa: E402
import scenario  # noqa: E402
import textured_camera  # noqa: E402
import textured_world  # noqa: E402

CAMERA_BENCH = os.path.join(ros_bench.devel_dir(), "lib/bullet_sim/bullet_sim_camera_bench")


@pytest.fixture(scope="module")
def textured(tmp_path_factory):
    return textured_world.write(ros_bench.WORLD, str(tmp_path_factory.mktemp("textured")))


def test_the_images_read_back_grey_floor_and_brown_bricks(textured):
    floor_file, wall_file = textured_world.texture_files(os.path.dirname(textured))
    floor = cv2.imread(floor_file, cv2.IMREAD_COLOR)  # BGR
    wall = cv2.imread(wall_file, cv2.IMREAD_COLOR)
    assert floor.shape == wall.shape == (256, 256, 3)
    b, g, r = (floor[:, :, k].astype(int) for k in range(3))
    assert (r == g).all() and (g == b).all()
    assert r.min() >= 70 and r.max() <= 170 and len(set(r.flatten())) > 90
    b, g, r = (wall[:, :, k].astype(int) for k in range(3))
    assert (r > b + 15).all() and (g > b).all()
    # Mortar rows: the first 3 texel rows of each of the 8 courses are one colour.
    assert (wall[0:3] == wall[0, 0]).all() and (wall[32:35] == wall[0, 0]).all()
    assert not (wall[3] == wall[0, 0]).all()


def test_the_ground_and_every_wall_wear_a_script_the_rest_is_the_plain_track(textured):
    root = ET.parse(textured).getroot()
    scripts = {}
    for model in root.iter("model"):
        script = model.find("link/visual/material/script")
        if script is not None:
            scripts[model.get("name")] = script
            for uri in script.findall("uri"):
                assert uri.text.startswith("file:///")
                assert os.path.isdir(uri.text[len("file://"):])
    assert scripts.pop("ground_plane").findtext("name") == textured_world.FLOOR_MATERIAL
    assert sorted(scripts) == ["wall_%02d" % k for k in range(scenario.WALL_COUNT)]
    assert {s.findtext("name") for s in scripts.values()} == {textured_world.WALL_MATERIAL}
    assert scenario.read_world(textured) == scenario.read_world(ros_bench.WORLD)


def test_the_floor_image_repeats_every_metre_of_the_100_m_plane(textured):
    # OGRE scales texture coordinates about the image's centre by 1/scale: the plane's image,
    # spanning its 100 m once, repeats 1/scale times.
    with open(os.path.join(os.path.dirname(textured), "materials/scripts/bench.material")) as f:
        script = f.read()
    floor = script[script.index("material " + textured_world.FLOOR_MATERIAL):
                   script.index("material " + textured_world.WALL_MATERIAL)]
    scale = [float(v) for v in floor.split("scale")[1].split()[:2]]
    assert scale == [textured_world.FLOOR_TILE_M / 100.0] * 2
    assert "scale" not in script[script.index("material " + textured_world.WALL_MATERIAL):]


@pytest.fixture(scope="module")
def burger(tmp_path_factory):
    if not os.path.exists(CAMERA_BENCH):
        pytest.skip("no built workspace: %s missing" % CAMERA_BENCH)
    path = str(tmp_path_factory.mktemp("urdf") / "burger.urdf")
    return ros_bench.burger_urdf(ros_bench.ros_env(11459), path)


def frame_of(world, burger, tmp_path):
    frame = str(tmp_path / "frame.ppm")
    out = subprocess.run([CAMERA_BENCH, "--save-frame", frame, burger, world, "0.1"],
                         check=True, stdout=subprocess.PIPE, universal_newlines=True).stdout
    assert "warning:" not in out
    return textured_camera.read_ppm(frame)


def test_bullet_sim_draws_the_images_and_the_check_tells_them_from_the_plain_track(
        textured, burger, tmp_path):
    width, height, pixels = frame_of(textured, burger, tmp_path)
    assert (width, height, len(pixels)) == (640, 480, 640 * 480)
    scenario.check_textured_frame(pixels, "bullet_sim")
    _, _, plain = frame_of(ros_bench.WORLD, burger, tmp_path)
    with pytest.raises(scenario.SanityError, match="textures were not drawn"):
        scenario.check_textured_frame(plain, "bullet_sim")
