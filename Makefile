# Two commands for a fresh Debian 12 machine:
#   make run    install what is missing, build, start the simulation
#   make test   install what is missing, build, run every test
# Debian's ROS Python modules need /usr/bin/python3, so /usr/bin comes first.
SHELL := /bin/bash
export PATH := /usr/bin:/bin:/usr/sbin:/sbin:$(PATH)
# noetic_compat's toolchain (exported by devel/setup.bash) is for overlays, not this build.
unexport CMAKE_TOOLCHAIN_FILE
JOBS ?= 2
# Packages to leave out of the build, e.g. CATKIN_BLACKLIST_PACKAGES="bullet_sim_rviz";
# empty: every package.
CATKIN_BLACKLIST_PACKAGES ?=
CATKIN_MAKE := catkin_make --source . --build build \
	-DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCATKIN_WHITELIST_PACKAGES="" \
	-DCATKIN_BLACKLIST_PACKAGES="$(CATKIN_BLACKLIST_PACKAGES)"

.PHONY: all setup build run test screenshots bench learning clean

all: build

setup:
	@scripts/setup.sh

build: setup
	@scripts/quiet_build.sh $(CATKIN_MAKE) -j$(JOBS)

run: build
	@scripts/run.sh

test: build
	@scripts/run_tests.sh

screenshots: build
	@scripts/screenshots.sh

# bullet_sim against MuJoCo and PyBullet (installed into build/bench_venv), one table; then
# the learning environment's agent steps per second (bench/learning.py).
bench: build
	@bench/compare
	@bench/learning.py

# torch, Stable-Baselines3 and Ray into build/learning_venv (large: never in `make setup`).
learning: build
	@scripts/setup.sh --learning

clean:
	rm -rf build devel
