#!/bin/bash
# Starts the workspace's main job: the TurtleBot3 Burger with its flag in RViz
# (roslaunch turtlebot_urdf model.launch). Without an X display it says so and
# starts only what needs no window.
set -eo pipefail
cd "$(dirname "$0")/.."
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
# shellcheck disable=SC1091
source devel/setup.bash
args=()
if [[ -z "${DISPLAY:-}" ]] || ! xdpyinfo >/dev/null 2>&1; then
  echo "run: no X display (DISPLAY='${DISPLAY:-}'): RViz cannot open a window, so it is not started."
  echo "run: starting the robot model without RViz (gui:=false); on a desktop, 'make run' shows RViz."
  args+=(gui:=false)
fi
exec roslaunch turtlebot_urdf model.launch "${args[@]}"
