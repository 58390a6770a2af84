# Type stub of the bullet_sim package: its names are those of bullet_sim._core.
from bullet_sim._core import Condition as Condition
from bullet_sim._core import DueSensor as DueSensor
from bullet_sim._core import Imu as Imu
from bullet_sim._core import JointStates as JointStates
from bullet_sim._core import LoadError as LoadError
from bullet_sim._core import NotFoundError as NotFoundError
from bullet_sim._core import Odometry as Odometry
from bullet_sim._core import Pose as Pose
from bullet_sim._core import Robot as Robot
from bullet_sim._core import Scan as Scan
from bullet_sim._core import SensorKind as SensorKind
from bullet_sim._core import Simulation as Simulation
from bullet_sim._core import Twist as Twist
from bullet_sim._core import World as World
