#!/bin/bash
# Builds and runs every test of the workspace (gtests, nosetests, rostests, GUI
# tests) inside one private X server, then prints a summary and exits non-zero
# if any test failed, errored or left no result.
set -uo pipefail
cd "$(dirname "$0")/.."
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
export ROS_HOME="${ROS_HOME:-$PWD/build/ros_home}"
export ROS_LOG_DIR="$ROS_HOME/log"
# ROS talks over loopback only, whatever the machine's name resolves to.
export ROS_HOSTNAME=localhost
export ROS_MASTER_URI=http://localhost:11311
unset ROS_IP
export LIBGL_ALWAYS_SOFTWARE=1
export QT_X11_NO_MITSHM=1
rm -rf build/test_results build/.tests_done
# ROS's setup scripts read unset variables.
set +u
# shellcheck disable=SC1091
source devel/setup.bash
set -u
# A line per result file as it appears, and the ten slowest at the end.
/usr/bin/python3 -u scripts/results_watch.py build/test_results --stop build/.tests_done &
progress_pid=$!
echo "running the tests (a line per result file; full output in build/test.log)"
# Every rostest carries its own time limit; this bound only guards the whole run.
timeout --kill-after=30 4800 xvfb-run -a -s "-screen 0 1920x1200x24 -nolisten tcp" \
  catkin_make --source . --build build -DCMAKE_BUILD_TYPE=Release \
  -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCATKIN_WHITELIST_PACKAGES="" run_tests -j1 > build/test.log 2>&1
run_status=$?
(( run_status == 0 )) || echo "catkin_make run_tests exited $run_status (see build/test.log)"
# The benchmark scripts' own checks (rates, sanity of the peers, their output parsing) and
# those of the progress lines printed here; no simulator is started. A failure shows in the
# summary through the result file.
/usr/bin/python3 -m pytest -q -p no:cacheprovider bench/ scripts/tests/ \
  --junitxml=build/test_results/bench/pytest-bench.xml > build/test_bench.log 2>&1
touch build/.tests_done
wait "$progress_pid"
/usr/bin/python3 scripts/test_summary.py build/test_results
summary_status=$?
(( run_status == 0 && summary_status == 0 ))
