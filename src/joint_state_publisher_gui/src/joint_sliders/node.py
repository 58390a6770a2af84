"""The ROS node around the model and the window: parameters in, JointState out."""
import random

import rospy
from PyQt5.QtCore import QObject, QTimer, pyqtSignal
from PyQt5.QtWidgets import QApplication
from sensor_msgs.msg import JointState

from joint_sliders.config import ConfigError, read_config
from joint_sliders.joint_model import JointModel, ModelError
from joint_sliders.layout_report import LayoutReporter
from joint_sliders.urdf_joints import UrdfError, parse_joints
from joint_sliders.window import JointWindow

SHUTDOWN_POLL_MS = 200
_UNSET = object()


def get_param(name, default=_UNSET):
    """A parameter from the node's private namespace, else the global one, else default."""
    for key in ('~' + name, name):
        if rospy.has_param(key):
            return rospy.get_param(key)
    if default is _UNSET:
        raise ConfigError(f'parameter {name} is not set (neither ~{name} nor {name})')
    return default


class SourceBridge(QObject):
    """Hands JointState messages from rospy's threads to the Qt thread."""

    received = pyqtSignal(object)

    def __init__(self):
        super().__init__()
        self.subscribers = []

    def subscribe(self, topics):
        """Subscribes to every source_list topic; keeps the subscribers."""
        self.subscribers = [rospy.Subscriber(t, JointState, self.received.emit, queue_size=10)
                            for t in topics]


class JointStateNode:
    """Publishes the model's joint states at the configured rate and merges sources."""

    def __init__(self, model, config, window):
        self.model = model
        self.config = config
        self.window = window
        self.publisher = rospy.Publisher('joint_states', JointState, queue_size=10)
        self.bridge = SourceBridge()
        self.bridge.received.connect(self.on_source)
        self.bridge.subscribe(config.source_list)
        self.timer = QTimer()
        self.timer.timeout.connect(self.publish)
        self.timer.start(max(1, int(round(1000.0 / config.rate_hz))))

    def on_source(self, msg):
        """Takes over the joints a source publishes and shows their positions."""
        if self.model.apply_source(msg.name, msg.position, msg.velocity, msg.effort):
            self.window.refresh()

    def publish(self):
        """Sends one JointState with every movable joint (none: an empty message)."""
        names, positions, velocities, efforts = self.model.joint_state(
            self.config.publish_default_velocities, self.config.publish_default_efforts)
        msg = JointState(name=names, position=positions, velocity=velocities, effort=efforts)
        msg.header.stamp = rospy.Time.now()
        self.publisher.publish(msg)


def load():
    """Reads parameters and the robot; returns (config, robot name, model)."""
    config = read_config(get_param)
    description = get_param('robot_description')
    if not isinstance(description, str):
        raise ConfigError('parameter robot_description is not a string of URDF')
    robot_name, specs = parse_joints(description)
    return config, robot_name, JointModel(specs, config.model)


def main(argv):
    """Runs the node until the window closes or ROS shuts down; returns the exit status."""
    rospy.init_node('joint_state_publisher_gui')
    try:
        config, robot_name, model = load()
    except (ConfigError, UrdfError, ModelError) as err:
        rospy.logfatal(f'joint_state_publisher_gui: {err}')
        return 1
    app = QApplication(rospy.myargv(argv))
    window = JointWindow(model, robot_name, random.Random(config.random_seed))
    node = JointStateNode(model, config, window)
    if config.layout_report:
        LayoutReporter(window, config.layout_report)
    watchdog = QTimer()
    watchdog.timeout.connect(lambda: rospy.is_shutdown() and app.quit())
    watchdog.start(SHUTDOWN_POLL_MS)
    node.publish()
    window.show()
    status = app.exec_()
    rospy.signal_shutdown('window closed')
    return status
