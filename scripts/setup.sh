#!/bin/bash
# Installs what the workspace needs and is missing: Debian packages listed in
# deps/apt-packages.txt and PyPI packages in deps/pip-requirements.txt (for
# Debian's /usr/bin/python3, which the ROS Python modules need). A second run
# only checks and exits. --bench also makes the benchmark's virtual environment.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=$(grep -v '^\s*#' deps/apt-packages.txt | awk 'NF {print $1}')
missing=()
for pkg in $packages; do
  status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$pkg")
done
if (( ${#missing[@]} )); then
  echo "setup: installing ${#missing[@]} Debian package(s): ${missing[*]}"
  sudo_cmd=()
  (( EUID == 0 )) || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "setup: all $(wc -w <<<"$packages") Debian packages present"
fi

# PyPI requirements: deps/pip-requirements.txt for /usr/bin/python3; with --bench also
# deps/pip-bench.txt (the peers of bench/compare) into the virtual environment
# build/bench_venv, so that the benchmark's packages never reach the workspace's Python.
pip_check() {  # prints the requirements of $2 that interpreter $1 lacks
  "$1" - "$2" <<'PY'
import sys
from importlib import metadata
missing = []
for line in open(sys.argv[1]):
    req = line.split('#', 1)[0].strip()
    if not req:
        continue
    name, _, version = req.partition('==')
    try:
        if version and metadata.version(name) != version:
            missing.append(req)
    except metadata.PackageNotFoundError:
        missing.append(req)
print(' '.join(missing))
PY
}

pip_missing=$(pip_check /usr/bin/python3 deps/pip-requirements.txt)
if [[ -n "$pip_missing" ]]; then
  echo "setup: installing for /usr/bin/python3: $pip_missing"
  /usr/bin/python3 -m pip install -q --break-system-packages --root-user-action=ignore $pip_missing
else
  echo "setup: PyPI packages of deps/pip-requirements.txt present"
fi

if [[ "${1:-}" == "--bench" ]]; then
  venv=build/bench_venv
  [[ -x "$venv/bin/python" ]] || { echo "setup: creating $venv"; mkdir -p build; /usr/bin/python3 -m venv "$venv"; }
  pip_missing=$(pip_check "$venv/bin/python" deps/pip-bench.txt)
  if [[ -n "$pip_missing" ]]; then
    echo "setup: installing into $venv: $pip_missing"
    "$venv/bin/python" -m pip install -q --disable-pip-version-check $pip_missing
  else
    echo "setup: PyPI packages of deps/pip-bench.txt present in $venv"
  fi
fi
