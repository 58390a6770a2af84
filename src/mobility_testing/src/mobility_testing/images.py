"""Reading screenshots and measuring colours in them."""
import cv2
import numpy as np


def load_png(path):
    """Returns an image file as an (H, W, 3) uint8 RGB array."""
    pixels = cv2.imread(path, cv2.IMREAD_COLOR)
    if pixels is None:
        raise ValueError(f'{path}: not a readable image')
    return cv2.cvtColor(pixels, cv2.COLOR_BGR2RGB)


def colour_mask(image, rgb, tolerance=30):
    """Boolean mask of pixels whose every channel is within tolerance of rgb."""
    diff = np.abs(image.astype(np.int16) - np.array(rgb, dtype=np.int16))
    return np.all(diff <= tolerance, axis=2)


def count_colour(image, rgb, tolerance=30):
    """Number of pixels within tolerance of rgb."""
    return int(colour_mask(image, rgb, tolerance).sum())


def hue_mask(image, predicate):
    """Mask of pixels for which predicate(r, g, b) (int arrays) is true."""
    r, g, b = (image[..., i].astype(np.int32) for i in range(3))
    return predicate(r, g, b)


# Colour classes as they appear in lit 3D views (RViz shading scales colours):
# each is a predicate on int32 channel arrays.
COLOUR_CLASSES = {
    'orange': lambda r, g, b: (r > 140) & (g > 0.25 * r) & (g < 0.65 * r) & (b < 0.25 * r),
    'red': lambda r, g, b: (r > 110) & (g < 0.3 * r) & (b < 0.3 * r),
    'blue': lambda r, g, b: (b > 110) & (r < 0.4 * b) & (g < 0.6 * b),
    'white': lambda r, g, b: (r > 200) & (g > 200) & (b > 200),
    'black': lambda r, g, b: (r < 22) & (g < 22) & (b < 22),
    'brown': lambda r, g, b: (r > 70) & (r > g + 15) & (g > b + 15) & (b > 0.2 * r),
    'grey': lambda r, g, b: (abs(r - g) < 10) & (abs(g - b) < 10) & (r > 60) & (r < 200),
}


def count_class(image, name):
    """Number of pixels of the named colour class (a key of COLOUR_CLASSES)."""
    return int(hue_mask(image, COLOUR_CLASSES[name]).sum())


def region_of_colour(image, rgb, tolerance=3, min_fraction=0.2):
    """Bounding box (top, bottom, left, right; exclusive ends) of the rows and
    columns in which at least min_fraction of the pixels have colour rgb: the
    extent of a view whose background is rgb (e.g. RViz's 3D panel)."""
    mask = colour_mask(image, rgb, tolerance)
    rows = np.flatnonzero(mask.mean(axis=1) >= min_fraction)
    cols = np.flatnonzero(mask.mean(axis=0) >= min_fraction)
    if rows.size == 0 or cols.size == 0:
        return None
    return int(rows[0]), int(rows[-1]) + 1, int(cols[0]), int(cols[-1]) + 1


def save_png(image, path):
    """Writes an (H, W, 3) uint8 RGB array as a PNG file."""
    if not cv2.imwrite(path, cv2.cvtColor(np.ascontiguousarray(image), cv2.COLOR_RGB2BGR)):
        raise ValueError(f'{path}: could not be written')
    return path


def shade_mask(image, rgb, ratio_tolerance=0.08, min_level=20):
    """Pixels that are `rgb` under some amount of light: a lit 3D view scales a surface's
    colour by its shading, so green/red and blue/red keep the colour's ratios. rgb may be
    0..1 floats (a material's diffuse colour); its red must be its largest channel."""
    r, g, b = (image[..., i].astype(np.float64) for i in range(3))
    ref = np.asarray(rgb, dtype=np.float64)
    red = np.maximum(r, 1.0)
    return ((r >= min_level)
            & (np.abs(g / red - ref[1] / ref[0]) <= ratio_tolerance)
            & (np.abs(b / red - ref[2] / ref[0]) <= ratio_tolerance))
