#!/usr/bin/python3
"""The generated Python classes of turtlebot3_msgs are those of the Noetic release.

The expected md5sums, fields and constants come from released_types.txt (the values ROBOTIS
publishes); a client built against the released package only talks to a peer whose md5sum
matches.
"""
import importlib
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import released_types  # noqa: E402


def message_class(name):
    return getattr(importlib.import_module('turtlebot3_msgs.msg'), name)


class TestPythonTypes(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.table = released_types.read()

    def test_every_type_has_the_released_md5sum(self):
        for name, md5 in self.table['md5']:
            with self.subTest(type=name):
                self.assertEqual(message_class(name)._type, 'turtlebot3_msgs/' + name)
                self.assertEqual(message_class(name)._md5sum, md5)

    def test_fields_in_the_released_order_and_types(self):
        for name, (expected, _) in released_types.definitions(self.table).items():
            cls = message_class(name)
            with self.subTest(type=name):
                self.assertEqual(list(zip(cls.__slots__, cls._slot_types)), expected)

    def test_constants_have_the_released_values(self):
        for name, constant, value in self.table['const']:
            with self.subTest(type=name, constant=constant):
                self.assertEqual(getattr(message_class(name), constant), int(value))

    def test_no_type_is_missing_or_extra(self):
        msg_dir = os.path.join(PACKAGE, 'msg')
        ours = sorted(f[:-len('.msg')] for f in os.listdir(msg_dir) if f.endswith('.msg'))
        self.assertEqual(ours, sorted(name for name, _ in self.table['md5']))
        for kind in ('srv', 'action'):  # the release has neither
            self.assertFalse(os.path.isdir(os.path.join(PACKAGE, kind)), kind)


if __name__ == '__main__':
    unittest.main()
