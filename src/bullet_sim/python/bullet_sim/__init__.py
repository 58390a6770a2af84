"""bullet_sim without ROS: load SDF worlds and URDF/SDF robots, step the physics, read the
sensors (scans, odometry, IMU, joint states, camera images) as NumPy arrays.

    import bullet_sim
    world = bullet_sim.World.from_file('roundTrack.world')
    sim = bullet_sim.Simulation(world, physics_step=0.001, seed=1)
    sim.spawn('burger', bullet_sim.Robot.from_urdf(urdf_text), pose=(0, 0, 0, 1.5675))
    sim.set_cmd_vel('burger', 0.1, 0.0)
    sim.step(200)
    scan = sim.read_scan('burger')      # scan.ranges: float32 array

Nothing here imports ROS; the core library links no ROS library. Errors: LoadError (a
description that cannot be loaded), NotFoundError (a KeyError and an IndexError: unknown
robot, sensor index, link or joint), ValueError (a bad argument). Methods release the GIL:
step separate Simulations from separate threads to run them in parallel.

Importing bullet_sim loads nothing compiled: the module's names come from bullet_sim._core on
first use, so that ROS clients of the generated bullet_sim.srv never load the core.
"""

# Found from the source folder first (a subprocess inherits the source folder the devel
# space's __init__ puts on sys.path), the package still spans the devel folder that holds
# _core and the generated messages.
from pkgutil import extend_path as _extend_path

__path__ = _extend_path(__path__, __name__)

__all__ = [
    'Condition', 'DueSensor', 'Imu', 'JointStates', 'LoadError', 'NotFoundError', 'Odometry',
    'Pose', 'Robot', 'Scan', 'SensorKind', 'Simulation', 'Twist', 'World',
]


def __getattr__(name):
    if name in __all__:
        from bullet_sim import _core
        value = getattr(_core, name)
        globals()[name] = value
        return value
    raise AttributeError('module %r has no attribute %r' % (__name__, name))


def __dir__():
    return sorted(set(globals()) | set(__all__))
