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
"""

from bullet_sim._core import (  # noqa: F401
    Condition,
    DueSensor,
    Imu,
    JointStates,
    LoadError,
    NotFoundError,
    Odometry,
    Pose,
    Robot,
    Scan,
    SensorKind,
    Simulation,
    Twist,
    World,
)

__all__ = [
    'Condition', 'DueSensor', 'Imu', 'JointStates', 'LoadError', 'NotFoundError', 'Odometry',
    'Pose', 'Robot', 'Scan', 'SensorKind', 'Simulation', 'Twist', 'World',
]
