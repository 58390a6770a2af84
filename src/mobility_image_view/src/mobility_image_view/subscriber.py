"""Receives frames of one image topic on rospy's thread and hands them to Qt's thread."""
import collections
import threading
import time

import rospy
from PyQt5.QtCore import QObject, pyqtSignal
from sensor_msgs.msg import Image

from mobility_image_view.conversion import ImageError, to_display_rgb
from mobility_image_view.rate import RateMeter

# A received message with its RGB view, or the reason it cannot be shown.
Received = collections.namedtuple('Received', 'topic message rgb error')


class ImageSubscriber(QObject):
    """Subscribes to at most one topic; emits `received` for every frame."""

    received = pyqtSignal(object)

    def __init__(self, parent=None):
        super().__init__(parent)
        self._subscriber = None
        self._lock = threading.Lock()
        self._meter = RateMeter(window_s=2.0)
        self.topic = ''

    def subscribe(self, topic):
        """Switches to topic (empty: none)."""
        if self._subscriber is not None:
            self._subscriber.unregister()
            self._subscriber = None
        with self._lock:
            self._meter.reset()
            self.topic = topic
        if topic:
            self._subscriber = rospy.Subscriber(topic, Image, self._on_image, callback_args=topic,
                                                queue_size=1, buff_size=2 ** 24)

    def rate_hz(self):
        """Measured arrival rate of the current topic (None: no recent frames)."""
        with self._lock:
            return self._meter.rate_hz(time.monotonic())

    def _on_image(self, message, topic):
        with self._lock:
            if topic != self.topic:
                return
            self._meter.tick(time.monotonic())
        try:
            received = Received(topic, message, to_display_rgb(message), '')
        except ImageError as error:
            received = Received(topic, message, None, str(error))
        self.received.emit(received)
