#!/usr/bin/python3
"""Draws a study's report.html from what raven_study report wrote (summary.json, trials.csv,
questionnaires.csv), with the figures inside the page.

  draw_study.py REPORT_DIR

Per task and metric: each scheme's trials (box) and each participant's mean (dots joined across
schemes).
Learning curves: per task, each scheme's metric against the task's repetition under it.
Questionnaires: each one's score per scheme and participant. Tuning: each participant's cost
per tuning trial. Tables: the paired comparisons, the recommended settings, the power analysis.
The numbers come from the C++ report; this script only draws them.
"""
import base64
import csv
import html
import io
import json
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SHOWN = ["completion_time_s", "overshoots", "path_length_m", "idle_time_s", "sparc",
         "velocity_cap_hits", "joint_limit_hits", "rings_placed", "rings_dropped",
         "instrument_collisions", "excessive_force_time_s", "out_of_view_time_s",
         "tip_range_left_m", "tip_range_right_m", "stick_range_left", "stick_range_right",
         "peak_grasp_force_n", "mean_grasp_force_n"]


QUESTIONNAIRE_TITLES = {"nasa-tlx": "NASA-TLX (lower: less workload)",
                        "surg-tlx": "SURG-TLX (lower: less workload)",
                        "sus": "SUS (higher: more usable)"}


def number(text):
    return float(text) if text not in ("", None) else None


def picture(fig, alt):
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=90, bbox_inches="tight")
    plt.close(fig)
    data = base64.b64encode(buffer.getvalue()).decode("ascii")
    return f'<img alt="{html.escape(alt)}" src="data:image/png;base64,{data}">'


def by_scheme(rows, metric):
    values = defaultdict(list)
    per_person = defaultdict(lambda: defaultdict(list))
    for r in rows:
        v = number(r[metric])
        if v is None:
            continue
        values[r["condition"]].append(v)
        per_person[r["participant"]][r["condition"]].append(v)
    return values, per_person


def metric_figures(rows, schemes, summary):
    """One figure per task: tasks differ in scale, so their trials are never pooled."""
    tasks = sorted({r["task"] for r in rows})
    return "".join(task_metric_figure(task, [r for r in rows if r["task"] == task], schemes,
                                      summary) for task in tasks)


def task_metric_figure(task, rows, schemes, summary):
    shown = [m for m in SHOWN if any(number(r[m]) is not None for r in rows)]
    if not shown:
        return ""
    columns = 3
    lines = (len(shown) + columns - 1) // columns
    fig, axes = plt.subplots(lines, columns, figsize=(4.2 * columns, 3.2 * lines), squeeze=False)
    for ax, metric in zip(axes.flat, shown):
        values, per_person = by_scheme(rows, metric)
        data = [values.get(s, []) for s in schemes]
        ax.boxplot(data, labels=schemes, showfliers=False)
        for person, means in per_person.items():
            xs = [i + 1 for i, s in enumerate(schemes) if means.get(s)]
            ys = [sum(means[s]) / len(means[s]) for s in schemes if means.get(s)]
            ax.plot(xs, ys, "o-", alpha=0.35, markersize=3)
        ax.set_title(f"{metric} ({summary['metrics'][metric]['better']} is better)", fontsize=9)
        ax.tick_params(labelsize=8)
    for ax in list(axes.flat)[len(shown):]:
        ax.axis("off")
    fig.suptitle(f"{task}, per scheme: trials (boxes) and each participant's mean (dots)")
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.3 / fig.get_figheight()))  # the title just above
    return picture(fig, f"metrics per scheme: {task}")


def learning_figure(rows, schemes):
    """Per task, a row of curves: each scheme's mean over participants against the task's
    repetition under the scheme (tasks differ in scale, so they are never averaged together)."""
    tasks = sorted({r["task"] for r in rows})
    if not tasks:
        return ""
    fig, axes = plt.subplots(len(tasks), 2, figsize=(11, 3.3 * len(tasks)), squeeze=False)
    for line, task in zip(axes, tasks):
        of_task = [r for r in rows if r["task"] == task]
        second = next((m for m in ("rings_placed", "overshoots")
                       if any(number(r[m]) is not None for r in of_task)), "path_length_m")
        for ax, metric in zip(line, ["completion_time_s", second]):
            for s in schemes:
                points = defaultdict(list)
                for r in of_task:
                    v = number(r[metric])
                    if r["condition"] == s and v is not None:
                        points[int(r["repetition"])].append(v)
                xs = sorted(points)
                ax.plot([x + 1 for x in xs], [sum(points[x]) / len(points[x]) for x in xs],
                        "o-", label=s)
            repetitions = max(int(r["repetition"]) for r in of_task) + 1
            ax.set_title(f"{task}: {metric}", fontsize=9)
            ax.set_xlabel(f"repetition of {task} under the scheme", fontsize=8)
            ax.set_xlim(0.5, repetitions + 0.5)  # one repetition: one column of points
            ax.set_xticks(range(1, repetitions + 1))
            ax.legend(fontsize=8)
    fig.suptitle("Learning curves per task and scheme (mean over participants)")
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    return picture(fig, "learning curves: " + ", ".join(tasks))


def questionnaire_figure(answers, schemes):
    if not answers:
        return "<p>No questionnaires were answered (virtual participants do not answer).</p>"
    names = sorted({a["questionnaire"] for a in answers})
    fig, axes = plt.subplots(1, len(names), figsize=(5 * len(names), 3.5), squeeze=False)
    for ax, name in zip(axes.flat, names):
        people = defaultdict(dict)
        for a in answers:
            if a["questionnaire"] == name:
                people[a["participant"]][a["condition"]] = float(a["score"])
        for person, scores in people.items():
            xs = [i for i, s in enumerate(schemes) if s in scores]
            ax.plot(xs, [scores[schemes[i]] for i in xs], "o-", alpha=0.5, label=person)
        ax.set_xticks(range(len(schemes)), schemes)
        ax.set_title(QUESTIONNAIRE_TITLES.get(name, f"{name} (mean of its items)"))
        if name in QUESTIONNAIRE_TITLES:
            ax.set_ylim(0, 100)
    return picture(fig, "questionnaire scores per scheme: " + ", ".join(names))


def proficiency_lines(summary):
    """Per task with a proficiency time, per scheme: trials within it, participants twice in a
    row (the FLS curriculum's consecutive rule)."""
    lines = []
    for task, line in sorted(summary.get("proficiency", {}).items()):
        schemes = "; ".join(
            f"{s}: {c['within']} of {c['trials']} trials within, {c['proficient']} of "
            f"{c['participants']} participants twice in a row"
            for s, c in sorted(line["schemes"].items()))
        lines.append(f"<li><b>{html.escape(task)}</b> (proficiency {line['time_s']:g} s): "
                     f"{html.escape(schemes)}</li>")
    return f"<ul>{''.join(lines)}</ul>" if lines else "<p>No task states a proficiency time.</p>"


def tuning_figure(rows):
    tuned = [r for r in rows if r["tuning"] == "1" and r["tuning_cost"]]
    if not tuned:
        return "<p>No tuning trials.</p>"
    fig, ax = plt.subplots(figsize=(6, 3.5))
    people = defaultdict(list)
    for r in tuned:
        people[r["participant"]].append(float(r["tuning_cost"]))
    for person, costs in people.items():
        ax.plot(range(1, len(costs) + 1), costs, "o-", alpha=0.6, label=person)
    ax.set_xlabel("tuning trial")
    ax.set_ylabel("cost")
    ax.legend(fontsize=7, ncol=2)
    return picture(fig, "tuning cost per trial")


def table(header, rows):
    head = "".join(f"<th>{html.escape(str(h))}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in row) + "</tr>"
                   for row in rows)
    return f"<table><tr>{head}</tr>{body}</table>"


def fmt(v, digits=3):
    if v is None:
        return "-"
    if isinstance(v, float):
        return f"{v:.{digits}g}"
    return v


def main(folder):
    folder = Path(folder)
    summary = json.loads((folder / "summary.json").read_text())
    with open(folder / "trials.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    with open(folder / "questionnaires.csv", newline="") as f:
        answers = list(csv.DictReader(f))
    compared = [r for r in rows if r["tuning"] == "0"]
    schemes = sorted(summary["schemes"])
    comparisons = table(
        ["task", "metric", "a", "b", "mean a", "mean b", "p (Holm)", "p raw", "d_z",
         "Wilcoxon p", "better"],
        [[c["task"] or "(asked)", c["metric"], c["a"], c["b"], fmt(c["mean_a"]), fmt(c["mean_b"]), fmt(c["p"]),
          fmt(c["p_raw"]), fmt(c["effect_size"]), fmt(c["wilcoxon_p"]),
          (c["better"] or "-") + (" *" if c["significant"] else "")]
         for c in summary["comparisons"]])
    recommended = table(
        ["participant", "settings", "predicted cost", "cost"],
        [[p, ", ".join(f"{k} {v:.3g}" for k, v in r["settings"].items()),
          fmt(r["predicted_cost"]), r["cost"]] for p, r in summary["recommended"].items()])
    power = summary["power"]
    stated = table(["effect d_z", "participants needed"],
                   [[s["effect_size"], s["participants_needed"]] for s in power["stated_effects"]])
    observed = table(["task", "metric", "a", "b", "observed d_z", "participants needed"],
                     [[o["task"] or "(asked)", o["metric"], o["a"], o["b"],
                       fmt(o["observed_effect"]),
                       o["participants_needed"]] for o in power["observed"]])
    page = f"""<!doctype html><html><head><meta charset="utf-8">
<title>Study {html.escape(summary['study'])}</title>
<style>body{{font-family:sans-serif;max-width:1300px;margin:auto}}
table{{border-collapse:collapse;font-size:12px}}td,th{{border:1px solid #ccc;padding:2px 6px}}</style>
</head><body>
<h1>Study {html.escape(summary['study'])}</h1>
<p>{len(summary['participants'])} participants ({summary['virtual_participants']} virtual),
{summary['trials']} trials. Multiple comparisons: {html.escape(summary['correction'])}.</p>
<h2>Metrics per scheme</h2>{metric_figures(compared, schemes, summary)}
<h2>Learning</h2>{learning_figure(compared, schemes)}
<h2>Proficiency</h2>{proficiency_lines(summary)}
<h2>Questionnaires</h2>{questionnaire_figure(answers, schemes)}
<h2>Paired comparisons</h2><p>* significant at 0.05 after the correction.</p>{comparisons}
<h2>Tuning</h2>{tuning_figure(rows)}{recommended}
<h2>Power</h2><p>{html.escape(power['test'])}, alpha {power['alpha']}, power {power['power']}.
{html.escape(power['note'])}.</p>{stated}{observed}
</body></html>"""
    (folder / "report.html").write_text(page)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
