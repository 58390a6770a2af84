"""Settings from the command line and private parameters."""
import tempfile
import unittest

from mobility_image_view.config import ConfigError, make_config


class ConfigTest(unittest.TestCase):
    def test_defaults(self):
        config = make_config([], {})
        self.assertEqual((config.topic, config.save_dir, config.print_status), ('', '', False))

    def test_topic_argument_wins_over_param(self):
        self.assertEqual(make_config(['/camera/image_raw'], {'topic': '/other'}).topic,
                         '/camera/image_raw')
        self.assertEqual(make_config([], {'topic': '/other'}).topic, '/other')

    def test_relative_topic_becomes_global(self):
        self.assertEqual(make_config(['camera/image_raw'], {}).topic, '/camera/image_raw')

    def test_save_dir_must_exist(self):
        with tempfile.TemporaryDirectory() as tmp:
            self.assertEqual(make_config([], {'save_dir': tmp}).save_dir, tmp)
        with self.assertRaisesRegex(ConfigError,
                                    '~save_dir "/no/such/dir" is not an existing directory'):
            make_config([], {'save_dir': '/no/such/dir'})

    def test_print_status_must_be_bool(self):
        self.assertTrue(make_config([], {'print_status': True}).print_status)
        with self.assertRaisesRegex(ConfigError, "~print_status must be true or false, got 'yes'"):
            make_config([], {'print_status': 'yes'})

    def test_two_topics_are_refused(self):
        with self.assertRaisesRegex(ConfigError, 'bad command line: /a /b'):
            make_config(['/a', '/b'], {})


if __name__ == '__main__':
    unittest.main()
