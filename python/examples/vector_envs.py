#!/usr/bin/env python3
"""N peg-transfer environments stepped together on worker threads (each step releases the
GIL): steps per second for N = 1, 2, 4, every environment following the expert.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/vector_envs.py [steps]
"""

import sys
import time

import raven_sim


def steps_per_second(n, steps):
    vector = raven_sim.VectorPegTransferEnv(n, randomize=True)
    vector.reset(list(range(n)))
    start = time.perf_counter()
    for _ in range(steps):
        vector.step(vector.expert_actions())
    elapsed = time.perf_counter() - start
    vector.close()
    return n * steps / elapsed


if __name__ == "__main__":
    steps = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    for n in (1, 2, 4):
        print(f"N = {n}: {steps_per_second(n, steps):7.1f} environment steps/s")
