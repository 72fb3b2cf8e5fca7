"""A cloned policy on a Raven-II over ROS (`python3 -m raven_sim.learn run`): the robot reached
through raven_sim.RobotOverRos, the same client, controller, caps and limits as the gamepad path,
on the wall clock; an image policy sees the cameras' topics (an RGB-D one their depth topics as
well), a state policy the rings' pose topics. The run is judged by the rings' topics where there are some (the twin node's), else by
what the cameras show (the policy's own ring locator).
"""

import sys

import numpy as np

from ._raven_sim import RobotOverRos, ring_placed
from .imitation import LAYOUT
from .rgbd_policy import RgbdPolicy, depth_key
from .vision import CAMERAS, SeeingPolicy, image_key, load_policy

TWIN_SCENE = "/peg_transfer/"  # the twin node's peg-transfer scene: its objects' topics


def twin_camera_topic(namespace, camera, depth=False):
    """The twin node's topic of a named camera's colour (or depth) images (raven_twin_node
    --cameras, --camera-depth)."""
    kind = "depth/image_raw" if depth else "image_raw"
    return f"{namespace.rstrip('/')}/cameras/{camera.replace('-', '_')}/{kind}"


def fitted(image, size):
    """`image` (H, W, 3) or a depth image (H, W) at the policy's (W, H): sampled at the nearest
    pixels when a camera gives another size."""
    width, height = size
    if image.shape[:2] == (height, width):
        return image
    rows = (np.arange(height) + 0.5) * image.shape[0] / height
    cols = (np.arange(width) + 0.5) * image.shape[1] / width
    return image[rows.astype(int)][:, cols.astype(int)]


def rings_on_targets(rings):
    """How many of six ring centres (18 values) rest on their target posts."""
    return sum(bool(ring_placed(r, job["to"]))
               for r, job in zip(np.reshape(rings, (6, 3)), LAYOUT["jobs"]))


class Judge:
    """Counts the rings placed: from their topics, else from what the policy's cameras show."""

    def __init__(self, robot, policy):
        self.robot, self.policy = robot, policy

    def __call__(self, observation):
        placed = self.robot.placed()
        if placed is not None:
            return placed
        return rings_on_targets(self.policy.locate(observation))


def camera_topics(args, policy):
    """The colour topics of the two task cameras, then (an RGB-D policy) their depth topics."""
    twin = args.platform == "twin"
    cameras = args.camera_topics or (
        [twin_camera_topic(args.robot_namespace, c) for c in CAMERAS] if twin else None)
    if not cameras:
        sys.exit("run --platform physical with an image policy: --camera-topics LEFT RIGHT names "
                 "the robot's left and right task cameras")
    if not isinstance(policy, RgbdPolicy):
        return list(cameras)
    depths = args.depth_topics or (
        [twin_camera_topic(args.robot_namespace, c, depth=True) for c in CAMERAS] if twin else
        None)
    if not depths:
        sys.exit("run --platform physical with an RGB-D policy: --depth-topics LEFT RIGHT names "
                 "the task cameras' depth images")
    return list(cameras) + list(depths)


def connect(args, policy):
    """The robot, its rings' topics and its cameras as --platform and the flags say."""
    scene = args.scene_namespace if args.scene_namespace is not None else (
        TWIN_SCENE if args.platform == "twin" else None)
    sees = isinstance(policy, SeeingPolicy)
    if not sees and not scene:
        sys.exit("run: a state policy reads the rings' poses; --scene-namespace names their topics "
                 "(a tracker's), or run an image policy")
    return RobotOverRos(robot_namespace=args.robot_namespace, arm_swap=not args.no_arm_swap,
                        scene_namespace=scene or None,
                        camera_topics=camera_topics(args, policy) if sees else [],
                        connect_timeout=args.connect_timeout)


def observe(robot, policy, seen):
    """The policy's observation now: the state, and for an image policy each camera's first
    image taken in after `seen` (received() when the last step ended): the colour images, then
    an RGB-D policy's depth images."""
    observation = {"state": robot.observe()}
    if isinstance(policy, SeeingPolicy):
        keys = [image_key(arm) for arm in (0, 1)] + [depth_key(arm) for arm in (0, 1)]
        for key, image in zip(keys, robot.images(seen)):
            observation[key] = fitted(image, policy.image_size)
    return observation


def run(args):
    import torch
    torch.set_num_threads(1)
    policy = load_policy(args.policy).fresh()
    robot = connect(args, policy)
    robot.make_ready()
    start = robot.time
    judge = Judge(robot, policy)
    observation = observe(robot, policy, robot.received())
    placed = judge(observation)
    print(f"ready at t = {start:.1f} s; {placed} rings on their target posts", flush=True)
    steps = refused = 0
    while placed < 6 and robot.time - start < args.time_limit:
        if args.max_steps is not None and steps >= args.max_steps:
            break
        steps += 1
        refused_now, faulted = robot.step(policy.act(observation))
        refused += refused_now
        observation = observe(robot, policy, robot.received())
        now = judge(observation)
        if now != placed:
            print(f"t = {robot.time - start:.1f} s: {now} rings placed", flush=True)
            placed = now
        if faulted:
            print(f"the robot e-stopped (FAULT) at t = {robot.time - start:.1f} s", flush=True)
            break
    print(f"{steps} steps in {robot.time - start:.1f} s, {refused} commands refused", flush=True)
    print(f"placed {placed} rings")
