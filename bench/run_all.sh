#!/bin/bash
# `make bench`: runs the workspace's benchmarks one after the other (they are not
# timed tests: each prints its figures, the real-time factor last).
set -uo pipefail
cd "$(dirname "$0")"
status=0
echo "== sim_rtf.sh: bullet_sim on the round track, every sensor subscribed"
./sim_rtf.sh || status=1
echo "== sim_camera_cost.py: camera frame cost in bullet_sim_node"
./sim_camera_cost.py || status=1
exit $status
