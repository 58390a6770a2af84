"""Where RViz's Orbit view puts a point of its fixed frame on the screen, and back.

RViz's Orbit camera sits at focal point + distance * (cos yaw cos pitch, sin yaw cos pitch,
sin pitch), looks at the focal point with +z up, and has a vertical field of view of
`Field of View` radians over the render area's height. The values come from the view of an
.rviz file, so a test can compute where the world's objects must appear."""
import math

import numpy as np
import yaml


class OrbitView:
    def __init__(self, focal_point, distance, yaw, pitch, fov_y):
        self.focal = np.asarray(focal_point, dtype=float)
        self.fov_y = float(fov_y)
        self.eye = self.focal + distance * np.array([math.cos(yaw) * math.cos(pitch),
                                                     math.sin(yaw) * math.cos(pitch),
                                                     math.sin(pitch)])
        forward = self.focal - self.eye
        self.forward = forward / np.linalg.norm(forward)
        right = np.cross(self.forward, [0.0, 0.0, 1.0])
        self.right = right / np.linalg.norm(right)
        self.up = np.cross(self.right, self.forward)

    @classmethod
    def from_rviz_config(cls, path):
        """The current Orbit view of an .rviz file (its target frame must be the fixed frame)."""
        with open(path) as f:
            view = yaml.safe_load(f)['Visualization Manager']['Views']['Current']
        if view['Class'] != 'rviz/Orbit':
            raise ValueError(f'{path}: the current view is {view["Class"]}, not rviz/Orbit')
        focal = view['Focal Point']
        return cls((focal['X'], focal['Y'], focal['Z']), view['Distance'], view['Yaw'],
                   view['Pitch'], view['Field of View'])

    def _pixels_per_unit(self, height):
        return 0.5 * height / math.tan(0.5 * self.fov_y)

    def project(self, point, area):
        """Screen pixel (x, y) of a 3D point for a render area (x, y, width, height)."""
        x0, y0, width, height = area
        d = np.asarray(point, dtype=float) - self.eye
        depth = d @ self.forward
        if depth <= 0:
            raise ValueError(f'point {point} is behind the camera')
        k = self._pixels_per_unit(height) / depth
        return (x0 + 0.5 * width + k * (d @ self.right),
                y0 + 0.5 * height - k * (d @ self.up))

    def ground_point(self, pixel, area, ground_z=0.0):
        """The point of the plane z = ground_z seen at screen pixel (x, y)."""
        x0, y0, width, height = area
        k = self._pixels_per_unit(height)
        ray = (self.forward + ((pixel[0] - x0 - 0.5 * width) / k) * self.right
               - ((pixel[1] - y0 - 0.5 * height) / k) * self.up)
        if abs(ray[2]) < 1e-12:
            raise ValueError(f'pixel {pixel} looks along the ground')
        t = (ground_z - self.eye[2]) / ray[2]
        if t <= 0:
            raise ValueError(f'pixel {pixel} looks above the horizon')
        return self.eye + t * ray
