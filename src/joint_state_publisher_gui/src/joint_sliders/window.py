"""The joint-slider window: a filter field, one row per free joint, Center and Randomize."""
from PyQt5.QtWidgets import (QHBoxLayout, QLabel, QLineEdit, QPushButton, QScrollArea,
                             QVBoxLayout, QWidget)

from joint_sliders.joint_row import JointRow

WINDOW_TITLE = 'Joint State Publisher'
NO_JOINTS_TEXT = ('This robot has no movable joints.\n'
                  'Empty joint states are published so that tf still works.')


class JointWindow(QWidget):
    """Edits the positions of a JointModel; rng (random.Random) drives Randomize."""

    def __init__(self, model, robot_name, rng, parent=None):
        super().__init__(parent)
        self.model = model
        self.rng = rng
        self.setWindowTitle(f'{WINDOW_TITLE} - {robot_name}' if robot_name else WINDOW_TITLE)
        self.rows = [JointRow(joint) for joint in model.slider_joints]
        layout = QVBoxLayout(self)
        self.filter_edit = QLineEdit(self)
        self.filter_edit.setPlaceholderText('Filter joints by name')
        self.filter_edit.setClearButtonEnabled(True)
        self.filter_edit.textChanged.connect(self.apply_filter)
        layout.addWidget(self.filter_edit)
        self.message = QLabel(NO_JOINTS_TEXT if not self.rows else '', self)
        self.message.setVisible(not self.rows)
        layout.addWidget(self.message)
        layout.addWidget(self._scroll_area(), 1)
        buttons = QHBoxLayout()
        self.center_button = QPushButton('Center', self)
        self.center_button.clicked.connect(self.center)
        self.randomize_button = QPushButton('Randomize', self)
        self.randomize_button.clicked.connect(self.randomize)
        for button in (self.center_button, self.randomize_button):
            button.setEnabled(bool(self.rows))
            buttons.addWidget(button)
        layout.addLayout(buttons)
        for row in self.rows:
            row.moved.connect(self._row_moved)

    def _scroll_area(self):
        inner = QWidget(self)
        rows_layout = QVBoxLayout(inner)
        rows_layout.setContentsMargins(0, 0, 0, 0)
        for row in self.rows:
            rows_layout.addWidget(row)
        rows_layout.addStretch(1)
        area = QScrollArea(self)
        area.setWidgetResizable(True)
        area.setWidget(inner)
        area.setMinimumHeight(min(len(self.rows), 8) * 34 + 8)
        return area

    def _row_moved(self, name, position):
        kept = self.model.set_position(name, position)
        if kept != position:
            self.refresh()

    def apply_filter(self, text):
        """Shows only the rows whose joint name contains text (case-insensitive)."""
        needle = text.strip().lower()
        for row in self.rows:
            row.setVisible(needle in row.joint.name.lower())

    def center(self):
        """All free joints to their zero."""
        self.model.center()
        self.refresh()

    def randomize(self):
        """All free joints to random positions within their ranges."""
        self.model.randomize(self.rng)
        self.refresh()

    def refresh(self):
        """Shows the model's positions (after Center, Randomize or a source message)."""
        for row in self.rows:
            row.show_position(row.joint.position)
