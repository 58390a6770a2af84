#!/usr/bin/python3
"""The query RViz makes at start-up finds the package and answers without an error."""
import subprocess
import unittest


class RvizMediaQuery(unittest.TestCase):
    def test_rospack_answers_rvizs_query_without_an_error(self):
        out = subprocess.run(['rospack', 'plugins', '--attrib=ogre_media_path', 'media_export'],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             universal_newlines=True, timeout=60)
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertNotIn('no such package', out.stderr)


if __name__ == '__main__':
    unittest.main()
