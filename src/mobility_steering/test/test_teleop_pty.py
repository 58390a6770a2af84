#!/usr/bin/python3
"""Runs teleop_keyboard in a pseudo-terminal, types keys, watches /cmd_vel and checks
that the terminal settings are restored on Ctrl-C and on SIGTERM."""
import os
import pty
import select
import signal
import subprocess
import sys
import termios
import unittest

import rospy
import rostest

from mobility_testing.waiting import wait_for

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from twist_recorder import TwistRecorder  # noqa: E402


class Teleop:
    """teleop_keyboard running on the slave side of a fresh pty."""

    def __init__(self, *ros_args):
        self.master, self.slave = pty.openpty()
        self.saved = termios.tcgetattr(self.slave)
        self.output = b''
        self.proc = subprocess.Popen(
            ['rosrun', 'mobility_steering', 'teleop_keyboard', *ros_args],
            stdin=self.slave, stdout=self.slave, stderr=self.slave, start_new_session=True)

    def read_output(self):
        while select.select([self.master], [], [], 0)[0]:
            try:
                self.output += os.read(self.master, 4096)
            except OSError:
                break
        return self.output.decode('utf-8', 'replace')

    def wait_output(self, text, timeout_s=30):
        wait_for(lambda: text in self.read_output(), timeout_s, f'{text!r} on the terminal')

    def raw_mode_active(self):
        return not termios.tcgetattr(self.slave)[3] & termios.ECHO

    def send(self, keys):
        os.write(self.master, keys.encode())

    def wait_exit(self, timeout_s=15):
        try:
            return self.proc.wait(timeout=timeout_s)
        finally:
            self.read_output()

    def close(self):
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()
        os.close(self.master)
        os.close(self.slave)


class TeleopPtyTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('teleop_pty_test')
        cls.recorder = TwistRecorder('/cmd_vel')

    def start(self, *ros_args):
        teleop = Teleop(*ros_args)
        self.addCleanup(teleop.close)
        teleop.wait_output('Driving on /cmd_vel')
        self.assertTrue(teleop.raw_mode_active(), 'terminal not in raw mode while running')
        self.recorder.wait_connected()
        mark = self.recorder.count()

        def stop_heard():
            teleop.send('k')
            return self.recorder.seen(0.0, 0.0, mark)
        # A message published while the connection is still being set up can be lost:
        # a stop key is repeated until one arrives, proving the whole path.
        wait_for(stop_heard, 10, 'a zero Twist after key k', poll_s=0.2)
        return teleop

    def type_and_expect(self, teleop, key, linear_x, angular_z):
        mark = self.recorder.count()
        teleop.send(key)
        try:
            wait_for(lambda: self.recorder.seen(linear_x, angular_z, mark), 10,
                     f'Twist ({linear_x}, {angular_z}) after key {key!r}')
        except AssertionError as err:
            raise AssertionError(f'{err}; received {self.recorder.since(mark)}; terminal: '
                                 f'{teleop.read_output()!r}') from None

    def test_keys_drive_and_ctrl_c_restores_terminal(self):
        teleop = self.start()
        self.type_and_expect(teleop, 'i', 0.1, 0.0)
        self.type_and_expect(teleop, 'j', 0.0, 1.0)
        self.type_and_expect(teleop, 'm', -0.1, -1.0)
        self.type_and_expect(teleop, 'k', 0.0, 0.0)
        teleop.send('w')
        teleop.wait_output('speed 0.110 m/s')
        self.type_and_expect(teleop, 'i', 0.11, 0.0)
        for _ in range(30):
            teleop.send('q')
        self.type_and_expect(teleop, 'u', 0.22, 2.84)
        mark = self.recorder.count()
        teleop.send('\x03')
        self.assertEqual(teleop.wait_exit(), 0, teleop.read_output())
        wait_for(lambda: self.recorder.seen(0.0, 0.0, mark), 10, 'a zero Twist on exit')
        self.assertEqual(termios.tcgetattr(teleop.slave), teleop.saved,
                         'terminal settings not restored after Ctrl-C')

    def test_sigterm_restores_terminal(self):
        teleop = self.start()
        self.type_and_expect(teleop, 'l', 0.0, -1.0)
        os.killpg(teleop.proc.pid, signal.SIGTERM)
        teleop.wait_exit()
        self.assertEqual(termios.tcgetattr(teleop.slave), teleop.saved,
                         'terminal settings not restored after SIGTERM')

    def test_repeat_rate(self):
        teleop = self.start('_repeat_rate:=5.0')
        self.type_and_expect(teleop, 'i', 0.1, 0.0)
        mark = self.recorder.count()
        wait_for(lambda: self.recorder.count() >= mark + 11, 10, '11 repeated messages')
        stamps = [t for t, _, _ in self.recorder.since(mark)][:11]
        rate_hz = 10 / (stamps[-1] - stamps[0])
        print(f'teleop repeat rate {rate_hz:.3f} Hz')
        self.assertAlmostEqual(rate_hz, 5.0, delta=0.25)
        teleop.send('\x03')
        self.assertEqual(teleop.wait_exit(), 0)


if __name__ == '__main__':
    rostest.rosrun('mobility_steering', 'teleop_keyboard_pty', TeleopPtyTest, sys.argv)
