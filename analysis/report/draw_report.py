#!/usr/bin/python3
"""Draws the disparity report's figures from the data raven_analyze wrote (PNG and index.html).

  draw_report.py REPORT_DIR

Fig. 6: each joint's trajectory per platform, the band between the smallest and largest trial.
Fig. 7: mean absolute difference per joint for every comparison (positions and velocities).
Fig. 8: simulation-minus-physical difference against time, joint position and joint velocity,
        with the LOWESS trend and the marginal densities.
Actuators: where recordings log them (the physical robot, our twin), mpos, mvel, Tau and dac_vals
        per joint over time (mean across trials) and per comparison (mean absolute difference,
        Fig. 7's form).
Grasp forces: for every rs file with a cf file beside it (a platform that measures contact forces,
        such as the twin), each grasper's jaw normal and friction forces over time.
The numbers come from the C++ analysis; this script only draws them.
"""
import csv
import html
import json
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

COLOURS = {"physical": "#1b6ca8", "ambf": "#d1495b", "twin": "#2a9d8f"}


def colour(name, index):
    return COLOURS.get(name, plt.cm.tab10(index % 10))


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def save(fig, out, title, name, dpi):
    """Titles, lays out, writes and closes a figure; its file name for the page."""
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out / name, dpi=dpi)
    plt.close(fig)
    return name


def joint_scale(joint):
    """Insertion in mm, revolute joints in rad."""
    return (1000.0, "mm") if joint["unit"] == "m" else (1.0, "rad")


def trajectories(out, metrics, joints):
    rows = defaultdict(lambda: defaultdict(list))
    for r in read_rows(out / "trajectories.csv"):
        series = rows[r["platform"]][int(r["column"])]
        series.append((float(r["time"]), float(r["min"]), float(r["max"]), float(r["mean"])))
    fig, axes = plt.subplots(2, 7, figsize=(24, 7), sharex=True)
    for k, joint in enumerate(joints):
        ax = axes[k // 7][k % 7]
        scale, unit = joint_scale(joint)
        for i, platform in enumerate(p["name"] for p in metrics["inputs"]["platforms"]):
            data = np.array(rows[platform][joint["column"]])
            if data.size == 0:
                continue
            c = colour(platform, i)
            ax.fill_between(data[:, 0], scale * data[:, 1], scale * data[:, 2], color=c, alpha=0.3,
                            linewidth=0)
            ax.plot(data[:, 0], scale * data[:, 3], color=c, linewidth=0.8, label=platform)
        ax.set_title(joint["name"], fontsize=10)
        ax.set_ylabel(unit)
        if k // 7 == 1:
            ax.set_xlabel("time (s)")
    axes[0][0].legend(fontsize=8)
    fig.suptitle("Joint trajectories: mean across trials, band = min-max across trials (Fig. 6)")
    fig.tight_layout()
    fig.savefig(out / "fig6_trajectories.png", dpi=90)
    plt.close(fig)
    return ["fig6_trajectories.png"]


def inconsistencies(out, metrics, joints):
    files = []
    comparisons = list(dict.fromkeys(r["comparison"] for r in metrics["per joint"]))
    for quantity in ("position", "velocity"):
        fig, (rev, ins) = plt.subplots(1, 2, figsize=(16, 5), gridspec_kw={"width_ratios": [6, 1]})
        value = {(r["comparison"], r["column"]): r for r in metrics["per joint"]
                 if r["quantity"] == quantity}
        revolute = [j for j in joints if j["unit"] == "rad"]
        prismatic = [j for j in joints if j["unit"] == "m"]
        width = 0.8 / max(len(comparisons), 1)
        for ax, group, scale in ((rev, revolute, 1.0), (ins, prismatic, 1000.0)):
            x = np.arange(len(group))
            for i, comparison in enumerate(comparisons):
                rows = [value[(comparison, j["column"])] for j in group]
                symbol = rows[0]["symbol"]
                heights = [scale * (r["as recorded"]["mean_abs"] or 0.0) for r in rows]
                removed = [scale * (r["first row removed"]["mean_abs"] or 0.0) for r in rows]
                ax.bar(x + i * width, heights, width, label=f"{symbol} {comparison}")
                ax.scatter(x + i * width, removed, marker="_", color="black", s=60, zorder=3,
                           label="first row removed" if i == 0 else None)
            ax.set_xticks(x + width * (len(comparisons) - 1) / 2)
            ax.set_xticklabels([j["name"] for j in group], rotation=45, ha="right", fontsize=8)
        per_second = "/s" if quantity == "velocity" else ""
        rev.set_ylabel(f"mean absolute difference (rad{per_second})")
        ins.set_ylabel(f"mm{per_second}")
        rev.legend(fontsize=8)
        files.append(save(fig, out, f"Inconsistency per joint, {quantity} (Fig. 7)",
                          f"fig7_inconsistency_{quantity}.png", 90))
    return files


def density(values, grid):
    """Gaussian kernel density (Scott's bandwidth)."""
    values = np.asarray(values)
    if values.size < 2 or np.std(values) == 0:
        return np.zeros_like(grid)
    bandwidth = 1.06 * np.std(values) * values.size ** (-0.2)
    u = (grid[:, None] - values[None, :]) / bandwidth
    return np.exp(-0.5 * u * u).sum(axis=1) / (values.size * bandwidth * np.sqrt(2 * np.pi))


def factors(out, metrics, joints):
    files = []
    scatter = defaultdict(list)
    for r in read_rows(out / "scatter.csv"):
        scatter[(r["comparison"], int(r["column"]), r["factor"])].append(
            (float(r["value"]), float(r["difference"])))
    trend = defaultdict(list)
    for r in read_rows(out / "lowess.csv"):
        trend[(r["comparison"], int(r["column"]), r["factor"])].append(
            (float(r["value"]), float(r["difference"])))
    correlation = {(r["comparison"], r["column"], r["factor"]): r for r in metrics["correlations"]}
    comparisons = list(dict.fromkeys(r["comparison"] for r in metrics["correlations"]))
    for comparison in comparisons:
        for factor in ("time", "joint position", "joint velocity"):
            fig, axes = plt.subplots(2, 7, figsize=(24, 8))
            for k, joint in enumerate(joints):
                ax = axes[k // 7][k % 7]
                key = (comparison, joint["column"], factor)
                points = np.array(scatter[key])
                if points.size == 0:
                    ax.set_axis_off()
                    continue
                scale, unit = joint_scale(joint)
                ax.scatter(points[:, 0], scale * points[:, 1], s=2, alpha=0.25, color="#555555")
                line = np.array(trend[key])
                if line.size:
                    ax.plot(line[:, 0], scale * line[:, 1], color="#d1495b", linewidth=1.5)
                r = correlation[key]
                rho = r["pearson_r_difference"]
                ax.set_title(f"{joint['name']}  r={rho:.2f}" if rho is not None else joint["name"],
                             fontsize=9)
                ax.set_ylabel(f"difference ({unit})", fontsize=8)
                ax.tick_params(labelsize=7)
                top = ax.inset_axes([0, 1.0, 1, 0.15], sharex=ax)
                side = ax.inset_axes([1.0, 0, 0.15, 1], sharey=ax)
                gx = np.linspace(points[:, 0].min(), points[:, 0].max(), 100)
                gy = np.linspace(scale * points[:, 1].min(), scale * points[:, 1].max(), 100)
                top.fill_between(gx, density(points[:, 0], gx), color="#1b6ca8", alpha=0.5)
                side.fill_betweenx(gy, density(scale * points[:, 1], gy), color="#1b6ca8",
                                   alpha=0.5)
                for a in (top, side):
                    a.set_axis_off()
            fig.suptitle(f"{comparison}: joint-position difference against {factor}, LOWESS in red, "
                         f"marginal densities (Fig. 8)", y=1.0)
            fig.tight_layout()
            name = f"fig8_{comparison.replace(' ', '_')}_{factor.replace(' ', '_')}.png"
            fig.savefig(out / name, dpi=80, bbox_inches="tight")
            plt.close(fig)
            files.append(name)
    return files


def grasp_forces(out):
    """One figure per cf recording listed in grasp_forces.csv; a file it cannot read is skipped."""
    listing = out / "grasp_forces.csv"
    figures = []
    for index, entry in enumerate(read_rows(listing) if listing.exists() else []):
        path = Path(entry["file"])
        try:
            rows = read_rows(path)
            time = np.array([float(r["time"]) for r in rows])
            series = {k: np.array([float(r[k]) for r in rows]) for k in rows[0] if k != "time"}
        except (OSError, KeyError, ValueError, IndexError) as error:
            print(f"draw_report: {path}: skipped ({error})", file=sys.stderr)
            continue
        fig, axes = plt.subplots(2, 1, figsize=(9, 5), sharex=True)
        for ax, arm in zip(axes, ("left", "right")):
            for jaw, style in (("jaw1", "-"), ("jaw2", "--")):
                ax.plot(time, series[f"{arm}_{jaw}_normal"], style, color="#1b6ca8",
                        label=f"{jaw} normal")
                ax.plot(time, series[f"{arm}_{jaw}_friction"], style, color="#d1495b",
                        label=f"{jaw} friction")
            ax.plot(time, series[f"{arm}_fz"], ":", color="k", label="total, vertical")
            ax.set_ylabel(f"{arm} grasper (N)")
            ax.legend(fontsize=7, ncol=5, loc="upper right")
        axes[-1].set_xlabel("time (s)")
        figures.append(save(fig, out, f"{entry['platform']}: grasp forces, {path.name}",
                            f"grasp_forces_{index + 1}.png", 80))
    return figures


def actuators(out):
    """Figs. 6 and 7 below the joints, from actuators.json and actuator_trajectories.csv."""
    listed = out / "actuators.json"
    if not listed.exists():
        return []
    report = json.loads(listed.read_text())
    if not report["comparisons"]:
        return []
    series = defaultdict(list)
    for r in read_rows(out / "actuator_trajectories.csv"):
        series[(r["platform"], r["signal"], r["arm"], r["joint"])].append(
            (float(r["time"]), float(r["mean"])))
    platforms = [p["name"] for p in report["platforms"] if p["logs actuators"]]
    signals = list(report["comparisons"][0]["signals"].keys())
    joints = ["shoulder", "elbow", "insertion", "roll", "wrist", "jaw1", "jaw2"]
    files = []
    for signal in signals:
        unit = report["comparisons"][0]["signals"][signal]["unit"]
        fig, axes = plt.subplots(2, 7, figsize=(24, 7), sharex=True)
        for a, arm in enumerate(("left", "right")):
            for j, joint in enumerate(joints):
                ax = axes[a][j]
                for i, platform in enumerate(platforms):
                    data = np.array(series[(platform, signal, arm, joint)])
                    if data.size:
                        ax.plot(data[:, 0], data[:, 1], color=colour(platform, i), linewidth=0.8,
                                label=platform)
                ax.set_title(f"{arm} {joint}", fontsize=10)
                ax.set_ylabel(unit)
        axes[0][0].legend(fontsize=8)
        axes[1][3].set_xlabel("time (s)")
        files.append(save(fig, out, f"{signal} per joint, mean across trials",
                          f"actuators_{signal}.png", 80))
    fig, axes = plt.subplots(1, len(signals), figsize=(24, 5))
    width = 0.8 / len(report["comparisons"])
    x = np.arange(14)
    for k, signal in enumerate(signals):
        ax = axes[k]
        for i, c in enumerate(report["comparisons"]):
            values = c["signals"][signal]["mean_abs"]
            ax.bar(x + i * width, values["left"] + values["right"], width,
                   label=f'{c["symbol"]} {c["comparison"]}')
        ax.set_xticks(x + width * (len(report["comparisons"]) - 1) / 2)
        ax.set_xticklabels([f"{a[0]}.{j}" for a in ("left", "right") for j in joints],
                           rotation=60, ha="right", fontsize=7)
        ax.set_title(f'{signal} ({report["comparisons"][0]["signals"][signal]["unit"]})')
    axes[0].legend(fontsize=8)
    files.append(save(fig, out, "Actuator signals: mean absolute difference per joint",
                      "actuators_inconsistency.png", 80))
    return files


def actuator_table(out):
    listed = out / "actuators.json"
    if not listed.exists():
        return ""
    rows = []
    for c in json.loads(listed.read_text())["comparisons"]:
        row = {"symbol": c["symbol"], "comparison": c["comparison"]}
        for signal, v in c["signals"].items():
            ratio = v.get("median_over_T_PP")
            row[signal] = "n/a" if ratio is None else f"{ratio:.2f}x"
        rows.append(row)
    if not rows:
        return ""
    columns = ["symbol", "comparison"] + [k for k in rows[0] if k not in ("symbol", "comparison")]
    return ("<h2>Actuator signals (median over joints of the mean absolute difference over the "
            f"robot's own T_PP)</h2>{table(rows, columns)}")


def table(rows, columns):
    head = "".join(f"<th>{html.escape(c)}</th>" for c in columns)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(r.get(c, '')))}</td>" for c in columns)
                   + "</tr>" for r in rows)
    return f"<table><tr>{head}</tr>{body}</table>"


def pictures(out):
    """The runs' snapshots and videos raven_analyze copied beside the report (pictures.json)."""
    listed = out / "pictures.json"
    if not listed.exists():
        return ""
    parts = []
    for item in json.loads(listed.read_text()):
        src = html.escape(item["file"])
        if item["kind"] == "image":
            parts.append(f'<figure><img src="{src}" alt="{src}">'
                         f'<figcaption>{src}</figcaption></figure>')
        else:
            poster = f' poster="{html.escape(item["poster"])}"' if "poster" in item else ""
            parts.append(f'<figure><video controls src="{src}"{poster}></video>'
                         f'<figcaption>{src}</figcaption></figure>')
    return "<h2>Pictures of the runs</h2>" + "".join(parts)


def page(out, metrics, figures):
    fmt = lambda v: "n/a" if v is None else f"{v:.4f}"  # noqa: E731
    summary = [dict(r, mean_abs=fmt(r["mean_abs"]),
                    mean_abs_first_row_removed=fmt(r["mean_abs_first_row_removed"]))
               for r in metrics["summary"]]
    platforms = [{"platform": p["label"], "role": p["role"], "trials": len(p["trials"]),
                  "files": ", ".join(Path(t["file"]).name for t in p["trials"])}
                 for p in metrics["inputs"]["platforms"]]
    issues = [{"file": Path(i["file"]).name, "excluded": "yes" if i["excluded"] else "no",
               "reason": i["reason"]} for i in metrics["inputs"]["file issues"]]
    images = "".join(f'<h3>{html.escape(f)}</h3><img src="{html.escape(f)}" alt="{html.escape(f)}">'
                     for f in figures)
    text = f"""<!doctype html>
<html><head><meta charset="utf-8"><title>Raven-II disparity report</title>
<style>body{{font-family:sans-serif;margin:2em}} table{{border-collapse:collapse;margin:1em 0}}
td,th{{border:1px solid #ccc;padding:3px 8px;font-size:13px}} img,video{{max-width:100%}}</style></head>
<body><h1>Raven-II disparity report</h1>
<p>Trials aligned by {html.escape(metrics["inputs"]["alignment"])}. Metrics: metrics.json,
metrics.csv, correlations.csv; figure data: trajectories.csv, scatter.csv, lowess.csv.</p>
<h2>Platforms</h2>{table(platforms, ["platform", "role", "trials", "files"])}
<h2>Files with problems</h2>{table(issues, ["file", "excluded", "reason"]) if issues else "<p>none</p>"}
<h2>Summary (mean absolute difference, averaged over trial pairs)</h2>
{table(summary, ["symbol", "comparison", "quantity", "group", "unit", "mean_abs",
                 "mean_abs_first_row_removed"])}
{actuator_table(out)}
<h2>Figures</h2>{images}
{pictures(out)}
</body></html>
"""
    (out / "index.html").write_text(text)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    metrics = json.loads((out / "metrics.json").read_text())
    joints = metrics["joints"]
    figures = trajectories(out, metrics, joints) + inconsistencies(out, metrics, joints)
    figures += factors(out, metrics, joints) + actuators(out) + grasp_forces(out)
    page(out, metrics, figures)
    print(f"draw_report: {len(figures)} figures and index.html in {out}")


if __name__ == "__main__":
    main()
