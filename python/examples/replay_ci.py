#!/usr/bin/env python3
"""Replays a ci file (the paper's controller inputs) on the twin through raven_sim, exactly as
`raven_controller --lock-step --replay-ci` does, and says how closely the twin followed the
physical robot's own recording of the same session: per joint, the RMS difference of jpos.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/replay_ci.py \
        ../shared/data/recordings/paper_2arm/2arm_ci.csv \
        ../shared/data/recordings/paper_2arm/2arm_physical_1.csv
"""

import sys
import tempfile

import numpy as np

import raven_sim

JOINTS = ["shoulder", "elbow", "insertion", "roll", "wrist", "jaw1", "jaw2"]


def replay(ci_file, out_dir):
    twin = raven_sim.Twin()
    twin.enable_and_home()
    session = raven_sim.ControllerSession(raven_sim.Controller(twin), raven_sim.read_ci(ci_file),
                                          out_dir, "replay")
    session.select(raven_sim.Mode.REPLAY_INPUTS)
    session.start_recording()
    session.run()
    return raven_sim.read_rs(next(str(p) for p in session.recordings if str(p).endswith("_rs.csv")))


def main(ci_file, physical_file):
    with tempfile.TemporaryDirectory() as out_dir:
        twin = replay(ci_file, out_dir)
    physical = raven_sim.read_rs(physical_file)
    rows = min(len(twin.rows), len(physical.rows))
    print(f"{rows} rows compared (twin {len(twin.rows)}, physical {len(physical.rows)})")
    for arm in (raven_sim.Arm.LEFT, raven_sim.Arm.RIGHT):
        difference = np.array([twin.joints(i, arm) - physical.joints(i, arm) for i in range(rows)])
        rms = np.sqrt((difference ** 2).mean(axis=0))
        cells = ", ".join(f"{name} {value:.4f}" for name, value in zip(JOINTS, rms))
        print(f"{arm.name.lower():5} arm, RMS twin - physical (rad, m): {cells}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
