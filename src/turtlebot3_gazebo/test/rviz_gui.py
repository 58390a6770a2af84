"""Shared steps of the round-track RViz tests: the window, its 3D view, the Simulation
panel's layout report, /clock and the simulator's model state."""
import json
import math
import os
import threading

import rospkg
import rospy
from gazebo_msgs.srv import GetModelState

from mobility_testing import images, x11
from mobility_testing.rviz_view import OrbitView
from mobility_testing.waiting import wait_for
from rosgraph_msgs.msg import Clock

TIMEOUT_S = 60.0
ROBOT = 'turtlebot3_burger'


def config_path():
    return os.path.join(rospkg.RosPack().get_path('turtlebot3_gazebo'), 'rviz',
                        'roundTrack.rviz')


def rviz_window():
    return x11.wait_window('RViz', TIMEOUT_S)


def view_area(window):
    """The screen rectangle of RViz's 3D view and the Orbit view of the config."""
    area = wait_for(lambda: (x11.render_areas(window) or [None])[0], TIMEOUT_S,
                    'RViz\'s 3D render window')
    return area, OrbitView.from_rviz_config(config_path())


class Panel:
    """The Simulation panel, through the layout report it writes (screen rectangles of its
    widgets and its texts), clicked and typed into with xdotool."""

    def __init__(self, window, report_path):
        self.window = window
        self.path = report_path

    def report(self):
        try:
            with open(self.path) as f:
                return json.load(f)
        except (OSError, ValueError):
            return None

    def wait_text(self, name, condition, what):
        def check():
            report = self.report()
            text = report['texts'][name] if report else None
            return text if text is not None and condition(text) else None
        return wait_for(check, TIMEOUT_S, what, poll_s=0.1)

    def _box(self, widget):
        return (self.report() or {}).get('widgets', {}).get(widget)

    def _window_point(self, widget, dx=None):
        # RViz settles its docks for a while after start: click where the widget has stayed.
        last = [None]

        def settled():
            box, previous = self._box(widget), last[0]
            last[0] = box
            return box if box is not None and box == previous else None
        box = wait_for(settled, TIMEOUT_S, f'panel widget {widget} settled in {self.path}',
                       poll_s=0.5)
        wx, wy, _, _ = x11.geometry(self.window)
        x = box['x'] + (box['w'] // 2 if dx is None else dx)
        return x - wx, box['y'] + box['h'] // 2 - wy

    def click(self, widget):
        self.wait_enabled(widget)
        x11.click(self.window, *self._window_point(widget))

    def wait_enabled(self, widget):
        wait_for(lambda: (self.report() or {}).get('widgets', {}).get(widget, {}).get('enabled'),
                 TIMEOUT_S, f'panel widget {widget} enabled', poll_s=0.1)

    def screenshot(self, path, margin_px=8):
        """Saves a picture of the panel's widgets (with a margin) at path ("" saves nothing)."""
        if not path:
            return
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        boxes = [b for b in self.report()['widgets'].values() if b['visible']]
        left = min(b['x'] for b in boxes) - margin_px
        top = min(b['y'] for b in boxes) - 4 * margin_px - 40   # the headline above the grid
        right = max(b['x'] + b['w'] for b in boxes) + margin_px
        bottom = max(b['y'] + b['h'] for b in boxes) + 4 * margin_px  # the result line
        screen = x11.screenshot_array('root', path)
        images.save_png(screen[max(top, 0):bottom, max(left, 0):right], path)

    def type_into(self, widget, text):
        """Replaces the text of a spin box or editable combo box."""
        self.wait_enabled(widget)
        x11.click(self.window, *self._window_point(widget, dx=10))
        x11.key(self.window, 'ctrl+a')
        x11.type_text(self.window, text)
        x11.key(self.window, 'Tab')


class ClockWatcher:
    """Keeps the newest /clock and how many arrived."""

    def __init__(self):
        self.lock = threading.Lock()
        self.latest = None
        self.count = 0
        self.sub = rospy.Subscriber('/clock', Clock, self._on_clock, queue_size=100)

    def _on_clock(self, msg):
        with self.lock:
            self.latest = msg.clock.to_sec()
            self.count += 1

    def now(self):
        with self.lock:
            return self.latest

    def wait(self, condition, what, timeout_s=TIMEOUT_S):
        return wait_for(lambda: self.now() is not None and condition(self.now()), timeout_s,
                        what, poll_s=0.01) and self.now()


def model_pose(name=ROBOT):
    """(x, y, yaw) of a model from /gazebo/get_model_state."""
    rospy.wait_for_service('/gazebo/get_model_state', TIMEOUT_S)
    res = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)(model_name=name)
    if not res.success:
        raise AssertionError(f'get_model_state {name}: {res.status_message}')
    q = res.pose.orientation
    yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
    return res.pose.position.x, res.pose.position.y, yaw


def angle_difference(a, b):
    return math.atan2(math.sin(a - b), math.cos(a - b))
