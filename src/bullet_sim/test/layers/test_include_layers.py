#!/usr/bin/python3
"""The include direction of bullet_sim's layers (include_layers.py), on the package's own
sources and on includes that break it."""
import os
import shutil
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import include_layers  # noqa: E402

PACKAGE = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))


def broken(relpath, include):
    return include_layers.violations(relpath, ['#include "%s"' % include])


class PackageSources(unittest.TestCase):
    def test_every_include_goes_down(self):
        self.assertEqual(include_layers.check_package(PACKAGE), [])

    def test_every_core_file_is_in_a_layer(self):
        for top in ('src/core', 'include/bullet_sim'):
            for folder, _, files in os.walk(os.path.join(PACKAGE, top)):
                for name in files:
                    relpath = os.path.relpath(os.path.join(folder, name), PACKAGE)
                    self.assertIsNotNone(include_layers.layer_of_path(relpath), relpath)


class Direction(unittest.TestCase):
    def test_description_never_includes_physics(self):
        found = broken('src/core/description/sdf/sdf_model.cpp', 'physics/physics_world.h')
        self.assertEqual(len(found), 1)
        self.assertIn('src/core/description/sdf/sdf_model.cpp:1: description includes '
                      'physics/physics_world.h (physics)', found[0][2])

    def test_nothing_below_the_simulation_includes_it(self):
        for relpath in ('src/core/physics/diff_drive.h', 'src/core/sensors/ray_sensor.cpp',
                        'include/bullet_sim/world/entity_frames.h'):
            self.assertEqual(len(broken(relpath, 'bullet_sim/simulation.h')), 1, relpath)

    def test_render_sits_on_top(self):
        self.assertEqual(broken('src/core/render/camera_renderer.cpp', 'bullet_sim/simulation.h'), [])
        self.assertEqual(len(broken('src/core/simulation.cpp', 'bullet_sim/render/depth_camera.h')), 1)

    def test_physics_uses_description_and_world(self):
        self.assertEqual(broken('src/core/physics/physics_robot.h', 'description/robot_plan.h'), [])
        self.assertEqual(broken('src/core/physics/physics_robot.h',
                                'bullet_sim/world/entity_frames.h'), [])
        self.assertEqual(len(broken('src/core/physics/physics_robot.h', 'sensors/ray_sensor.h')), 1)

    def test_node_sees_public_headers_only(self):
        self.assertEqual(broken('src/node/topics/robot_io.cpp', 'bullet_sim/simulation.h'), [])
        self.assertEqual(broken('src/node/topics/robot_io.cpp', 'runner/sim_runner.h'), [])
        found = broken('src/node/topics/robot_io.cpp', 'sensors/ray_sensor.h')
        self.assertEqual(len(found), 1)
        self.assertIn('include/bullet_sim/ only', found[0][2])

    def test_python_module_sees_public_headers_only(self):
        self.assertEqual(broken('src/python/module.cpp', 'bullet_sim/simulation.h'), [])
        self.assertEqual(broken('src/python/module.cpp', 'bullet_sim/render/camera_renderer.h'), [])
        self.assertEqual(broken('src/python/module.cpp', 'pybind11/numpy.h'), [])
        found = broken('src/python/module.cpp', 'physics/physics_world.h')
        self.assertEqual(len(found), 1)
        self.assertIn('python uses the core through include/bullet_sim/ only', found[0][2])
        self.assertEqual(len(broken('src/python/module.cpp', 'topics/robot_io.h')), 1)

    def test_other_headers_are_not_judged(self):
        self.assertEqual(broken('src/core/description/xml_values.h', 'tinyxml2.h'), [])
        self.assertEqual(include_layers.violations('test/core/burger.cpp',
                                                   ['#include "physics/physics_world.h"']), [])

    def test_a_file_outside_the_layer_folders_is_named(self):
        root = tempfile.mkdtemp()
        try:
            os.makedirs(os.path.join(root, 'src/core/physics'))
            with open(os.path.join(root, 'src/core/stray.cpp'), 'w') as stray:
                stray.write('#include "physics/physics_world.h"\n')
            with open(os.path.join(root, 'src/core/physics/drive.cpp'), 'w') as drive:
                drive.write('#include <vector>\n#include "sensors/imu_sensor.h"\n')
            messages = sorted(include_layers.check_package(root))
        finally:
            shutil.rmtree(root)
        self.assertEqual(len(messages), 2, messages)
        self.assertIn('src/core/physics/drive.cpp:2: physics includes sensors/imu_sensor.h',
                      messages[0])
        self.assertIn("src/core/stray.cpp: in no layer's folder", messages[1])


if __name__ == '__main__':
    unittest.main()
