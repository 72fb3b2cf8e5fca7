#!/usr/bin/env bash
# A lab with only a physical Raven-II builds the robot's side without the simulator: configures
# this tree with -DRAVEN_SIMULATOR=OFF in a fresh directory, builds raven_controller and
# raven_analyze, checks that nothing of the engine was compiled, of the twin only its motor model
# (raven_motor_model: drive train, control law, mechanics, calibration, force estimator), that no
# Bullet flag reached a compile line, and that the program refuses the in-process twin by name.
#   tests/architecture/robot_side_build.sh <source dir> <scratch build dir>
set -euo pipefail
src="$1"
build="$2"
rm -rf "$build"
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRAVEN_SIMULATOR=OFF -DRAVEN_WERROR=ON \
  > "$build.configure.log" 2>&1 || { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j"${RAVEN_JOBS:-2}" --target raven_controller raven_analyze \
  > "$build.build.log" 2>&1 || { tail -50 "$build.build.log"; exit 1; }
engine_objects="$(find "$build" -name '*.o' -path '*ambf_like*' | wc -l)"
twin_objects="$(find "$build" -name '*.o' -path '*twin*' -not -path '*raven_motor_model.dir*' | wc -l)"
[ "$engine_objects" -eq 0 ] && [ "$twin_objects" -eq 0 ] ||
  { echo "robot side: $engine_objects engine and $twin_objects twin objects built"; exit 1; }
if grep -rqi 'bullet' "$build/compile_commands.json"; then
  echo "robot side: a compile line names Bullet"
  exit 1
fi
set +e
refusal="$("$build/controller/raven_controller" --platform twin --no-gamepad --no-keyboard 2>&1)"
status=$?
set -e
[ "$status" -ne 0 ] || { echo "robot side: --platform twin did not fail"; exit 1; }
echo "$refusal" | grep -q "needs the simulator" || { echo "robot side: $refusal"; exit 1; }
"$build/analysis/raven_analyze" --help > /dev/null
echo "robot side: raven_controller and raven_analyze built without the simulator" \
  "($(find "$build" -name '*.o' | wc -l) objects, none of ambf_like, of twin its motor model only)"
