#!/usr/bin/env python3
"""The peg transfer from Python: the main job's scripted operator drives the environment step by
step through raven_sim, and all six rings land on their target posts.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/peg_transfer.py [--seed N] [--randomize]
"""

import argparse
import time

import raven_sim


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--randomize", action="store_true", help="draw the scene from the seed")
    args = parser.parse_args()

    env = raven_sim.PegTransferEnv(randomize=args.randomize)
    observation, info = env.reset(seed=args.seed)
    start, steps, total = time.perf_counter(), 0, 0.0
    terminated = truncated = False
    while not (terminated or truncated):
        observation, reward, terminated, truncated, info = env.step(env.expert_action())
        steps += 1
        total += reward
        if reward:
            print(f"t = {info['time']:6.2f} s: {info['placed']} of 6 placed")
    wall = time.perf_counter() - start
    print(f"placed {info['placed']}/6 in {steps} steps, {info['time']:.1f} s of robot time, "
          f"{wall:.1f} s of wall time ({info['time'] / wall:.1f}x real time); return {total:g}")
    return 0 if info["placed"] == 6 else 1


if __name__ == "__main__":
    raise SystemExit(main())
