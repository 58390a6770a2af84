#!/usr/bin/python3
"""A test node that publishes and subscribes std_msgs/String topics given on the command
line: `fixture_node.py --pub /a /b --sub /c` (publishes at 2 Hz so the graph is live)."""
import argparse

import rospy
from std_msgs.msg import String


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('--pub', nargs='*', default=[])
    parser.add_argument('--sub', nargs='*', default=[])
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node('fixture_node')
    publishers = [rospy.Publisher(t, String, queue_size=1) for t in args.pub]
    for topic in args.sub:
        rospy.Subscriber(topic, String, lambda _msg: None)
    rate = rospy.Rate(2)
    while not rospy.is_shutdown():
        for pub in publishers:
            pub.publish(String(data=rospy.get_name()))
        rate.sleep()


if __name__ == '__main__':
    try:
        main()
    except rospy.ROSInterruptException:
        pass
