#!/usr/bin/python3
"""Draws raven_analyze forces' estimate: each arm's tool force (x, y, z) and jaw squeezes over
the recording, each with its band of +-2 sd, and the twin's own forces beside them when a cf
file is given.

  draw_forces.py OUT_DIR [CF_FILE]      (reads OUT_DIR/forces.csv, writes OUT_DIR/forces.png)
"""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

CHANNELS = ["fx", "fy", "fz", "jaw1_normal", "jaw2_normal"]


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names, values = rows[0], np.array(rows[1:], dtype=float)
    return {name: values[:, i] for i, name in enumerate(names)}


def main(out_dir, cf_path=None):
    est = read_columns(Path(out_dir) / "forces.csv")
    truth = read_columns(cf_path) if cf_path else None
    fig, axes = plt.subplots(len(CHANNELS), 2, figsize=(12, 11), sharex=True)
    t = est["time"]
    for col, arm in enumerate(["left", "right"]):
        for row, channel in enumerate(CHANNELS):
            ax = axes[row][col]
            name = f"{arm}_{channel}"
            value, sd = est[name], est[name + "_sd"]
            ax.fill_between(t, value - 2 * sd, value + 2 * sd, color="#2a9d8f", alpha=0.25,
                            linewidth=0, label="estimate +- 2 sd")
            ax.plot(t, value, color="#2a9d8f", linewidth=0.8, label="estimate")
            if truth is not None and name in truth:
                ax.plot(truth["time"], truth[name], color="#d1495b", linewidth=0.8,
                        label="twin's contact force")
            ax.set_ylabel(f"{name} (N)", fontsize=8)
            if row == 0:
                ax.set_title(f"{arm} arm")
                ax.legend(fontsize=7, loc="upper right")
    for ax in axes[-1]:
        ax.set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(Path(out_dir) / "forces.png", dpi=110)


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(*sys.argv[1:])
