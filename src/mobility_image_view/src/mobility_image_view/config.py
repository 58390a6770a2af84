"""The viewer's settings from its command line and private ROS parameters."""
import argparse
import collections
import os

Config = collections.namedtuple('Config', 'topic save_dir print_status')


class ConfigError(ValueError):
    """A setting has a bad value; the message names it."""


def _parser():
    parser = argparse.ArgumentParser(
        prog='image_view_gui',
        description='Shows a sensor_msgs/Image topic. Private parameters: ~topic, '
                    '~save_dir (save frames there without asking), ~print_status.')
    parser.add_argument('topic', nargs='?', default='',
                        help='image topic to show at start, e.g. /camera/image_raw')
    return parser


def make_config(argv, params):
    """Config from argv (ROS remappings already removed) and a dict of private params.

    A topic argument wins over ~topic. Raises ConfigError naming the bad value."""
    try:
        args = _parser().parse_args(argv)
    except SystemExit as exit_request:
        if exit_request.code == 0:
            raise
        raise ConfigError(f'bad command line: {" ".join(argv)}') from exit_request
    topic = args.topic or params.get('topic', '')
    if not isinstance(topic, str):
        raise ConfigError(f'~topic must be a string, got {topic!r}')
    if topic and not topic.startswith('/'):
        topic = '/' + topic
    save_dir = params.get('save_dir', '')
    if not isinstance(save_dir, str):
        raise ConfigError(f'~save_dir must be a string, got {save_dir!r}')
    if save_dir and not os.path.isdir(save_dir):
        raise ConfigError(f'~save_dir "{save_dir}" is not an existing directory')
    print_status = params.get('print_status', False)
    if not isinstance(print_status, bool):
        raise ConfigError(f'~print_status must be true or false, got {print_status!r}')
    return Config(topic, save_dir, print_status)
