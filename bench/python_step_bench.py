#!/usr/bin/env python3
"""raven_sim's cost from Python, for raven_bench's "python" section (prints one JSON object).

Per repetition, alternating: the twin (our Raven-II alone, homed) stepped one 1 ms cycle per
Python call, and the same number of cycles in one call (the C++ loop); then N = 1, 2, 4
peg-transfer environments stepped together on threads, each following the expert. Once: 60
demonstrations recorded (`learn record`, --max-steps each) by one worker, then by two.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_step_bench.py [--repeat 3]
"""

import argparse
import contextlib
import io
import json
import os
import tempfile
import time

import raven_sim
from raven_sim import learn


def per_step_us(repeat, cycles):
    twin = raven_sim.Twin()
    twin.enable_and_home()
    twin.advance(1.0)  # settled
    python, cpp = [], []
    for _ in range(repeat):
        start = time.perf_counter()
        twin.advance(cycles * 0.001)
        cpp.append((time.perf_counter() - start) / cycles * 1e6)
        start = time.perf_counter()
        for _ in range(cycles):
            twin.advance(0.001)
        python.append((time.perf_counter() - start) / cycles * 1e6)
    return python, cpp


def vector_rates(repeat, n, steps):
    rates, robot = [], []
    for r in range(repeat):
        vector = raven_sim.VectorPegTransferEnv(n, randomize=True)
        vector.reset([r * n + i for i in range(n)])
        t0 = [env.core.time for env in vector.envs]
        start = time.perf_counter()
        for _ in range(steps):
            vector.step(vector.expert_actions())
        elapsed = time.perf_counter() - start
        rates.append(n * steps / elapsed)
        robot.append(sum(env.core.time - t for env, t in zip(vector.envs, t0)) / elapsed)
        vector.close()
    return rates, robot


def record_seconds(workers, episodes, steps):
    """Wall seconds `learn record` takes for `episodes` demonstrations of `steps` steps."""
    with tempfile.TemporaryDirectory() as d, contextlib.redirect_stdout(io.StringIO()):
        start = time.perf_counter()
        learn.main(["record", "--episodes", str(episodes), "--seeds", f"1-{episodes}",
                    "--max-steps", str(steps), "--workers", str(workers),
                    "--out", os.path.join(d, "demos.hdf5")])
        return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--cycles", type=int, default=20000)
    parser.add_argument("--env-steps", type=int, default=100)
    parser.add_argument("--demos", type=int, default=60)
    parser.add_argument("--demo-steps", type=int, default=100)
    args = parser.parse_args()
    python, cpp = per_step_us(args.repeat, args.cycles)
    result = {"python_us": python, "cpp_us": cpp, "cycles": args.cycles,
              "env_steps": args.env_steps, "vector": {}}
    for n in (1, 2, 4):
        rates, robot = vector_rates(args.repeat, n, args.env_steps)
        result["vector"][str(n)] = {"steps_per_s": rates, "robot_s_per_s": robot}
    result["record"] = {"demos": args.demos, "steps": args.demo_steps,
                        "seconds": {str(w): record_seconds(w, args.demos, args.demo_steps)
                                    for w in (1, 2)}}
    print(json.dumps(result))


if __name__ == "__main__":
    main()
