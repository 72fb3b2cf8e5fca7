"""Demonstrations in robomimic's HDF5 layout: data/demo_<k>/{actions, rewards, dones, obs/state},
each demo's num_samples and seed as attributes, the environment's arguments in
data.attrs["env_args"] (JSON). Episodes are recorded by running a driver (the expert, a policy)
while a labeller (the expert) says what it should have done."""

import json

import numpy as np

from .env import PegTransferEnv
from .imitation import ACTION

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


def write_demo(data, seed, observations, actions, rewards, source):
    k = len(data.keys())
    demo = data.create_group(f"demo_{k}")
    demo.attrs["num_samples"] = len(actions)
    demo.attrs["seed"] = seed
    demo.attrs["source"] = source
    demo.create_dataset("obs/state", data=np.asarray(observations, np.float64))
    demo.create_dataset("actions", data=np.asarray(actions, np.float64))
    demo.create_dataset("rewards", data=np.asarray(rewards, np.float64))
    dones = np.zeros(len(actions), np.int64)
    dones[-1] = 1
    demo.create_dataset("dones", data=dones)
    data.attrs["total"] = int(data.attrs["total"]) + len(actions)


def load_demos(path):
    """Per demo: its states and actions."""
    import h5py
    with h5py.File(path, "r") as f:
        demos = [f["data"][k] for k in sorted(f["data"].keys(), key=lambda k: int(k[5:]))]
        return ([np.asarray(d["obs/state"]) for d in demos],
                [np.asarray(d["actions"]) for d in demos])


def load_all(paths):
    """Every demo of every file: their states and actions."""
    states, actions = [], []
    for path in paths:
        s, a = load_demos(path)
        states += s
        actions += a
    return states, actions


def run_episode(env, seed, drive, label, max_steps=None):
    """One episode: `drive(state, label)` gives the executed action, `label(state)` the
    recorded one (called every step), until it ends or after `max_steps`. Returns observations,
    labels, rewards, the last info."""
    state, _ = env.reset(seed=seed)
    observations, labels, rewards = [], [], []
    info = {"placed": env.core.placed}
    while max_steps is None or len(labels) < max_steps:
        wanted = label(state)
        observations.append(state)
        labels.append(wanted)
        state, reward, terminated, truncated, info = env.step(drive(state, wanted))
        rewards.append(reward)
        if terminated or truncated:
            break
    return observations, labels, rewards, info


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
        before = observation[14:28].copy()  # the commanded targets
        observations.append(observation)
        observation, reward, terminated, truncated, info = pad.step(row)
        actions.append(observation[14:28] - before)
        rewards.append(reward)
        if terminated or truncated:
            break
    source = f"gamepad session {ci_path}"
    f, data = open_demos(out, {**ENV_KWARGS, "randomize": randomize}, source)
    write_demo(data, seed if randomize else -1, observations, actions, rewards, source)
    f.close()
    return len(actions), info["placed"]
