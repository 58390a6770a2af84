#!/bin/bash
# Installs what the workspace needs and is missing: Debian packages listed in
# deps/apt-packages.txt, those of deps/apt-packages-optional.txt that the release
# packages (Debian 12 and 13 differ), and PyPI packages in deps/pip-requirements.txt (for
# Debian's /usr/bin/python3, which the ROS Python modules need). A second run
# only checks and exits. --bench also makes the benchmark's virtual environment, --learning
# the learning one (deps/pip-learning.txt: torch, Stable-Baselines3, Ray).
set -euo pipefail
cd "$(dirname "$0")/.."

list_packages() { grep -v '^\s*#' "$1" | awk 'NF {print $1}'; }
not_installed() {  # prints the packages of "$@" that dpkg does not have installed
  (( $# )) || return 0
  local installed
  installed=$(dpkg-query -W -f='${Package} ${Status}\n' "$@" 2>/dev/null | awk '/ install ok installed$/ {print $1}' || true)
  for pkg in "$@"; do
    grep -qxF "$pkg" <<<"$installed" || echo "$pkg"
  done
}
packaged() {  # prints the packages of "$@" that apt can install on this release
  (( $# )) || return 0
  LC_ALL=C apt-cache policy "$@" 2>/dev/null | awk '
    /^[^ ]/ {pkg = $1; sub(/:$/, "", pkg)}
    /^  Candidate:/ && $2 != "(none)" {print pkg}'
}

packages=$(list_packages deps/apt-packages.txt)
optional=$(list_packages deps/apt-packages-optional.txt)
mapfile -t missing < <(not_installed $packages)
mapfile -t optional_missing < <(not_installed $optional)
# An optional package that this release does not package is left out without asking apt
# again; when required packages are missing the lists are updated first and asked again.
mapfile -t optional_wanted < <(packaged "${optional_missing[@]}")
if (( ${#missing[@]} + ${#optional_wanted[@]} )); then
  sudo_cmd=()
  (( EUID == 0 )) || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  mapfile -t optional_wanted < <(packaged "${optional_missing[@]}")
  install=("${missing[@]}" "${optional_wanted[@]}")
  echo "setup: installing ${#install[@]} Debian package(s): ${install[*]}"
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${install[@]}"
else
  echo "setup: all $(wc -w <<<"$packages") Debian packages present"
fi
mapfile -t optional_absent < <(not_installed $optional)
if (( ${#optional_absent[@]} )); then
  echo "setup: not packaged for this release (optional): ${optional_absent[*]}"
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
    name = name.split('[', 1)[0]  # extras: the distribution's own version
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
  # xacro 1.13.3 comes as source: built by Debian's setuptools through PEP 517 (pip 25 of
  # Debian 13 deprecates the legacy setup.py build), with nothing fetched for the build.
  /usr/bin/python3 -m pip install -q --break-system-packages --root-user-action=ignore \
    --use-pep517 --no-build-isolation $pip_missing
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

# --learning: torch, Stable-Baselines3 and Ray (deps/pip-learning.txt) for training and
# batch runs on the Python module, into build/learning_venv. It sees the system's packages
# (Debian's NumPy, which the module was built against, and gymnasium); they are large
# (torch brings CUDA's libraries from PyPI), so never part of `make setup`.
if [[ "${1:-}" == "--learning" ]]; then
  venv=build/learning_venv
  [[ -x "$venv/bin/python" ]] || {
    echo "setup: creating $venv"; mkdir -p build
    /usr/bin/python3 -m venv --system-site-packages "$venv"; }
  pip_missing=$(pip_check "$venv/bin/python" deps/pip-learning.txt)
  if [[ -n "$pip_missing" ]]; then
    echo "setup: installing into $venv: $pip_missing"
    "$venv/bin/python" -m pip install -q --disable-pip-version-check \
      -c deps/pip-learning-constraints.txt $pip_missing
  else
    echo "setup: PyPI packages of deps/pip-learning.txt present in $venv"
  fi
fi
