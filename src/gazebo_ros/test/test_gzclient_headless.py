"""gzclient without an X server (DISPLAY unset, or naming a display nobody serves): it says
so and exits 0 at once, where RViz would abort (exit -6)."""
import os
import subprocess
import unittest

import rospkg

GZCLIENT = os.path.join(rospkg.RosPack().get_path('gazebo_ros'), 'scripts', 'gzclient')


def run_gzclient(display):
    env = dict(os.environ, PATH='/usr/bin:/bin:' + os.environ['PATH'])
    env.pop('DISPLAY', None)
    if display is not None:
        env['DISPLAY'] = display
    return subprocess.run([GZCLIENT], env=env, capture_output=True, text=True, timeout=30)


class GzclientHeadless(unittest.TestCase):
    def test_without_display_variable(self):
        result = run_gzclient(None)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stderr.strip(), "gzclient: no X display (DISPLAY=''): "
                         "the simulation runs without its view")

    def test_with_a_display_nobody_serves(self):
        result = run_gzclient(':59999')
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stderr.strip(), "gzclient: no X display (DISPLAY=':59999'): "
                         "the simulation runs without its view")


if __name__ == '__main__':
    unittest.main()
