"""Learning in the twin: demonstrations, behaviour cloning, DAgger, evaluation.

    python3 -m raven_sim.learn record --episodes 40 --seeds 1000-1039 --out demos.hdf5
    python3 -m raven_sim.learn convert --ci session_ci.csv --seed 7 --out person.hdf5
    python3 -m raven_sim.learn train --demos demos.hdf5 --out bc_state.pt
    python3 -m raven_sim.learn dagger --policy bc_state.pt --episodes 10 --seeds 3000-3009 \\
        --collect dagger.hdf5
    python3 -m raven_sim.learn train --demos demos.hdf5 dagger.hdf5 --out bc_state.pt
    python3 -m raven_sim.learn evaluate --policy bc_state.pt --seeds 1-20
    python3 -m raven_sim.learn record --episodes 20 --seeds 3000-3019 --obs state,rgb \\
        --camera left-task,right-task --out images.hdf5
    python3 -m raven_sim.learn train --obs rgb --demos images.hdf5 --state-policy bc_state.pt \\
        --out bc_rgb.pt
    python3 -m raven_sim.learn join --image-policy bc_rgb.pt --state-policy bc_state.pt \\
        --out bc_rgb.pt
    python3 -m raven_sim.learn join --rgbd --state-policy bc_state.pt --out bc_rgbd.pt
    python3 -m raven_sim.learn locate --policy bc_rgb.pt --demos held_out.hdf5
    python3 -m raven_sim.learn run --policy bc_rgb.pt --platform twin   # a raven_twin_node

record: the main job's scripted operator on randomised scenes (one seed per episode), in small
steps (imitation.SteppedExpert), into robomimic's HDF5 layout (raven_sim.demos). The actions are
joint deltas (14, both arms' targets minus the current ones, left arm first), the waypoints where
the expert was heading (the actions capped per step); --obs state,rgb,... adds camera images
(--camera, --image-size). With --noise the
executed action carries Gaussian noise (DART, Laskey et al. 2017) while the label stays the
operator's, so the demonstrations show how to recover from small errors.

convert: a gamepad session on the twin (a ci file of the controller) replayed in the environment
on its scene, recorded in the same layout.

train: behaviour cloning, one multilayer perceptron for either arm from its imitation.ArmFeatures
to its waypoint (standardised, mean squared error, Adam), on the CPU. With --obs rgb: an image
policy (vision.ImagePolicy), a ring locator trained on the demos' task-camera images that the
state policy --state-policy acts through. With --rings-from IMAGE_POLICY: the acting part
trained on the rings that policy's locator sees in the demos' images (its errors included),
saved with that locator as an image policy.

join: an image policy's ring locator acting through another state policy (the locator only
sees rings; a state policy trained again needs no new locator). With --rgbd: the image policy
whose eyes are a model fit, not a network (rgbd_policy.RgbdPolicy: each ring's shape fitted to
what each arm's RGB-D task camera sees of it, raven_sim.ring_fit).

dagger: one round of DAgger (Ross et al. 2011): the policy drives on new seeds (the expert's
action instead with probability --beta) while the expert, taking up the task from each state
the policy reached, labels it; the episodes join --collect, and train on all the files gives
the next policy.

locate: how well an image policy's ring locator sees the rings of recorded demonstrations (their
task-camera images against the rings' recorded centres): the mean and 90th percentile error in
mm, per file (record held-out episodes under the looks to check, e.g. --randomize
scenario/ranges/looks.yaml).

evaluate: the policy (state or image) on randomised scenes (--workers episodes side by side); its
last line is
"placed N/M rings; K/E episodes all six". --ring-error MM shows a state policy every ring MM off
in the board's plane (each ring's direction drawn from the seed): how precisely the cameras of an
image policy acting through it must see the rings.

run: the policy on a Raven-II over ROS (raven_sim.RobotOverRos): the twin node in another process
(--platform twin: its rings' topics and its rendered cameras) or the physical robot (--platform
physical: its own topics, and --camera-topics for an image policy), through the same client,
controller, caps and limits as the gamepad path, on the wall clock. Its last line is
"placed N rings".
"""

import argparse
import sys

import numpy as np

from . import demos
from .env import OBSERVATIONS, PegTransferEnv
from .imitation import Policy, RingsSeenOff, SteppedExpert, fit
from .rgbd_policy import RgbdPolicy
from .robot import run
from .vision import KIND as IMAGE_POLICY
from .vision import (ImagePolicy, fit_locator, load_located, load_locator_samples,
                     load_policy, locator_of)

# DART's noise scale per joint (rad; the insertion m), times --noise.
NOISE_SCALE = np.array([0.004, 0.004, 0.0004, 0.02, 0.02, 0.02, 0.02] * 2)


def seed_range(text):
    """'A-B' (inclusive) or 'A' -> list of seeds."""
    try:
        if "-" in text:
            first, last = (int(x) for x in text.split("-", 1))
        else:
            first = last = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"seeds are A-B or A, not '{text}'") from None
    if last < first:
        raise argparse.ArgumentTypeError(f"seeds {text}: the last comes before the first")
    return list(range(first, last + 1))


def observation_keys(text):
    keys = [k.strip() for k in text.split(",") if k.strip()]
    for k in keys:
        if k not in OBSERVATIONS:
            raise argparse.ArgumentTypeError(f"observation '{k}': each one of {OBSERVATIONS}")
    if "state" not in keys:
        raise argparse.ArgumentTypeError("observations include 'state' (the expert's and the "
                                         "state policy's input)")
    return keys


def image_size(text):
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"an image size is WxH, not '{text}'") from None
    if w < 8 or h < 8:
        raise argparse.ArgumentTypeError(f"image size {text}: at least 8x8")
    return w, h


def bounded(kind, low, high=None, above=False):
    """An argparse type: a finite `kind` (int or float) at least `low` (above: more than it) and at
    most `high`. float() reads 'nan' and 'inf', which no option here means."""
    what = (("a whole number" if kind is int else "a finite number") + (" > " if above else " >= ")
            + f"{low:g}" + ("" if high is None else f" and <= {high:g}"))

    def read(text):
        try:
            value = kind(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"'{text}' is not {what}") from None
        fits = np.isfinite(value) and (value > low if above else value >= low) and (
            high is None or value <= high)
        if not fits:
            raise argparse.ArgumentTypeError(f"'{text}' is not {what}")
        return value

    return read


COUNT = bounded(int, 1)  # episodes, steps, workers, threads, layers: at least one
POSITIVE = bounded(float, 0.0, above=True)  # a time, a rate
NON_NEGATIVE = bounded(float, 0.0)  # a noise, a distance


def enough_seeds(args):
    if len(args.seeds) < args.episodes:
        sys.exit(f"{args.command}: {args.episodes} episodes need as many seeds, "
                 f"got {len(args.seeds)}")


def collect(env, expert, seeds, drive, data, source, max_steps=None, policy=None):
    """Episodes on `seeds`, `drive(observation, label)` acting and the expert labelling, into
    `data`; prints each and returns the rings placed. `policy` (if any) starts each episode
    afresh."""
    placed = 0
    for seed in seeds:
        if policy is not None:
            policy.reset()
        placed += store(data, seed, demos.run_episode(env, seed, drive, expert, max_steps), source)
    return placed


def store(data, seed, episode, source):
    """Writes `episode` (of `seed`) into `data`, prints it, and returns the rings it placed."""
    demos.write_demo(data, seed, episode.observations, episode.actions, episode.waypoints,
                     episode.rewards, source, episode.variation, episode.expert_jobs)
    placed = episode.info["placed"]
    print(f"seed {seed}: {len(episode.rewards)} steps, placed {placed}/6", flush=True)
    return placed


def record_seed(kwargs, seed, noise, noise_seed, max_steps):
    """One demonstration on `seed`'s scene in its own environment, its DART noise drawn from
    (noise_seed, seed): the same episode whichever worker runs it, and beside which others."""
    env = PegTransferEnv(**kwargs)
    rng = np.random.default_rng([noise_seed, seed])

    def noisy(_, label):
        return label + rng.normal(0.0, 1.0, label.shape) * NOISE_SCALE * noise

    return demos.run_episode(env, seed, noisy, SteppedExpert(env), max_steps)


def record(args):
    """Demonstrations on --workers threads (the twin steps without Python's lock), written to
    the file in seed order by this thread alone."""
    from concurrent.futures import ThreadPoolExecutor
    enough_seeds(args)
    if args.workers < 1:
        sys.exit(f"record: --workers {args.workers}: at least one")
    kwargs = {**demos.ENV_KWARGS, "actuation": args.actuation, "randomize": args.randomize}
    if args.obs != ["state"]:
        kwargs = {**kwargs, "obs": args.obs, "camera": args.camera.split(","),
                  "image_size": args.image_size}
    source = f"expert, DART noise {args.noise}"
    f, data = demos.open_demos(args.out, kwargs, source)
    seeds = args.seeds[:args.episodes]
    with ThreadPoolExecutor(args.workers) as pool:
        episodes = pool.map(
            lambda seed: record_seed(kwargs, seed, args.noise, args.noise_seed, args.max_steps),
            seeds)
        placed = sum(store(data, seed, e, source) for seed, e in zip(seeds, episodes))
    total = int(data.attrs["total"])
    f.close()
    print(f"{args.episodes} demonstrations, {total} steps, placed {placed}/{6 * args.episodes}: "
          f"{args.out}")


def convert(args):
    steps, placed = demos.convert(args.ci, args.seed, args.out)
    print(f"{args.ci}: {steps} steps, placed {placed}/6: {args.out}")


def train(args):
    import torch
    torch.set_num_threads(args.threads)
    if args.obs == "rgb":
        return train_image_policy(args)
    start = Policy.load(args.init) if args.init else None
    if start is not None and args.hold_gate and not start.gated:
        sys.exit(f"train --hold-gate: {args.init} has no hold gate to go on training")
    locator = None
    if args.rings_from:  # the acting part of an image policy, on the rings its locator sees
        saved = torch.load(args.rings_from)
        if saved.get("kind") != IMAGE_POLICY:
            sys.exit(f"train --rings-from: {args.rings_from} is not an image policy")
        locator = locator_of(saved)
        states, waypoints, jobs = load_located(args.demos, locator)
    else:
        states, waypoints, jobs = demos.load_all(args.demos)
    policy, samples, seconds = fit(states, waypoints, [args.width] * args.layers, args.epochs,
                                   args.batch, args.lr, args.seed, start=start, expert_jobs=jobs,
                                   gated=args.hold_gate)
    if locator is not None:
        policy = ImagePolicy(locator, policy, saved["image_size"])
    policy.save(args.out, demos=args.demos, samples=samples, seconds=seconds,
                rings_from=args.rings_from)
    print(f"trained on {len(states)} demonstrations, {samples} steps, in {seconds:.0f} s: "
          f"{args.out}")


def train_image_policy(args):
    """The ring locator on the demos' task-camera images, joined to the state policy."""
    if not args.state_policy:
        sys.exit("train --obs rgb: --state-policy names the state policy that acts on the rings "
                 "the images show")
    start = None
    if args.init:  # go on training an image policy's locator
        import torch
        saved = torch.load(args.init)
        if saved.get("kind") != IMAGE_POLICY:
            sys.exit(f"train --obs rgb --init: {args.init} is not an image policy")
        start = locator_of(saved)
    images, rings = load_locator_samples(args.demos)
    size = (images.shape[3], images.shape[2])
    print(f"{len(images)} arm images of {size[0]}x{size[1]}", flush=True)
    locator, error, seconds = fit_locator(images, rings, args.epochs, args.batch, args.lr,
                                          args.seed, start=start)
    policy = ImagePolicy(locator, Policy.load(args.state_policy), size)
    policy.save(args.out, demos=args.demos, samples=len(images), seconds=seconds,
                state_policy=args.state_policy, ring_error_mm=error)
    print(f"trained the ring locator on {len(images)} arm images in {seconds:.0f} s (last "
          f"epoch's ring error {error:.2f} mm), with {args.state_policy}: {args.out}")


def join(args):
    """An image policy's ring locator, or the RGB-D ring fit (--rgbd), acting through a state
    policy: the eyes see rings, whatever acts on them."""
    import torch
    if args.rgbd:
        joined = RgbdPolicy(Policy.load(args.state_policy))
        joined.save(args.out, state_policy=args.state_policy)
        print(f"rings fitted in the RGB-D task cameras with {args.state_policy}: {args.out}")
        return
    saved = torch.load(args.image_policy)
    if saved.get("kind") != IMAGE_POLICY:
        sys.exit(f"join: {args.image_policy} is not an image policy (train --obs rgb makes one)")
    joined = ImagePolicy(locator_of(saved), Policy.load(args.state_policy), saved["image_size"])
    joined.save(args.out, state_policy=args.state_policy, locator_of=args.image_policy)
    print(f"the ring locator of {args.image_policy} with {args.state_policy}: {args.out}")


def locate(args):
    """The ring locator's error on each file's images, in mm."""
    import torch
    single_threaded()
    saved = torch.load(args.policy)
    if saved.get("kind") != IMAGE_POLICY:
        sys.exit(f"locate: {args.policy} is not an image policy")
    locator = locator_of(saved)
    for path in args.demos:
        images, rings = load_locator_samples([path])
        with torch.no_grad():
            seen = torch.cat([locator(torch.as_tensor(images[i:i + 256]))
                              for i in range(0, len(images), 256)]).numpy()
        errors = np.linalg.norm((seen - rings).reshape(-1, 3, 3), axis=2).ravel()
        print(f"{path}: {len(errors)} rings in {len(images)} arm images: mean error "
              f"{errors.mean():.2f} mm, 90 % within {np.percentile(errors, 90):.2f} mm")


def single_threaded():
    """A small network's inference is fastest on one thread, and leaves the others free."""
    import torch
    torch.set_num_threads(1)


def dagger(args):
    enough_seeds(args)
    single_threaded()
    rng = np.random.default_rng(args.noise_seed)
    policy = load_policy(args.policy)
    # An image policy's episodes keep its camera images: its ring locator learns from them.
    kwargs = {**demos.ENV_KWARGS, **policy.env_kwargs, "actuation": args.actuation,
              "randomize": args.randomize}
    env = PegTransferEnv(**kwargs)

    def drive(observation, label):
        action = policy.act(observation)  # every step: the policy keeps its memory
        return label if rng.random() < args.beta else action

    f, data = demos.open_demos(args.collect, kwargs, "DAgger", mode="a")
    # The policy steers: the operator answers from the state it reached, not from its own plan.
    expert = SteppedExpert(env, from_state=True)
    placed = collect(env, expert, args.seeds[:args.episodes], drive, data,
                     f"DAgger: {args.policy} driving, beta {args.beta}", args.max_steps, policy)
    f.close()
    print(f"the policy (beta {args.beta}) placed {placed}/{6 * args.episodes}; the expert's "
          f"labels joined {args.collect}")


def drawn(variation):
    """What a scene's draw varied, in a few words (reset's info["variation"])."""
    if variation.get("nominal", True):
        return "the nominal scene"
    words = (f"rings Shore A {variation['ring_shore_a']:.1f}, kDF {variation['ring_kDF']:.2f}, "
             f"board friction {variation['board_friction']:.2f}, "
             f"motors within {variation['actuation_sd']:g} sd of the fit")
    if (variation.get("depth_noise_m", 0.0), variation.get("depth_scale", 1.0),
            variation.get("depth_baseline_m", 0.0)) != (0.0, 1.0, 0.0):
        words += (f", depth x{variation['depth_scale']:.3f} with "
                  f"{1e3 * variation['depth_noise_m']:.1f} mm at 1 m, "
                  f"a {1e3 * variation['depth_baseline_m']:.0f} mm baseline")
    return words


def evaluate_seed(policy, seed, time_limit, actuation="motors", randomize=True, launch_file=None,
                  ring_error=0.0):
    """One episode of the policy on `seed`'s scene (of `launch_file`, else the shipped one):
    (rings placed, a line saying how it went and on what scene). `ring_error` (m, a state policy):
    every ring seen that far off (imitation.RingsSeenOff)."""
    policy = policy.fresh()  # its own memory of the episode: episodes may run side by side
    if ring_error > 0.0:
        policy = RingsSeenOff(policy, ring_error, seed)
    env = PegTransferEnv(**{**demos.ENV_KWARGS, **policy.env_kwargs, "time_limit": time_limit,
                            "actuation": actuation, "randomize": randomize,
                            "launch_file": launch_file})
    episode = demos.run_episode(env, seed, lambda observation, _: policy.act(observation))
    info = episode.info
    why = f" (the world failed: {info['failure']})" if "failure" in info else ""
    seen = f"; rings seen {ring_error * 1000:g} mm off" if ring_error > 0.0 else ""
    return info["placed"], (f"seed {seed}: placed {info['placed']}/6 in {env.core.time:.0f} s"
                            f"{why}; {drawn(episode.variation)}{seen}")


def evaluate(args):
    """Episodes on threads (the twin steps without Python's lock), printed in seed order."""
    from concurrent.futures import ThreadPoolExecutor
    single_threaded()
    policy = load_policy(args.policy)
    if args.ring_error > 0.0 and not isinstance(policy, Policy):
        sys.exit(f"--ring-error: {args.policy} is an image policy; it takes a state policy")
    with ThreadPoolExecutor(args.workers) as pool:
        runs = pool.map(lambda seed: evaluate_seed(policy, seed, args.time_limit, args.actuation,
                                                   args.randomize,
                                                   ring_error=args.ring_error / 1000.0),
                        args.seeds)
        placed = []
        for rings, line in runs:
            placed.append(rings)
            print(line, flush=True)
    print(f"placed {sum(placed)}/{6 * len(args.seeds)} rings; "
          f"{sum(p == 6 for p in placed)}/{len(args.seeds)} episodes all six")


def add_randomize(parser):
    scene = parser.add_mutually_exclusive_group()
    scene.add_argument("--randomize", nargs="?", const=True, default=True, metavar="RANGES.yaml",
                       help="each episode's scene drawn from its seed (the default): from the "
                            "shipped ranges, or from RANGES.yaml's (ring_offset, ring_kDF, "
                            "ring_shore_a, board_friction; docs/learning.md)")
    scene.add_argument("--nominal", dest="randomize", action="store_false",
                       help="the nominal scene in every episode (the seed still seeds the "
                            "episode's noise)")


def add_actuation(parser):
    parser.add_argument("--actuation", choices=["motors", "ideal"], default="motors",
                        help="what drives the twin's joints: motors (the Raven-II's motor-level "
                             "actuation, the default) or ideal (ideal joint servos)")


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m raven_sim.learn", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("record", help="the expert's demonstrations (HDF5)")
    p.add_argument("--episodes", type=COUNT, required=True)
    p.add_argument("--seeds", type=seed_range, required=True, help="A-B: one per episode")
    p.add_argument("--obs", type=observation_keys, default=["state"],
                   help="state and any of rgb, depth, segmentation (stored as obs/<camera>_<kind>)")
    p.add_argument("--camera", default="overview",
                   help="the images' views, comma-separated (e.g. grasper-left,left-task)")
    p.add_argument("--image-size", type=image_size, default=(128, 96), help="WxH")
    p.add_argument("--max-steps", type=COUNT, help="an episode's steps at most")
    p.add_argument("--noise", type=NON_NEGATIVE, default=0.0, help="DART noise, times NOISE_SCALE")
    p.add_argument("--noise-seed", type=int, default=0,
                   help="with the episode's seed, seeds its noise")
    p.add_argument("--workers", type=COUNT, default=2, help="episodes recorded side by side")
    p.add_argument("--out", required=True)
    add_actuation(p)
    add_randomize(p)
    p.set_defaults(run=record)
    p = sub.add_parser("convert", help="a gamepad session's ci file replayed into HDF5")
    p.add_argument("--ci", required=True)
    p.add_argument("--seed", type=int,
                   help="the randomised scene the session ran on (default: the nominal scene, "
                        "as raven_controller's peg-transfer twin)")
    p.add_argument("--out", required=True)
    p.set_defaults(run=convert)
    p = sub.add_parser("train", help="behaviour cloning on the CPU")
    p.add_argument("--demos", required=True, nargs="+", help="one or more HDF5 files")
    p.add_argument("--out", required=True)
    p.add_argument("--width", type=COUNT, default=256)
    p.add_argument("--layers", type=COUNT, default=3)
    p.add_argument("--epochs", type=COUNT, default=30)
    p.add_argument("--batch", type=COUNT, default=512)
    p.add_argument("--lr", type=POSITIVE, default=2e-3)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--threads", type=COUNT, default=2, help="torch's CPU threads")
    p.add_argument("--hold-gate", action="store_true",
                   help="a state policy that also learns whether the operator holds each arm, "
                        "and regresses only the waypoints it moves to (imitation.fit)")
    p.add_argument("--init", help="a policy to go on training (its network and scaling; with "
                   "--obs rgb an image policy, whose ring locator goes on training)")
    p.add_argument("--obs", choices=["state", "rgb"], default="state",
                   help="rgb: an image policy (vision.ImagePolicy): a ring locator trained on "
                        "the demos' task-camera images, acting through --state-policy "
                        "(scripts/retrain-image-policy.sh: --epochs 16 --batch 128 --lr 1e-3)")
    p.add_argument("--state-policy", help="with --obs rgb: the state policy that acts")
    p.add_argument("--rings-from", metavar="IMAGE_POLICY",
                   help="with --obs state: train on the rings this image policy's locator sees "
                        "in the demos' task-camera images instead of the recorded ones, and save "
                        "an image policy (that locator acting through what was trained)")
    p.set_defaults(run=train)
    p = sub.add_parser("join", help="an image policy's eyes with another state policy")
    eyes = p.add_mutually_exclusive_group(required=True)
    eyes.add_argument("--image-policy", help="the image policy whose ring locator is kept")
    eyes.add_argument("--rgbd", action="store_true",
                      help="rings fitted in each arm's RGB-D task camera (rgbd_policy.RgbdPolicy)")
    p.add_argument("--state-policy", required=True, help="the state policy that acts")
    p.add_argument("--out", required=True)
    p.set_defaults(run=join)
    p = sub.add_parser("locate", help="an image policy's ring error on recorded images")
    p.add_argument("--policy", required=True, help="the image policy whose locator is measured")
    p.add_argument("--demos", nargs="+", required=True, help="demonstrations with task images")
    p.set_defaults(run=locate)
    p = sub.add_parser("dagger", help="a DAgger round: the policy drives, the expert labels")
    p.add_argument("--policy", required=True, help="the policy that drives")
    p.add_argument("--episodes", type=COUNT, required=True)
    p.add_argument("--seeds", type=seed_range, required=True, help="A-B: one per episode")
    p.add_argument("--beta", type=bounded(float, 0.0, 1.0), default=0.0,
                   help="the share of steps the expert drives instead")
    p.add_argument("--noise-seed", type=int, default=0)
    p.add_argument("--max-steps", type=COUNT, default=1500,
                   help="an episode's steps at most (the expert needs 500-900)")
    p.add_argument("--collect", required=True, help="the HDF5 file the episodes join")
    add_actuation(p)
    add_randomize(p)
    p.set_defaults(run=dagger)
    p = sub.add_parser("evaluate", help="the policy on randomised scenes")
    p.add_argument("--policy", required=True)
    p.add_argument("--seeds", type=seed_range, required=True)
    p.add_argument("--time-limit", type=POSITIVE, default=240.0)
    p.add_argument("--workers", type=COUNT, default=1, help="episodes run side by side")
    p.add_argument("--ring-error", type=NON_NEGATIVE, default=0.0, metavar="MM",
                   help="a state policy sees every ring this far off in the board's plane, each "
                        "in its own direction drawn from the seed: the camera precision it needs")
    add_actuation(p)
    add_randomize(p)
    p.set_defaults(run=evaluate)
    p = sub.add_parser("run", help="the policy on a Raven-II over ROS (a twin node or the robot)")
    p.add_argument("--policy", required=True)
    p.add_argument("--platform", choices=["twin", "physical"], required=True,
                   help="twin: a raven_twin_node serving the peg-transfer scene with --cameras "
                        "(and --camera-depth for an RGB-D policy; its rings' topics judge the "
                        "run); physical: the robot's own topics")
    p.add_argument("--robot-namespace", default="", help="the robot's (or node's) namespace")
    p.add_argument("--camera-topics", nargs=2, metavar=("LEFT", "RIGHT"),
                   help="the left and right arms' task cameras (sensor_msgs/Image; default on "
                        "the twin: <namespace>/cameras/left_task/image_raw and right_task)")
    p.add_argument("--depth-topics", nargs=2, metavar=("LEFT", "RIGHT"),
                   help="for an RGB-D policy, the same cameras' depth images (sensor_msgs/Image "
                        "32FC1 m or 16UC1 mm, registered to the colour images; default on the "
                        "twin: <namespace>/cameras/left_task/depth/image_raw and right_task)")
    p.add_argument("--scene-namespace",
                   help="where the rings' poses are (AMBF's <ns><ring>/State; default on the "
                        "twin: /peg_transfer/; none on the robot: the cameras judge)")
    p.add_argument("--no-arm-swap", action="store_true",
                   help="each arm on its own measured_js (upstream swaps them)")
    p.add_argument("--time-limit", type=POSITIVE, default=240.0, help="s of the robot's clock")
    p.add_argument("--max-steps", type=COUNT, help="steps at most (default: the time limit's)")
    p.add_argument("--connect-timeout", type=POSITIVE, default=10.0,
                   help="wall s to find the topics")
    p.set_defaults(run=run)
    args = parser.parse_args(argv)
    args.run(args)


if __name__ == "__main__":
    main()
