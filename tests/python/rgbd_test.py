#!/usr/bin/python3
"""The RGB-D image policy (raven_sim.ring_fit, raven_sim.rgbd_policy): the ring's surface and its
fit against hand-made points, the tracker taking up a ring that dropped onto its post, the
twin's rendered task cameras giving every ring to a fraction of a millimetre, a camera moved from
its calibration found again from the board, a policy that acts on what it sees and never on the
true rings, and the shipped bc_rgbd.pt on a seed it never saw.
Needs scipy, torch and headless OpenGL for the rendered parts (skipped, saying so, without
it)."""

import math
import os
import unittest

import numpy as np

import raven_sim
from raven_sim import board_calibration, imitation, learn, rgbd_policy, vision
from raven_sim.ring_fit import RingShape, RingTracker, TaskCamera, facet_scale, fit_ring
from vision_test import task_cameras

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SHIPPED_STATE = os.path.join(ROOT, "python", "policies", "bc_state.pt")
SHIPPED_RGBD = os.path.join(ROOT, "python", "policies", "bc_rgbd.pt")
SMOOTH = RingShape(0.008, 0.002, 0.005)  # the design's ring, drawn smooth


def surface_points(shape, centre, axis=(0.0, 0.0, 1.0), toward=None, count=400, seed=0):
    """Points on the ring's surface (of `shape`, at `centre` about `axis`); with `toward` (a
    direction) only those whose outward normal faces it: what a camera that way sees."""
    rng = np.random.default_rng(seed)
    axis = np.asarray(axis, dtype=np.float64) / np.linalg.norm(axis)
    x = np.cross(axis, [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 1.0, 0.0])
    x /= np.linalg.norm(x)
    y = np.cross(axis, x)
    points = []
    while len(points) < count:
        u, v = rng.uniform(0, 2 * math.pi, 2)
        radial = np.cos(u) * x + np.sin(u) * y
        point = centre + (shape.radius + shape.radial * np.cos(v)) * radial + \
            shape.axial * np.sin(v) * axis
        normal = shape.axial * np.cos(v) * radial + shape.radial * np.sin(v) * axis
        if toward is None or normal @ toward > 0:
            points.append(point)
    return np.array(points)


class RingSurface(unittest.TestCase):
    def test_a_polygons_sides_lie_inside_its_circle_by_their_mean_distance(self):
        self.assertEqual(facet_scale(0), 1.0)
        for sides in (4, 8, 16):
            t = math.pi / sides
            side = np.linspace(-t, t, 200001)  # a side's points, by their angle from its middle
            mean = np.mean(math.cos(t) / np.cos(side))
            self.assertAlmostEqual(facet_scale(sides), mean, places=5)
        self.assertGreater(facet_scale(16), facet_scale(8))
        drawn = RingShape(0.008, 0.002, 0.005, stations=16, tube_stations=8)
        self.assertAlmostEqual(drawn.radius, 0.008 * facet_scale(16))
        self.assertAlmostEqual(drawn.axial, 0.005 * facet_scale(8))

    def test_a_point_on_the_surface_is_on_it_and_one_outside_a_millimetre_off(self):
        centre = np.array([0.3, 0.06, -0.2])
        on = surface_points(SMOOTH, centre, count=50)
        self.assertLess(np.abs(SMOOTH.distances(on, centre, np.array([0, 0, 1.0]))).max(), 1e-9)
        outer = centre + np.array([[0.008 + 0.002 + 0.001, 0.0, 0.0]])  # 1 mm beyond the wall
        self.assertAlmostEqual(SMOOTH.distances(outer, centre, np.array([0, 0, 1.0]))[0], 0.001,
                               places=6)


class RingFit(unittest.TestCase):
    def test_the_half_a_camera_sees_gives_the_centre_and_the_tilt(self):
        centre = np.array([0.3, 0.06, -0.195])
        for axis in ((0.0, 0.0, 1.0), (0.2, -0.1, 1.0)):
            seen = surface_points(SMOOTH, centre, axis, toward=np.array([0, -0.7, 0.7]))
            found, cost = fit_ring(SMOOTH, seen, centre + np.array([0.0007, -0.0007, 0.0007]))
            self.assertLess(np.linalg.norm(found - centre), 1e-5, axis)
            self.assertLess(cost, 1e-12)

    def test_a_ring_that_dropped_onto_its_post_is_taken_up_there(self):
        post = np.array([-0.266, 0.1])
        resting = np.array([*post, -0.1995])
        seen = surface_points(SMOOTH, resting, toward=np.array([0, -0.7, 0.7]))
        camera = TaskCamera([-0.3, -0.05, 0.0], [-0.3, 0.08, -0.19], 0.6)
        # Its last estimate: carried over the post, 4.5 mm higher and 2 mm to the side, where a
        # fit from it alone settles in a wrong minimum (seen in an episode, 3.6 mm off).
        tracker = RingTracker(camera, SMOOTH, [resting + [0.002, -0.002, 0.0045]], [post])
        found = tracker.best_fit(seen, tracker.estimates[0])
        self.assertLess(np.linalg.norm(found - resting), 1e-4)

    def test_a_ring_that_slipped_from_the_jaws_is_taken_up_where_it_fell(self):
        lying = np.array([-0.30, 0.08, -0.1995])
        seen = surface_points(SMOOTH, lying, toward=np.array([0, -0.7, 0.7]), count=150)
        other = np.array([-0.334, 0.058, -0.1995])  # another ring, where it is seen
        camera = TaskCamera([-0.3, -0.05, 0.0], [-0.3, 0.08, -0.19], 0.6)
        carried = lying + [0.0, 0.0, 0.027]  # last seen in the jaws, 27 mm up: beyond the gate
        tracker = RingTracker(camera, SMOOTH, [carried, other], [])
        found = tracker.fallen(seen, 0)  # none of these lies within the gate of either ring
        self.assertEqual(len(found), len(seen))
        self.assertLess(np.linalg.norm(tracker.best_fit(found, carried) - lying), 1e-4)
        self.assertEqual(len(tracker.fallen(seen[:5], 0)), 0)  # too few to be a ring


def rgbd_cameras(seed, size=(128, 96), randomize=True):
    """An environment with both arms' RGB-D task cameras and its first observation."""
    return task_cameras(size, ("state", "rgb", "depth"), seed, randomize)


class RenderedRings(unittest.TestCase):
    def test_every_ring_is_found_in_the_rendered_images_to_a_fifth_of_a_millimetre(self):
        _, o = rgbd_cameras(seed=11)  # rings drawn up to 1 mm off their posts' centres
        policy = rgbd_policy.RgbdPolicy(imitation.Policy.load(SHIPPED_STATE))
        true = o["state"][imitation.RINGS].reshape(6, 3)
        seen = policy.locate(o).reshape(6, 3)
        errors = np.linalg.norm(seen - true, axis=1)
        self.assertLess(errors.max(), 2e-4, errors)

    def test_it_acts_on_the_rings_it_sees_never_on_the_true_ones(self):
        _, o = rgbd_cameras(seed=3)
        policy = rgbd_policy.RgbdPolicy(imitation.Policy.load(SHIPPED_STATE))
        acted = policy.fresh().act(o)
        wrong = dict(o)
        wrong["state"] = o["state"].copy()
        wrong["state"][imitation.RINGS] = 1e3  # rings a kilometre away
        self.assertTrue(np.array_equal(policy.fresh().act(wrong), acted))
        blind = dict(o)
        blind[rgbd_policy.depth_key(0)] = np.full_like(o[rgbd_policy.depth_key(0)], np.inf)
        looking = policy.fresh()
        looking.locate(o)  # its cameras found, its rings seen once
        looking.trackers[0].estimates += 0.003  # where it last saw them
        moved = looking.trackers[0].estimates.copy()
        seen = looking.locate(blind).reshape(6, 3)
        left, right = rgbd_policy.RING_ROWS
        self.assertTrue(np.array_equal(seen[left], moved))  # unseen: kept where last seen
        true = o["state"][imitation.RINGS].reshape(6, 3)
        self.assertLess(np.linalg.norm(seen[right] - true[right], axis=1).max(), 2e-4)


class CameraFoundFromTheBoard(unittest.TestCase):
    def test_a_camera_mounted_again_is_found_from_the_board_it_sees(self):
        # At the ranges' edges each task camera aims 3 mm off on every axis, is turned 2 degrees
        # in yaw and pitch and stands 3 % nearer or farther than calibrated.
        _, o = rgbd_cameras(seed=3, randomize=os.path.join(ROOT, "scenario", "ranges",
                                                           "edges.yaml"))
        true = o["state"][imitation.RINGS].reshape(6, 3)
        layout = raven_sim.peg_layout()
        shape = RingShape.of_layout(layout)
        for arm in (0, 1):
            calibrated = TaskCamera(**raven_sim.task_camera(arm))
            found = board_calibration.calibrate(calibrated, o[vision.image_key(arm)],
                                                o[rgbd_policy.depth_key(arm)], layout,
                                                rgbd_policy.POSTS)
            rows = rgbd_policy.RING_ROWS[arm]
            errors = []
            for camera in (calibrated, found):
                tracker = RingTracker(camera, shape, true[rows], rgbd_policy.POSTS)
                seen = tracker.update(o[vision.image_key(arm)], o[rgbd_policy.depth_key(arm)])
                errors.append(np.linalg.norm(seen - true[rows], axis=1).max())
            self.assertGreater(errors[0], 0.003, arm)  # the old calibration: millimetres off
            self.assertLess(errors[1], 2e-4, arm)

    def test_a_dark_scene_seen_turned_is_not_taken_for_a_camera_turned_round(self):
        # Seed 20 at the ranges' edges: the lights at 0.7, the board darkened, each camera
        # turned 2 degrees down and aside. The board's top alone is the same seen from any yaw
        # about its aim point, and an unbounded fit turned both cameras 4 rad round (rings
        # 30-70 mm off): a camera mounted again lies within 0.2 rad and 20 mm of its calibration.
        _, o = rgbd_cameras(seed=20, randomize=os.path.join(ROOT, "scenario", "ranges",
                                                            "edges.yaml"))
        true = o["state"][imitation.RINGS].reshape(6, 3)
        seen = rgbd_policy.RgbdPolicy(imitation.Policy.load(SHIPPED_STATE)).locate(o)
        self.assertLess(np.linalg.norm(seen.reshape(6, 3) - true, axis=1).max(), 2e-4)

    def test_a_stereo_cameras_depth_scale_is_found_with_its_pose(self):
        # Seed 5 at depth.yaml's edges: each depth read 2 % long (4 mm at 0.2 m, every ring
        # 0.8 mm off unless found), its noise and the shadows of a 55 mm baseline besides. Left
        # free, the fit ran to a camera at its aim point with a tenfold scale, every point
        # collapsed onto the board (rings 60-160 mm off).
        env, o = rgbd_cameras(seed=5, randomize=os.path.join(ROOT, "scenario", "ranges",
                                                             "depth.yaml"))
        drawn = env.reset(seed=5)[1]["variation"]
        self.assertEqual(drawn["depth_scale"], 1.02)
        true = o["state"][imitation.RINGS].reshape(6, 3)
        layout = raven_sim.peg_layout()
        for arm in (0, 1):
            found = board_calibration.calibrate(TaskCamera(**raven_sim.task_camera(arm)),
                                                o[vision.image_key(arm)],
                                                o[rgbd_policy.depth_key(arm)], layout,
                                                rgbd_policy.POSTS)
            self.assertAlmostEqual(found.depth_scale, drawn["depth_scale"], delta=0.001)
            rows = rgbd_policy.RING_ROWS[arm]
            tracker = RingTracker(found, RingShape.of_layout(layout), true[rows],
                                  rgbd_policy.POSTS)
            seen = tracker.update(o[vision.image_key(arm)], o[rgbd_policy.depth_key(arm)])
            self.assertLess(np.linalg.norm(seen - true[rows], axis=1).max(), 2e-4, arm)


class ShippedRgbdPolicy(unittest.TestCase):
    def test_the_shipped_rgbd_policy_places_rings_on_an_unseen_seed(self):
        import torch
        torch.set_num_threads(1)
        rgbd_cameras(seed=57, size=(16, 12))  # skips without headless OpenGL
        # On the default twin (the Raven-II's motor-level actuation); its state policy's
        # demonstrations ran on seeds 1000-1029 and 2000-2029.
        placed, line = learn.evaluate_seed(vision.load_policy(SHIPPED_RGBD), 57, 120.0)
        self.assertGreaterEqual(placed, 3, line)


if __name__ == "__main__":
    unittest.main()
