"""Entry point of the image viewer: ROS node, settings, Qt application."""
import signal
import sys

import rosgraph
import rospy
from PyQt5.QtCore import QTimer
from PyQt5.QtWidgets import QApplication

from mobility_image_view import topics
from mobility_image_view.config import ConfigError, make_config
from mobility_image_view.subscriber import ImageSubscriber
from mobility_image_view.window import ImageViewWindow

PARAMS = ('topic', 'save_dir', 'print_status')


def main(argv=None):
    """Runs the viewer until its window closes or ROS shuts down; returns the exit code."""
    argv = rospy.myargv(sys.argv if argv is None else argv)
    if not rosgraph.is_master_online():
        print(f'image_view_gui: no ROS master at {rosgraph.get_master_uri()}: start roscore '
              'first', file=sys.stderr)
        return 1
    rospy.init_node('image_view', anonymous=True, disable_signals=True)
    params = {name: rospy.get_param('~' + name) for name in PARAMS
              if rospy.has_param('~' + name)}
    try:
        config = make_config(argv[1:], params)
    except ConfigError as error:
        print(f'image_view_gui: {error}', file=sys.stderr)
        return 2
    app = QApplication(argv[:1])
    app.setApplicationName('Image View')
    master = rosgraph.Master(rospy.get_name())
    window = ImageViewWindow(config, ImageSubscriber(),
                             lambda: topics.query_image_topics(master))
    window.show()
    signal.signal(signal.SIGINT, lambda *_: app.quit())
    signal.signal(signal.SIGTERM, lambda *_: app.quit())
    watchdog = QTimer()
    watchdog.timeout.connect(lambda: rospy.is_shutdown() and app.quit())
    watchdog.start(200)
    code = app.exec_()
    rospy.signal_shutdown('window closed')
    return code
