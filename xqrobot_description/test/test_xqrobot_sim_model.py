"""The xqrobot's simulation model (urdf/xqrobot.urdf.xacro) is the article's robot: the
same links, joints and visuals as urdf/xqrobot_base.urdf, plus a collision of each
visual's shape, an inertial of a solid of that shape, and the skid-steer plugin on the
two drive wheels."""
import os
import subprocess
import unittest
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.dirname(HERE)
BASE = os.path.join(PACKAGE, 'urdf', 'xqrobot_base.urdf')
SIM = os.path.join(PACKAGE, 'urdf', 'xqrobot.urdf.xacro')


def expand(path):
    out = subprocess.run(['xacro', path], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         universal_newlines=True, check=True)
    return ET.fromstring(out.stdout)


def numbers(element, attribute, default='0 0 0'):
    text = default if element is None else element.get(attribute, default)
    return [float(v) for v in text.split()]


def shape(geometry):
    (child,) = list(geometry)
    return child.tag, {k: float(v) for k, v in child.attrib.items()}


class XqrobotSimModel(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.base = ET.parse(BASE).getroot()
        cls.sim = expand(SIM)

    def assert_close(self, a, b, what):
        self.assertEqual(len(a), len(b), what)
        for x, y in zip(a, b):
            self.assertAlmostEqual(x, y, places=9, msg=what)

    def test_joints_are_the_articles(self):
        base = {j.get('name'): j for j in self.base.findall('joint')}
        sim = {j.get('name'): j for j in self.sim.findall('joint')}
        self.assertEqual(set(sim), set(base))
        for name, joint in base.items():
            other = sim[name]
            self.assertEqual(other.get('type'), joint.get('type'), name)
            self.assertEqual(other.find('parent').get('link'), joint.find('parent').get('link'))
            self.assertEqual(other.find('child').get('link'), joint.find('child').get('link'))
            for attribute in ('xyz', 'rpy'):
                self.assert_close(numbers(other.find('origin'), attribute),
                                  numbers(joint.find('origin'), attribute), name + ' origin')
            self.assert_close(numbers(other.find('axis'), 'xyz'),
                              numbers(joint.find('axis'), 'xyz'), name + ' axis')

    def test_visuals_are_the_articles_and_collisions_their_shapes(self):
        base = {l.get('name'): l for l in self.base.findall('link')}
        sim = {l.get('name'): l for l in self.sim.findall('link')}
        self.assertEqual(set(sim), set(base))
        for name, link in base.items():
            visual, other = link.find('visual'), sim[name].find('visual')
            self.assertEqual(shape(other.find('geometry')), shape(visual.find('geometry')), name)
            self.assertEqual(other.find('material').get('name'),
                             visual.find('material').get('name'))
            for attribute in ('xyz', 'rpy'):
                self.assert_close(numbers(other.find('origin'), attribute),
                                  numbers(visual.find('origin'), attribute), name)
            collision = sim[name].find('collision')
            self.assertEqual(shape(collision.find('geometry')), shape(visual.find('geometry')))

    def test_inertials_are_solids_of_the_shapes(self):
        masses = {'base_link': 1.0, 'left_wheel_link': 0.05, 'right_wheel_link': 0.05,
                  'front_caster_link': 0.01, 'back_caster_link': 0.01}
        for link in self.sim.findall('link'):
            inertial = link.find('inertial')
            m = float(inertial.find('mass').get('value'))
            self.assertEqual(m, masses[link.get('name')])
            inertia = {k: float(v) for k, v in inertial.find('inertia').attrib.items()}
            kind, size = shape(link.find('collision/geometry'))
            if kind == 'cylinder':  # about its own axis m r^2 / 2
                r, h = size['radius'], size['length']
                self.assertAlmostEqual(inertia['izz'], m * r * r / 2, places=12)
                self.assertAlmostEqual(inertia['ixx'], m * (3 * r * r + h * h) / 12, places=12)
            else:
                r = size['radius']
                self.assertAlmostEqual(inertia['ixx'], 0.4 * m * r * r, places=12)

    def test_skid_steer_drives_the_two_wheels(self):
        plugins = self.sim.findall('gazebo/plugin')
        self.assertEqual([p.get('filename') for p in plugins],
                         ['libgazebo_ros_skid_steer_drive.so'])
        p = plugins[0]
        self.assertEqual(p.find('leftFrontJoint').text, 'left_wheel_joint')
        self.assertEqual(p.find('leftRearJoint').text, 'left_wheel_joint')
        self.assertEqual(p.find('rightFrontJoint').text, 'right_wheel_joint')
        self.assertEqual(p.find('rightRearJoint').text, 'right_wheel_joint')
        # The wheels' track and diameter, from the joints and the wheel cylinder.
        y = numbers(self.base.find("joint[@name='left_wheel_joint']/origin"), 'xyz')[1]
        self.assertAlmostEqual(float(p.find('wheelSeparation').text), 2 * y)
        wheel = self.base.find("link[@name='left_wheel_link']/visual/geometry/cylinder")
        self.assertAlmostEqual(float(p.find('wheelDiameter').text), 2 * float(wheel.get('radius')))


if __name__ == '__main__':
    unittest.main()
