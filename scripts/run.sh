#!/bin/bash
# Starts the workspace's main job: the TurtleBot3 Burger with its flag on the
# round track in the simulator, with RViz (roslaunch turtlebot3_gazebo
# roundTrack_simulation.launch). Without an X display it says so and starts
# only what needs no window. Extra arguments go to roslaunch (e.g.
# real_time_factor:=2).
set -eo pipefail
cd "$(dirname "$0")/.."
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
# shellcheck disable=SC1091
source devel/setup.bash
args=()
if [[ -z "${DISPLAY:-}" ]] || ! xdpyinfo >/dev/null 2>&1; then
  echo "run: no X display (DISPLAY='${DISPLAY:-}'): RViz cannot open a window, so it is not started."
  echo "run: starting the simulation headless (gui:=false); drive it with 'rosrun mobility_steering teleop_keyboard'."
  args+=(gui:=false)
fi
exec roslaunch turtlebot3_gazebo roundTrack_simulation.launch "${args[@]}" "$@"
