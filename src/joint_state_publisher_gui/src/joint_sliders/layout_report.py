"""Test hook: writes where the window's widgets are, so GUI tests can click
and drag them with xdotool without guessing pixel positions.

Coordinates are relative to the top-level window (what `xdotool mousemove
--window` expects). The file is rewritten atomically whenever it changes."""
import json
import os

from PyQt5.QtCore import QObject, QTimer
from PyQt5.QtWidgets import QStyle, QStyleOptionSlider

REPORT_PERIOD_MS = 100


def _rect(widget, rect, window):
    top_left = widget.mapTo(window, rect.topLeft())
    return {'x': top_left.x(), 'y': top_left.y(), 'w': rect.width(), 'h': rect.height()}


def _slider_parts(slider, window):
    option = QStyleOptionSlider()
    slider.initStyleOption(option)
    style = slider.style()
    groove = style.subControlRect(QStyle.CC_Slider, option, QStyle.SC_SliderGroove, slider)
    handle = style.subControlRect(QStyle.CC_Slider, option, QStyle.SC_SliderHandle, slider)
    return {'groove': _rect(slider, groove, window), 'handle': _rect(slider, handle, window),
            'step': slider.value(), 'steps': slider.maximum()}


def describe(window):
    """A JSON-ready description of the window's rows, buttons and message."""
    rows = []
    for row in window.rows:
        entry = {'name': row.joint.name, 'visible': row.isVisible(),
                 'lower': row.joint.lower, 'upper': row.joint.upper,
                 'position': row.joint.position,
                 'value_text': row.value_box.text()}
        if row.isVisible():
            entry['slider'] = _slider_parts(row.slider, window)
            entry['value_box'] = _rect(row.value_box, row.value_box.rect(), window)
        rows.append(entry)
    widgets = {'filter': window.filter_edit, 'center': window.center_button,
               'randomize': window.randomize_button}
    return {'title': window.windowTitle(), 'rows': rows,
            'message': window.message.text() if window.message.isVisible() else '',
            'widgets': {k: _rect(w, w.rect(), window) for k, w in widgets.items()},
            'size': {'w': window.width(), 'h': window.height()}}


class LayoutReporter(QObject):
    """Keeps a JSON file describing the window up to date while the window is shown."""

    def __init__(self, window, path):
        super().__init__(window)
        self.window = window
        self.path = path
        self.last = None
        self.timer = QTimer(self)
        self.timer.timeout.connect(self.write)
        self.timer.start(REPORT_PERIOD_MS)

    def write(self):
        """Rewrites the file if the window is shown and something changed."""
        if not self.window.isVisible():
            return
        text = json.dumps(describe(self.window), indent=1, sort_keys=True)
        if text == self.last:
            return
        tmp = self.path + '.tmp'
        with open(tmp, 'w', encoding='utf-8') as out:
            out.write(text)
        os.replace(tmp, self.path)
        self.last = text
