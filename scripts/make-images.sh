#!/usr/bin/env bash
# Makes the pictures the README and docs/viewer.md show, headless (no display, no Xvfb): the main
# job's snapshot from every named view before and after the run, and the first frame of a short
# clip from the left grasper's camera. Run from the repository root after a build:
#   ./scripts/make-images.sh            (writes docs/images/peg_*.png)
# AMBF's Raven-II meshes are drawn when ../shared/data (or $RAVEN_AMBF_MESHES) has them.
set -euo pipefail
build="${RAVEN_BUILD:-build}"
images="docs/images"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

"$build/scenario/raven_peg_transfer" -q --record no --out "$work/run" \
  --snapshot "$images/peg" --views overview,left-task,right-task,grasper-left,grasper-right
# A 15 s clip from the left grasper's camera; its first frame is kept, the clip is not.
"$build/scenario/raven_peg_transfer" -q --record no --out "$work/clip" --time-limit 15 \
  --video "$work/clip/grasper_left.mp4" --video-view grasper-left --video-size 640x360 \
  --video-first-frame "$images/peg_clip_grasper-left_first_frame.png"
ls -l "$images"/peg_*.png
