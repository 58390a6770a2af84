#!/usr/bin/python3
"""Every gazebo_msgs type has the md5sum of ROS Noetic's gazebo_msgs 2.9.2.

A client built against the original package (rospy, roscpp, a recorded bag) only talks to
a peer whose md5sum matches; the expected values below are those of the Noetic release.
The one type added, StepControl (gazebo_ros_pkgs pull request 1280, never released), has
the md5sum of its fields as that request defines them.
"""
import importlib
import unittest

NOETIC_MD5 = {
    'msg': {
        'ContactState': '48c0ffb054b8c444f870cecea1ee50d9',
        'ContactsState': 'acbcb1601a8e525bf72509f18e6f668d',
        'LinkState': '0818ebbf28ce3a08d48ab1eaa7309ebe',
        'LinkStates': '48c080191eb15c41858319b4d8a609c2',
        'ModelState': '9330fd35f2fcd82d457e54bd54e10593',
        'ModelStates': '48c080191eb15c41858319b4d8a609c2',
        'ODEJointProperties': '1b744c32a920af979f53afe2f9c3511f',
        'ODEPhysics': '667d56ddbd547918c32d1934503dc335',
        'PerformanceMetrics': '884f71fd5037b886ec5e126b83c4425a',
        'SensorPerformanceMetric': '01762ded18cfe9ebc7c8222667c99547',
        'WorldState': 'de1a9de3ab7ba97ac0e9ec01a4eb481e',
    },
    'srv': {
        'ApplyBodyWrench': '585b9f9618aa0581b207e2f2d90866bc',
        'ApplyJointEffort': 'c0039811b8cc919490b3cff748cdf46b',
        'BodyRequest': '5eade9afe7f232d78005bd0cafeab755',
        'DeleteLight': 'ae11ea8100d536d5b92c2b5917abf912',
        'DeleteModel': '9ce56b4e9e54616de25d796dc972a262',
        'GetJointProperties': '7b30be900f50aa21efec4a0ec92d91c9',
        'GetLightProperties': 'df2cef87e13e2e6990e81e8aaa454c19',
        'GetLinkProperties': '0e06a70386d0ee3fb880c02f23fcd821',
        'GetLinkState': '09d6c98cce97b35f7ab9bd70300657ab',
        'GetModelProperties': '5717f7bd34ed990fa80e28b3015027a3',
        'GetModelState': '4c515e936d3319c9610c559c60bfc3d4',
        'GetPhysicsProperties': '575a5e74786981b7df2e3afc567693a6',
        'GetWorldProperties': '36bb0f2eccf4d8be971410c22818ba3f',
        'JointRequest': '0be1351618e1dc030eb7959d9a4902de',
        'SetJointProperties': '15a76e921b1410c698d82782ea5fa370',
        'SetJointTrajectory': '88f5c10979e3f9649d5ae87a3b12aa65',
        'SetLightProperties': 'e6f13430c57278bb364aca53a1bf5ebf',
        'SetLinkProperties': 'd534ce1b36ee99de0ffa806c3a6348f0',
        'SetLinkState': '8a5146eb66ae4d26b0860b08f3f271be',
        'SetModelConfiguration': '10e3139d3b669c40afc057d38956fff7',
        'SetModelState': '5b3ab0281d4f5445def017e3a2e4a07b',
        'SetPhysicsProperties': '97e2057080558ce4730434b5fae75c91',
        'SpawnModel': '9ed9c82c96abe1a00c3e8cdaeee24413',
    },
}

# Not in the Noetic release: md5 of the request's fields text followed by the response's,
# "uint32 steps" + "bool success\nstring status_message", as genmsg sums a service.
ADDED_MD5 = {'srv': {'StepControl': 'df8bc3b8af44eb36a9c4981b1dc4b41c'}}


def expected_types(kind):
    return {**NOETIC_MD5[kind], **ADDED_MD5.get(kind, {})}


class TestMd5sums(unittest.TestCase):
    def test_every_type_has_the_noetic_md5sum(self):
        for kind in NOETIC_MD5:
            module = importlib.import_module('gazebo_msgs.' + kind)
            for name, md5 in expected_types(kind).items():
                with self.subTest(type=name):
                    self.assertEqual(getattr(module, name)._md5sum, md5)

    def test_no_type_is_missing_or_extra(self):
        for kind in NOETIC_MD5:
            module = importlib.import_module('gazebo_msgs.' + kind)
            # A service's halves are <Name>Request and <Name>Response; the service
            # class itself carries _request_class.
            generated = {n for n in dir(module)
                         if not n.startswith('_') and hasattr(getattr(module, n), '_md5sum')
                         and (kind == 'msg' or hasattr(getattr(module, n), '_request_class'))}
            self.assertEqual(generated, set(expected_types(kind)), kind)

    def test_service_halves_carry_the_field_names_clients_use(self):
        from gazebo_msgs.srv import GetModelStateResponse, SpawnModelRequest
        self.assertEqual(SpawnModelRequest.__slots__,
                         ['model_name', 'model_xml', 'robot_namespace', 'initial_pose',
                          'reference_frame'])
        self.assertEqual(GetModelStateResponse.__slots__,
                         ['header', 'pose', 'twist', 'success', 'status_message'])


if __name__ == '__main__':
    unittest.main()
