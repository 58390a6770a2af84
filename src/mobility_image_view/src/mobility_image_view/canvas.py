"""The widget that draws the current frame, fitted to the window or at 1:1."""
from PyQt5.QtCore import QRect, QSize, Qt
from PyQt5.QtGui import QColor, QImage, QPainter
from PyQt5.QtWidgets import QSizePolicy, QWidget

BACKGROUND = QColor(48, 48, 48)
TEXT = QColor(230, 230, 230)


def qimage_from_rgb(rgb):
    """A QImage owning a copy of an (H, W, 3) uint8 RGB array."""
    height, width = rgb.shape[:2]
    return QImage(rgb.data, width, height, 3 * width, QImage.Format_RGB888).copy()


def fitted_rect(image_size, area):
    """The largest rectangle of the image's aspect ratio centred in area (QRect)."""
    scaled = image_size.scaled(area.size(), Qt.KeepAspectRatio)
    left = area.x() + (area.width() - scaled.width()) // 2
    top = area.y() + (area.height() - scaled.height()) // 2
    return QRect(left, top, scaled.width(), scaled.height())


class ImageCanvas(QWidget):
    """Shows a QImage, or a plain message when there is nothing to draw."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self._image = None
        self._message = 'no topic selected'
        self._fit = True
        self.setSizePolicy(QSizePolicy.Expanding, QSizePolicy.Expanding)
        self.setMinimumSize(160, 120)

    def set_image(self, image):
        """Draws image (a QImage) from now on."""
        resized = self._image is None or self._image.size() != image.size()
        self._image, self._message = image, ''
        if resized and not self._fit:
            self.resize(image.size())
        self.update()

    def message(self):
        """The message shown instead of a picture ('' while a picture is shown)."""
        return self._message

    def set_message(self, text):
        """Replaces the picture by a centred message."""
        self._image, self._message = None, text
        self.update()

    def set_fit(self, fit):
        """Fit the picture to the widget (True) or draw it pixel for pixel (False)."""
        self._fit = fit
        if not fit and self._image is not None:
            self.resize(self._image.size())
        self.update()

    def sizeHint(self):
        if self._image is not None and not self._fit:
            return self._image.size()
        return QSize(640, 480)

    def paintEvent(self, _event):
        painter = QPainter(self)
        painter.fillRect(self.rect(), BACKGROUND)
        if self._image is None:
            painter.setPen(TEXT)
            painter.drawText(self.rect().adjusted(12, 12, -12, -12),
                             Qt.AlignCenter | Qt.TextWordWrap, self._message)
        elif self._fit:
            painter.setRenderHint(QPainter.SmoothPixmapTransform)
            painter.drawImage(fitted_rect(self._image.size(), self.rect()), self._image)
        else:
            painter.drawImage(0, 0, self._image)
        painter.end()
