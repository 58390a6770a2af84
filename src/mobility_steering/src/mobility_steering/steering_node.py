"""ROS side of the steering window: parameters, the Twist publisher, the 10 Hz tick."""
import os
import sys
import threading

import rospy
from geometry_msgs.msg import Twist
from PyQt5 import QtCore, QtWidgets

from mobility_steering.config import ConfigError, SteeringConfig
from mobility_steering.periodic import PeriodicThread
from mobility_steering.publish_policy import PublishPolicy
from mobility_steering.steering_window import SteeringWindow
from mobility_steering.velocity import Range, SteeringState


def make_twist(linear_mps, angular_radps):
    msg = Twist()
    msg.linear.x = linear_mps
    msg.angular.z = angular_radps
    return msg


class SteeringPublisher:
    """Publishes the window's state on a tick, following the PublishPolicy."""

    def __init__(self, state, topic, zero_repeats):
        self._state = state
        self._lock = threading.Lock()
        self._policy = PublishPolicy(zero_repeats)
        self._publisher = None
        self.topic = None
        self.set_topic(topic)

    def set_topic(self, topic):
        with self._lock:
            if topic == self.topic:
                return
            if self._publisher is not None:
                self._publisher.unregister()
            self._publisher = rospy.Publisher(topic, Twist, queue_size=1)
            self.topic = topic
            self._policy.restart()

    def tick(self):
        with self._lock:
            linear, angular = self._state.linear_mps, self._state.angular_radps
            if self._policy.tick(linear != 0.0 or angular != 0.0):
                self._publisher.publish(make_twist(linear, angular))

    def publish_stop(self):
        """One zero Twist, e.g. when the window closes while the robot moves."""
        with self._lock:
            self._publisher.publish(make_twist(0.0, 0.0))


def main(argv=None):
    argv = rospy.myargv(sys.argv if argv is None else argv)
    rospy.init_node('robot_steering', anonymous=True)
    try:
        config = SteeringConfig.from_params(lambda name, default: rospy.get_param('~' + name,
                                                                                  default))
    except ConfigError as err:
        rospy.logfatal(str(err))
        return 2
    if not (os.environ.get('DISPLAY') or os.environ.get('WAYLAND_DISPLAY')):
        rospy.logfatal('the steering window needs a display (DISPLAY is not set); in a '
                       'terminal use: rosrun mobility_steering teleop_keyboard')
        return 1
    state = SteeringState(Range(config.vx_min_mps, config.vx_max_mps),
                          Range(config.vw_min_radps, config.vw_max_radps),
                          config.vx_step_mps, config.vw_step_radps)
    app = QtWidgets.QApplication(argv)
    window = SteeringWindow(state, config.topic)
    publisher = SteeringPublisher(state, config.topic, config.zero_repeats)

    def on_topic(topic):
        try:
            publisher.set_topic(topic)
        except ValueError as err:
            window.set_status(f'bad topic {topic!r}: {err}')

    def show_status():
        verb = 'publishing' if state.moving else 'idle on'
        window.set_status(f'{verb} {publisher.topic} at {config.rate_hz:g} Hz')

    window.topic_changed.connect(on_topic)
    window.command_changed.connect(show_status)
    show_status()
    ticker = PeriodicThread(1.0 / config.rate_hz, publisher.tick)
    ticker.start()
    rospy.on_shutdown(lambda: QtCore.QMetaObject.invokeMethod(app, 'quit',
                                                              QtCore.Qt.QueuedConnection))
    # Python runs signal handlers (rospy's SIGINT) only between bytecodes: a timer hands
    # control back to Python regularly while Qt's C++ event loop runs.
    signal_pump = QtCore.QTimer()
    signal_pump.timeout.connect(lambda: None)
    signal_pump.start(200)
    window.show()
    status = app.exec_()
    ticker.stop()
    if state.moving and not rospy.is_shutdown():
        publisher.publish_stop()
    return status
