"""The commands of the two source texts resolve here as they are typed: every
`rosrun` and `roslaunch` target, the URDF tools on the article's file, and the
plain programs the texts call (sudo, gedit, catkin_create_pkg)."""
import os
import shutil
import subprocess
import tempfile
import unittest

import rospkg

ROSPACK = rospkg.RosPack()

ROSRUN = [
    ('rqt_robot_steering', 'rqt_robot_steering'),
    ('rqt_image_view', 'rqt_image_view'),
    ('rqt_graph', 'rqt_graph'),
    ('rviz', 'rviz'),
    ('xacro', 'xacro'),
]
ROSLAUNCH = [
    ('turtlebot3_gazebo', 'roundTrack_simulation.launch'),
    ('turtlebot_urdf', 'model.launch'),
    ('xqrobot_description', 'display_xqrobot.launch'),
]
NODES_OF_LAUNCHES = [
    ('joint_state_publisher_gui', 'joint_state_publisher_gui'),
    ('robot_state_publisher', 'robot_state_publisher'),
    ('bullet_sim', 'bullet_sim_node'),
]


def run(*args, cwd=None):
    return subprocess.run(args, capture_output=True, text=True, timeout=60, cwd=cwd)


class SeedCommandsTest(unittest.TestCase):
    def test_rosrun_targets_resolve_to_executables(self):
        for package, executable in ROSRUN + NODES_OF_LAUNCHES:
            result = run('rosrun', '--prefix', 'echo', package, executable)
            self.assertEqual(result.returncode, 0, f'rosrun {package} {executable}: {result.stderr}')
            path = result.stdout.split()[0]
            self.assertTrue(os.access(path, os.X_OK), f'{package}/{executable}: {path}')

    def test_overlays_come_from_the_workspace(self):
        for package, executable in [('rqt_graph', 'rqt_graph'),
                                    ('joint_state_publisher_gui', 'joint_state_publisher_gui')]:
            path = run('rosrun', '--prefix', 'echo', package, executable).stdout.split()[0]
            self.assertFalse(path.startswith('/usr/'), f'{package} resolves to {path}')

    def test_roslaunch_files_resolve(self):
        for package, launch in ROSLAUNCH:
            result = run('roslaunch', '--files', package, launch)
            self.assertEqual(result.returncode, 0, f'roslaunch {package} {launch}: {result.stderr}')
            self.assertIn(os.path.join(ROSPACK.get_path(package), 'launch', launch), result.stdout)

    def test_urdf_tools_on_the_article_file(self):
        source = os.path.join(ROSPACK.get_path('xqrobot_description'), 'urdf')
        with tempfile.TemporaryDirectory() as tmp:
            shutil.copy(os.path.join(source, 'xqrobot_base.urdf'), tmp)
            self.assertEqual(run('check_urdf', 'xqrobot_base.urdf', cwd=tmp).returncode, 0)
            self.assertEqual(run('urdf_to_graphiz', 'xqrobot_base.urdf', cwd=tmp).returncode, 0)
            self.assertTrue(os.path.getsize(os.path.join(tmp, 'xqrobot.gv')) > 0)
            self.assertTrue(os.path.getsize(os.path.join(tmp, 'xqrobot.pdf')) > 0)

    def test_plain_programs_exist(self):
        for program in ('sudo', 'gedit', 'catkin_create_pkg', 'check_urdf', 'urdf_to_graphiz'):
            self.assertIsNotNone(shutil.which(program), f'{program} is not on PATH')
        self.assertEqual(run('sudo', '-n', 'true').returncode, 0)


if __name__ == '__main__':
    unittest.main()
