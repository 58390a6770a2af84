#!/bin/bash
# Benchmark of bullet_sim: the headless round-track scenario (Burger from the spawn pose
# driving a slow circle in the west lane, 1 kHz physics, lidar, IMU, odometry, tf, joint states and /clock all published to a
# subscriber) run as fast as possible for a fixed sim time. Prints the sensor rates (sim
# time) and the real-time factor as the last line. bench/compare runs it beside the core
# alone, MuJoCo and PyBullet.
# Usage: bench/sim_rtf.sh [SIM_SECONDS]   (default 30; needs a built devel/ space,
#        or BENCH_DEVEL=/path/to/devel; BENCH_NODE_PREFIX runs the node under a tool that
#        keeps its process id, e.g. "valgrind --tool=callgrind --callgrind-out-file=/abs/f")
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
SIM_S="${1:-30}"
WARMUP_S=1
PORT="${BENCH_ROS_PORT:-11457}"
DEVEL="${BENCH_DEVEL:-$PWD/devel}"
WORLD="$PWD/src/turtlebot3_gazebo/worlds/roundTrack.world"
WORK="$(mktemp -d)"
set +u  # the catkin setup scripts read unset variables
# shellcheck disable=SC1091
source "$DEVEL/setup.bash"
set -u
export ROS_MASTER_URI="http://localhost:$PORT" ROS_HOME="$WORK/ros_home"

pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$WORK"
}
trap cleanup EXIT

if rosparam list > /dev/null 2>&1; then
  echo "a ROS master already runs on port $PORT: set BENCH_ROS_PORT to a free port"; exit 1
fi
roscore -p "$PORT" > "$WORK/roscore.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do rosparam list > /dev/null 2>&1 && break; sleep 0.1; done
rosparam list > /dev/null || { echo "roscore did not start on port $PORT"; exit 1; }

rosrun xacro xacro turtlebot3_description/urdf/turtlebot3_burger.urdf.xacro > "$WORK/burger.urdf"
rosparam set robot_description -t "$WORK/burger.urdf"
rosrun --prefix "${BENCH_NODE_PREFIX:-}" bullet_sim bullet_sim_node _world_file:="$WORLD" \
  _real_time_factor:=0 _robot_name:=turtlebot3_burger _spawn_yaw:=1.5675 _paused:=true \
  > "$WORK/node.log" 2>&1 &
node_pid=$!
pids+=("$node_pid")

# The node starts paused; a latched command makes the robot drive a 0.33 m circle (a
# robot at rest sleeps and would cost nothing). Wait until the node has it.
rostopic pub -l /cmd_vel geometry_msgs/Twist '{linear: {x: 0.1}, angular: {z: 0.3}}' \
  > "$WORK/cmd_vel.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do
  rostopic info /cmd_vel 2>/dev/null | grep -A3 Subscribers | grep -q bullet_sim && break
  sleep 0.1
done
sleep 0.5

echo "bullet_sim, round track, ${SIM_S} s of sim time after ${WARMUP_S} s warm-up:"
rosrun bullet_sim bench_rate_listener "$WARMUP_S" "$SIM_S" > "$WORK/rates.txt"
kill -INT "$node_pid"
wait "$node_pid" || true
head -n -1 "$WORK/rates.txt"
rtf="$(tail -n 1 "$WORK/rates.txt" | awk '{print $NF}')"
echo "real-time factor $rtf"
