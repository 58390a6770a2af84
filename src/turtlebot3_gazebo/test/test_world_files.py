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


def load_models_generator():
    scripts = os.path.join(PACKAGE_DIR, "scripts")
    import sys
    sys.path.insert(0, scripts)
    spec = importlib.util.spec_from_file_location(
        "make_playground_models", os.path.join(scripts, "make_playground_models.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class PlaygroundModels(unittest.TestCase):
    def test_models_and_obstacle_world_match_their_generator(self):
        for relative, data in load_models_generator().files().items():
            with open(os.path.join(PACKAGE_DIR, relative), "rb") as generated:
                self.assertEqual(generated.read(), data, relative)

    def test_cone_mesh_is_a_closed_cone_of_the_stated_size(self):
        import struct
        path = os.path.join(PACKAGE_DIR, "models/traffic_cone/meshes/traffic_cone.stl")
        with open(path, "rb") as stl:
            data = stl.read()
        count = struct.unpack_from("<I", data, 80)[0]
        self.assertEqual(len(data), 84 + 50 * count)
        self.assertEqual(count, 12 + 32)  # the foot's 6 faces, 32 cone facets
        vertices = [struct.unpack_from("<3f", data, 84 + 50 * i + 12 + 12 * k)
                    for i in range(count) for k in range(3)]
        xs, ys, zs = zip(*vertices)
        self.assertAlmostEqual(max(zs), 0.30, places=6)
        self.assertAlmostEqual(min(zs), 0.0, places=6)
        self.assertAlmostEqual(max(xs), 0.10, places=6)  # the 0.2 m foot
        # Facet normals point away from the cone's axis on its sides.
        for i in range(12, count):
            n = struct.unpack_from("<3f", data, 84 + 50 * i)
            cx, cy, _ = [sum(c) / 3 for c in zip(*vertices[3 * i:3 * i + 3])]
            self.assertGreater(n[0] * cx + n[1] * cy, 0)

    def test_obstacle_world_includes_every_model_by_uri(self):
        world = ET.parse(os.path.join(PACKAGE_DIR, "worlds", "roundTrack_obstacles.world"))
        uris = [u.text for u in world.getroot().iter("uri")]
        self.assertEqual(uris[:3], ["model://sun", "model://ground_plane", "model://papptown_track"])
        self.assertEqual(sorted(set(uris[3:])), ["model://cardboard_box", "model://traffic_cone"])
        for model in ("papptown_track", "traffic_cone", "cardboard_box"):
            config = ET.parse(os.path.join(PACKAGE_DIR, "models", model, "model.config"))
            sdf_file = config.getroot().find("sdf").text
            self.assertTrue(os.path.isfile(os.path.join(PACKAGE_DIR, "models", model, sdf_file)))
        box = ET.parse(os.path.join(PACKAGE_DIR, "models/cardboard_box/model.sdf")).getroot()
        self.assertIsNone(box.find("model/static"), "the box must be movable")
        # A uniform box: ixx = m (y^2 + z^2) / 12 with m 0.5, 0.30 x 0.30 x 0.25 m.
        self.assertAlmostEqual(float(box.find("model/link/inertial/inertia/ixx").text),
                               0.5 * (0.09 + 0.0625) / 12, places=6)
