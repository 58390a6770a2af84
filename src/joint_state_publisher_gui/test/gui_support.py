"""Shared steps of the window tests: the layout report, joint_states, slider pixels."""
import json
import math
import os
import threading

import rospy
from sensor_msgs.msg import JointState

from mobility_testing import x11
from mobility_testing.waiting import wait_for

WINDOW_REGEX = '^Joint State Publisher'
TIMEOUT_S = 30.0


def read_layout(path):
    """The window's layout report, or None while it has not been written."""
    if not os.path.exists(path):
        return None
    with open(path, encoding='utf-8') as f:
        return json.load(f)


def remove_layout(path):
    """Deletes the layout report at the end of a test (it lives in /tmp)."""
    if os.path.exists(path):
        os.remove(path)


def wait_layout(path, condition, what):
    """Waits until the layout report satisfies condition(layout); returns it."""
    def check():
        layout = read_layout(path)
        return layout if layout is not None and condition(layout) else None
    return wait_for(check, TIMEOUT_S, what)


def row(layout, name):
    """The report entry of the slider row of joint name."""
    return next(r for r in layout['rows'] if r['name'] == name)


def centre(rect):
    """Centre pixel of a report rectangle."""
    return rect['x'] + rect['w'] // 2, rect['y'] + rect['h'] // 2


def radians_per_pixel(entry):
    """How far a slider moves its joint per pixel of handle travel.

    The handle's left edge travels from the groove's left end to its right
    end minus the handle width while the joint goes from lower to upper."""
    slider = entry['slider']
    travel_px = slider['groove']['w'] - slider['handle']['w']
    return (entry['upper'] - entry['lower']) / travel_px


class JointStateWatcher:
    """Keeps the latest message on /joint_states."""

    def __init__(self):
        self.lock = threading.Lock()
        self.latest = None
        self.count = 0
        self.sub = rospy.Subscriber('joint_states', JointState, self._on_msg, queue_size=10)

    def _on_msg(self, msg):
        with self.lock:
            self.latest = msg
            self.count += 1

    def positions(self):
        """{name: position} of the latest message, or None before the first one."""
        with self.lock:
            msg = self.latest
        return None if msg is None else dict(zip(msg.name, msg.position))

    def wait_positions(self, condition, what):
        """Waits for a message whose positions satisfy condition; returns the positions."""
        def check():
            positions = self.positions()
            return positions if positions is not None and condition(positions) else None
        return wait_for(check, TIMEOUT_S, what)


def open_window():
    """Waits for the slider window and returns its X id."""
    return x11.wait_window(WINDOW_REGEX, TIMEOUT_S)


def close_to(value, expected, tolerance):
    """True when |value - expected| <= tolerance (angles compared modulo 2 pi)."""
    diff = math.remainder(value - expected, 2.0 * math.pi)
    return abs(diff) <= tolerance
