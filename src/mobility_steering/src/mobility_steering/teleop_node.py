"""ROS side of the terminal teleop: reads keys, publishes Twist, restores the terminal."""
import sys
import time

import rospy
from geometry_msgs.msg import Twist

from mobility_steering.config import ConfigError, TeleopConfig
from mobility_steering.periodic import next_deadline
from mobility_steering.teleop_keys import HELP, TeleopState
from mobility_steering.terminal import CTRL_C, NotATerminal, RawTerminal

IDLE_POLL_S = 0.1


def _say(text):
    sys.stdout.write(text.replace('\n', '\r\n') + '\r\n')
    sys.stdout.flush()


def _publish(publisher, linear_mps, angular_radps):
    msg = Twist()
    msg.linear.x = linear_mps
    msg.angular.z = angular_radps
    publisher.publish(msg)


def run(config, terminal, publisher):
    """The key loop; returns when Ctrl-C is read or ROS shuts down."""
    state = TeleopState(config.speed_mps, config.turn_radps, config.speed_limit_mps,
                        config.turn_limit_radps)
    period_s = 1.0 / config.repeat_rate_hz if config.repeat_rate_hz > 0 else None
    deadline = time.monotonic()
    _say(f'Driving on {config.topic} (Ctrl-C quits)\n{HELP}\n{state.status()}')
    while not rospy.is_shutdown():
        wait_s = deadline - time.monotonic() if period_s else IDLE_POLL_S
        key = terminal.read_key(wait_s)
        if key == CTRL_C:
            break
        if key is not None:
            if state.handle_key(key) == 'speed':
                _say(state.status())
            _publish(publisher, *state.command())
        if period_s and time.monotonic() >= deadline:
            _publish(publisher, *state.command())
            deadline = next_deadline(deadline, time.monotonic(), period_s)
    _publish(publisher, 0.0, 0.0)


def main():
    rospy.init_node('teleop_keyboard', anonymous=True)
    try:
        config = TeleopConfig.from_params(lambda name, default: rospy.get_param('~' + name,
                                                                                default))
    except ConfigError as err:
        rospy.logfatal(str(err))
        return 2
    publisher = rospy.Publisher(config.topic, Twist, queue_size=1)
    try:
        with RawTerminal(sys.stdin.fileno()) as terminal:
            run(config, terminal, publisher)
    except NotATerminal as err:
        rospy.logfatal(str(err))
        return 2
    return 0
