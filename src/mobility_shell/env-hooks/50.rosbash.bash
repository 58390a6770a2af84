# Loads the rosbash shell functions (roscd, rosls, rosed, roscp, ...) for bash.
# Debian keeps them in bash-completion's folder, and the hook meant to load
# them points at a path that does not exist; sourcing this workspace's
# devel/setup.bash therefore loads them here.
if [ -n "${BASH_VERSION:-}" ] && [ -f /usr/share/bash-completion/completions/rosbash ]; then
  . /usr/share/bash-completion/completions/rosbash
fi
