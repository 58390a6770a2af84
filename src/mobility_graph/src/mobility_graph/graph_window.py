"""The graph window: toolbar (refresh, mode, debug hiding, filter, auto-refresh, fit,
save) over a zoomable view of the graph as Graphviz lays it out.

ROS-free: the window is handed a `fetch` callable returning a SystemState."""
import time

from PyQt5 import QtCore, QtGui, QtSvg, QtWidgets

from mobility_graph import graph_model
from mobility_graph.dot_writer import to_dot
from mobility_graph.render import RenderError, render, write_graph

TITLE = 'Node Graph'
MODE_LABELS = ((graph_model.MODE_NODES, 'Nodes only'),
               (graph_model.MODE_ALL, 'Nodes/Topics (all)'))
SAVE_FILTERS = 'SVG image (*.svg);;PNG image (*.png);;Graphviz DOT (*.dot)'


class GraphView(QtWidgets.QGraphicsView):
    """Shows one SVG; the wheel zooms around the mouse, dragging pans."""

    def __init__(self):
        super().__init__()
        self.setScene(QtWidgets.QGraphicsScene(self))
        self.setDragMode(QtWidgets.QGraphicsView.ScrollHandDrag)
        self.setTransformationAnchor(QtWidgets.QGraphicsView.AnchorUnderMouse)
        self.setRenderHints(QtGui.QPainter.Antialiasing | QtGui.QPainter.TextAntialiasing
                            | QtGui.QPainter.SmoothPixmapTransform)
        self.setBackgroundBrush(QtGui.QColor('white'))
        self._renderer = None

    def show_svg(self, svg_bytes):
        self.scene().clear()
        self._renderer = QtSvg.QSvgRenderer(QtCore.QByteArray(svg_bytes))
        item = QtSvg.QGraphicsSvgItem()
        item.setSharedRenderer(self._renderer)
        self.scene().addItem(item)
        self.scene().setSceneRect(item.boundingRect().adjusted(-20, -20, 20, 20))

    def fit(self):
        rect = self.scene().sceneRect()
        if rect.isEmpty():
            return
        self.fitInView(rect, QtCore.Qt.KeepAspectRatio)
        if self.transform().m11() > 1.5:
            self.setTransform(QtGui.QTransform.fromScale(1.5, 1.5))

    def wheelEvent(self, event):
        factor = 1.2 if event.angleDelta().y() > 0 else 1 / 1.2
        self.scale(factor, factor)


class GraphWindow(QtWidgets.QMainWindow):
    def __init__(self, fetch, options, auto_refresh_s=0.0):
        super().__init__()
        self._fetch = fetch
        self._dot_text = ''
        self.setWindowTitle(TITLE)
        self.resize(1100, 700)
        self.view = GraphView()
        self.setCentralWidget(self.view)
        self._build_toolbar(options, auto_refresh_s)
        self._timer = QtCore.QTimer(self)
        self._timer.timeout.connect(self.refresh)
        self._install_shortcuts()
        self._on_auto_refresh()
        self.refresh()

    def _install_shortcuts(self):
        shortcuts = (('F5', self.refresh),
                     ('Ctrl+1', lambda: self.mode_combo.setCurrentIndex(0)),
                     ('Ctrl+2', lambda: self.mode_combo.setCurrentIndex(1)),
                     ('Ctrl+D', self.debug_check.toggle),
                     ('Ctrl+F', self.filter_edit.setFocus),
                     ('Ctrl+0', self.view.fit),
                     ('Ctrl+S', self._save))
        for keys, slot in shortcuts:
            QtWidgets.QShortcut(QtGui.QKeySequence(keys), self).activated.connect(slot)

    def _build_toolbar(self, options, auto_refresh_s):
        bar = self.addToolBar('Graph')
        bar.setMovable(False)
        bar.addAction('Refresh', self.refresh).setToolTip('Read the master again (F5)')
        self.mode_combo = QtWidgets.QComboBox()
        for mode, label in MODE_LABELS:
            self.mode_combo.addItem(label, mode)
        self.mode_combo.setCurrentIndex([m for m, _ in MODE_LABELS].index(options.mode))
        self.mode_combo.setToolTip('Ctrl+1 nodes only, Ctrl+2 nodes and topics')
        self.mode_combo.currentIndexChanged.connect(self._on_mode)
        bar.addWidget(self.mode_combo)
        self.debug_check = QtWidgets.QCheckBox('Hide debug')
        self.debug_check.setToolTip('Hide /rosout and this tool itself (Ctrl+D)')
        self.debug_check.setChecked(options.hide_debug)
        self.debug_check.toggled.connect(self.refresh)
        bar.addWidget(self.debug_check)
        bar.addSeparator()
        bar.addWidget(QtWidgets.QLabel(' Filter: '))
        self.filter_edit = QtWidgets.QLineEdit(options.filter_text)
        self.filter_edit.setPlaceholderText('regex, comma-separated; -regex excludes')
        self.filter_edit.setMinimumWidth(240)
        self.filter_edit.editingFinished.connect(self.refresh)
        bar.addWidget(self.filter_edit)
        bar.addSeparator()
        self.auto_check = QtWidgets.QCheckBox('Auto-refresh every')
        self.auto_check.setChecked(auto_refresh_s > 0)
        self.auto_spin = QtWidgets.QDoubleSpinBox()
        self.auto_spin.setRange(0.5, 60.0)
        self.auto_spin.setSuffix(' s')
        self.auto_spin.setValue(auto_refresh_s if auto_refresh_s > 0 else 2.0)
        self.auto_check.toggled.connect(self._on_auto_refresh)
        self.auto_spin.valueChanged.connect(self._on_auto_refresh)
        bar.addWidget(self.auto_check)
        bar.addWidget(self.auto_spin)
        bar.addSeparator()
        bar.addAction('Fit', self.view.fit)
        bar.addAction('Save as...', self._save)

    def options(self):
        return graph_model.Options(mode=self.mode_combo.currentData(),
                                   hide_debug=self.debug_check.isChecked(),
                                   filter_text=self.filter_edit.text())

    def _on_mode(self):
        self._dot_text = ''
        self.refresh()

    def _on_auto_refresh(self):
        if self.auto_check.isChecked():
            self._timer.start(int(self.auto_spin.value() * 1000))
        else:
            self._timer.stop()

    def refresh(self):
        """Reads the master, rebuilds the graph, redraws only when it changed."""
        try:
            graph = graph_model.build_graph(self._fetch(), self.options())
            dot_text = to_dot(graph)
            if dot_text != self._dot_text:
                refit = not self._dot_text
                self.view.show_svg(render(dot_text, 'svg'))
                self._dot_text = dot_text
                if refit:
                    self.view.fit()
        except (RuntimeError, ValueError) as err:
            self.statusBar().showMessage(f'Error: {err}')
            return
        counts = (len(graph.names(graph_model.NODE)), len(graph.names(graph_model.TOPIC)),
                  len(graph.edges))
        self.statusBar().showMessage('{} nodes, {} topics, {} edges; updated {}'.format(
            *counts, time.strftime('%H:%M:%S')))

    def _save(self):
        path, chosen = QtWidgets.QFileDialog.getSaveFileName(self, 'Save graph', 'rosgraph.svg',
                                                             SAVE_FILTERS)
        if not path:
            return
        if '.' not in path.rsplit('/', 1)[-1]:
            path += '.' + chosen.split('*.')[1].rstrip(')')
        try:
            write_graph(path, self._dot_text)
        except RenderError as err:
            QtWidgets.QMessageBox.warning(self, 'Save graph', str(err))
            return
        self.statusBar().showMessage(f'saved {path}')
