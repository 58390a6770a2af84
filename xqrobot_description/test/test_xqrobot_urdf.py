"""The xqrobot URDF: valid, 5 links and 4 joints as the article draws them, and
its dimensions: wheels and casters touch one ground plane 0.015 m below the
chassis."""
import os
import tempfile
import unittest
import xml.etree.ElementTree as ET

from mobility_testing import urdf_model

URDF = os.path.join(os.path.dirname(__file__), '..', 'urdf', 'xqrobot_base.urdf')

JOINTS = {
    'left_wheel_joint': ('continuous', 'base_link', 'left_wheel_link'),
    'right_wheel_joint': ('continuous', 'base_link', 'right_wheel_link'),
    'front_caster_joint': ('continuous', 'base_link', 'front_caster_link'),
    'back_caster_joint': ('continuous', 'base_link', 'back_caster_link'),
}


def floats(text):
    return [float(v) for v in text.split()]


class XqrobotModelTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(URDF) as f:
            cls.text = f.read()
        cls.root = ET.fromstring(cls.text)

    def test_check_urdf_passes(self):
        code, output = urdf_model.check_urdf(self.text)
        self.assertEqual(code, 0, output)
        self.assertIn('root Link: base_link has 4 child(ren)', output)

    def test_five_links_four_joints(self):
        self.assertEqual(urdf_model.joints(self.text), JOINTS)
        self.assertEqual(urdf_model.links(self.text),
                         {'base_link'} | {c for _, _, c in JOINTS.values()})
        self.assertEqual(urdf_model.roots(self.text), {'base_link'})

    def test_wheels_turn_about_y(self):
        for name in ('left_wheel_joint', 'right_wheel_joint'):
            axis = self.root.find(f"joint[@name='{name}']/axis")
            self.assertEqual(floats(axis.get('xyz')), [0, 1, 0])

    def test_dimensions_and_ground_clearance(self):
        chassis = self.root.find("link[@name='base_link']/visual/geometry/cylinder")
        self.assertEqual((float(chassis.get('radius')), float(chassis.get('length'))), (0.1, 0.08))
        chassis_bottom = -float(chassis.get('length')) / 2
        bottoms = []
        for name in JOINTS:
            joint = self.root.find(f"joint[@name='{name}']")
            z = floats(joint.find('origin').get('xyz'))[2]
            link = joint.find('child').get('link')
            geometry = self.root.find(f"link[@name='{link}']/visual/geometry")
            shape = geometry.find('cylinder')
            if shape is None:
                shape = geometry.find('sphere')
                self.assertAlmostEqual(float(shape.get('radius')), 0.0075)
            else:
                self.assertAlmostEqual(float(shape.get('radius')), 0.0325)
                self.assertAlmostEqual(float(shape.get('length')), 0.015)
            bottoms.append(z - float(shape.get('radius')))
        for bottom in bottoms:
            self.assertAlmostEqual(bottom, bottoms[0], places=9)
        self.assertAlmostEqual(chassis_bottom - bottoms[0], 0.015, places=9)

    def test_urdf_to_graphiz_draws_the_tree(self):
        with tempfile.TemporaryDirectory() as tmp:
            graph = urdf_model.graphiz(self.text, tmp)
        for name, (_, parent, child) in JOINTS.items():
            self.assertIn(f'"{parent}" -> "{name}"', graph)
            self.assertIn(f'"{name}" -> "{child}"', graph)


if __name__ == '__main__':
    unittest.main()
