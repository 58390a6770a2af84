"""Tests of multi_robot.py's rate check (no simulator needed): /usr/bin/python3 -m pytest bench/"""
import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import multi_robot  # noqa: E402
import scenario  # noqa: E402


def listener_output(rates):
    """bench_rate_listener's lines for `rates` ({topic: Hz}), then its last two lines."""
    lines = ["%-22s %8.1f Hz (sim time)" % (topic, hz) for topic, hz in sorted(rates.items())]
    return "\n".join(lines + ["sim 20.00 s in 2.000 s wall", "real-time factor 10.0"])


def all_topics(count, camera_hz=None):
    rates = {"/tf": 30.0 * count}
    for ns in multi_robot.namespaces(count):
        prefix = "/" if ns == "/" else "/%s/" % ns
        rates.update({prefix + topic: hz for topic, hz in multi_robot.RATES_HZ.items()})
        if camera_hz is not None:
            rates.update({prefix + topic: camera_hz for topic in multi_robot.CAMERA_RATES_HZ})
    return rates


def test_every_topic_at_its_rate_passes():
    assert multi_robot.check_rates(listener_output(all_topics(4)), 4, False) == 1.0


def test_a_slow_robot_topic_fails_naming_it():
    rates = all_topics(4)
    rates["/tb3_3/imu"] = 150.0
    with pytest.raises(scenario.SanityError, match="/tb3_3/imu came at 150.0 Hz"):
        multi_robot.check_rates(listener_output(rates), 4, False)


def test_camera_topics_may_drop_and_their_delivered_share_is_returned():
    rates = all_topics(1, camera_hz=30.0)
    assert multi_robot.check_rates(listener_output(rates), 1, True) == 1.0
    # Colour images all there, depth images at 27 Hz, clouds at 12 Hz: 69 of 90 per second.
    rates["/camera/depth/image_raw"], rates["/camera/points"] = 27.0, 12.0
    assert multi_robot.check_rates(listener_output(rates), 1, True) == pytest.approx(69 / 90)


def test_a_camera_topic_that_never_came_fails():
    rates = all_topics(1, camera_hz=30.0)
    rates["/camera/points"] = 0.0
    with pytest.raises(scenario.SanityError, match="/camera/points came at 0.0 Hz"):
        multi_robot.check_rates(listener_output(rates), 1, True)


# The simulator's log lines, as the nodelet in the listener's process writes them to the
# same output.
SIMULATOR_LOG = ("\x1b[0m[ INFO] [1795624053.366758144]: sim time 0.000 s, real-time factor "
                 "0.00, turtlebot3_burger at x 0.000 y 0.000 yaw 1.567\x1b[0m")


def test_the_simulators_log_lines_are_not_the_listeners_figures():
    assert not multi_robot.FIGURES_END.search("subscribed\n" + SIMULATOR_LOG + "\n")
    assert not multi_robot.SUBSCRIBED.search(SIMULATOR_LOG + "\n")


def test_the_listeners_last_line_is_found_among_the_simulators_log_lines():
    output = "\n".join(["subscribed", SIMULATOR_LOG, listener_output(all_topics(1)),
                        SIMULATOR_LOG]) + "\n"
    assert multi_robot.SUBSCRIBED.search(output)
    assert multi_robot.FIGURES_END.findall(output) == ["real-time factor 10.0"]
    assert multi_robot.check_rates(output, 1, False) == 1.0
