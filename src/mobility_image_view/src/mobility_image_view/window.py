"""The image viewer's main window: topic drop-down, zoom, save frame, status."""
import os
import sys

from PyQt5.QtCore import Qt, QTimer
from PyQt5.QtGui import QKeySequence
from PyQt5.QtWidgets import (QAction, QActionGroup, QComboBox, QFileDialog, QLabel,
                             QMainWindow, QScrollArea, QStyle, QToolBar)

from mobility_image_view import saving, status, topics
from mobility_image_view.canvas import ImageCanvas, qimage_from_rgb
from mobility_image_view.conversion import ImageError

TITLE = 'Image View'
STATUS_PERIOD_MS = 500


class ImageViewWindow(QMainWindow):
    """Shows one sensor_msgs/Image topic chosen from the master's image topics.

    list_topics() returns the image topic names (raises topics.MasterUnavailable);
    subscriber is an ImageSubscriber; config is a config.Config."""

    def __init__(self, config, subscriber, list_topics):
        super().__init__()
        self._config = config
        self._subscriber = subscriber
        self._list_topics = list_topics
        self._last = None
        self._saved_count = 0
        self._canvas = ImageCanvas()
        self._scroll = QScrollArea()
        self._scroll.setWidget(self._canvas)
        self._scroll.setWidgetResizable(True)
        self._scroll.setAlignment(Qt.AlignCenter)
        self.setCentralWidget(self._scroll)
        self._status_label = QLabel()
        self.statusBar().addPermanentWidget(self._status_label)
        self._build_toolbar()
        self.resize(800, 640)
        subscriber.received.connect(self._on_received)
        self._timer = QTimer(self)
        self._timer.timeout.connect(self._update_status)
        self._timer.start(STATUS_PERIOD_MS)
        self.refresh_topics()
        self.select_topic(config.topic)

    def _build_toolbar(self):
        bar = QToolBar('Image')
        bar.setMovable(False)
        bar.setToolButtonStyle(Qt.ToolButtonTextBesideIcon)
        self.addToolBar(bar)
        self._combo = QComboBox()
        label = QLabel(' &Topic ')
        label.setBuddy(self._combo)
        bar.addWidget(label)
        self._combo.setMinimumContentsLength(28)
        self._combo.setSizeAdjustPolicy(QComboBox.AdjustToMinimumContentsLengthWithIcon)
        self._combo.setPlaceholderText('choose an image topic')
        self._combo.setToolTip('sensor_msgs/Image topics known to the ROS master (Alt+T)')
        self._combo.activated.connect(lambda _i: self.select_topic(self._combo.currentText()))
        bar.addWidget(self._combo)
        refresh = self._action(bar, 'Refresh', QStyle.SP_BrowserReload, 'F5',
                               'List the image topics again (F5)')
        refresh.triggered.connect(self.refresh_topics)
        bar.addSeparator()
        zoom = QActionGroup(self)
        self._fit_action = self._action(bar, 'Fit', None, 'Ctrl+F',
                                        'Scale the image to the window (Ctrl+F)', zoom)
        self._fit_action.setChecked(True)
        one = self._action(bar, '1:1', None, 'Ctrl+1',
                           'One image pixel per screen pixel (Ctrl+1)', zoom)
        self._fit_action.toggled.connect(self._set_fit)
        one.toggled.connect(lambda on: self._set_fit(not on))
        bar.addSeparator()
        save = self._action(bar, 'Save frame', QStyle.SP_DialogSaveButton, QKeySequence.Save,
                            'Save the last received frame as PNG (Ctrl+S)')
        save.triggered.connect(self.save_frame)
        self._combo.setFocus()

    def _action(self, bar, text, icon, shortcut, tip, group=None):
        action = QAction(text, self)
        if icon is not None:
            action.setIcon(self.style().standardIcon(icon))
        action.setShortcut(QKeySequence(shortcut))
        action.setToolTip(tip)
        if group is not None:
            action.setCheckable(True)
            group.addAction(action)
        bar.addAction(action)
        return action

    def refresh_topics(self):
        """Fills the drop-down from the master, keeping the selected topic."""
        try:
            names = self._list_topics()
        except topics.MasterUnavailable as error:
            self.statusBar().showMessage(str(error))
            names = []
        current = self._subscriber.topic
        entries = topics.choices(names, current)
        self._combo.blockSignals(True)
        self._combo.clear()
        self._combo.addItems(entries)
        self._combo.setCurrentIndex(entries.index(current) if current else -1)
        self._combo.blockSignals(False)
        self._print('topics: ' + ' '.join(entries))

    def select_topic(self, topic):
        """Shows topic from now on ('' shows nothing)."""
        if topic == self._subscriber.topic and topic:
            return
        self._subscriber.subscribe(topic)
        self._last = None
        if topic and self._combo.findText(topic) < 0:
            self.refresh_topics()
        self._combo.setCurrentIndex(self._combo.findText(topic) if topic else -1)
        self.setWindowTitle(f'{TITLE} - {topic}' if topic else TITLE)
        self._show_message(f'waiting for frames on {topic}' if topic
                           else 'no topic selected: choose one above')
        self._update_status()

    def _set_fit(self, fit):
        self._scroll.setWidgetResizable(fit)
        self._canvas.set_fit(fit)

    def _on_received(self, received):
        if received.topic != self._subscriber.topic:
            return
        self._last = received
        if received.error:
            self._show_message(received.error)
        else:
            self._canvas.set_image(qimage_from_rgb(received.rgb))

    def _show_message(self, text):
        if text != self._canvas.message():
            self._print('message: ' + text)
        self._canvas.set_message(text)

    def _current_fields(self):
        message = self._last.message if self._last else None
        return (self._subscriber.topic, message.encoding if message else '',
                message.width if message else 0, message.height if message else 0,
                self._subscriber.rate_hz())

    def _update_status(self):
        fields = self._current_fields()
        self._status_label.setText(status.status_text(*fields))
        self._print(status.status_line(*fields))

    def save_frame(self):
        """Saves the last received frame as PNG (into ~save_dir without asking)."""
        if self._last is None:
            self.statusBar().showMessage('no frame received yet: nothing to save', 5000)
            return
        self._saved_count += 1
        name = saving.frame_file_name(self._last.topic, self._saved_count)
        if self._config.save_dir:
            path = os.path.join(self._config.save_dir, name)
        else:
            path, _ = QFileDialog.getSaveFileName(self, 'Save frame', name, 'PNG image (*.png)')
            if not path:
                return
        try:
            exact = saving.save_frame(self._last.message, path)
        except (ImageError, OSError) as error:
            self.statusBar().showMessage(f'could not save {path}: {error}', 10000)
            print(f'save failed: {path}: {error}', file=sys.stderr, flush=True)
            return
        note = '' if exact else ' (32FC1 stored as its 8-bit view)'
        self.statusBar().showMessage(f'saved {path}{note}', 10000)
        print(f'saved: {path}', flush=True)

    def _print(self, line):
        if self._config.print_status:
            print(line, flush=True)
