# Source this to use ROS 1's command-line tools on this project's messages:
#   source scripts/ros-env.sh && rostopic echo -n 1 /ravenstate
# Debian's ROS tools must run under /usr/bin/python3; the generated raven_2, crtk_msgs and
# raven_twin Python messages live in the build tree. Its crtk_msgs is upstream's 1.3 (every
# message and service, the same MD5s) plus the robot's older operating_state, so it can stand in
# for a user's own crtk_msgs without breaking `import crtk` or the robot's topics.
_raven_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PYTHONPATH="${BUILD_DIR:-$_raven_root/build}/python${PYTHONPATH:+:$PYTHONPATH}"
alias rostopic='/usr/bin/python3 /usr/bin/rostopic'
alias rosnode='/usr/bin/python3 /usr/bin/rosnode'
alias rosbag='/usr/bin/python3 /usr/bin/rosbag'
unset _raven_root
