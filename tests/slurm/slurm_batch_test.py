#!/usr/bin/env python3
"""Peg-transfer batches on a real Slurm cluster: the private single-node cluster
(scripts/slurm/private-cluster.sh), a batch of 8 randomised seeds as a 4-task array through
scripts/slurm/submit-batch.sh, raven_batch merge, and each run equal, field for field (timings
aside), to the same seed run in one process; then a task cancelled mid-run, the merge naming its
shard, and its resubmission completing the batch with no seed twice.

Usage: slurm_batch_test.py <build folder>. Exits 77 (ctest: skipped), saying why, where Slurm
cannot run: no slurm-wlm, or not root (the private cluster's slurmd launches jobs as root).
"""

import json
import os
import pathlib
import select
import shutil
import subprocess
import sys
import tempfile
import unittest

BUILD = pathlib.Path(sys.argv.pop(1) if len(sys.argv) > 1 else "build").resolve()
ROOT = pathlib.Path(__file__).resolve().parents[2]
CLUSTER = ROOT / "scripts" / "slurm" / "private-cluster.sh"
SUBMIT = ROOT / "scripts" / "slurm" / "submit-batch.sh"
RAVEN_BATCH = BUILD / "scenario" / "raven_batch"
PEG_TRANSFER = BUILD / "scenario" / "raven_peg_transfer"

FIRST_SEED, RUNS, SHARDS = 11, 8, 4
# On ideal servos: what is checked is the cluster's sharding and merge, which the twin's
# actuation does not touch, and ideal servos run a scene about three times as fast as the motors.
OPTIONS = ["--randomize", "--actuation", "ideal", "--record", "no", "-q"]
# Wall-clock fields: the only ones two runs of one seed may disagree on.
TIMINGS = {"wall_time_s", "loop_time_s", "real_time_factor", "loop_frequency_hz"}
INCOMPLETE = 3  # raven_batch merge's exit status when shards must run again
# Seconds a submission may take before the test fails (under ctest's own 900 s timeout, so the
# cluster is still stopped): 8 runs take about a minute here.
DEADLINE = 400


def skip_reason():
    path = os.environ.get("PATH", "") + ":/usr/sbin"
    missing = [t for t in ("slurmctld", "slurmd", "sbatch") if not shutil.which(t, path=path)]
    if missing:
        return f"Slurm is not installed ({', '.join(missing)} missing; scripts/install-deps.sh installs slurm-wlm)"
    if os.geteuid() != 0:
        return "not root: the private cluster's slurmd must run as root to launch jobs"
    return None


def without_timings(row):
    return {key: value for key, value in row.items() if key not in TIMINGS}


def read_rows(path):
    return {row["seed"]: row for row in map(json.loads, path.read_text().splitlines())}


class SlurmBatch(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="raven-slurm-")
        cls.addClassCleanup(cls.tmp.cleanup)
        cls.work = pathlib.Path(cls.tmp.name)
        cls.cluster = cls.work / "cluster"
        started = subprocess.run([str(CLUSTER), "start", str(cls.cluster)], capture_output=True,
                                 text=True, check=False)
        # Stopped even when setUpClass fails later (cleanups run last in, first out).
        cls.addClassCleanup(subprocess.run, [str(CLUSTER), "stop", str(cls.cluster)],
                            check=False, stdout=subprocess.DEVNULL)
        if started.returncode != 0:
            raise RuntimeError(f"the private cluster did not start:\n{started.stderr}")
        # submit-batch.sh --wait asks squeue every second instead of every 10.
        cls.env = dict(os.environ, SLURM_CONF=str(cls.cluster / "slurm.conf"),
                       RAVEN_BUILD=str(BUILD), RAVEN_SLURM_POLL="1")
        # The same seeds in one process, the reference every shard's run must equal.
        reference = cls.work / "one_process"
        subprocess.run([str(PEG_TRANSFER), "--seed", str(FIRST_SEED), "--runs", str(RUNS),
                        "--threads", "2", "--out", str(reference), *OPTIONS],
                       check=True, stdout=subprocess.DEVNULL)
        cls.reference = read_rows(reference / "runs.jsonl")

    def submit(self, out, *extra, wait=True):
        command = [str(SUBMIT), "--out", str(out)] + (["--wait"] if wait else []) + list(extra)
        process = subprocess.Popen(command, env=self.env, stdout=subprocess.PIPE, text=True)
        self.addCleanup(process.kill)  # a failed test leaves no sbatch --wait behind
        self.addCleanup(process.stdout.close)
        return process

    def new_batch(self, out, wait=True):
        return self.submit(out, "--runs", str(RUNS), "--shards", str(SHARDS), "--seed",
                           str(FIRST_SEED), "--", *OPTIONS, wait=wait)

    def merge(self, out):
        return subprocess.run([str(RAVEN_BATCH), "merge", str(out)], capture_output=True,
                              text=True, check=False)

    def assert_equals_one_process(self, out):
        merged = [json.loads(line) for line in (out / "runs.jsonl").read_text().splitlines()]
        seeds = [row["seed"] for row in merged]
        self.assertEqual(seeds, list(range(FIRST_SEED, FIRST_SEED + RUNS)))  # each once, in order
        for row in merged:
            self.assertFalse(row["stopped"])
            self.assertEqual(without_timings(row), without_timings(self.reference[row["seed"]]),
                             f"seed {row['seed']}")
        summary = json.loads((out / "summary.json").read_text())
        self.assertTrue(summary["whole"])
        self.assertEqual(summary["runs"], RUNS)
        self.assertEqual(summary["rings_placed"],
                         sum(r["placed"] for r in self.reference.values()))
        self.assertEqual(summary["steps"], sum(r["steps"] for r in self.reference.values()))

    def test_a_4_task_array_equals_one_process_run_for_run(self):
        out = self.work / "batch"
        submitted = self.new_batch(out)
        waited = submitted.communicate(timeout=DEADLINE)[0]
        self.assertEqual(submitted.returncode, 0, waited)  # --wait merged: whole
        # Every task ran its own shard: one log and one results file each.
        self.assertEqual(len(list((out / "slurm").glob("shard-*-job*.out"))), SHARDS)
        for index in range(1, SHARDS + 1):
            self.assertTrue((out / f"runs-shard{index}of{SHARDS}.jsonl").exists())
        merged = self.merge(out)
        self.assertEqual(merged.returncode, 0, merged.stdout + merged.stderr)
        self.assertIn("whole: every seed once", merged.stdout)
        self.assertEqual(json.loads((out / "batch.json").read_text())["options"], OPTIONS)
        self.assert_equals_one_process(out)

    def test_b_a_cancelled_task_is_named_and_its_resubmission_completes_the_batch(self):
        out = self.work / "faulty"
        submitted = self.new_batch(out)
        job = next(line for line in submitted.stdout if line.startswith("submitted job"))
        job = job.split()[2].rstrip(":")  # "submitted job 12: shards 1-4 of 4, ..."
        # Shard 2 runs seeds 12 and 16: once its first run's row is written, it is in its second.
        shard_file = out / f"runs-shard2of{SHARDS}.jsonl"
        with subprocess.Popen(["tail", "-F", "-n", "+1", str(shard_file)], stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL, text=True) as follow:
            ready, _, _ = select.select([follow.stdout], [], [], DEADLINE)
            self.assertTrue(ready, f"no run of shard 2 finished in {DEADLINE} s")
            first = json.loads(follow.stdout.readline())
            subprocess.run(["scancel", f"{job}_2"], env=self.env, check=True)
            follow.kill()
        self.assertEqual(first["seed"], FIRST_SEED + 1)
        waited = submitted.communicate(timeout=DEADLINE)[0]
        # --wait merges once every task has ended: shard 2 is not whole.
        shard_log = "".join(p.read_text() for p in (out / "slurm").glob("shard-2-*.out"))
        self.assertEqual(submitted.returncode, INCOMPLETE, waited + shard_log)

        incomplete = self.merge(out)
        self.assertEqual(incomplete.returncode, INCOMPLETE, incomplete.stdout + incomplete.stderr)
        self.assertIn(f"shard 2/{SHARDS}: 1 of 2 runs finished; missing seeds {FIRST_SEED + 5}",
                      incomplete.stdout)
        self.assertIn("run shards 2 again", incomplete.stdout)
        for other in (1, 3, 4):
            self.assertNotIn(f"shard {other}/{SHARDS}:", incomplete.stdout)
        self.assertFalse((out / "summary.json").exists())  # nothing merged from a partial batch

        resubmitted = self.submit(out, "--array", "2")
        waited = resubmitted.communicate(timeout=DEADLINE)[0]
        self.assertEqual(resubmitted.returncode, 0, waited)
        merged = self.merge(out)
        self.assertEqual(merged.returncode, 0, merged.stdout + merged.stderr)
        self.assert_equals_one_process(out)


if __name__ == "__main__":
    reason = skip_reason()
    if reason:
        print(f"skipped: {reason}")
        sys.exit(77)
    unittest.main(verbosity=2)
