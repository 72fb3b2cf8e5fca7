#!/usr/bin/env python3
"""An abusive policy in PegTransferEnv never flings a ring or blows the world up (issue 45): on
randomised scenes of three seeds the expert grasps until a ring is lifted, then its jaws are
clamped shut to their stop, crushing the ring, while the arms wander about the expert's targets.
Every ring must stay finite and near the board, and no step may end in the world's guard. With
the linearly implicit step alone, seed 2 flung its ring 22 km.

Usage: env_abuse_test.py; PYTHONPATH must hold build/python.
"""

import os
import tempfile
import unittest

import numpy as np

import raven_sim

RINGS = raven_sim.part("rings")  # the six ring centres of the observation


def jaws_shut(action, low):
    """`action` with each arm's jaws at their stop, the grasper's angle (jaw1 - jaw2) kept."""
    for first in (5, 12):  # jaw1 of the left arm, then of the right (ArmJoints order)
        spread = action[first] - action[first + 1]
        shut = low[first] + low[first + 1]
        action[first], action[first + 1] = (shut + spread) / 2, (shut - spread) / 2
    return action


class AbusivePolicy(unittest.TestCase):
    def check_rings(self, observation, start, seed):
        rings = observation[RINGS].reshape(6, 3)
        self.assertTrue(np.isfinite(rings).all(), f"seed {seed}: {rings}")
        moved = np.linalg.norm(rings[:, :2] - start[:, :2], axis=1)
        # The arms reach about 0.15 m from where a ring starts: a ring found farther was flung.
        self.assertLess(moved.max(), 0.3, f"seed {seed}: rings moved {moved} m")
        rise = rings[:, 2] - start[:, 2]
        self.assertGreater(rise.min(), -0.05, f"seed {seed}: a ring fell through")
        self.assertLess(rise.max(), 0.3, f"seed {seed}: a ring flew up {rise.max()} m")

    def step(self, env, action, seed):
        observation, _, _, truncated, info = env.step(
            np.clip(action, env.action_space.low, env.action_space.high))
        self.assertNotIn("failure", info, f"seed {seed}")
        self.assertFalse(truncated, f"seed {seed}")
        return observation

    def test_jaws_shut_on_a_lifted_ring_while_the_arms_wander_keep_every_ring_bounded(self):
        # Ideal servos: they crush for as long as they are told to. The motor twin's jaw motors
        # wind up against the ring until the robot e-stops, as the robot's would, and the
        # episode then ends (info["faulted"]) before the world has been pushed this hard.
        for seed in (1, 2, 3):
            env = raven_sim.PegTransferEnv(randomize=True, time_limit=1e4, actuation="ideal")
            observation, _ = env.reset(seed=seed)
            start = observation[RINGS].reshape(6, 3).copy()
            low, high = env.action_space.low, env.action_space.high
            for _ in range(400):  # the expert, until some ring is lifted 1 cm
                observation = self.step(env, np.asarray(env.expert_action()), seed)
                if (observation[RINGS].reshape(6, 3)[:, 2] - start[:, 2]).max() > 0.01:
                    break
            else:
                self.fail(f"seed {seed}: the expert lifted no ring")
            rng = np.random.default_rng(seed)
            for _ in range(100):  # crushed: jaws at their stop, joints wandering about the expert's
                action = jaws_shut(np.asarray(env.expert_action()), low)
                action += rng.uniform(-0.01, 0.01, 14) * (high - low)
                observation = self.step(env, action, seed)
                self.check_rings(observation, start, seed)

    def test_on_the_motor_twin_crushing_ends_in_an_e_stop_not_a_blow_up(self):
        env = raven_sim.PegTransferEnv(randomize=True, time_limit=1e4)  # the motors
        observation, _ = env.reset(seed=1)
        start = observation[RINGS].reshape(6, 3).copy()
        low = env.action_space.low
        for _ in range(2000):
            action = jaws_shut(np.asarray(env.expert_action()), low)
            observation, _, _, truncated, info = env.step(
                np.clip(action, low, env.action_space.high))
            self.assertNotIn("failure", info)
            self.check_rings(observation, start, 1)
            if truncated:
                break
        self.assertTrue(truncated and info["faulted"], info)


# A 0.1 kg arm on a hinge, to be driven far harder than anything in a scene of a metre allows.
HINGED_ARM = """bodies: [BODY base, BODY arm]
joints: [JOINT base-arm]
BODY base: {name: base, mass: 0, collision shape: BOX, collision geometry: {x: 0.1, y: 0.1, z: 0.1}}
BODY arm:
  name: arm
  mass: 0.1
  collision shape: BOX
  collision geometry: {x: 0.4, y: 0.02, z: 0.02}
  collision offset: {position: {x: 0.2, y: 0, z: 0}}
  inertial offset: {position: {x: 0.2, y: 0, z: 0}}
  location: {position: {x: 0, y: 0, z: 1}}
JOINT base-arm:
  name: base-arm
  parent: BODY base
  child: BODY arm
  parent pivot: {x: 0, y: 0, z: 1}
  parent axis: {x: 0, y: 0, z: 1}
  child axis: {x: 0, y: 0, z: 1}
  type: revolute
"""


class WorldGuard(unittest.TestCase):
    def test_a_world_driven_past_what_its_scene_allows_raises_naming_body_step_and_time(self):
        with tempfile.TemporaryDirectory() as folder:
            model = os.path.join(folder, "arm.yaml")
            with open(model, "w") as f:
                f.write(HINGED_ARM)
            world = raven_sim.World.from_models([model])
        world.joint("base-arm").command_effort(1e4)  # 10 kN m on a 0.1 kg arm
        with self.assertRaises(raven_sim.SimulationDiverged) as caught:
            world.step(1000)
        message = str(caught.exception)
        self.assertRegex(message, r"the simulation diverged at step \d+ \(t = [0-9.]+ s\): "
                                  r"rigid body '[^']*arm' moves at [0-9.e+]+ m/s, faster than "
                                  r"the scene allows \([0-9.]+ m/s\)")
        self.assertIsInstance(caught.exception, RuntimeError)


if __name__ == "__main__":
    unittest.main()
