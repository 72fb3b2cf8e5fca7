#!/usr/bin/env bash
# Shows the twin node publishing the robot's topics at 1 kHz: starts a private rosmaster on a free
# port, raven_twin_node on the wall clock, and runs `rostopic hz` on one of its topics.
#   scripts/twin-node-hz.sh [seconds] [topic] [-- raven_twin_node flags, e.g. --actuation ideal]
# Needs a build (scripts/build.sh). Everything it starts is stopped on exit.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
node_bin="$build/twin/ros/raven_twin_node"
[ -x "$node_bin" ] || { echo "twin-node-hz: $node_bin not built; run scripts/build.sh" >&2; exit 1; }
seconds="${1:-5}"
topic="${2:-/ravenstate}"
shift $(( $# < 2 ? $# : 2 ))
[ "${1:-}" = "--" ] && shift

tmp="$(mktemp -d)"
port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
export ROS_MASTER_URI="http://127.0.0.1:$port" ROS_HOME="$tmp" ROS_LOG_DIR="$tmp/log" ROS_IP=127.0.0.1
export PYTHONPATH="$build/python${PYTHONPATH:+:$PYTHONPATH}"
master="" node=""
cleanup() {
  [ -n "$node" ] && kill -INT "$node" 2>/dev/null || true
  [ -n "$master" ] && kill "$master" 2>/dev/null || true
  wait 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT

/usr/bin/python3 /usr/bin/rosmaster --core -p "$port" > "$tmp/master.log" 2>&1 &
master=$!
for _ in $(seq 100); do
  /usr/bin/python3 -c "import rosgraph; rosgraph.Master('/hz').getPid()" 2>/dev/null && break
  sleep 0.1
done
"$node_bin" "$@" > "$tmp/node.log" 2>&1 &
node=$!
echo "twin-node-hz: raven_twin_node $* on $ROS_MASTER_URI; rostopic hz $topic for $seconds s"
timeout --signal=INT "$seconds" /usr/bin/python3 /usr/bin/rostopic hz "$topic" || true
echo "--- raven_twin_node log:"
cat "$tmp/node.log"
