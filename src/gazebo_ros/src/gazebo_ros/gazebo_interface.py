"""Client helpers for the simulator's spawn and configuration services, with the names
and arguments of gazebo_ros's Python API (`from gazebo_ros import gazebo_interface`)."""
import time

import rosgraph
import rospy
from gazebo_msgs.srv import SetModelConfiguration, SpawnModel


def wait_for_service(service_name, poll_s=0.01):
    """Returns once the master knows `service_name`. rospy.wait_for_service looks only every
    0.3 s, which at a launch would keep the robot waiting for up to that long after the
    simulator is up."""
    resolved = rospy.resolve_name(service_name)
    master = rosgraph.Master(rospy.get_name())
    while not rospy.is_shutdown():
        try:
            master.lookupService(resolved)
            return
        except rosgraph.MasterError:  # not registered yet
            time.sleep(poll_s)
        except OSError:  # the master itself is not up yet
            time.sleep(poll_s)
    raise rospy.ROSInterruptException('shut down while waiting for service %s' % resolved)


def _call(service_name, service_type, *args):
    rospy.loginfo('Waiting for service %s', service_name)
    wait_for_service(service_name)
    try:
        response = rospy.ServiceProxy(service_name, service_type)(*args)
    except rospy.ServiceException as error:
        rospy.logerr('%s call failed: %s', service_name, error)
        return False
    (rospy.loginfo if response.success else rospy.logerr)(
        '%s: %s', service_name, response.status_message)
    return response.success


def spawn_sdf_model_client(model_name, model_xml, robot_namespace, initial_pose,
                           reference_frame, gazebo_namespace):
    return _call(gazebo_namespace + '/spawn_sdf_model', SpawnModel, model_name, model_xml,
                 robot_namespace, initial_pose, reference_frame)


def spawn_urdf_model_client(model_name, model_xml, robot_namespace, initial_pose,
                            reference_frame, gazebo_namespace):
    return _call(gazebo_namespace + '/spawn_urdf_model', SpawnModel, model_name, model_xml,
                 robot_namespace, initial_pose, reference_frame)


def set_model_configuration_client(model_name, model_param_name, joint_names, joint_positions,
                                   gazebo_namespace):
    return _call(gazebo_namespace + '/set_model_configuration', SetModelConfiguration,
                 model_name, model_param_name, joint_names, joint_positions)
