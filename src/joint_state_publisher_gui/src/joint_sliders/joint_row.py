"""One line of the window: joint name, slider and a typed value with its unit."""
from PyQt5.QtCore import Qt, pyqtSignal
from PyQt5.QtWidgets import QDoubleSpinBox, QHBoxLayout, QLabel, QSlider, QWidget

from joint_sliders.slider_scale import SLIDER_STEPS, from_step, to_step

SLIDER_MIN_WIDTH_PX = 300


class JointRow(QWidget):
    """Moves one free joint; emits moved(name, position) when the user changes it."""

    moved = pyqtSignal(str, float)

    def __init__(self, joint, parent=None):
        super().__init__(parent)
        self.joint = joint
        self.label = QLabel(joint.name, self)
        self.slider = QSlider(Qt.Horizontal, self)
        self.slider.setRange(0, SLIDER_STEPS)
        self.slider.setMinimumWidth(SLIDER_MIN_WIDTH_PX)
        self.slider.setObjectName('slider_' + joint.name)
        self.value_box = QDoubleSpinBox(self)
        self.value_box.setObjectName('value_' + joint.name)
        self.value_box.setDecimals(4 if joint.unit == 'm' else 3)
        self.value_box.setRange(joint.lower, joint.upper)
        self.value_box.setSingleStep((joint.upper - joint.lower) / 100.0 or 0.01)
        self.value_box.setSuffix(' ' + joint.unit)
        self.value_box.setKeyboardTracking(False)
        self.value_box.setMinimumWidth(110)
        self.value_box.setToolTip(f'{joint.type}, {joint.lower:g} .. {joint.upper:g} '
                                  f'{joint.unit}; type a value and press Enter')
        layout = QHBoxLayout(self)
        layout.setContentsMargins(4, 2, 4, 2)
        layout.addWidget(self.label, 2)
        layout.addWidget(self.slider, 5)
        layout.addWidget(self.value_box, 0)
        self.slider.valueChanged.connect(self._slider_moved)
        self.value_box.valueChanged.connect(self._value_typed)
        self.show_position(joint.position)

    def show_position(self, position):
        """Shows a position without reporting it back as a user change."""
        for widget in (self.slider, self.value_box):
            widget.blockSignals(True)
        if not self.slider.isSliderDown():
            self.slider.setValue(to_step(position, self.joint.lower, self.joint.upper))
        self.value_box.setValue(position)
        for widget in (self.slider, self.value_box):
            widget.blockSignals(False)

    def _slider_moved(self, step):
        position = from_step(step, self.joint.lower, self.joint.upper)
        self.value_box.blockSignals(True)
        self.value_box.setValue(position)
        self.value_box.blockSignals(False)
        self.moved.emit(self.joint.name, position)

    def _value_typed(self, position):
        self.slider.blockSignals(True)
        self.slider.setValue(to_step(position, self.joint.lower, self.joint.upper))
        self.slider.blockSignals(False)
        self.moved.emit(self.joint.name, position)
