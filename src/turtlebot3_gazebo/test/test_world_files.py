"""The committed round-track world is what its generator writes from the wall table, and
both worlds are well-formed SDF with the expected models."""
import importlib.util
import os
import unittest
import xml.etree.ElementTree as ET

PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load_generator():
    path = os.path.join(PACKAGE_DIR, "scripts", "make_round_track_world.py")
    spec = importlib.util.spec_from_file_location("make_round_track_world", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class WorldFiles(unittest.TestCase):
    def test_round_track_matches_its_generator(self):
        with open(os.path.join(PACKAGE_DIR, "worlds", "roundTrack.world")) as world_file:
            self.assertEqual(world_file.read(), load_generator().world_text())

    def test_round_track_walls_follow_the_table(self):
        table = load_generator().WALLS_X_Y_YAW_LENGTH
        world = ET.parse(os.path.join(PACKAGE_DIR, "worlds", "roundTrack.world")).getroot()
        walls = [m for m in world.iter("model") if m.get("name").startswith("wall_")]
        self.assertEqual(len(walls), 21)
        for wall, (x, y, yaw, length) in zip(walls, table):
            pose = [float(v) for v in wall.find("pose").text.split()]
            self.assertEqual(pose, [x, y, 0.25, 0, 0, yaw])
            size = [float(v) for v in wall.find("link/collision/geometry/box/size").text.split()]
            self.assertEqual(size, [0.015, length, 0.5])
        start_line = world.find("world/model[@name='start_line']")
        self.assertIsNone(start_line.find("link/collision"), "the start line must not collide")

    def test_empty_world_has_ground_and_sun(self):
        world = ET.parse(os.path.join(PACKAGE_DIR, "worlds", "empty.world")).getroot()
        self.assertEqual([m.get("name") for m in world.iter("model")], ["ground_plane"])
        self.assertEqual(world.find("world/light").get("type"), "directional")
        self.assertEqual(float(world.find("world/physics/max_step_size").text), 0.001)
