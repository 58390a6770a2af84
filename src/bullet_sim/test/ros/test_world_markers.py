#!/usr/bin/python3
"""/gazebo/world_markers against the world file it was made from: the file is read here
with ElementTree (not the simulator's SDF reader), and every wall must be one cube
marker in frame world whose pose and size match within 1 mm and whose colour is the
visual's diffuse colour."""
import math
import threading
import time
import unittest
import xmlrpc.client
import xml.etree.ElementTree as ET

import numpy as np
import rosgraph
import rospy
import rostest
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import SetModelState
from visualization_msgs.msg import Marker, MarkerArray

MM = 1e-3


def numbers(text):
    return [float(v) for v in text.split()]


def rotation(roll, pitch, yaw):
    """SDF pose rotation (fixed axes x, y, z: Rz * Ry * Rx)."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch),
                              math.cos(yaw), math.sin(yaw))
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


def quaternion_matrix(q):
    x, y, z, w = q.x, q.y, q.z, q.w
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def box_visuals(world_file):
    """{model name: (centre, rotation, size, rgba)} of the models with one box visual whose
    model, link and visual poses are all at the origin but the model's."""
    boxes = {}
    for model in ET.parse(world_file).getroot().iter('model'):
        size = model.find('link/visual/geometry/box/size')
        if size is None:
            continue
        pose = numbers(model.findtext('pose', '0 0 0 0 0 0'))
        boxes[model.get('name')] = (np.array(pose[:3]), rotation(*pose[3:]),
                                    np.array(numbers(size.text)),
                                    numbers(model.find('link/visual/material/diffuse').text))
    return boxes


class WorldMarkers(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('world_markers_test')
        received = threading.Event()
        cls.array = None

        def on_array(msg):
            cls.array = msg
            received.set()
        sub = rospy.Subscriber('/gazebo/world_markers', MarkerArray, on_array)
        if not received.wait(60):
            raise AssertionError('no message on /gazebo/world_markers within 60 s')
        sub.unregister()

    def test_every_wall_is_one_marker_where_the_file_puts_it(self):
        boxes = box_visuals(rospy.get_param('~world_file'))
        walls = {name: b for name, b in boxes.items() if name.startswith('wall_')}
        self.assertEqual(len(walls), 21)
        drawn = [m for m in self.array.markers if m.action == Marker.ADD]
        for name, (centre, rot, size, rgba) in walls.items():
            mine = [m for m in drawn if m.ns == name]
            self.assertEqual(len(mine), 1, name)
            m = mine[0]
            self.assertEqual(m.header.frame_id, 'world')
            self.assertEqual(m.type, Marker.CUBE, name)
            np.testing.assert_allclose([m.scale.x, m.scale.y, m.scale.z], size, atol=MM)
            position = np.array([m.pose.position.x, m.pose.position.y, m.pose.position.z])
            np.testing.assert_allclose(position, centre, atol=MM, err_msg=name)
            # Corners of the box from the marker and from the file agree within 1 mm.
            marker_rot = quaternion_matrix(m.pose.orientation)
            for corner in ([1, 1, 1], [1, -1, -1], [-1, 1, -1]):
                local = 0.5 * size * np.array(corner)
                np.testing.assert_allclose(position + marker_rot @ local, centre + rot @ local,
                                           atol=MM, err_msg=name)
            np.testing.assert_allclose([m.color.r, m.color.g, m.color.b, m.color.a], rgba,
                                       atol=1e-6, err_msg=name)
            self.assertEqual(rgba, [0.57, 0.417, 0.25, 1.0])

    def test_the_array_starts_clean_and_has_the_ground_and_start_line(self):
        self.assertEqual(self.array.markers[0].action, Marker.DELETEALL)
        names = sorted(m.ns for m in self.array.markers[1:])
        self.assertEqual(len(names), 23)
        self.assertIn('ground_plane', names)
        self.assertIn('start_line', names)

    def test_the_spawned_burger_is_on_model_markers_at_its_links(self):
        # Gazebo's window shows a robot whatever else runs: here its visuals come on
        # /gazebo/model_markers, and not with the world's. The Burger spawned at the
        # origin, paused: its visuals lie within its 0.14 m footprint, up to the flag's top.
        received = threading.Event()
        arrays = []

        def on_array(msg):
            arrays.append(msg)
            received.set()
        sub = rospy.Subscriber('/gazebo/model_markers', MarkerArray, on_array)
        self.assertTrue(received.wait(60), 'no message on /gazebo/model_markers within 60 s')
        sub.unregister()
        markers = arrays[-1].markers
        self.assertEqual(markers[0].action, Marker.DELETEALL)
        self.assertEqual({m.ns for m in markers[1:]}, {'burger'})
        self.assertNotIn('burger', {m.ns for m in self.array.markers})
        self.assertGreaterEqual(len(markers) - 1, 8)  # base, wheels, caster, lidar, poles, ...
        for m in markers[1:]:
            self.assertEqual(m.header.frame_id, 'world')
            self.assertLess(math.hypot(m.pose.position.x, m.pose.position.y), 0.12, m.id)
            self.assertGreater(m.pose.position.z, 0.0)
            self.assertLess(m.pose.position.z, 0.6)

    def test_who_subscribes_after_a_move_gets_the_model_where_it_is_now(self):
        # Nobody listens to /gazebo/model_markers while the Burger is moved 1.5 m: the node
        # does not check that topic then, and must check it again once a listener connects.
        # Runs after the test above (unittest's name order), which found it at the origin.
        master = rosgraph.Master('/world_markers_test')
        node = xmlrpc.client.ServerProxy(master.lookupNode('/bullet_sim'))

        def node_sends_model_markers():
            # getBusInfo: [id, peer, direction, transport, topic, connected, ...] per link
            _, _, links = node.getBusInfo('/world_markers_test')
            return any(link[2] == 'o' and link[4] == '/gazebo/model_markers' for link in links)
        deadline = time.monotonic() + 30
        while node_sends_model_markers():
            self.assertLess(time.monotonic(), deadline, 'a subscriber of model_markers stayed')
            time.sleep(0.05)
        rospy.wait_for_service('/gazebo/set_model_state', timeout=30)
        state = ModelState(model_name='burger', reference_frame='world')
        state.pose.position.x, state.pose.position.y = 1.2, -0.9
        state.pose.orientation.w = 1.0
        self.assertTrue(rospy.ServiceProxy('/gazebo/set_model_state', SetModelState)(state)
                        .success)

        moved = threading.Event()

        def on_array(msg):
            # The latched array first (it may still show the Burger at the origin), then
            # the current one: every visual within the 0.14 m footprint of (1.2, -0.9).
            burger = [m for m in msg.markers[1:] if m.ns == 'burger']
            if len(burger) >= 8 and all(
                    math.hypot(m.pose.position.x - 1.2, m.pose.position.y + 0.9) < 0.12
                    for m in burger):
                moved.set()
        sub = rospy.Subscriber('/gazebo/model_markers', MarkerArray, on_array)
        self.assertTrue(moved.wait(30), 'model_markers never showed the Burger where it was moved')
        sub.unregister()


if __name__ == '__main__':
    rostest.rosrun('bullet_sim', 'world_markers', WorldMarkers)
