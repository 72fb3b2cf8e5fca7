"""Behaviour cloning of the peg transfer's scripted operator: the expert in small steps, what a
policy sees, the policy, and its training.

The expert (`SteppedExpert`) is the environment's `expert_action()` cut into steps of at most
STEP_CAP per joint: the operator's one long orientation move over a ring becomes several, so
every action is of one scale (the operator's others are already within a millimetre or 0.05 rad).
Labels are computed from the current targets, so in a state a learner reached the expert says
how to go on from there (what DART's noisy demonstrations and DAgger's relabelling need).

A policy sees `Features`: the state, per arm each ring's centre relative to its commanded tool
point (in the world frame, the rings' frame: raven_sim.tool_points) and the nearest one's within
NEAR (the millimetres a grasp is decided on, at their own scale), the
targets' change in the last step (what the arm just did), and per arm how many steps its
targets have stood still (up to HOLD_MEMORY): the operator waits, and a policy that only saw the
present could not count.
"""

import time

import numpy as np

from ._raven_sim import tool_points

ACTION = "joint_deltas"
# At most this per step and joint: 0.1 rad for the rotary joints, 2 mm of insertion.
STEP_CAP = np.array([0.1, 0.1, 0.002, 0.1, 0.1, 0.1, 0.1] * 2)
HOLD_MEMORY = 20
STILL = 1e-7  # a change of the targets below this is standing still (rad or m)
NEAR = 0.02  # m: the nearest ring's offset from a tool, clipped
TARGETS = slice(14, 28)
RINGS = slice(54, 72)


class SteppedExpert:
    """The scripted operator's targets reached in steps of at most STEP_CAP. The operator is
    asked again once a step reached its last target (or the targets stopped getting nearer to it:
    a joint limit), from wherever the targets are then."""

    def __init__(self, env):
        self.env = env
        self.reset()

    def reset(self):
        self.goal = None
        self.remaining = np.inf

    def act(self, state):
        current = state[TARGETS]
        if self.goal is None or np.abs(self.goal - current).max() >= self.remaining:
            self.goal = current + self.env.expert_action()
        left = self.goal - current
        step = np.clip(left, -STEP_CAP, STEP_CAP)
        # Not clipped: this step reaches the goal, and the next call asks the operator again.
        self.remaining = 0.0 if np.array_equal(step, left) else np.abs(left).max()
        return step


class Features:
    """What the policy sees, from the observations so far of one episode."""

    size = 72 + 2 * 18 + 2 * 3 + 14 + 2

    def __init__(self):
        self.reset()

    def reset(self):
        self.previous = None
        self.held = np.zeros(2)

    def __call__(self, state):
        targets = state[TARGETS]
        moved = np.zeros(14) if self.previous is None else targets - self.previous
        for arm in range(2):
            still = np.all(np.abs(moved[7 * arm:7 * arm + 7]) < STILL)
            self.held[arm] = min(self.held[arm] + 1, HOLD_MEMORY) if still else 0
        self.previous = targets.copy()
        rings = state[RINGS].reshape(6, 3)
        relative = [rings - tool for tool in tool_points(targets)]
        nearest = [np.clip(r[np.argmin(np.linalg.norm(r, axis=1))], -NEAR, NEAR)
                   for r in relative]
        return np.hstack([state, *(r.ravel() for r in relative), *nearest, moved,
                          self.held / HOLD_MEMORY])

    @staticmethod
    def of_episode(states):
        features = Features()
        return np.vstack([features(s) for s in states])


def make_network(inputs, outputs, hidden):
    import torch
    layers, width = [], inputs
    for h in hidden:
        layers += [torch.nn.Linear(width, h), torch.nn.ReLU()]
        width = h
    layers.append(torch.nn.Linear(width, outputs))
    return torch.nn.Sequential(*layers)


class Policy:
    """A cloned policy: a standardised MLP from Features to the next joint deltas."""

    def __init__(self, network, stats, hidden):
        self.network, self.stats, self.hidden = network, stats, hidden
        self.features = Features()

    def reset(self):
        self.features.reset()

    def act(self, state):
        import torch
        x = (self.features(state) - self.stats["input_mean"]) / self.stats["input_std"]
        with torch.no_grad():
            y = self.network(torch.as_tensor(x, dtype=torch.float32)[None])[0].numpy()
        return (y * self.stats["action_std"] + self.stats["action_mean"]).astype(np.float64)

    def save(self, path, **about):
        import torch
        torch.save({"network": self.network.state_dict(), "hidden": self.hidden,
                    "stats": {k: v.tolist() for k, v in self.stats.items()},
                    "features": Features.size, "action": ACTION, **about}, path)

    @staticmethod
    def load(path):
        import torch
        saved = torch.load(path)
        if saved.get("features") != Features.size:
            raise ValueError(f"{path}: a policy for another observation ({saved.get('features')} "
                             f"inputs, this version has {Features.size}); train it again")
        stats = {k: np.asarray(v) for k, v in saved["stats"].items()}
        network = make_network(Features.size, len(stats["action_mean"]), saved["hidden"])
        network.load_state_dict(saved["network"])
        network.eval()
        return Policy(network, stats, saved["hidden"])


def fit(states, actions, hidden, epochs, batch=256, lr=1e-3, seed=0, log=print, start=None):
    """Trains a Policy on episodes (lists of state and action arrays): Adam with a cosine
    schedule, mean squared error on standardised actions. `start`: a policy to go on from."""
    import torch
    torch.manual_seed(seed)
    x = np.vstack([Features.of_episode(s) for s in states])
    y = np.vstack(actions)
    if start is None:
        stats = {"input_mean": x.mean(0), "input_std": x.std(0) + 1e-6,
                 "action_mean": y.mean(0), "action_std": y.std(0) + 1e-6}
        network = make_network(x.shape[1], y.shape[1], hidden)
    else:
        stats, network, hidden = start.stats, start.network, start.hidden
        network.train()
    xt = torch.as_tensor((x - stats["input_mean"]) / stats["input_std"], dtype=torch.float32)
    yt = torch.as_tensor((y - stats["action_mean"]) / stats["action_std"], dtype=torch.float32)
    optimiser = torch.optim.Adam(network.parameters(), lr=lr)
    batches = (len(xt) + batch - 1) // batch
    schedule = torch.optim.lr_scheduler.CosineAnnealingLR(optimiser, epochs * batches)
    generator = torch.Generator().manual_seed(seed)
    began = time.time()
    for epoch in range(epochs):
        order = torch.randperm(len(xt), generator=generator)
        total = 0.0
        for i in range(0, len(xt), batch):
            rows = order[i:i + batch]
            loss = torch.nn.functional.mse_loss(network(xt[rows]), yt[rows])
            optimiser.zero_grad()
            loss.backward()
            optimiser.step()
            schedule.step()
            total += loss.item() * len(rows)
        if epoch % 10 == 0 or epoch == epochs - 1:
            log(f"epoch {epoch}: loss {total / len(xt):.5f} ({time.time() - began:.0f} s)")
    network.eval()
    return Policy(network, stats, list(hidden)), len(xt), time.time() - began
