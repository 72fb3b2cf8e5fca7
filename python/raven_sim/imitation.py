"""Behaviour cloning of the peg transfer's scripted operator: the expert in small steps, what a
policy sees, the policy, and its training.

The expert (`SteppedExpert`) is the environment's `expert_action()` cut into steps of at most
STEP_CAP per joint: the operator's one long orientation move over a ring becomes several, so
every action is of one scale (the operator's others are already within a millimetre or 0.05 rad).
Labels are computed from the current targets, so in a state a learner reached the expert says
how to go on from there (what DART's noisy demonstrations and DAgger's relabelling need).

What a policy learns is the expert's waypoint, where its targets are heading, relative to the
current ones; it acts by moving at most STEP_CAP towards it. Heading for a point converges on it
(an error in the waypoint moves the end a little, never past it), where learning the capped step
itself leaves the policy to guess the step at which a long move stops, and an overshoot feeds on
itself. The waypoints span three orders of magnitude (a millimetre's joint change to a 2 rad
turn), so they are learnt as asinh(waypoint / RESOLUTION): to a relative accuracy at every scale.
The operator either holds an arm (a wait: every joint's waypoint zero) or moves some joint by 3.4
resolutions or more. A regression trained on both answers a state where the features leave it
unsure with a step between, too small to arrive, and the arm creeps on such steps without end. A
gated policy (fit's `gated`, `learn train --hold-gate`) learns the hold as a class of its own and
the waypoint from the moves alone: a whole move or none.

The policy is one network for either arm (each arm moves its own three rings, as the operator's
routines do): it sees one arm's `ArmFeatures` and gives that arm's waypoint. An arm's features
are its own (the arm, its targets, its tool point in the world frame, the rings' frame:
raven_sim.tool_points; its grasp wrench), per ring of its jobs where the ring is from the tool,
from its start and target posts and above the board, with whether it rests on its target (the
layout's design values: raven_sim.peg_layout; the C++ judgement: raven_sim.ring_placed); which
job is the first not done and that ring's offset within NEAR (the millimetres a grasp is decided
on, at their own scale); and how many steps the targets have stood still (up to HOLD_MEMORY):
the operator waits, and a policy that only saw the present could not count. The other arm is
not seen: in the demonstrations the two arms keep in step, which a policy must not learn to rely
on. Nor are the policy's own last moves (the targets' change, the joints' lag behind them): a
clone that sees them learns to repeat them, and repeats its own errors (the copycat problem, Wen
et al. 2020).
"""

import time

import numpy as np

from ._raven_sim import peg_layout, ring_placed, tool_points
from .env import part

ACTION = "joint_deltas"
OUTPUT = "asinh(waypoint / RESOLUTION), per arm"
GATED = "asinh(waypoint / RESOLUTION) of a move, then the logit that the arm holds, per arm"
# At most this per step and joint: 0.1 rad for the rotary joints, 2 mm of insertion.
STEP_CAP = np.array([0.1, 0.1, 0.002, 0.1, 0.1, 0.1, 0.1] * 2)
# Waypoints are learnt at this resolution: linear below it, logarithmic above (rad; m).
RESOLUTION = np.array([0.002, 0.002, 0.0002, 0.002, 0.002, 0.002, 0.002])
HOLD_MEMORY = 20
HOLD = 0.5  # learnt resolutions: an arm's waypoint under this in every joint holds it
STILL = 2e-4  # targets changing less than this per step stand still (rad or m; the
#               operator's moves change some joint by a millimetre's 1e-3 or more)
NEAR = 0.02  # m: the current ring's offset from the tool, clipped
TARGETS = part("targets")
RINGS = part("rings")
LAYOUT = peg_layout()
REST_Z = LAYOUT["board_top"] + LAYOUT["ring_height"] / 2  # a ring's centre lying on the board
JOBS_PER_ARM = sum(j["arm"] == 0 for j in LAYOUT["jobs"])


def joints_of(arm):
    """An arm's joints in a vector of both arms' (the targets, an action, a waypoint)."""
    both, own = part("targets"), part("targets", arm)
    return slice(own.start - both.start, own.stop - both.start)


class SteppedExpert:
    """The scripted operator's targets reached in steps of at most STEP_CAP. The operator is
    asked again once a step reached its last target (or the targets stopped getting nearer to it:
    a joint limit), from wherever the targets are then."""

    def __init__(self, env, from_state=False):
        """`from_state`: the operator takes up the task from the state reached each time it is
        asked (env.expert_action(from_state=True)), for episodes another driver steers."""
        self.env = env
        self.from_state = from_state
        self.reset()

    def reset(self):
        self.goal = None
        self.remaining = np.inf

    def act(self, state):
        current = state[TARGETS]
        if self.goal is None or np.abs(self.goal - current).max() >= self.remaining:
            self.goal = current + self.env.expert_action(self.from_state)
        left = self.goal - current
        step = np.clip(left, -STEP_CAP, STEP_CAP)
        # Not clipped: this step reaches the goal, and the next call asks the operator again.
        self.remaining = 0.0 if np.array_equal(step, left) else np.abs(left).max()
        return step

    def waypoint(self, state):
        """Where the last act() was heading, relative to the targets in `state`."""
        return self.goal - state[TARGETS]


class ArmFeatures:
    """What the policy sees of one arm, from the observations so far of one episode."""

    _BEFORE_JOB = 1 + 7 + 3 + 6 + 3 * 9  # the arm, targets, tool, wrench, per ring
    JOB = slice(_BEFORE_JOB, _BEFORE_JOB + 4)  # the first job not done, one-hot
    size = JOB.stop + 3 + 1

    def __init__(self, arm):
        self.arm = arm
        jobs = [j for j in LAYOUT["jobs"] if j["arm"] == arm]
        self.rings = [LAYOUT["jobs"].index(j) for j in jobs]
        self.starts = np.array([j["from"] for j in jobs])
        self.ends = np.array([j["to"] for j in jobs])
        self.reset()

    def reset(self):
        self.previous = None
        self.held = 0

    def __call__(self, state, tool):
        """`tool`: this arm's tool point at its targets (raven_sim.tool_points)."""
        own = joints_of(self.arm)
        targets = state[TARGETS][own]
        moved = np.zeros(7) if self.previous is None else targets - self.previous
        self.held = min(self.held + 1, HOLD_MEMORY) if np.all(np.abs(moved) < STILL) else 0
        self.previous = targets.copy()
        rings = state[RINGS].reshape(6, 3)[self.rings]
        lift = rings[:, 2] - REST_Z
        placed = np.array([ring_placed(r, end) for r, end in zip(rings, self.ends)])
        current = int(np.argmin(placed)) if not placed.all() else 3
        near = np.zeros(3) if current == 3 else np.clip(rings[current] - tool, -NEAR, NEAR)
        wrench = state[part("wrenches", self.arm)]
        per_ring = np.hstack([rings - tool, rings[:, :2] - self.starts, rings[:, :2] - self.ends,
                              lift[:, None], placed[:, None]])
        return np.hstack([1.0 - 2.0 * self.arm, targets, tool, wrench, per_ring.ravel(),
                          np.eye(4)[current], near, self.held / HOLD_MEMORY])


class Features:
    """Both arms' features (rows, left first) from the observations so far of one episode."""

    def __init__(self):
        self.arms = [ArmFeatures(0), ArmFeatures(1)]

    def reset(self):
        for a in self.arms:
            a.reset()

    def __call__(self, state):
        tools = tool_points(state[TARGETS])
        return np.vstack([a(state, tools[a.arm]) for a in self.arms])

    @staticmethod
    def of_episode(states):
        """Per arm, its features in every state: a (2, steps, ArmFeatures.size) array."""
        features = Features()
        return np.stack([features(s) for s in states], axis=1)


def holds(waypoints):
    """Per row of an arm's waypoints (n, 7): whether the operator holds the arm there (every
    joint under HOLD resolutions; its moves change some joint by 3.4 or more)."""
    return (np.abs(waypoints) / RESOLUTION).max(axis=1) < HOLD


def to_learnt(waypoints):
    """Per arm's seven joints: the scale a network learns waypoints at."""
    return np.arcsinh(waypoints / RESOLUTION)


def from_learnt(values):
    return np.sinh(values) * RESOLUTION


def make_network(inputs, outputs, hidden):
    import torch
    layers, width = [], inputs
    for h in hidden:
        layers += [torch.nn.Linear(width, h), torch.nn.ReLU()]
        width = h
    layers.append(torch.nn.Linear(width, outputs))
    return torch.nn.Sequential(*layers)


class Policy:
    """A cloned policy: a standardised MLP from an arm's features to its waypoint (learnt scale),
    run for each arm; it acts by moving at most STEP_CAP towards it. A gated one also gives the
    logit that the arm holds, and holds it where that is positive (fit's `gated`)."""

    env_kwargs = {}  # the observations it needs of PegTransferEnv besides the defaults: none

    def __init__(self, network, stats, hidden, gated=False):
        self.network, self.stats, self.hidden, self.gated = network, stats, hidden, gated
        self.features = Features()

    def reset(self):
        self.features.reset()

    def fresh(self):
        """The same network with a memory of its own (the features' hold counts)."""
        return Policy(self.network, self.stats, self.hidden, self.gated)

    def act(self, observation):
        """Both arms' joint deltas (14) from the observation (the state, or a dict with it)."""
        import torch
        state = observation["state"] if isinstance(observation, dict) else observation
        x = (self.features(state) - self.stats["input_mean"]) / self.stats["input_std"]
        with torch.no_grad():
            y = self.network(torch.as_tensor(x, dtype=torch.float32)).numpy().astype(np.float64)
        waypoint = from_learnt(y[:, :7] * self.stats["output_std"] + self.stats["output_mean"])
        if self.gated:
            waypoint[y[:, 7] > 0.0] = 0.0
        return np.clip(waypoint.ravel(), -STEP_CAP, STEP_CAP)

    def checkpoint(self, **about):
        """What save() writes: the network, its scaling and what it was made from."""
        return {"network": self.network.state_dict(), "hidden": self.hidden,
                "stats": {k: v.tolist() for k, v in self.stats.items()},
                "features": ArmFeatures.size, "output": GATED if self.gated else OUTPUT,
                **about}

    def save(self, path, **about):
        import torch
        torch.save(self.checkpoint(**about), path)

    @staticmethod
    def from_checkpoint(saved, path):
        if saved.get("features") != ArmFeatures.size or saved.get("output") not in (OUTPUT, GATED):
            raise ValueError(f"{path}: a policy of another version ({saved.get('features')} "
                             f"inputs per arm, output {saved.get('output')}; this version: "
                             f"{ArmFeatures.size}, {OUTPUT} or {GATED}); train it again")
        gated = saved["output"] == GATED
        stats = {k: np.asarray(v) for k, v in saved["stats"].items()}
        network = make_network(ArmFeatures.size, len(stats["output_mean"]) + gated,
                               saved["hidden"])
        network.load_state_dict(saved["network"])
        network.eval()
        return Policy(network, stats, saved["hidden"], gated)

    @staticmethod
    def load(path):
        import torch
        return Policy.from_checkpoint(torch.load(path), path)


class RingsSeenOff:
    """A state policy that sees every ring `error` m from where it is, in the board's plane, each
    ring in its own direction drawn once from `seed`: what a camera's steady error of that size
    costs the policy (learn evaluate --ring-error)."""

    def __init__(self, policy, error, seed):
        self.policy, self.error, self.seed = policy, error, seed
        angles = np.random.default_rng(seed).uniform(0.0, 2.0 * np.pi, 6)
        self.offsets = error * np.column_stack([np.cos(angles), np.sin(angles), np.zeros(6)])

    @property
    def env_kwargs(self):
        return self.policy.env_kwargs

    def reset(self):
        self.policy.reset()

    def fresh(self):
        return RingsSeenOff(self.policy.fresh(), self.error, self.seed)

    def act(self, observation):
        state = np.array(observation["state"] if isinstance(observation, dict) else observation,
                         dtype=np.float64)
        state[RINGS] += self.offsets.ravel()
        return self.policy.act(state)


def hold_and_move_loss(predicted, target):
    """A gated policy's loss (target: the learnt waypoint, then 1 where the operator held): the
    hold's binary cross-entropy plus the squared error of the waypoints it moved to. Its holds
    teach the regression nothing, so a state where the operator sometimes holds and sometimes
    moves gives a whole move or none, never the average of both (a step too small to arrive)."""
    import torch
    held = target[:, -1]
    loss = torch.nn.functional.binary_cross_entropy_with_logits(predicted[:, -1], held)
    moved = held < 0.5
    if moved.any():
        loss = loss + torch.nn.functional.mse_loss(predicted[moved, :-1], target[moved, :-1])
    return loss


def train_network(network, inputs, targets, epochs, batch, lr, seed, measure, log_epoch,
                  loss_of=None):
    """Trains `network` on the tensors (inputs, targets): `loss_of(predicted, target)` (mean
    squared error unless told) over shuffled batches, Adam with a cosine schedule. Per epoch it
    calls log_epoch(epoch, the sum of measure(predicted, target, loss) over its batches, seconds
    so far). Leaves the network in evaluation mode; returns the last epoch's sum and the seconds
    it took."""
    import torch
    loss_of = loss_of or torch.nn.functional.mse_loss
    optimiser = torch.optim.Adam(network.parameters(), lr=lr)
    batches = (len(inputs) + batch - 1) // batch
    schedule = torch.optim.lr_scheduler.CosineAnnealingLR(optimiser, epochs * batches)
    generator = torch.Generator().manual_seed(seed)
    began = time.time()
    total = 0.0
    for epoch in range(epochs):
        order = torch.randperm(len(inputs), generator=generator)
        total = 0.0
        for i in range(0, len(inputs), batch):
            rows = order[i:i + batch]
            predicted = network(inputs[rows])
            loss = loss_of(predicted, targets[rows])
            optimiser.zero_grad()
            loss.backward()
            optimiser.step()
            schedule.step()
            total += measure(predicted.detach(), targets[rows], loss.item())
        log_epoch(epoch, total, time.time() - began)
    network.eval()
    return total, time.time() - began


def labelled_as_seen(features, expert_jobs):
    """Per arm-step of an episode (features: (2, steps, size)), whether the operator's label
    answers what the features show: not once it has moved past a ring of the arm that is not on
    its target post (given up after its re-grasps, or knocked off later). The features then name
    that ring as the job while the operator works on the next ring or holds still, done; cloned,
    such steps teach a policy to stand before a ring it has not placed. All, for demos recorded
    without `expert_jobs`."""
    if expert_jobs is None:
        return np.ones(features.shape[:2], bool)
    first_not_done = features[:, :, ArmFeatures.JOB].argmax(axis=2)
    return np.asarray(expert_jobs).T <= first_not_done


def fit(states, waypoints, hidden, epochs, batch=512, lr=2e-3, seed=0, log=print, start=None,
        expert_jobs=None, gated=False):
    """Trains a Policy on episodes (lists of state and waypoint arrays): Adam with a cosine
    schedule, mean squared error on the standardised learnt scale, on the arm-steps whose labels
    answer what the policy sees (labelled_as_seen, from each episode's `expert_jobs`, if given).
    `gated`: a hold gate besides, the regression on the moves alone (hold_and_move_loss).
    `start`: a policy to go on from (gated if it is)."""
    import torch
    torch.manual_seed(seed)
    jobs = expert_jobs if expert_jobs is not None else [None] * len(states)
    features = [Features.of_episode(s) for s in states]
    kept = [labelled_as_seen(f, j) for f, j in zip(features, jobs)]
    x = np.vstack([f[arm][k[arm]] for f, k in zip(features, kept) for arm in (0, 1)])
    # Each arm's rows in the order of_episode gives them: per episode the left arm, then the right.
    raw = np.vstack([w[k[arm]][:, joints_of(arm)] for w, k in zip(waypoints, kept)
                     for arm in (0, 1)])
    y = to_learnt(raw)
    gated = start.gated if start is not None else gated
    held = holds(raw) if gated else np.zeros(len(raw), bool)
    log(f"{len(x)} of {sum(k.size for k in kept)} arm-steps labelled as the policy sees them"
        + (f", {held.mean():.1%} of them holds" if gated else ""))
    if start is None:
        stats = {"input_mean": x.mean(0), "input_std": x.std(0) + 1e-6,
                 "output_mean": y[~held].mean(0), "output_std": y[~held].std(0) + 1e-6}
        network = make_network(x.shape[1], y.shape[1] + gated, hidden)
    else:
        stats, network, hidden = start.stats, start.network, start.hidden
        network.train()
    xt = torch.as_tensor((x - stats["input_mean"]) / stats["input_std"], dtype=torch.float32)
    yt = torch.as_tensor((y - stats["output_mean"]) / stats["output_std"], dtype=torch.float32)
    if gated:
        yt = torch.cat([yt, torch.as_tensor(held, dtype=torch.float32)[:, None]], dim=1)

    def log_epoch(epoch, total, seconds):
        if epoch % 10 == 0 or epoch == epochs - 1:
            log(f"epoch {epoch}: loss {total / len(xt):.5f} ({seconds:.0f} s)")

    _, seconds = train_network(network, xt, yt, epochs, batch, lr, seed,
                               lambda predicted, target, loss: loss * len(target), log_epoch,
                               hold_and_move_loss if gated else None)
    return Policy(network, stats, list(hidden), gated), len(xt), seconds
