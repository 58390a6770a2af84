#!/usr/bin/python3
"""The AutoRace chapter's pictures (src/turtlebot3_gazebo/doc/): the user's commands run
under an X server, then, with the Burger in the first left turn, ImageMagick screenshots of
the Gazebo window (RViz) and of rqt_image_view showing detect_lane's projected lane image.

    xvfb-run -a -s "-screen 0 1600x1000x24" autorace_pictures.py OUT_DIR

needs the AutoRace overlay built and sourced (README, Autonomous driving).
"""
import os
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', '..', 'mobility_testing', 'src'))
from mobility_testing import x11  # noqa: E402
from mobility_testing.ports import free_port  # noqa: E402
from mobility_testing.waiting import wait_for  # noqa: E402

COMMANDS = [
    'roslaunch turtlebot3_gazebo turtlebot3_autorace_2020.launch',
    'roslaunch turtlebot3_autorace_camera intrinsic_camera_calibration.launch',
    'roslaunch turtlebot3_autorace_camera extrinsic_camera_calibration.launch',
    'roslaunch turtlebot3_autorace_detect detect_lane.launch',
    'roslaunch turtlebot3_autorace_driving turtlebot3_autorace_control_lane.launch',
    'rosrun image_transport republish compressed in:=/detect/image_lane raw '
    'out:=/detect/image_lane_raw',
    'rosrun rqt_image_view rqt_image_view /detect/image_lane_raw']


def robot_x():
    import rospy
    from gazebo_msgs.srv import GetModelState
    try:
        return rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)('autorace', '') \
            .pose.position.x
    except rospy.ServiceException:
        return 0.0


def main(out_dir):
    x11.require_display()
    port = free_port()
    os.environ.update(ROS_MASTER_URI='http://localhost:%d' % port, TURTLEBOT3_MODEL='burger',
                      PATH='/usr/bin:/bin:' + os.environ.get('PATH', ''))
    processes = []
    try:
        for i, command in enumerate(COMMANDS):
            words = command.split()
            if i == 0:
                words[1:1] = ['-p', str(port)]
            processes.append(subprocess.Popen(words, stdout=subprocess.DEVNULL,
                                              stderr=subprocess.DEVNULL, start_new_session=True))
            time.sleep(10 if i == 0 else 3)
        import rospy
        rospy.init_node('autorace_pictures', disable_signals=True)
        wait_for(lambda: robot_x() > 1.70, 600, 'the Burger in the first left turn')
        time.sleep(3)  # the image viewer's next frames
        os.makedirs(out_dir, exist_ok=True)
        x11.screenshot(x11.wait_window('RViz'), os.path.join(out_dir, 'autorace_rviz.png'))
        x11.screenshot(x11.wait_window('image_lane_raw|Image View|image view'),
                       os.path.join(out_dir, 'autorace_lane_image.png'))
    finally:
        for process in reversed(processes):
            os.killpg(process.pid, signal.SIGINT)
        for process in processes:
            try:
                process.wait(30)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)


if __name__ == '__main__':
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, '..', '..', 'doc'))
