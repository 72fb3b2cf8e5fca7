#!/usr/bin/env python3
"""Soak test: a long lock-step session of the twin node driven at 1 kHz over ROS, then a long
peg-transfer batch, each watched for growth of its resident memory (RSS) and its step time from
the first tenth of the run to the last. Run through scripts/soak.sh (its header has the usage).

Growth, the figure it prints and checks (under 5 %), compares the first tenth with the last:
- RSS: how much each process's highest anonymous RSS (heap and stacks) within the tenth grew,
  over its whole RSS in the first tenth (a process that leaks a little each cycle grows its peak;
  a steady one repeats it; the files mapped in, mostly libraries' code, come and go with the
  paths run and the host's memory and are no leak), sampled every --interval wall seconds;
- step time: the processes' CPU time (user and system) per simulated millisecond within the tenth,
  so that other work on the machine does not count as growth. The session's progress is the last
  whole row of its rs recording; the batch's is its finished runs' steps (runs.jsonl). A virtual
  machine's cores change speed under it, which CPU time counts as the code's own (on a quiet
  host a forty-minute session's node read 0.22 to 0.29 ms and back, its controller with it); so a fixed reference work is timed at every sample, and the growth checked is the
  step time's over the reference's (both raw figures are printed). Beside it, the share of the
  host's CPUs busy with other work in each tenth: a growth is the code's only where that share
  stayed small.
The session's tenths are of the steady dance after O5's ramp (the whole session when it is too
short for that), by simulated time; the batch's are of its runs after the warm-up, by runs (its
memory while the first tenth is running, and after all but the last tenth have finished). The
session's recording is then checked whole: one row per controller turn (as the controller
reports), every row with the header's fields, indices contiguous, times increasing, the last at
the session's end.
"""
import argparse
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

LIMIT_PERCENT = 5.0
BATCH_RUNS_PER_HOUR = 500  # 1,000 runs for a two-hour soak
# Each run ends after this much simulated time: its world built, homed, two rings grasped, carried
# and placed, and torn down. A whole nominal run (115 s simulated, six rings) takes about 22 s of
# a core here, so 1,000 of them would take three hours of both cores; cut, the batch takes one.
BATCH_RUN_SECONDS = 30.0
# A tenth's peak RSS is of the worlds alive at once. Two workers' peaks vary by a quarter with how
# their runs line up (anonymous 58 to 74 MiB over ten runs here), and only a tenth of many runs
# is sure to catch the highest; one worker's peak repeats within 1 MiB run after run. So a batch
# with fewer runs than this runs on one thread, a longer one on two.
TWO_THREADS_FROM_RUNS = 200
# A worker's first runs size its heap: glibc serves a world's large blocks by mmap until it frees
# one, then raises its mmap threshold and keeps later worlds' blocks in the heap (about 15 % more
# RSS over the first two runs, flat after). The batch's tenths are of the runs after them.
WARMUP_RUNS_PER_THREAD = 2
# O5's dance grows its amplitude over its first 2,000 turns (DanceSettings::ramp_per_call is 0.5/500
# of full scale a turn), and the work of a cycle with it.
DANCE_RAMP_TURNS = 2000
CLOCK_TICKS = os.sysconf("SC_CLK_TCK")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def usage(pid):
    """(RssAnon in KiB, CPU seconds, VmRSS in KiB) of a live process, None once it has gone.
    A leak grows the anonymous pages (heap, stacks); the rest of the RSS is files mapped in,
    mostly the libraries' code, paged in the first time a path runs and out under the host's
    memory pressure (the controller's 44 MiB are 37 MiB of them)."""
    try:
        status = Path(f"/proc/{pid}/status").read_text()
        stat = Path(f"/proc/{pid}/stat").read_text()
    except (FileNotFoundError, ProcessLookupError):
        return None
    kib = {line.split(":")[0]: int(line.split()[1]) for line in status.splitlines()
           if line.startswith(("RssAnon:", "VmRSS:"))}
    fields = stat.rsplit(")", 1)[1].split()  # after the command name, which may hold spaces
    cpu = (int(fields[11]) + int(fields[12])) / CLOCK_TICKS  # utime, stime
    return (kib["RssAnon"], cpu, kib["VmRSS"]) if len(kib) == 2 else None


def reference_work():
    """CPU seconds a fixed piece of work (about 10 ms) takes this process now. A virtual
    machine's cores change speed under it (its host's other guests, their clocks), which CPU
    time counts as the code's own; timed beside the soak, this says how much."""
    start = time.process_time()
    sum(i * i for i in range(200000))
    return time.process_time() - start


def host_usage():
    """(monotonic wall seconds, CPU seconds the whole host has been busy, the reference work's
    CPU seconds) now; the first two from /proc/stat."""
    fields = [int(x) for x in Path("/proc/stat").read_text().split("\n")[0].split()[1:]]
    idle = fields[3] + fields[4]  # idle, iowait
    busy = (sum(fields[:8]) - idle) / CLOCK_TICKS  # through steal
    return time.monotonic(), busy, reference_work()


def last_row_time(csv_path):
    """Simulated time of the last whole row of a growing rs recording, None before the first."""
    with open(csv_path, "rb") as f:
        f.seek(0, os.SEEK_END)
        f.seek(max(0, f.tell() - 65536))
        lines = f.read().split(b"\n")
    whole = [line for line in lines[:-1] if line and not line.startswith(b",")]
    return float(whole[-1].split(b",")[1]) if whole else None


def row_time(csv_path, index):
    """Simulated time of a recording's row `index`, None when it has fewer rows."""
    with open(csv_path) as f:
        for i, line in enumerate(f):
            if i == index + 1:
                return float(line.split(",")[1])
    return None


def fresh_folder(path):
    """An empty folder (a kept folder's earlier run is removed)."""
    shutil.rmtree(path, ignore_errors=True)
    path.mkdir(parents=True)
    return path


def keep_samples(samples, path):
    """The samples as JSON lines (progress, {process: [anon KiB, cpu s, rss KiB]},
    [wall s, host busy s, reference s]),
    for a look at how a figure grew over the run."""
    with open(path, "w") as f:
        for sample in samples:
            f.write(json.dumps(sample) + "\n")


def growth(first, last):
    return 100.0 * (last / first - 1.0)


def figure(what, first_last, load=None, reference=None):
    """One printed figure. A step time's growth is the code's: its CPU time per simulated ms
    over the reference work's CPU time, from the first tenth to the last (the raw figure and
    the reference's own change are in the detail); an RSS's is as measured."""
    a, b = first_last[:2]
    if what.startswith("rss"):
        whole = first_last[2]
        # The anonymous pages' growth as a share of the whole footprint: a leak's size next to
        # the process's, not next to a heap that is a small part of it.
        return {"what": what, "growth_percent": 100.0 * (b - a) / whole[0],
                "detail": f"anonymous {a / 1024:.1f} -> {b / 1024:.1f} MiB; all resident "
                f"{whole[0] / 1024:.1f} -> {whole[1] / 1024:.1f} MiB"}
    detail = f"{a:.4f} -> {b:.4f} ms of CPU per simulated ms, {growth(a, b):+.2f} %"
    if load is not None:
        detail += f"; other work on the host {load[0]:.0f} % -> {load[1]:.0f} %"
    detail += f"; the reference work {growth(*reference):+.2f} %"
    return {"what": what, "growth_percent": growth(a / reference[0], b / reference[1]),
            "raw_growth_percent": growth(a, b), "detail": detail}


class RosMaster:
    """A private rosmaster on a free port, its environment for the children, stopped by PID."""

    def __init__(self, work):
        port = free_port()
        self.env = dict(os.environ, ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_IP="127.0.0.1",
                        ROS_HOME=str(work), ROS_LOG_DIR=str(work / "log"))
        self.process = subprocess.Popen(["/usr/bin/python3", "/usr/bin/rosmaster", "--core", "-p",
                                         str(port)], env=self.env,
                                        stdout=open(work / "master.log", "w"),
                                        stderr=subprocess.STDOUT)
        probe = ["/usr/bin/python3", "-c", "import rosgraph; rosgraph.Master('/soak').getPid()"]
        for _ in range(100):
            if subprocess.run(probe, env=self.env, capture_output=True).returncode == 0:
                return
            time.sleep(0.1)
        raise SystemExit(f"soak: rosmaster did not come up; see {work / 'master.log'}")

    def stop(self):
        self.process.terminate()
        self.process.wait()


def watch(processes, interval, progress):
    """Samples (progress, {name: (rss_kib, cpu_s)}, host_usage()) every interval while every
    process lives; progress() is None until there is some."""
    samples = []
    while all(p.poll() is None for p in processes.values()):
        done = progress()
        used = {name: usage(p.pid) for name, p in processes.items()}
        if done is not None and None not in used.values():
            samples.append((done, used, host_usage()))
        time.sleep(interval)
    return samples


class Tenths:
    """The samples of a run's first and last tenth, and what grew from one to the other."""

    def __init__(self, first, last, what):
        if len(first) < 2 or len(last) < 2:
            raise SystemExit(f"soak: fewer than two samples in a tenth of the {what}; run longer "
                             "or sample more often (--interval)")
        self.first, self.last = first, last

    def rss(self, name):
        """(first, last, (first, last) of the whole RSS) peak anonymous RSS of one process in
        KiB: what a leak grows."""
        def peak(field):
            return tuple(max(used[name][field] for _, used, _ in part)
                         for part in (self.first, self.last))
        return peak(0) + (peak(2),)

    def cpu_per_progress(self, names, progress_of=lambda done: done):
        """(first, last) CPU seconds of the named processes per unit of progress."""
        def slope(part):
            cpu = [sum(used[n][1] for n in names) for _, used, _ in part]
            return (cpu[-1] - cpu[0]) / (progress_of(part[-1][0]) - progress_of(part[0][0]))
        return slope(self.first), slope(self.last)

    def reference(self):
        """(first, last) median CPU seconds of the reference work: the host's own speed."""
        def median(part):
            times = sorted(sample[2][2] for sample in part)
            return times[len(times) // 2]
        return median(self.first), median(self.last)

    def other_load(self, names):
        """(first, last) share (%) of the host's CPUs busy with work other than the named
        processes': CPU time is the process's own, but another job on the same cores still slows
        it (caches, memory bandwidth), so a growth is the code's only on a quiet host."""
        def share(part):
            (_, first, (wall0, busy0, _)), (_, last, (wall1, busy1, _)) = part[0], part[-1]
            ours = sum(last[n][1] - first[n][1] for n in names)
            # The kernel counts a process's time and the CPUs' apart: a few % either way.
            return max(0.0, 100.0 * (busy1 - busy0 - ours) / ((wall1 - wall0) * os.cpu_count()))
        return share(self.first), share(self.last)


def check_recording(csv_path, turns, duration):
    """Problems with a finished rs recording: empty list when it is whole."""
    lines = Path(csv_path).read_text().split("\n")
    if lines[-1] != "":
        return [f"{csv_path}: the last row has no line end (cut off)"]
    header, rows = lines[0].split(","), lines[1:-1]
    problems = []
    if len(rows) != turns:
        problems.append(f"{csv_path}: {len(rows)} rows for {turns} controller turns")
    last_time = -1.0
    for i, line in enumerate(rows):
        fields = line.split(",")
        if len(fields) != len(header):
            problems.append(f"{csv_path} row {i}: {len(fields)} fields, the header has {len(header)}")
            break
        if int(fields[0]) != i:
            problems.append(f"{csv_path} row {i}: index {fields[0]}")
            break
        t = float(fields[1])
        if not t > last_time:
            problems.append(f"{csv_path} row {i}: time {t} after {last_time}")
            break
        last_time = t
    if last_time < duration - 0.1:
        problems.append(f"{csv_path}: ends at {last_time:.3f} s of a {duration:.3f} s session")
    return problems


def soak_session(build, work, seconds, interval):
    """The twin node in lock-step, raven_controller's O5 dance on it at 1 kHz for `seconds`."""
    master = RosMaster(work)
    processes = {}
    out = fresh_folder(work / "session")
    try:
        processes["twin node"] = subprocess.Popen(
            [str(build / "twin/ros/raven_twin_node"), "--lock-step"], env=master.env,
            stdout=open(work / "node.log", "w"), stderr=subprocess.STDOUT)
        processes["controller"] = subprocess.Popen(
            [str(build / "controller/raven_controller"), "--twin-over-ros", "--twin-ns", "",
             "--lock-step", "--mode", "o5", "--rate", "1000", "--duration", str(seconds),
             "--no-gamepad", "--no-keyboard", "--record", "yes", "--name", "soak", "--out",
             str(out)], env=master.env, stdout=open(work / "controller.log", "w"),
            stderr=subprocess.STDOUT)

        def recorded():
            files = sorted(out.glob("soak_*_rs.csv"))
            return last_row_time(files[0]) if files else None

        samples = watch(processes, interval, recorded)
        if processes["controller"].wait() != 0:
            raise SystemExit(f"soak: raven_controller failed; see {work / 'controller.log'}")
    finally:
        for p in processes.values():
            if p.poll() is None:
                p.send_signal(signal.SIGINT)
                p.wait()
        master.stop()

    log = (work / "controller.log").read_text()
    turns = int(log.split("done: ")[1].split(" turns")[0])
    rs = sorted(out.glob("soak_*_rs.csv"))[0]
    problems = check_recording(rs, turns, seconds)
    ramp_end = row_time(rs, DANCE_RAMP_TURNS)
    steady = [s for s in samples if ramp_end is not None and s[0] >= ramp_end]
    after_ramp = len(steady) >= 20
    steady = steady if after_ramp else samples
    s0, s1 = steady[0][0], steady[-1][0]
    tenths = Tenths([s for s in steady if s[0] <= s0 + (s1 - s0) / 10],
                    [s for s in steady if s[0] >= s1 - (s1 - s0) / 10], "session")
    rows = [(f"rss {name}", tenths.rss(name)) for name in processes]
    rows.append(("cpu session", tenths.cpu_per_progress(list(processes)),
                 tenths.other_load(list(processes)), tenths.reference()))
    # Each process's own share, to tell which one grows.
    rows += [(f"cpu {name}", tenths.cpu_per_progress([name]), None, tenths.reference())
             for name in processes]
    keep_samples(samples, work / "session-samples.jsonl")
    what = (f"{seconds:.0f} s simulated, {turns} turns, tenths "
            + (f"after O5's ramp ({ramp_end:.0f} s)" if after_ramp else "with O5's ramp"))
    return rows, problems, what


def soak_batch(build, work, runs, interval, run_seconds):
    """raven_peg_transfer's nominal scene `runs` times: every run the same work, so any change from
    the first tenth of runs to the last is the process's own. `run_seconds`: each run ends after
    that much simulated time (0: when its six rings are done)."""
    out = fresh_folder(work / "batch")
    jsonl = out / "runs.jsonl"
    limit = ["--time-limit", f"{run_seconds:g}"] if run_seconds else []
    threads = 2 if runs >= TWO_THREADS_FROM_RUNS else 1
    batch = subprocess.Popen(
        [str(build / "scenario/raven_peg_transfer"), "--runs", str(runs), "--threads",
         str(threads), "--record", "no", "--out", str(out), "-q"] + limit,
        stdout=open(work / "batch.log", "w"), stderr=subprocess.STDOUT)

    def finished():
        return jsonl.read_text().count("\n") if jsonl.exists() else 0

    samples = watch({"batch": batch}, interval, finished)
    if batch.wait() != 0:
        raise SystemExit(f"soak: raven_peg_transfer failed; see {work / 'batch.log'}")
    results = [json.loads(line) for line in jsonl.read_text().splitlines()]
    if len(results) != runs:
        raise SystemExit(f"soak: the batch wrote {len(results)} of {runs} runs")
    simulated_after = [0.0]  # simulated seconds of the first k finished runs
    for r in results:
        simulated_after.append(simulated_after[-1] + r["sim_time_s"])
    warm = threads * WARMUP_RUNS_PER_THREAD
    tenth = max(2, (runs - warm) // 10)  # two runs at least: the step time is a slope over runs
    tenths = Tenths([s for s in samples if warm <= s[0] <= warm + tenth],
                    [s for s in samples if s[0] >= runs - tenth], "batch")
    keep_samples(samples, work / "batch-samples.jsonl")
    rows = [("rss batch", tenths.rss("batch")),
            ("cpu batch", tenths.cpu_per_progress(["batch"], lambda done: simulated_after[done]),
             tenths.other_load(["batch"]), tenths.reference())]
    placed = sum(r["placed"] for r in results)
    each = f", each cut at {run_seconds:g} s simulated" if run_seconds else ""
    return rows, (f"{runs} nominal runs on {threads} thread{'s' if threads > 1 else ''}{each}, "
                  f"{placed} of {6 * runs} placed")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", type=Path, required=True)
    length = parser.add_mutually_exclusive_group()
    length.add_argument("--hours", type=float, help="simulated hours of the session")
    length.add_argument("--minutes", type=float, help="simulated minutes of the session")
    parser.add_argument("--interval", type=float, help="wall seconds between samples")
    parser.add_argument("--keep", type=Path, help="keep the logs and recordings in this folder")
    parser.add_argument("--json", type=Path, help="write the figures to this file")
    parser.add_argument("--only", choices=["session", "batch"],
                        help="run one part alone (a two-hour soak's session and batch take about "
                        "four hours on two cores; each part's figures stand on their own)")
    parser.add_argument("--run-seconds", type=float, default=BATCH_RUN_SECONDS,
                        help="end each batch run after this many simulated seconds; 0: whole runs "
                        f"(default {BATCH_RUN_SECONDS:g})")
    parser.add_argument("--check", choices=["all", "memory"], default="all",
                        help="what fails the run: all (RSS, step time, the recording) or memory "
                        "(RSS and the recording; a short run's step time is the host's noise)")
    args = parser.parse_args()
    hours = args.hours if args.hours is not None else (args.minutes or 10.0) / 60.0
    if not hours > 0:
        raise SystemExit("soak: --hours / --minutes must be positive")
    if not args.run_seconds >= 0:
        raise SystemExit("soak: --run-seconds must be 0 (whole runs) or positive")
    seconds = 3600.0 * hours
    runs = max(10, round(BATCH_RUNS_PER_HOUR * hours))
    interval = args.interval or min(5.0, max(0.2, seconds / 600.0))

    with tempfile.TemporaryDirectory(prefix="soak-") as tmp:
        work = args.keep or Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        parts = {"session": f"a {seconds:.0f} s lock-step session at 1 kHz",
                 "batch": f"a {runs}-run batch"}
        if args.only:
            parts = {args.only: parts[args.only]}
        print(f"soak: {', then '.join(parts.values())} (samples every {interval:g} s, logs in "
              f"{work})", flush=True)
        session_rows, problems, session_what = [], [], None
        if "session" in parts:
            session_rows, problems, session_what = soak_session(args.build, work, seconds,
                                                                interval)
            print(f"session: {session_what}", flush=True)
        batch_rows, batch_what = [], None
        if "batch" in parts:
            batch_rows, batch_what = soak_batch(args.build, work, runs, interval,
                                                args.run_seconds)
            print(f"batch: {batch_what}")

    figures = [figure(*row) for row in session_rows + batch_rows]
    for f in figures:
        print(f"  {f['what']:<16} {f['growth_percent']:+6.2f} %  ({f['detail']})")
    for problem in problems:
        print(f"  recording: {problem}")
    rss = max(f["growth_percent"] for f in figures if f["what"].startswith("rss"))
    step = max(f["growth_percent"] for f in figures if f["what"].startswith("cpu"))
    if args.json:
        args.json.write_text(json.dumps({
            "hours": hours, "parts": list(parts), "session": session_what, "batch": batch_what,
            "rss_growth_percent": rss, "step_time_growth_percent": step,
            "recording_whole": not problems, "figures": figures}, indent=1))
    print(f"rss growth {rss:.2f} %, step time growth {step:.2f} %")
    step_ok = args.check == "memory" or step < LIMIT_PERCENT
    return 0 if rss < LIMIT_PERCENT and step_ok and not problems else 1


if __name__ == "__main__":
    sys.exit(main())
