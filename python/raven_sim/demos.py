"""Demonstrations in robomimic's HDF5 layout: data/demo_<k>/{actions, rewards, dones, obs/state},
each demo's num_samples, seed and scene draw (variation, JSON) as attributes, the environment's
arguments in data.attrs["env_args"] (JSON); besides, data/demo_<k>/waypoints: where the expert was heading,
relative to the current targets (the actions are these capped per step), and expert_jobs: per step
and arm, how many rings the operator had finished with (placed, or given up after its re-grasps).
Episodes are recorded by running a driver (the expert, a policy) while a labeller (the expert)
says what it should have done."""

import json

import numpy as np

from .env import PegTransferEnv, part
from .imitation import ACTION, JOBS_PER_ARM

ENV_KWARGS = {"action_type": ACTION, "randomize": True, "time_limit": 240.0}


def open_demos(path, env_kwargs, source, mode="w"):
    """The file's data group (created, or opened to append with mode="a")."""
    import h5py
    f = h5py.File(path, mode)
    if "data" in f:
        return f, f["data"]
    data = f.create_group("data")
    data.attrs["env_args"] = json.dumps({"env_name": "PegTransferEnv", "type": "raven_sim",
                                         "env_kwargs": env_kwargs})
    data.attrs["source"] = source
    data.attrs["total"] = 0
    return f, data


def stored(key):
    """Where observation `key` (e.g. an image key "cameras/left-task/rgb") is kept in a demo."""
    return f"obs/{key.replace('/', '_')}"


def write_demo(data, seed, observations, actions, waypoints, rewards, source, variation=None,
               expert_jobs=None):
    k = len(data.keys())
    demo = data.create_group(f"demo_{k}")
    demo.attrs["num_samples"] = len(actions)
    demo.attrs["seed"] = seed
    demo.attrs["source"] = source
    if variation is not None:  # the scene's draw, as reset's info["variation"] gives it
        demo.attrs["variation"] = json.dumps(variation)
    if isinstance(observations[0], dict):  # images besides the state: obs/<camera>_<kind>
        for key in observations[0]:
            array = np.stack([o[key] for o in observations])
            demo.create_dataset(stored(key), data=array,
                                compression="lzf" if array.ndim > 2 else None)
    else:
        demo.create_dataset("obs/state", data=np.asarray(observations, np.float64))
    demo.create_dataset("actions", data=np.asarray(actions, np.float64))
    demo.create_dataset("waypoints", data=np.asarray(waypoints, np.float64))
    demo.create_dataset("rewards", data=np.asarray(rewards, np.float64))
    if expert_jobs:  # per step and arm, the operator's jobs finished when it labelled the step
        demo.create_dataset("expert_jobs", data=np.asarray(expert_jobs, np.int64))
    dones = np.zeros(len(actions), np.int64)
    dones[-1] = 1
    demo.create_dataset("dones", data=dones)
    data.attrs["total"] = int(data.attrs["total"]) + len(actions)


def load_demos(path):
    """Per demo: its states, waypoints and the operator's jobs finished per step and arm (None
    where an earlier version recorded it without them)."""
    import h5py
    with h5py.File(path, "r") as f:
        demos = [f["data"][k] for k in sorted(f["data"].keys(), key=lambda k: int(k[5:]))]
        missing = [d.name for d in demos if "waypoints" not in d]
        if missing:
            raise ValueError(f"{path}: {missing[0]} has no waypoints (recorded by an earlier "
                             "version); record it again")
        return ([np.asarray(d["obs/state"]) for d in demos],
                [np.asarray(d["waypoints"]) for d in demos], [expert_jobs_of(d) for d in demos])


def expert_jobs_of(demo):
    """A demo's expert_jobs, or None where an earlier version recorded none."""
    return np.asarray(demo["expert_jobs"]) if "expert_jobs" in demo else None


def load_all(paths):
    """Every demo of every file: their states, waypoints and the operator's jobs."""
    states, waypoints, jobs = [], [], []
    for path in paths:
        s, w, j = load_demos(path)
        states += s
        waypoints += w
        jobs += j
    return states, waypoints, jobs


class Episode:
    """What one episode recorded: per step the observation, the expert's action and waypoint
    (if an expert labelled it) and the reward; the last step's info; the scene's draw."""

    def __init__(self):
        self.observations, self.actions, self.waypoints, self.rewards = [], [], [], []
        self.expert_jobs = []  # per labelled step, the operator's jobs finished per arm
        self.info = {}
        self.variation = {}  # reset's info["variation"]


def run_episode(env, seed, drive, expert=None, max_steps=None):
    """One episode: `drive(observation, label)` gives the executed action, the expert (if any)
    labels every step (`label`: its action, else None), until the episode ends, the expert has
    finished every job of both arms (it would only hold its targets), or after `max_steps`.
    Returns the Episode."""
    observation, started = env.reset(seed=seed)
    episode = Episode()
    episode.info = {"placed": env.core.placed}
    episode.variation = started["variation"]
    if expert is not None:
        expert.reset()
    while max_steps is None or len(episode.rewards) < max_steps:
        state = observation["state"] if isinstance(observation, dict) else observation
        label = None
        if expert is not None:
            label, waypoint = expert.act(state), expert.waypoint(state)
            jobs = env.expert_jobs_finished()
            if (jobs == JOBS_PER_ARM).all():
                break
            episode.actions.append(label)
            episode.waypoints.append(waypoint)
            episode.expert_jobs.append(jobs)
        episode.observations.append(observation)
        action = drive(observation, label)
        observation, reward, terminated, truncated, episode.info = env.step(action)
        episode.rewards.append(reward)
        if terminated or truncated:
            break
    return episode


def convert(ci_path, seed, out):
    """A gamepad session (the controller's ci file) replayed in the environment on its scene
    (`seed` of a randomised scene, or None for the nominal one), recorded as one demo (the
    actions: the joint deltas the pad's readings gave)."""
    from ._raven_sim import read_ci
    inputs = read_ci(ci_path)
    randomize = seed is not None
    pad = PegTransferEnv(action_type="pad", randomize=randomize, time_limit=1e9)
    observation, _ = pad.reset(seed=seed if randomize else 0)
    observations, actions, rewards = [], [], []
    info = {"placed": pad.core.placed}
    for row in inputs:
        before = observation[part("targets")].copy()
        observations.append(observation)
        observation, reward, terminated, truncated, info = pad.step(row)
        actions.append(observation[part("targets")] - before)
        rewards.append(reward)
        if terminated or truncated:
            break
    source = f"gamepad session {ci_path}"
    f, data = open_demos(out, {**ENV_KWARGS, "randomize": randomize}, source)
    # A pad's reading moves the targets once: its waypoint is its action.
    write_demo(data, seed if randomize else -1, observations, actions, actions, rewards, source)
    f.close()
    return len(actions), info["placed"]
