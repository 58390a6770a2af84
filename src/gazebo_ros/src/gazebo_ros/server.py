"""gzserver's command line, translated for bullet_sim_node.

The launch files of gazebo_ros start `gzserver [-u] [-r] [--verbose] -e ode [extra] WORLD`
followed by ROS remappings. bullet_sim honours the world, `-u` (start paused) and
`--seed`; the other options have no meaning for it and are reported once, never an error.
"""

# gzserver options that take a value, and those that do not (Gazebo 11's list).
OPTIONS_WITH_VALUE = {'-e', '--physics', '-p', '--play', '--record_path', '--record_period',
                      '--record_filter', '--record_encoding', '--iters', '-s',
                      '--server-plugin', '-o', '--profile', '--seed', '--minimal_comms'}
FLAGS = {'-u', '--pause', '-r', '--record', '--verbose', '-q', '--quiet', '--lockstep',
         '--help', '-h', '--version', '-v', '--minimal_comms'}


class ServerArgs(object):
    def __init__(self):
        self.world = None
        self.paused = False
        self.seed = None
        self.physics = 'ode'
        self.ignored = []      # options accepted without effect
        self.remappings = []   # ROS arguments (name:=value), passed on


def parse(argv):
    """Splits gzserver's arguments; raises ValueError for a missing option value."""
    args = ServerArgs()
    i = 0
    while i < len(argv):
        word = argv[i]
        if ':=' in word:
            args.remappings.append(word)
        elif word in ('-u', '--pause'):
            args.paused = True
        elif word in OPTIONS_WITH_VALUE - {'--minimal_comms'}:
            if i + 1 >= len(argv):
                raise ValueError('gzserver option %s needs a value' % word)
            value = argv[i + 1]
            if word == '--seed':
                args.seed = int(value)
            elif word in ('-e', '--physics'):
                args.physics = value
            else:
                args.ignored.append('%s %s' % (word, value))
            i += 1
        elif word.startswith('-'):
            args.ignored.append(word)
        elif word:
            args.world = word
        i += 1
    return args


def node_arguments(args, world_path):
    """bullet_sim_node's private parameters for these gzserver arguments."""
    params = ['_world_file:=' + world_path, '_paused:=' + ('true' if args.paused else 'false')]
    if args.seed is not None:
        params.append('_seed:=%d' % args.seed)
    return params + args.remappings
