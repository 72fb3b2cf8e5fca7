#!/usr/bin/env python3
"""raven_sim, the twin in process from Python: the world, the twin's commands and refusals, a
bad model file's error, the paper's 2arm replay identical to raven_controller's, the forces
read back from a robot recording's motors, and the peg
transfer environment (a whole episode placing all six, the same seed the same episode, N at once).

Usage: raven_sim_test.py <raven_controller>; PYTHONPATH must hold build/python.
"""

import gc
import math
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import raven_sim

CONTROLLER = sys.argv.pop(1) if len(sys.argv) > 1 else ""
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
MODELS = os.path.join(ROOT, "raven_description", "models")
LEFT_TOOL, RIGHT_TOOL = raven_sim.part("tool_poses", 0), raven_sim.part("tool_poses", 1)
PAPER_CI = os.path.join(ROOT, "..", "shared", "data", "recordings", "paper_2arm", "2arm_ci.csv")


class WorldFromPython(unittest.TestCase):
    def test_load_step_and_read_the_peg_scene(self):
        world = raven_sim.World.from_launch(os.path.join(MODELS, "peg_transfer", "launch.yaml"))
        self.assertEqual(len(world.soft_bodies), 6)
        ring = world.soft_body(world.soft_bodies[0])
        before = ring.nodes
        self.assertEqual(before.shape[1], 3)
        world.step(100)
        self.assertAlmostEqual(world.time, 100 * world.step_size, places=12)
        after = ring.nodes
        self.assertTrue(np.isfinite(after).all())
        # A ring resting on its post stays there (within a millimetre) under gravity.
        self.assertLess(np.abs(after.mean(axis=0) - before.mean(axis=0)).max(), 1e-3)
        self.assertGreater(len(world.contacts()), 0)
        self.assertIn("shoulder", world.joints)

    def test_a_bad_model_file_raises_naming_file_line_and_key(self):
        text = pathlib.Path(MODELS, "raven2", "raven2_left.yaml").read_text()
        bad = re.sub(r"mass: [0-9.e-]+", "mass: -2.5", text, count=1)
        line = text[:re.search(r"mass: [0-9.e-]+", text).start()].count("\n") + 1
        with tempfile.TemporaryDirectory() as directory:
            path = os.path.join(directory, "bad.yaml")
            pathlib.Path(path).write_text(bad)
            with self.assertRaises(raven_sim.LoadError) as caught:
                raven_sim.World.from_models([path])
        message = str(caught.exception)
        self.assertIn(f"{path}:{line}:", message)
        self.assertIn("/mass", message)
        self.assertIn("negative", message)


class TwinFromPython(unittest.TestCase):
    def test_commands_results_and_refusals_as_in_cpp(self):
        twin = raven_sim.Twin()
        refused = twin.send(raven_sim.ServoJp(raven_sim.Arm.LEFT, np.zeros(7)))
        self.assertFalse(refused)
        self.assertIn("DISABLED", refused.note)
        twin.enable_and_home()
        self.assertTrue(twin.operating_status.ready)
        q = twin.setpoint_js(raven_sim.Arm.LEFT).position
        goal = q.copy()
        goal[0] += 0.02
        self.assertTrue(twin.send(raven_sim.ServoJp(raven_sim.Arm.LEFT, goal)))
        twin.advance(0.02)  # 0.02 rad at 0.0025 rad a cycle: 8 cycles
        self.assertAlmostEqual(twin.setpoint_js(raven_sim.Arm.LEFT).position[0], goal[0], 12)
        nan = goal.copy()
        nan[3] = math.nan
        result = twin.send(raven_sim.ServoJp(raven_sim.Arm.LEFT, nan))
        self.assertFalse(result)
        self.assertIn("'roll' is NaN", result.note)
        self.assertEqual(twin.measured_cp(raven_sim.Arm.RIGHT).shape, (4, 4))

    def test_the_twins_world_outlives_the_python_twin_object(self):
        world = raven_sim.Twin().world
        gc.collect()
        world.step(10)
        self.assertGreater(len(world.bodies), 0)


class ReplayFromPython(unittest.TestCase):
    def test_the_2arm_replay_gives_raven_controllers_rows_bit_for_bit(self):
        if not os.path.exists(PAPER_CI):
            self.skipTest(f"{PAPER_CI} is absent (../shared/data holds the paper's recordings)")
        if not CONTROLLER:
            self.skipTest("no raven_controller given")
        with tempfile.TemporaryDirectory() as directory:
            cpp, py = os.path.join(directory, "cpp"), os.path.join(directory, "py")
            subprocess.run([CONTROLLER, "--platform", "twin", "--lock-step", "--replay-ci",
                            PAPER_CI, "--record", "yes", "--name", "cpp", "--out", cpp, "--no-gamepad",
                            "--no-keyboard"], check=True, capture_output=True, timeout=600)
            twin = raven_sim.Twin()
            twin.enable_and_home()
            session = raven_sim.ControllerSession(raven_sim.Controller(twin),
                                                  raven_sim.read_ci(PAPER_CI), py, "py")
            session.select(raven_sim.Mode.REPLAY_INPUTS)
            session.start_recording()
            session.run()
            rs = [str(p) for p in session.recordings if str(p).endswith("_rs.csv")]
            expected = [os.path.join(cpp, f) for f in os.listdir(cpp) if f.endswith("_rs.csv")]
            self.assertEqual(len(rs), 1)
            self.assertEqual(pathlib.Path(rs[0]).read_bytes(), pathlib.Path(expected[0]).read_bytes())
            self.assertEqual(len(raven_sim.read_rs(rs[0]).rows), 1351)


class ForcesFromPython(unittest.TestCase):
    def test_a_robot_recording_gives_each_cf_column_with_its_sd(self):
        trial = os.path.join(os.path.dirname(PAPER_CI), "2arm_physical_1.csv")
        if not os.path.exists(trial):
            self.skipTest(f"{trial} is absent (../shared/data holds the paper's recordings)")
        forces = raven_sim.estimate_forces(trial)
        for arm in ("left", "right"):
            for channel in ("fx", "fy", "fz", "jaw1_normal", "jaw2_normal"):
                self.assertEqual(len(forces[f"{arm}_{channel}"]), 1351)
                self.assertTrue((forces[f"{arm}_{channel}_sd"] > 0).all(), channel)
        with self.assertRaisesRegex(ValueError, "no_such_rs.csv"):
            raven_sim.estimate_forces("no_such_rs.csv")
        with self.assertRaisesRegex(ValueError, "no_such_profile.yaml"):
            raven_sim.estimate_forces(trial, calibration="no_such_profile.yaml")
        with self.assertRaisesRegex(ValueError, "grip depth 0"):
            raven_sim.estimate_forces(trial, grip_depth=0.0)


class PegTransferEnvironment(unittest.TestCase):
    def test_the_expert_places_all_six_in_one_episode(self):
        env = raven_sim.PegTransferEnv()
        observation, info = env.reset(seed=0)
        self.assertTrue(env.observation_space.contains(observation))
        self.assertEqual(info["placed"], 0)
        total = 0.0
        while True:
            action = env.expert_action()
            self.assertTrue(env.action_space.contains(action))
            observation, reward, terminated, truncated, info = env.step(action)
            total += reward
            if terminated or truncated:
                break
        self.assertTrue(terminated)
        self.assertEqual(info["placed"], 6)
        self.assertEqual(total, 6.0)
        self.assertEqual(info["refused"], 0)
        self.assertFalse(info["faulted"])  # no e-stop on the way

    def test_the_twin_behind_the_episode_reports_its_motors_and_contacts(self):
        env = raven_sim.PegTransferEnv()
        with self.assertRaises(Exception):
            env.twin  # no episode yet
        observation, _ = env.reset(seed=0)
        for _ in range(5):
            observation = env.step(env.expert_action())[0]
        twin = env.twin
        state = twin.raven_state()
        self.assertEqual(state.runlevel, 3)  # pedal down: the motors' control law runs
        self.assertAlmostEqual(state.time, env.core.time, places=9)
        left = twin.measured_js(raven_sim.Arm.LEFT).position
        np.testing.assert_array_equal(left, observation[raven_sim.part("joints", 0)])
        # The shoulder's motor holds the arm up: its Tau carries the gravity term (gold: |tau_g|
        # 0.01-0.11 N m, ../shared/reference/raven2-actuation.md §3).
        self.assertGreater(abs(state.tau[0]), 0.005)
        self.assertIsNotNone(twin.measured_cf(raven_sim.Arm.RIGHT))

    def run_steps(self, env, seed, steps):
        observations = [env.reset(seed=seed)[0]]
        for _ in range(steps):
            observations.append(env.step(env.expert_action())[0])
        return np.stack(observations)

    def test_the_same_seed_gives_the_same_episode(self):
        env = raven_sim.PegTransferEnv(randomize=True)
        first = self.run_steps(env, 5, 40)
        again = self.run_steps(env, 5, 40)
        other = self.run_steps(env, 6, 40)
        self.assertTrue(np.array_equal(first, again))
        rings = raven_sim.part("rings")
        self.assertFalse(np.array_equal(first[0, rings], other[0, rings]),
                         "seeds 5 and 6 drew one scene")

    def test_the_state_is_read_by_the_cpp_layouts_names(self):
        layout = raven_sim.observation_layout()
        self.assertEqual(set(layout), {"joints", "targets", "tool_poses", "wrenches", "rings"})
        spans = sorted((part.start, part.stop) for part, _ in layout.values())
        self.assertEqual(spans[0][0], 0)
        self.assertEqual(spans[-1][1], raven_sim.PegTransferCore.observation_size)
        self.assertTrue(all(a[1] == b[0] for a, b in zip(spans, spans[1:])), "the parts tile it")
        state, _ = raven_sim.PegTransferEnv().reset(seed=0)
        # Every ring rests threaded on its start post and on no target post, by C++'s judgement.
        for i, job in enumerate(raven_sim.peg_layout()["jobs"]):
            centre = state[raven_sim.part("rings", i)]
            self.assertTrue(raven_sim.ring_placed(centre, job["from"]), job["ring"])
            self.assertFalse(raven_sim.ring_placed(centre, job["to"]), job["ring"])
        quaternion = state[raven_sim.part("tool_poses", 1)][3:]
        self.assertAlmostEqual(float(np.linalg.norm(quaternion)), 1.0, places=12)

    def test_pad_actions_and_bad_actions(self):
        env = raven_sim.PegTransferEnv(action_type="pad")
        start = env.reset(seed=0)[0]
        push = np.zeros(14)
        push[1] = -1.0  # left stick forward
        for _ in range(20):
            observation = env.step(push)[0]
        left_targets = raven_sim.part("targets", 0)
        self.assertGreater(np.abs(observation[left_targets] - start[left_targets]).max(), 1e-3)
        joints = raven_sim.PegTransferEnv()
        joints.reset(seed=0)
        bad = joints.expert_action()
        bad[4] = math.nan
        with self.assertRaisesRegex(ValueError, r"action\[4\] is nan"):
            joints.step(bad)

    def test_joint_deltas_replay_the_experts_targets(self):
        targets = raven_sim.PegTransferEnv()
        deltas = raven_sim.PegTransferEnv(action_type="joint_deltas")
        self.assertEqual(deltas.action_space.shape, (14,))
        self.assertAlmostEqual(deltas.action_space.high[2], 0.33)  # the insertion's range, m
        a, b = targets.reset(seed=3)[0], deltas.reset(seed=3)[0]
        for _ in range(30):
            a = targets.step(targets.expert_action())[0]
            b = deltas.step(deltas.expert_action())[0]
        np.testing.assert_allclose(a, b, atol=1e-9)

    def test_period_control_and_tool_deltas(self):
        env = raven_sim.PegTransferEnv(action_type="tool_deltas", control="period", period=0.1)
        self.assertEqual(env.action_space.shape, (8,))
        start = env.reset(seed=0)[0]
        t0 = env.core.time
        push = np.zeros(8)
        push[0] = 0.004  # the left tool tip +4 mm along the controller's x each step
        push[3] = start[19] + start[20]  # both jaws' opening as it is
        push[7] = start[26] + start[27]
        for k in range(10):
            observation = env.step(push)[0]
            self.assertAlmostEqual(env.core.time - t0, 0.1 * (k + 1), places=9)
        # In measured_cp's frame.
        moved = np.linalg.norm(observation[LEFT_TOOL][:3] - start[LEFT_TOOL][:3])
        self.assertGreater(moved, 0.002)  # under the caps: at most what ten pushes asked
        self.assertLess(moved, 0.041)
        # The right tool stands still.
        np.testing.assert_allclose(observation[RIGHT_TOOL][:3], start[RIGHT_TOOL][:3], atol=2e-4)
        with self.assertRaisesRegex(ValueError, "8 values, not 14"):
            env.step(np.zeros(14))
        with self.assertRaisesRegex(ValueError, "period"):
            raven_sim.PegTransferEnv(control="period", period=0.0)
        with self.assertRaisesRegex(ValueError, "tool_deltas"):
            raven_sim.PegTransferEnv(action_type="cartesian")

    def test_vectorised_environments_match_one_by_one(self):
        vector = raven_sim.VectorPegTransferEnv(2, randomize=True)
        observations, _ = vector.reset([1, 2])
        for _ in range(10):
            observations = vector.step(vector.expert_actions())[0]
        vector.close()
        for i, seed in enumerate((1, 2)):
            alone = self.run_steps(raven_sim.PegTransferEnv(randomize=True), seed, 10)
            self.assertTrue(np.array_equal(observations[i], alone[-1]))


if __name__ == "__main__":
    unittest.main()
