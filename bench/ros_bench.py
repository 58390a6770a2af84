"""Helpers of the benchmark scripts that run ROS processes: the devel space's environment
with a private master port, roscore, the Burger's URDF, child processes that end with the
script, a work folder that goes with it, and a node's resident memory."""
import atexit
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORLD = os.path.join(ROOT, "src/turtlebot3_gazebo/worlds/roundTrack.world")
BURGER_XACRO = os.path.join(ROOT, "turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro")


def work_folder(prefix="bench_"):
    """A fresh folder under the system's temp folder, removed with everything in it when
    the script ends (sys.exit included)."""
    path = tempfile.mkdtemp(prefix=prefix)
    atexit.register(shutil.rmtree, path, ignore_errors=True)
    return path


def load_average():
    """The 1-, 5- and 15-minute load averages, as /proc/loadavg gives them."""
    with open("/proc/loadavg") as loadavg:
        return " ".join(loadavg.read().split()[:3])


def median_range(values, digits=3):
    """"median (min-max)" of `values`."""
    return "%.*f (%.*f-%.*f)" % (digits, statistics.median(values), digits, min(values),
                                 digits, max(values))


def devel_dir():
    return os.environ.get("BENCH_DEVEL", os.path.join(ROOT, "devel"))


def ros_env(port, devel=None):
    """The environment of `source devel/setup.bash` with the master on `port`."""
    devel = devel or devel_dir()
    out = subprocess.run(["bash", "-c", "source %s/setup.bash && env -0" % devel],
                         check=True, stdout=subprocess.PIPE).stdout
    env = dict(item.split("=", 1) for item in out.decode().split("\0") if "=" in item)
    env["ROS_MASTER_URI"] = "http://localhost:%d" % port
    env["PATH"] = "/usr/bin:/bin:" + env.get("PATH", "")
    return env


def adopt_env(env):
    """Makes this process see `env` (rospy reads os.environ and needs the devel PYTHONPATH)."""
    os.environ.update(env)
    sys.path[:0] = [p for p in env.get("PYTHONPATH", "").split(":") if p and p not in sys.path]


def master_up(env):
    return subprocess.run(["rosparam", "list"], env=env, stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL).returncode == 0


def wait_for(condition, what, timeout_s=30.0, poll_s=0.05):
    deadline = time.monotonic() + timeout_s
    while not condition():
        if time.monotonic() > deadline:
            raise RuntimeError("%s: not within %.0f s" % (what, timeout_s))
        time.sleep(poll_s)


class Processes:
    """Child processes that are interrupted (SIGINT, as roslaunch does) when the block ends."""

    def __init__(self):
        self.procs = []

    def __enter__(self):
        return self

    def start(self, args, env, **kwargs):
        kwargs.setdefault("stdout", subprocess.DEVNULL)
        kwargs.setdefault("stderr", subprocess.DEVNULL)
        proc = subprocess.Popen(args, env=env, **kwargs)
        self.procs.append(proc)
        return proc

    def __exit__(self, *exc):
        for proc in reversed(self.procs):
            if proc.poll() is None:
                proc.send_signal(2)
                try:
                    proc.wait(timeout=15)
                except subprocess.TimeoutExpired:
                    proc.kill()
                    proc.wait()


def start_master(procs, env, port):
    if master_up(env):
        raise RuntimeError("a ROS master already runs on port %d: choose another port" % port)
    procs.start(["roscore", "-p", str(port)], env)
    wait_for(lambda: master_up(env), "roscore on port %d" % port)


def burger_urdf(env, path):
    """Writes the Burger's URDF (xacro of the description package) to `path`."""
    with open(path, "w") as out:
        subprocess.run(["rosrun", "xacro", "xacro", BURGER_XACRO], env=env, check=True,
                       stdout=out)
    return path


def depth_burger_urdf(urdf, path):
    """Writes the Burger with its camera made a depth camera (as a Gazebo user does it: sensor
    type depth, the openni_kinect plugin) to `path`, for the depth frame's cost."""
    with open(urdf) as f:
        text = f.read()
    for old, new in (('<sensor name="camera" type="camera">', '<sensor name="camera" type="depth">'),
                     ("libgazebo_ros_camera.so", "libgazebo_ros_openni_kinect.so")):
        if old not in text:
            raise RuntimeError("%s: no %s to make the camera a depth camera" % (urdf, old))
        text = text.replace(old, new)
    with open(path, "w") as out:
        out.write(text)
    return path


def resident_mb(pid, field="VmRSS"):
    """Resident memory of a process in MB (VmRSS now, VmHWM at its peak)."""
    with open("/proc/%d/status" % pid) as status:
        for line in status:
            if line.startswith(field + ":"):
                return int(line.split()[1]) / 1024.0
    raise RuntimeError("no %s for pid %d" % (field, pid))


def descendants(pid):
    """Process ids of every descendant of `pid`, from /proc."""
    children = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open("/proc/%s/stat" % entry) as stat:
                    ppid = int(stat.read().rsplit(")", 1)[1].split()[1])
            except OSError:
                continue
            children.setdefault(ppid, []).append(int(entry))
    found, todo = [], [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            found.append(child)
            todo.append(child)
    return found


def process_named(pids, name):
    for pid in pids:
        try:
            with open("/proc/%d/comm" % pid) as comm:
                if comm.read().strip() == name[:15]:
                    return pid
        except OSError:
            continue
    return None
