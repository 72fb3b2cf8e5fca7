#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs (idempotent; run as root or with sudo).
# --main-job: only what building and running the main job needs (the quick start); without it,
# everything the tests, the bench, the fuzzers, the Python module and the cluster scripts use too.
set -euo pipefail

main_job=(
  build-essential cmake ninja-build pkg-config git
  libbullet-dev libbullet-extras-dev libeigen3-dev libassimp-dev
  libyaml-cpp-dev liburdfdom-dev liburdfdom-headers-dev libtinyxml-dev
  libsdl2-dev libcli11-dev libspdlog-dev nlohmann-json3-dev libnlopt-cxx-dev libboost-dev
  libcpp-httplib-dev
  libroscpp-dev libstd-msgs-dev libsensor-msgs-dev libgeometry-msgs-dev
  ros-std-msgs ros-sensor-msgs ros-geometry-msgs python3-gencpp python3-genmsg python3-genpy
  libglfw3-dev libgl-dev libopengl-dev libglx-dev libgl1-mesa-dri libstb-dev
  libegl-dev libegl-mesa0 libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
)
the_rest=(
  libgtest-dev libgmock-dev libbenchmark-dev time
  pybind11-dev python3-dev
  python3-rosmaster rosout python3-roslaunch python3-rostopic python3-rosnode python3-rosbag
  python3-sensor-msgs python3-geometry-msgs
  python3-rospy python3-pykdl python3-matplotlib python3-numpy python3-torch python3-h5py python3-scipy
  xvfb xauth chromium chromium-driver python3-selenium
  clang libfuzzer-14-dev
  slurm-wlm parallel
)

packages=("${main_job[@]}")
[ "${1:-}" = "--main-job" ] || packages+=("${the_rest[@]}")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
