"""A task camera's pose found from what it sees of the board: the board's top and the posts that
stand on it, in its depth image. A camera mounted again by hand sits a few millimetres and a
degree or two from where it was calibrated, and a ring seen through the old calibration is
several millimetres off; the board and its posts do not move, so an episode's first depth image
says where the camera is.

The pose (the point it aims at, in the calibrated aim point's horizontal plane, the camera's yaw
and pitch and its distance from that point; its roll and field of view are taken as calibrated)
is fitted by robust least squares so that every pixel, taken back into the world through it,
lies on the board's top or on a post. The rings' pixels are left out (a ring around a post
would pull the camera onto it); pixels of anything else (the arms, the background) lie on
neither and count little (soft L1, its scale narrowed from 5 mm to 0.5 mm as the fit closes
in). Only the posts fix the camera across the board, and they are narrow: their points weigh
more, and the fit starts from the calibration and from poses around it, the cheapest kept.

Then the depth's scale is fitted with the pose, from the best pose: a stereo camera's depth is
off by up to 2 % (Intel's figure for its D400 series), 4 mm at the task cameras' 0.2 m, which
moves every ring 0.8 mm; the posts, spread across the image, tell a longer depth from a camera
moved back. Every parameter is held within what a camera mounted again by hand and a depth
camera's bias can be: the board's top alone looks the same from any yaw about the aim point, and
a far pose can fit it as well as the right one.
"""

import itertools
import math

import numpy as np

from .ring_fit import TaskCamera, ring_pixels

POST_WEIGHT = 5.0  # a point on a post counts this many times one on the board's top
# m: the soft L1 scales, coarse to fine (a camera a few millimetres off sees the posts that far)
ROBUST_SCALES = (0.005, 0.0015, 0.0005)
# the parameters' sizes: m, m, rad, rad, m and the depth's scale
SCALES = np.array([0.001, 0.001, 0.01, 0.01, 0.001, 0.01])
FAR = 0.02  # m: a point farther than this from the board's top and every post is not the board's
# The starts around the calibration: the aim point this far along x and y and the view turned
# this much, each either way (as far as a camera mounted again by hand moves).
START_SHIFT = 0.003  # m
START_TURN = 0.03  # rad
# How far the fit may take the camera's distance and its depth's scale from the calibration's
# (factors), its aim point and its view. Unbounded, the scale and the distance ran off to where
# every point collapses onto one point of the board (a distance of 0 and a scale of 10), and in
# a dark scene the view turned 4 rad round its aim point (rings 30-70 mm off).
DISTANCE_RANGE = (0.8, 1.25)
DEPTH_SCALE_RANGE = (0.95, 1.05)
REACH = 0.02  # m: the aim point within this of the calibration's, on each axis
TURN = 0.2  # rad: the yaw and the pitch within this of the calibration's


def camera_at(target, yaw, pitch, distance, fov_y, depth_scale=1.0):
    """The camera looking at `target` from `distance` along yaw and pitch (viewer::Camera's
    angles: the eye lies at the target plus distance (cos p cos y, cos p sin y, sin p))."""
    back = np.array([math.cos(pitch) * math.cos(yaw), math.cos(pitch) * math.sin(yaw),
                     math.sin(pitch)])
    return TaskCamera(np.asarray(target) + distance * back, target, fov_y, depth_scale)


def angles_of(camera):
    """The yaw and pitch of a TaskCamera's view."""
    back = -camera.forward
    return math.atan2(back[1], back[0]), math.asin(back[2])


def scene_distances(points, board_top, posts, post_radius, post_height):
    """Each point's distance from the board's top or the nearest post (its side or its top),
    whichever is nearer (m), a post's weighted by POST_WEIGHT, at most FAR."""
    best = np.abs(points[:, 2] - board_top)
    top = board_top + post_height
    for x, y in posts:
        across = np.hypot(points[:, 0] - x, points[:, 1] - y)
        side = np.abs(across - post_radius) + np.maximum(points[:, 2] - top, 0.0)
        cap = np.abs(points[:, 2] - top) + np.maximum(across - post_radius, 0.0)
        post = np.minimum(side, cap)
        near = (points[:, 2] > board_top + 0.001) & (post < best)
        best = np.where(near, POST_WEIGHT * post, best)
    return np.minimum(best, FAR)


def calibrate(camera, rgb, depth, layout, posts):
    """`camera` (the calibration: a TaskCamera with its target) moved, and its depth's scale
    found, to where its colour and depth images (H, W, 3 and H, W: m along the axis) show the board (`layout`:
    raven_sim.peg_layout(), with the posts' height and radius) and its `posts` (P, 2) to be."""
    from scipy.optimize import least_squares
    depth = np.asarray(depth, dtype=np.float64)
    ring = ring_pixels(rgb)
    ring[1:, :] |= ring[:-1, :].copy()  # and the pixels beside them: a ring's edge
    ring[:-1, :] |= ring[1:, :].copy()
    ring[:, 1:] |= ring[:, :-1].copy()
    ring[:, :-1] |= ring[:, 1:].copy()
    every = ~ring
    height = camera.target[2]

    def at(x):
        return camera_at([x[0], x[1], height], x[2], x[3], x[4], camera.fov_y, x[5])

    def residuals(x):
        return scene_distances(at(x).points(depth, every), layout["board_top"], posts,
                               layout["post_radius"], layout["post_height"])

    def fitted(x, free, within):
        """`x` with its first `free` parameters fitted, coarse to fine, the rest held."""
        def partial(y):
            return residuals(np.concatenate([y, x[free:]]))
        y = x[:free]
        for scale in ROBUST_SCALES:
            fit = least_squares(partial, y, bounds=within, loss="soft_l1", f_scale=scale,
                                x_scale=SCALES[:free], max_nfev=100)
            y = fit.x
        return fit.cost, np.concatenate([y, x[free:]])

    calibrated = np.array([camera.target[0], camera.target[1], *angles_of(camera),
                           np.linalg.norm(camera.eye - camera.target), camera.depth_scale])
    reach = np.array([REACH, REACH, TURN, TURN])
    bounds = (np.concatenate([calibrated[:4] - reach, [calibrated[4] * DISTANCE_RANGE[0],
                                                       DEPTH_SCALE_RANGE[0]]]),
              np.concatenate([calibrated[:4] + reach, [calibrated[4] * DISTANCE_RANGE[1],
                                                       DEPTH_SCALE_RANGE[1]]]))
    starts = [calibrated] + [
        calibrated + np.array([sx * START_SHIFT, sy * START_SHIFT, yaw * START_TURN, 0, 0, 0])
        for sx, sy, yaw in itertools.product((-1, 1), repeat=3)]
    # The pose first, the depth's scale held as calibrated, then both from the best pose (the
    # scale free from every start put one camera of 20 scenes at the ranges' edges 42 mm off).
    pose_bounds = (bounds[0][:5], bounds[1][:5])
    _, pose = min((fitted(start, 5, pose_bounds) for start in starts), key=lambda fit: fit[0])
    _, best = fitted(pose, 6, bounds)
    return at(best)
