"""Learning in the twin: demonstrations, behaviour cloning, evaluation.

    python3 -m raven_sim.learn record --episodes 40 --seeds 1000-1039 --out demos.hdf5
    python3 -m raven_sim.learn convert --ci session_ci.csv --seed 7 --out person.hdf5
    python3 -m raven_sim.learn train --demos demos.hdf5 --out bc_state.pt
    python3 -m raven_sim.learn evaluate --policy bc_state.pt --seeds 1-20

record: the main job's scripted operator on randomised scenes (one seed per episode), in
robomimic's HDF5 layout: data/demo_<k>/{actions, rewards, dones, obs/state}, the environment's
arguments in data.attrs["env_args"] (JSON). The actions are joint deltas (14, both arms' targets
minus the current ones, left arm first). With --noise the executed action carries Gaussian noise
(DART, Laskey et al. 2017) while the label stays the operator's, so the demonstrations show how
to recover from the small errors a learnt policy makes.

convert: a gamepad session on the twin (a ci file of the controller) replayed in the environment
on its scene (the nominal one, or a randomised scene's seed), recorded in the same layout (the
actions: the joint deltas the pad's readings gave).

train: behaviour cloning, a multilayer perceptron from the state and the previous action to the
next action (inputs and outputs standardised, mean squared error, Adam), on the CPU.

evaluate: the policy on randomised scenes; its last line is
"placed N/M rings; K/E episodes all six".
"""

import argparse
import json
import sys
import time

import numpy as np

from .env import PegTransferEnv

ACTION = "joint_deltas"
ENV_KWARGS = {"action_type": ACTION, "randomize": True, "time_limit": 240.0}
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
        if k != "state":
            raise argparse.ArgumentTypeError(
                f"observation '{k}': only 'state' is recorded so far (camera observations are "
                "not in the environment yet)")
    return keys


def write_demo(group, k, seed, observations, actions, rewards):
    demo = group.create_group(f"demo_{k}")
    demo.attrs["num_samples"] = len(actions)
    demo.attrs["seed"] = seed
    demo.create_dataset("obs/state", data=np.asarray(observations, np.float64))
    demo.create_dataset("actions", data=np.asarray(actions, np.float64))
    demo.create_dataset("rewards", data=np.asarray(rewards, np.float64))
    dones = np.zeros(len(actions), np.int64)
    dones[-1] = 1
    demo.create_dataset("dones", data=dones)


def open_demos(path, env_kwargs, source):
    import h5py
    f = h5py.File(path, "w")
    data = f.create_group("data")
    data.attrs["env_args"] = json.dumps({"env_name": "PegTransferEnv", "type": "raven_sim",
                                         "env_kwargs": env_kwargs})
    data.attrs["source"] = source
    return f, data


def record(args):
    if len(args.seeds) < args.episodes:
        sys.exit(f"record: {args.episodes} episodes need as many seeds, got {len(args.seeds)}")
    rng = np.random.default_rng(args.noise_seed)
    env = PegTransferEnv(**ENV_KWARGS)
    f, data = open_demos(args.out, ENV_KWARGS, f"expert, DART noise {args.noise}")
    total = placed = 0
    for k, seed in enumerate(args.seeds[:args.episodes]):
        observation, _ = env.reset(seed=seed)
        observations, actions, rewards = [], [], []
        while True:
            label = env.expert_action()
            executed = label + rng.normal(0.0, 1.0, label.shape) * NOISE_SCALE * args.noise
            observations.append(observation)
            actions.append(label)
            observation, reward, terminated, truncated, info = env.step(executed)
            rewards.append(reward)
            if terminated or truncated:
                break
        write_demo(data, k, seed, observations, actions, rewards)
        total += len(actions)
        placed += info["placed"]
        print(f"demo_{k}: seed {seed}, {len(actions)} steps, placed {info['placed']}/6",
              flush=True)
    data.attrs["total"] = total
    f.close()
    print(f"{args.episodes} demonstrations, {total} steps, placed {placed}/{6 * args.episodes}: "
          f"{args.out}")


def convert(args):
    from ._raven_sim import read_ci
    inputs = read_ci(args.ci)
    randomize = args.seed is not None
    pad = PegTransferEnv(action_type="pad", randomize=randomize, time_limit=1e9)
    observation, _ = pad.reset(seed=args.seed if randomize else 0)
    observations, actions, rewards = [], [], []
    for row in inputs:
        before = observation[14:28].copy()  # the commanded targets
        observations.append(observation)
        observation, reward, terminated, truncated, info = pad.step(row)
        actions.append(observation[14:28] - before)
        rewards.append(reward)
        if terminated or truncated:
            break
    f, data = open_demos(args.out, {**ENV_KWARGS, "randomize": randomize},
                         f"gamepad session {args.ci}")
    write_demo(data, 0, args.seed if randomize else -1, observations, actions, rewards)
    data.attrs["total"] = len(actions)
    f.close()
    print(f"{args.ci}: {len(actions)} steps, placed {info['placed']}/6: {args.out}")


def load_demos(path):
    import h5py
    with h5py.File(path, "r") as f:
        demos = [f["data"][k] for k in sorted(f["data"].keys())]
        states = [np.asarray(d["obs/state"]) for d in demos]
        actions = [np.asarray(d["actions"]) for d in demos]
    return states, actions


def policy_inputs(states, actions):
    """Per step: the state and the action before it (zeros at the start)."""
    previous = np.vstack([np.zeros((1, actions.shape[1])), actions[:-1]])
    return np.hstack([states, previous])


class Policy:
    """The cloned policy: a standardised MLP from (state, previous action) to the action."""

    def __init__(self, network, stats):
        self.network, self.stats = network, stats
        self.previous = None

    def reset(self):
        self.previous = np.zeros_like(self.stats["action_mean"])

    def act(self, state):
        import torch
        x = np.hstack([state, self.previous])
        x = (x - self.stats["input_mean"]) / self.stats["input_std"]
        with torch.no_grad():
            y = self.network(torch.as_tensor(x, dtype=torch.float32)[None])[0].numpy()
        action = y * self.stats["action_std"] + self.stats["action_mean"]
        self.previous = action
        return action.astype(np.float64)

    @staticmethod
    def load(path):
        import torch
        saved = torch.load(path)
        network = make_network(saved["inputs"], saved["outputs"], saved["hidden"])
        network.load_state_dict(saved["network"])
        network.eval()
        stats = {k: np.asarray(v) for k, v in saved["stats"].items()}
        return Policy(network, stats)


def make_network(inputs, outputs, hidden):
    import torch
    layers, width = [], inputs
    for h in hidden:
        layers += [torch.nn.Linear(width, h), torch.nn.ReLU()]
        width = h
    layers.append(torch.nn.Linear(width, outputs))
    return torch.nn.Sequential(*layers)


def train(args):
    import torch
    torch.manual_seed(args.seed)
    states, actions = load_demos(args.demos)
    x = np.vstack([policy_inputs(s, a) for s, a in zip(states, actions)])
    y = np.vstack(actions)
    stats = {"input_mean": x.mean(0), "input_std": x.std(0) + 1e-6,
             "action_mean": y.mean(0), "action_std": y.std(0) + 1e-6}
    xt = torch.as_tensor((x - stats["input_mean"]) / stats["input_std"], dtype=torch.float32)
    yt = torch.as_tensor((y - stats["action_mean"]) / stats["action_std"], dtype=torch.float32)
    hidden = [args.width] * args.layers
    network = make_network(xt.shape[1], yt.shape[1], hidden)
    optimiser = torch.optim.Adam(network.parameters(), lr=args.lr)
    start = time.time()
    generator = torch.Generator().manual_seed(args.seed)
    for epoch in range(args.epochs):
        order = torch.randperm(len(xt), generator=generator)
        total = 0.0
        for i in range(0, len(xt), args.batch):
            batch = order[i:i + args.batch]
            loss = torch.nn.functional.mse_loss(network(xt[batch]), yt[batch])
            optimiser.zero_grad()
            loss.backward()
            optimiser.step()
            total += loss.item() * len(batch)
        if epoch % 10 == 0 or epoch == args.epochs - 1:
            print(f"epoch {epoch}: loss {total / len(xt):.4f}", flush=True)
    torch.save({"network": network.state_dict(), "inputs": xt.shape[1], "outputs": yt.shape[1],
                "hidden": hidden, "stats": {k: v.tolist() for k, v in stats.items()},
                "obs": ["state"], "action": ACTION, "demos": str(args.demos),
                "samples": len(xt)}, args.out)
    print(f"trained on {len(states)} demonstrations, {len(xt)} steps, in "
          f"{time.time() - start:.0f} s: {args.out}")


def evaluate(args):
    policy = Policy.load(args.policy)
    env = PegTransferEnv(**{**ENV_KWARGS, "time_limit": args.time_limit})
    placed_total = all_six = 0
    for seed in args.seeds:
        state, _ = env.reset(seed=seed)
        policy.reset()
        while True:
            state, _, terminated, truncated, info = env.step(policy.act(state))
            if terminated or truncated:
                break
        placed_total += info["placed"]
        all_six += info["placed"] == 6
        why = f" (the world failed: {info['failure']})" if "failure" in info else ""
        print(f"seed {seed}: placed {info['placed']}/6 in {env.core.time:.0f} s{why}", flush=True)
    print(f"placed {placed_total}/{6 * len(args.seeds)} rings; {all_six}/{len(args.seeds)} "
          "episodes all six")


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m raven_sim.learn", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("record", help="the expert's demonstrations (HDF5)")
    p.add_argument("--episodes", type=int, required=True)
    p.add_argument("--seeds", type=seed_range, required=True, help="A-B: one per episode")
    p.add_argument("--obs", type=observation_keys, default=["state"])
    p.add_argument("--noise", type=float, default=0.0, help="DART noise, times NOISE_SCALE")
    p.add_argument("--noise-seed", type=int, default=0)
    p.add_argument("--out", required=True)
    p.set_defaults(run=record)
    p = sub.add_parser("convert", help="a gamepad session's ci file replayed into HDF5")
    p.add_argument("--ci", required=True)
    p.add_argument("--seed", type=int,
                   help="the randomised scene the session ran on (default: the nominal scene, "
                        "as raven_controller's peg-transfer twin)")
    p.add_argument("--out", required=True)
    p.set_defaults(run=convert)
    p = sub.add_parser("train", help="behaviour cloning on the CPU")
    p.add_argument("--demos", required=True)
    p.add_argument("--obs", type=observation_keys, default=["state"])
    p.add_argument("--out", required=True)
    p.add_argument("--epochs", type=int, default=60)
    p.add_argument("--batch", type=int, default=256)
    p.add_argument("--lr", type=float, default=1e-3)
    p.add_argument("--width", type=int, default=256)
    p.add_argument("--layers", type=int, default=3)
    p.add_argument("--seed", type=int, default=0)
    p.set_defaults(run=train)
    p = sub.add_parser("evaluate", help="the policy on randomised scenes")
    p.add_argument("--policy", required=True)
    p.add_argument("--seeds", type=seed_range, required=True)
    p.add_argument("--time-limit", type=float, default=240.0)
    p.set_defaults(run=evaluate)
    args = parser.parse_args(argv)
    args.run(args)


if __name__ == "__main__":
    main()
