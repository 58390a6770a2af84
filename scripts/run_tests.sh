#!/bin/bash
# Builds the test programs (-j2) and runs every test of the workspace (gtests, pytests,
# rostests, GUI tests, the benchmark scripts' own checks) on TEST_JOBS workers at once
# (default 2), each worker with its own Xvfb server (scripts/test_runner.py); then prints
# a summary and exits non-zero if any test failed, errored, outlived its time limit or
# left no result.
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
rm -rf build/test_results build/test_output
# ROS's setup scripts read unset variables.
set +u
# shellcheck disable=SC1091
source devel/setup.bash
set -u
echo "building the test programs (full output in build/test_build.log)"
if ! /usr/bin/python3 -u scripts/test_build.py --log build/test_build.log -- \
    catkin_make --source . --build build -DCMAKE_BUILD_TYPE=Release \
    -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCATKIN_WHITELIST_PACKAGES="" tests -j"${JOBS:-2}"; then
  echo "building the test programs failed; last lines of build/test_build.log:"
  tail -n 40 build/test_build.log
  exit 1
fi
echo "running the tests (a line per result file; full output in build/test.log)"
# Every job carries its own time limit; this bound only guards the whole run.
timeout --kill-after=30 4800 /usr/bin/python3 -u scripts/test_runner.py build \
  --jobs "${TEST_JOBS:-2}" --only "${TEST_ONLY:-}" --repo . --log build/test.log
run_status=$?
(( run_status == 0 )) || echo "the test runner exited $run_status (see build/test.log)"
/usr/bin/python3 scripts/test_summary.py build/test_results
summary_status=$?
(( run_status == 0 && summary_status == 0 ))
