#!/usr/bin/env python3
"""A policy run through the robot's interface: `python3 -m raven_sim.learn run` against
raven_twin_node in another process over a real rosmaster, on the wall clock, with the node's
rendered task cameras (colour, and depth for the RGB-D policy); the same command's refusals when
what the policy needs is missing.

Usage: robot_run_test.py <raven_twin_node>; PYTHONPATH must hold the build tree's python/.
"""

import os
import re
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from ros_processes import RosMaster, TwinNode  # noqa: E402

NODE = sys.argv.pop(1) if len(sys.argv) > 1 else ""
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
POLICIES = os.path.join(ROOT, "python", "policies")
SCENE = os.path.join(ROOT, "raven_description", "models", "peg_transfer", "launch.yaml")


def learn(*args, timeout=600):
    return subprocess.run(["/usr/bin/python3", "-m", "raven_sim.learn", *args],
                          capture_output=True, text=True, timeout=timeout)


class RunRefusesWhatItCannotDo(unittest.TestCase):
    def test_an_image_policy_on_the_robot_needs_its_cameras(self):
        run = learn("run", "--policy", os.path.join(POLICIES, "bc_rgb.pt"), "--platform",
                    "physical", timeout=120)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("--camera-topics LEFT RIGHT", run.stderr)

    def test_an_rgbd_policy_on_the_robot_needs_its_depth_images_too(self):
        run = learn("run", "--policy", os.path.join(POLICIES, "bc_rgbd.pt"), "--platform",
                    "physical", "--camera-topics", "/left/image_raw", "/right/image_raw",
                    timeout=120)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("--depth-topics LEFT RIGHT", run.stderr)

    def test_a_state_policy_on_the_robot_needs_the_rings_poses(self):
        run = learn("run", "--policy", os.path.join(POLICIES, "bc_state.pt"), "--platform",
                    "physical", timeout=120)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("--scene-namespace", run.stderr)


class PolicyOnATwinNode:
    """A policy run against a raven_twin_node of its own (another process, real time, the
    robot's motor-level actuation, both task cameras); the node's ring topics judge. A subclass
    names the node's namespace and its extra arguments."""

    NAMESPACE = ""
    NODE_ARGS = ()

    @classmethod
    def setUpClass(cls):
        if not NODE:
            raise unittest.SkipTest("no raven_twin_node given")
        cls.master = RosMaster()
        cls.node = TwinNode(NODE, cls.master.dir.name, cls.NAMESPACE, "--launch", SCENE,
                            "--soft-body-sleep", "--cameras", "left-task,right-task",
                            *cls.NODE_ARGS)

    @classmethod
    def tearDownClass(cls):
        cls.node.stop()
        cls.master.stop()

    def assert_places(self, policy, seconds, least):
        """`learn run --policy policy` for `seconds` of the node's clock ends with "placed N
        rings", N at least `least`."""
        run = learn("run", "--policy", os.path.join(POLICIES, policy), "--platform", "twin",
                    "--robot-namespace", self.NAMESPACE, "--time-limit", str(seconds),
                    "--connect-timeout", "30")
        self.assertEqual(run.returncode, 0, run.stderr[-3000:])
        last = run.stdout.strip().splitlines()[-1]
        found = re.fullmatch(r"placed (\d) rings", last)
        self.assertIsNotNone(found, run.stdout)
        self.assertGreaterEqual(int(found.group(1)), least, run.stdout + self.node.output()[-2000:])


class RunOnTheTwinNode(PolicyOnATwinNode, unittest.TestCase):
    """The image policy drives the twin node from its camera topics."""

    NAMESPACE = "/r1"

    def test_the_image_policy_places_rings_through_the_robots_interface(self):
        self.assert_places("bc_rgb.pt", 120, 1)


class RunRgbdOnTheTwinNode(PolicyOnATwinNode, unittest.TestCase):
    """The RGB-D image policy drives the twin node from its colour and depth camera topics (the
    node renders both, as an RGB-D camera's driver publishes them)."""

    NAMESPACE = "/r2"
    NODE_ARGS = ("--camera-depth",)

    def test_the_rgbd_policy_places_four_rings_through_the_robots_interface(self):
        self.assert_places("bc_rgbd.pt", 240, 4)


if __name__ == "__main__":
    unittest.main()
