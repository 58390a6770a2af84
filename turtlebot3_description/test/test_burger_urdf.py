"""The expanded Burger: valid for check_urdf, exactly the specified links and
joints, a single root, its Gazebo tags carrying the Burger's figures."""
import os
import tempfile
import unittest
import xml.etree.ElementTree as ET

from mobility_testing import urdf_model

XACRO = os.path.join(os.path.dirname(__file__), '..', 'urdf', 'turtlebot3_burger.urdf.xacro')

BURGER_JOINTS = {
    'base_joint': ('fixed', 'base_footprint', 'base_link'),
    'wheel_left_joint': ('continuous', 'base_link', 'wheel_left_link'),
    'wheel_right_joint': ('continuous', 'base_link', 'wheel_right_link'),
    'caster_back_joint': ('fixed', 'base_link', 'caster_back_link'),
    'imu_joint': ('fixed', 'base_link', 'imu_link'),
    'scan_joint': ('fixed', 'base_link', 'base_scan'),
    'pole_left_joint': ('fixed', 'base_link', 'pole_left_link'),
    'pole_right_joint': ('fixed', 'base_link', 'pole_right_link'),
    'mountplate_joint': ('fixed', 'pole_right_link', 'mountplate_link'),
    'camera_joint': ('fixed', 'base_link', 'camera_link'),
    'camera_optical_joint': ('fixed', 'camera_link', 'camera_optical_link'),
}
FLAG_JOINTS = {
    'pole_mountplate_joint': ('fixed', 'mountplate_link', 'pole_link'),
    'flag_pole_joint': ('continuous', 'pole_link', 'flag_link'),
}


def expected_links(joints):
    return {'base_footprint'} | {child for _, _, child in joints.values()}


class BurgerModelTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.with_flag = urdf_model.xacro(XACRO)
        cls.without_flag = urdf_model.xacro(XACRO, 'flag:=false')

    def test_check_urdf_passes_with_and_without_flag(self):
        for text in (self.with_flag, self.without_flag):
            code, output = urdf_model.check_urdf(text)
            self.assertEqual(code, 0, output)
            self.assertIn('root Link: base_footprint', output)

    def test_joints_and_links_with_flag(self):
        joints = dict(BURGER_JOINTS, **FLAG_JOINTS)
        self.assertEqual(urdf_model.joints(self.with_flag), joints)
        self.assertEqual(urdf_model.links(self.with_flag), expected_links(joints))
        self.assertEqual(urdf_model.roots(self.with_flag), {'base_footprint'})

    def test_joints_and_links_without_flag(self):
        self.assertEqual(urdf_model.joints(self.without_flag), BURGER_JOINTS)
        self.assertEqual(urdf_model.links(self.without_flag), expected_links(BURGER_JOINTS))
        self.assertEqual(urdf_model.roots(self.without_flag), {'base_footprint'})

    def test_wheel_geometry_puts_axles_one_radius_above_ground(self):
        root = ET.fromstring(self.with_flag)
        base_z = float(root.find("joint[@name='base_joint']/origin").get('xyz').split()[2])
        for side in ('left', 'right'):
            joint_z = float(root.find(f"joint[@name='wheel_{side}_joint']/origin")
                            .get('xyz').split()[2])
            wheel = root.find(f"link[@name='wheel_{side}_link']/collision/geometry/cylinder")
            self.assertAlmostEqual(base_z + joint_z, float(wheel.get('radius')), places=6)
            self.assertAlmostEqual(float(wheel.get('length')), 0.018)

    def test_urdf_to_graphiz_draws_every_link(self):
        with tempfile.TemporaryDirectory() as tmp:
            graph = urdf_model.graphiz(self.with_flag, tmp)
        for link in urdf_model.links(self.with_flag):
            self.assertIn(f'"{link}"', graph)
        self.assertIn('"base_footprint" -> "base_joint"', graph)

    def test_gazebo_tags_hold_the_burger_figures(self):
        root = ET.fromstring(self.with_flag)
        ray = root.find("gazebo[@reference='base_scan']/sensor[@type='ray']")
        self.assertEqual(ray.findtext('update_rate'), '5')
        self.assertEqual(ray.findtext('ray/scan/horizontal/samples'), '360')
        self.assertAlmostEqual(float(ray.findtext('ray/range/min')), 0.12)
        self.assertAlmostEqual(float(ray.findtext('ray/range/max')), 3.5)
        self.assertAlmostEqual(float(ray.findtext('ray/noise/stddev')), 0.01)
        self.assertEqual(ray.find('plugin').get('filename'), 'libgazebo_ros_laser.so')
        plugins = {p.get('filename'): p for p in root.findall('gazebo/plugin')}
        drive = plugins['libgazebo_ros_diff_drive.so']
        self.assertAlmostEqual(float(drive.findtext('wheelSeparation')), 0.160)
        self.assertAlmostEqual(float(drive.findtext('wheelDiameter')), 0.066)
        self.assertEqual(drive.findtext('leftJoint'), 'wheel_left_joint')
        self.assertEqual(drive.findtext('updateRate'), '30')
        self.assertEqual(plugins['libgazebo_ros_imu.so'].findtext('updateRate'), '200')
        camera = root.find("gazebo[@reference='camera_link']/sensor[@type='camera']/camera")
        self.assertEqual(camera.findtext('image/width'), '640')
        self.assertEqual(camera.findtext('image/height'), '480')
        self.assertAlmostEqual(float(camera.findtext('horizontal_fov')), 1.5707)

    def test_xacro_typo_fails_with_the_parser_message(self):
        with tempfile.NamedTemporaryFile('w', suffix='.xacro') as bad:
            bad.write(open(XACRO).read().replace('${wheel_radius}', '${wheel_raduis}', 1))
            bad.flush()
            with self.assertRaises(RuntimeError) as ctx:
                urdf_model.xacro(bad.name)
        self.assertIn("name 'wheel_raduis' is not defined", str(ctx.exception))


if __name__ == '__main__':
    unittest.main()
