#!/bin/bash
# Regenerates doc/xqrobot_sliders.png: starts a private roscore and the slider
# window for the xqrobot, moves two joints with xdotool, screenshots the window.
# Run under an X server, e.g.:
#   xvfb-run -a -s "-screen 0 1600x1200x24" src/joint_state_publisher_gui/doc/take_screenshot.sh
# after sourcing the workspace's devel/setup.bash.
set -euo pipefail
export PATH=/usr/bin:/bin:$PATH
DOC=$(cd "$(dirname "$0")" && pwd)
WORK=$(mktemp -d)
PORT=${SCREENSHOT_ROS_PORT:-11437}
export ROS_MASTER_URI=http://localhost:$PORT ROS_HOME=$WORK QT_X11_NO_MITSHM=1
roscore -p "$PORT" > "$WORK/roscore.log" 2>&1 &
CORE=$!
GUI=
cleanup() { [ -n "$GUI" ] && kill "$GUI"; kill "$CORE"; wait; rm -rf "$WORK"; }
trap cleanup EXIT
timeout 30 bash -c 'until rosparam list >/dev/null 2>&1; do sleep 0.2; done'
rosparam set -t "$(rospack find xqrobot_description)/urdf/xqrobot_base.urdf" robot_description
rosrun joint_state_publisher_gui joint_state_publisher_gui \
  _layout_report:="$WORK/layout.json" > "$WORK/gui.log" 2>&1 &
GUI=$!
/usr/bin/python3 - "$WORK/layout.json" "$DOC/xqrobot_sliders.png" <<'PY'
import json, os, sys
from mobility_testing import x11
from mobility_testing.waiting import wait_for

report, out = sys.argv[1:]
window = x11.wait_window('^Joint State Publisher')
wait_for(lambda: os.path.exists(report), 30, 'the layout report')
layout = json.load(open(report))
rows = {r['name']: r for r in layout['rows']}
handle = rows['left_wheel_joint']['slider']['handle']
x, y = handle['x'] + handle['w'] // 2, handle['y'] + handle['h'] // 2
x11.drag(window, x, y, x + 90, y)
box = rows['front_caster_joint']['value_box']
x11.click(window, box['x'] + box['w'] // 2, box['y'] + box['h'] // 2)
x11.key(window, 'ctrl+a')
x11.key(window, 'minus')
x11.type_text(window, '1.2')
x11.key(window, 'Return')
x11.click(window, 5, 5)

def shown():
    rows = {r['name']: r for r in json.load(open(report))['rows']}
    return rows['front_caster_joint']['position'] == -1.2 and \
        rows['left_wheel_joint']['position'] > 0.5
wait_for(shown, 30, 'both joints moved in the window')
x11.screenshot(window, out)
print('wrote', out)
PY
