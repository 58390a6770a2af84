#!/bin/bash
# Runs a build command, showing only progress headlines, a line as each package starts
# compiling, warnings and errors, and each package's time at the end (build_progress.py);
# the full output goes to build/build.log. Python runs unbuffered, so that catkin_make's
# headlines come in order with make's lines. Exits with the command's status and, on
# failure, shows the log's last lines.
set -o pipefail
mkdir -p build
PYTHONUNBUFFERED=1 "$@" 2>&1 | tee build/build.log | /usr/bin/python3 -u "$(dirname "$0")/build_progress.py"
status=${PIPESTATUS[0]}
if (( status != 0 )); then
  echo "build failed (exit $status); last lines of build/build.log:"
  tail -n 40 build/build.log
fi
exit "$status"
