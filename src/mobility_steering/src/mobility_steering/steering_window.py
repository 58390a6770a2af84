"""The steering window: topic field, linear/angular sliders with editable limits, stop.

The window edits a SteeringState and knows nothing about ROS: the owner reads the state
(see steering_node) and is told about topic changes through `topic_changed`."""
from PyQt5 import QtCore, QtGui, QtWidgets

from mobility_steering import velocity

TITLE = 'Robot Steering'
SCALE = round(1 / velocity.RESOLUTION)


def _to_slider(value):
    return int(round(value * SCALE))


class _LimitBox(QtWidgets.QDoubleSpinBox):
    def __init__(self, value, unit):
        super().__init__()
        self.setRange(-100.0, 100.0)
        self.setDecimals(2)
        self.setSingleStep(0.01)
        self.setSuffix(f' {unit}')
        self.setValue(value)
        self.setKeyboardTracking(False)
        self.setAlignment(QtCore.Qt.AlignRight)


class SteeringWindow(QtWidgets.QWidget):
    """Top-level steering widget; `status_text` is set by the owner (publishing state)."""

    topic_changed = QtCore.pyqtSignal(str)
    command_changed = QtCore.pyqtSignal()

    def __init__(self, state, topic, parent=None):
        super().__init__(parent)
        self.state = state
        self.setWindowTitle(TITLE)
        self.setMinimumSize(440, 480)
        self._build(topic)
        self._install_shortcuts()
        self.refresh()

    def _build(self, topic):
        layout = QtWidgets.QVBoxLayout(self)
        topic_row = QtWidgets.QHBoxLayout()
        topic_row.addWidget(QtWidgets.QLabel('Topic:'))
        self.topic_edit = QtWidgets.QLineEdit(topic)
        self.topic_edit.setToolTip('geometry_msgs/Twist topic; press Enter to switch')
        self.topic_edit.editingFinished.connect(self._on_topic_edited)
        topic_row.addWidget(self.topic_edit)
        layout.addLayout(topic_row)

        layout.addWidget(self._linear_group(), stretch=1)
        layout.addWidget(self._angular_group())

        self.stop_button = QtWidgets.QPushButton('STOP')
        self.stop_button.setMinimumHeight(64)
        self.stop_button.setStyleSheet(
            'QPushButton { background-color: #c62828; color: white; font-size: 22pt;'
            ' font-weight: bold; border-radius: 6px; }'
            'QPushButton:pressed { background-color: #8e0000; }')
        self.stop_button.clicked.connect(lambda: self._act(velocity.STOP))
        layout.addWidget(self.stop_button)

        self.help_label = QtWidgets.QLabel(
            'Keys:  W/S linear \u00b1   A/D angular \u00b1   X/Z zero them   Space stop')
        self.help_label.setStyleSheet('color: #555;')
        self.help_label.setWordWrap(True)
        layout.addWidget(self.help_label)
        self.status_label = QtWidgets.QLabel('idle')
        self.status_label.setFrameShape(QtWidgets.QFrame.StyledPanel)
        layout.addWidget(self.status_label)

    def _linear_group(self):
        group = QtWidgets.QGroupBox('Linear velocity (x)')
        grid = QtWidgets.QGridLayout(group)
        self.vx_max_box = _LimitBox(self.state.linear_range.maximum, 'm/s')
        self.vx_min_box = _LimitBox(self.state.linear_range.minimum, 'm/s')
        self.linear_slider = QtWidgets.QSlider(QtCore.Qt.Vertical)
        self.linear_slider.setTickPosition(QtWidgets.QSlider.TicksBothSides)
        self.linear_slider.setMinimumHeight(160)
        self.linear_slider.valueChanged.connect(
            lambda v: self._set(self.state.set_linear, v / SCALE))
        self.linear_value = QtWidgets.QLabel()
        self.linear_value.setStyleSheet('font-size: 16pt; font-weight: bold;')
        zero = QtWidgets.QPushButton('Zero linear (X)')
        zero.clicked.connect(lambda: self._act(velocity.LINEAR_ZERO))
        grid.addWidget(QtWidgets.QLabel('max'), 0, 0)
        grid.addWidget(self.vx_max_box, 0, 1)
        grid.addWidget(self.linear_slider, 1, 1, alignment=QtCore.Qt.AlignHCenter)
        grid.addWidget(QtWidgets.QLabel('min'), 2, 0)
        grid.addWidget(self.vx_min_box, 2, 1)
        grid.addWidget(self.linear_value, 1, 2, alignment=QtCore.Qt.AlignCenter)
        grid.addWidget(zero, 2, 2)
        grid.setColumnStretch(2, 1)
        grid.setRowStretch(1, 1)
        for box in (self.vx_min_box, self.vx_max_box):
            box.valueChanged.connect(self._on_linear_limits)
        return group

    def _angular_group(self):
        group = QtWidgets.QGroupBox('Angular velocity (z), left turn positive')
        grid = QtWidgets.QGridLayout(group)
        self.vw_max_box = _LimitBox(self.state.angular_range.maximum, 'rad/s')
        self.vw_min_box = _LimitBox(self.state.angular_range.minimum, 'rad/s')
        self.angular_slider = QtWidgets.QSlider(QtCore.Qt.Horizontal)
        self.angular_slider.setInvertedAppearance(True)
        self.angular_slider.setTickPosition(QtWidgets.QSlider.TicksBothSides)
        self.angular_slider.valueChanged.connect(
            lambda v: self._set(self.state.set_angular, v / SCALE))
        self.angular_value = QtWidgets.QLabel()
        self.angular_value.setStyleSheet('font-size: 16pt; font-weight: bold;')
        zero = QtWidgets.QPushButton('Zero angular (Z)')
        zero.clicked.connect(lambda: self._act(velocity.ANGULAR_ZERO))
        grid.addWidget(self.vw_max_box, 0, 0)
        grid.addWidget(self.angular_slider, 0, 1)
        grid.addWidget(self.vw_min_box, 0, 2)
        grid.addWidget(QtWidgets.QLabel('max (left)'), 1, 0, alignment=QtCore.Qt.AlignHCenter)
        grid.addWidget(self.angular_value, 1, 1, alignment=QtCore.Qt.AlignCenter)
        grid.addWidget(QtWidgets.QLabel('min (right)'), 1, 2, alignment=QtCore.Qt.AlignHCenter)
        grid.addWidget(zero, 2, 1, alignment=QtCore.Qt.AlignCenter)
        grid.setColumnStretch(1, 1)
        for box in (self.vw_min_box, self.vw_max_box):
            box.valueChanged.connect(self._on_angular_limits)
        return group

    def _install_shortcuts(self):
        for key_text, action in velocity.KEY_ACTIONS.items():
            shortcut = QtWidgets.QShortcut(QtGui.QKeySequence(key_text.capitalize()), self)
            shortcut.activated.connect(lambda a=action: self._act(a))
        self.stop_button.setFocus()

    def _act(self, action):
        self.state.apply(action)
        self.refresh()

    def _set(self, setter, value):
        setter(value)
        self.refresh()

    def _on_topic_edited(self):
        self.topic_changed.emit(self.topic_edit.text().strip())

    def _on_linear_limits(self):
        self._apply_limits(self.vx_min_box, self.vx_max_box, self.state.set_linear_range)

    def _on_angular_limits(self):
        self._apply_limits(self.vw_min_box, self.vw_max_box, self.state.set_angular_range)

    def _apply_limits(self, min_box, max_box, setter):
        try:
            setter(velocity.Range(min_box.value(), max_box.value()))
        except ValueError as err:
            self.status_label.setText(f'limits not applied: {err}')
            return
        self.refresh()

    def refresh(self):
        """Shows the state in the widgets (without feeding the change back)."""
        s = self.state
        for slider, value_range, value in (
                (self.linear_slider, s.linear_range, s.linear_mps),
                (self.angular_slider, s.angular_range, s.angular_radps)):
            slider.blockSignals(True)
            slider.setRange(_to_slider(value_range.minimum), _to_slider(value_range.maximum))
            span = slider.maximum() - slider.minimum()
            slider.setTickInterval(max(1, span // 10))
            slider.setPageStep(max(1, span // 10))
            slider.setValue(_to_slider(value))
            slider.blockSignals(False)
        self.linear_value.setText(f'{s.linear_mps:+.3f} m/s')
        self.angular_value.setText(f'{s.angular_radps:+.3f} rad/s')
        self.command_changed.emit()

    def set_status(self, text):
        self.status_label.setText(text)
