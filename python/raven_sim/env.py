"""The peg transfer as a learning environment, in Gymnasium's API convention.

One step is one manual-loop iteration of the controller a gamepad drives (control="waypoint": until
the arms' setpoints reach the action's targets under the controller's velocity caps, at least 2 ms
of robot time, and then until the arms arrive there or stop, at most 0.5 s, a stopped arm's
shortfall made up: scenario::arrival()) or exactly `period` seconds (control="period": a move cut
short there, or held after it arrives). The action (action_type) is both arms' joint targets
("joints", 14 values, left arm first, ArmJoints order: shoulder, elbow, insertion (m), roll, wrist,
jaw1, jaw2), deltas from the current targets ("joint_deltas", 14, at most a joint's range), per arm
the tool tip's displacement with the wrist locked and the jaws' opening ("tool_deltas", 8: dx, dy,
dz in m (at most 5 mm) in the controller's frame {B}, the one a gamepad's sticks move the tool in
(not the observation's pose frame), then jaw1 + jaw2 in rad), or a pad reading ("pad", a ci row of
14 values). Actions are clipped to their bounds, their targets to the joint limits.

Observations (obs): "state" alone gives the vector below; with "rgb" (H, W, 3) uint8, "depth"
(H, W) float32 metres along the camera's axis (+inf where nothing is) or "segmentation" (H, W)
int32 ids (SEGMENT_IDS), the observation is a dict of them (keys "<kind>" for one camera,
"<camera>/<kind>" for several; camera: any named view, e.g. "overview", "left-task",
"right-task", "grasper-left", "grasper-right"), rendered headless at image_size (W, H). The
state (72 values) is, per arm (left first), its measured joints, commanded targets, tool pose
(x, y, z, qw, qx, qy, qz) and grasp force and torque; then each ring's centre (ring1..ring6):
`state[part("targets")]`, `state[part("rings", 2)]` (the C++ layout's names and places,
raven_sim.observation_layout()). The reward is the change in the number of rings resting
threaded on their target posts (+1 as one comes to rest there, -1 if one leaves); an episode
terminates with all six placed and is truncated at the time limit. The main job's scripted
operator is the expert: `expert_action()`. The same seed and actions give the same episode.

randomize=True draws each episode's scene from its reset seed (the rings' start poses, silicone
and friction, the board's friction, the motors' fitted mechanics within the calibration's standard
deviations, and, if the ranges say so, the cameras' look: scenario/scene_variation.hpp's ranges),
randomize="f.yaml" from that file's ranges; reset's info["variation"] is the draw.

The twin is the Raven-II's motor-level one by default (actuation="motors": its motors, cables and
control software drive the joints, and what the jaws touch loads the motors), or ideal joint
servos (actuation="ideal").
"""

import json
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from ._raven_sim import PegCameras, PegTransferCore, observation_layout

try:  # Gymnasium when it is there; the same API without it
    import gymnasium
    from gymnasium.spaces import Box, Dict
    _Env = gymnasium.Env
except ImportError:
    _Env = object

    class Dict:
        """A dictionary of spaces (gymnasium.spaces.Dict's fields)."""

        def __init__(self, spaces):
            self.spaces = dict(spaces)

        def __getitem__(self, key):
            return self.spaces[key]

        def keys(self):
            return self.spaces.keys()

        def contains(self, x):
            return set(x) == set(self.spaces) and all(s.contains(x[k])
                                                      for k, s in self.spaces.items())

        def sample(self, rng=None):
            return {k: s.sample(rng) for k, s in self.spaces.items()}

    class Box:
        """A box of real vectors (gymnasium.spaces.Box's fields, for describing and sampling)."""

        def __init__(self, low, high, shape=None, dtype=np.float64):
            self.dtype = np.dtype(dtype)
            self.shape = tuple(shape) if shape is not None else np.shape(low)
            self.low = np.broadcast_to(np.asarray(low, self.dtype), self.shape).copy()
            self.high = np.broadcast_to(np.asarray(high, self.dtype), self.shape).copy()

        def contains(self, x):  # as Gymnasium's: lists are taken as the space's dtype
            if not isinstance(x, np.ndarray):
                x = np.asarray(x, dtype=self.dtype)
            return bool(np.can_cast(x.dtype, self.dtype) and x.shape == self.shape and
                        np.all(x >= self.low) and np.all(x <= self.high))

        def sample(self, rng=None):
            rng = rng or np.random.default_rng()
            low = np.maximum(self.low, np.finfo(np.float64).min / 4)
            high = np.minimum(self.high, np.finfo(np.float64).max / 4)
            return rng.uniform(low, high).astype(self.dtype)

STATE_LAYOUT = observation_layout()  # name: (slice, values per item)


def part(name, item=None):
    """The slice of the state holding part `name` ("joints", "targets", "tool_poses", "wrenches",
    "rings"), or only its item `item` (an arm, 0 left / 1 right; or a ring, 0-5)."""
    whole, size = STATE_LAYOUT[name]
    if item is None:
        return whole
    start = whole.start + size * item
    return slice(start, start + size)


# A pad reading's ranges: sticks in [-1, 1], triggers on the paper's 0 .. 3.996, buttons 0 or 1.
PAD_LOW = [-1, -1, 0, 0, -1, -1, 0, 0, 0, 0, 0, 0, 0, 0]
PAD_HIGH = [1, 1, 3.996, 1, 1, 1, 3.996, 1, 1, 1, 1, 1, 1, 1]
OBSERVATIONS = ("state", "rgb", "depth", "segmentation")
# Segmentation ids (scenario/peg_cameras.hpp): 0 background, 1 the board's plate, 2-7 the start
# posts of ring1..ring6, 8-13 their target posts, 14-19 the rings ring1..ring6, 20 the left arm's
# links, 21 the left jaws, 22 the right arm's links, 23 the right jaws, 24 anything else.
SEGMENT_IDS = 25


class PegTransferEnv(_Env):
    """The peg transfer on the in-process twin (see the module's documentation)."""

    metadata = {"render_modes": []}

    def __init__(self, action_type="joints", randomize=False, time_limit=240.0, launch_file=None,
                 control="waypoint", period=0.05, obs=("state",), camera="overview",
                 image_size=(128, 96), actuation="motors"):
        kinds = ("joints", "joint_deltas", "tool_deltas", "pad")
        if action_type not in kinds:
            raise ValueError(f"action_type is '{action_type}': expected one of {kinds}")
        core_action = "joints" if action_type == "pad" else action_type
        # randomize: True draws each scene from the shipped ranges, a path from that YAML's.
        ranges = None if isinstance(randomize, bool) else str(randomize)
        self.core = PegTransferCore(bool(randomize), time_limit, launch_file, core_action,
                                    control, period, actuation, ranges)
        self.action_type = action_type
        self.obs = (obs,) if isinstance(obs, str) else tuple(obs)
        unknown = [k for k in self.obs if k not in OBSERVATIONS]
        if unknown or not self.obs:
            raise ValueError(f"obs {self.obs}: each one of {OBSERVATIONS}")
        self.cameras = [camera] if isinstance(camera, str) else list(camera)
        self.image_size = tuple(int(v) for v in image_size)
        self._cameras = None
        # float64 throughout (Gymnasium's Box defaults to float32, which the twin's values are not).
        state = Box(-np.inf, np.inf, (PegTransferCore.observation_size,), dtype=np.float64)
        if self.obs == ("state",):  # the plain vector, as before cameras
            self.observation_space = state
        else:
            w, h = self.image_size
            spaces = {"state": state} if "state" in self.obs else {}
            image = {"rgb": Box(0, 255, (h, w, 3), dtype=np.uint8),
                     "depth": Box(0.0, np.inf, (h, w), dtype=np.float32),
                     "segmentation": Box(0, SEGMENT_IDS - 1, (h, w), dtype=np.int32)}
            for kind in self.obs:
                if kind == "state":
                    continue
                for name in self.cameras:
                    spaces[self._key(name, kind)] = image[kind]
            self.observation_space = Dict(spaces)
        if action_type != "pad":
            self.action_space = Box(self.core.action_low, self.core.action_high, dtype=np.float64)
        else:
            self.action_space = Box(np.array(PAD_LOW, np.float64), np.array(PAD_HIGH, np.float64),
                                    dtype=np.float64)
        self._next_seed = 0

    def reset(self, *, seed=None, options=None):
        """A new episode from `seed` (None: the previous seed + 1, from 0). `options` is
        accepted for Gymnasium's signature and not used: the scene is set at construction."""
        seed = self._next_seed if seed is None else int(seed)
        self._next_seed = seed + 1
        observation = self.core.reset(seed)
        if self.obs != ("state",):  # the world is new: so are its cameras
            self._cameras = PegCameras(self.core, self.cameras, *self.image_size)
        return (self._observe(observation),
                {"seed": seed, "placed": self.core.placed, "time": self.core.time,
                 "variation": json.loads(self.core.variation)})

    def _key(self, camera, kind):
        return kind if len(self.cameras) == 1 else f"{camera}/{kind}"

    def _observe(self, state):
        if self.obs == ("state",):
            return state
        out = {"state": state} if "state" in self.obs else {}
        images = self._cameras.render(self.core, "rgb" in self.obs, "depth" in self.obs,
                                      "segmentation" in self.obs)
        for name, rendered in zip(self.cameras, images):
            for kind, array in rendered.items():
                out[self._key(name, kind)] = array
        return out

    def step(self, action):
        action = np.asarray(action, dtype=np.float64)
        if self.action_type == "pad":
            result = self.core.step_pad(action)
        else:
            result = self.core.step(action)
        info = {"placed": result.placed, "refused": result.refused, "time": self.core.time,
                "faulted": result.faulted}  # e-stopped: truncated, every later command refused
        if result.failure:  # the world's guard stopped it: truncated, the last good observation
            info["failure"] = result.failure
        return (self._observe(result.observation), result.reward, result.terminated,
                result.truncated, info)

    def save_state(self):
        """The episode's state now: the world (bodies, rings' nodes, contacts and their warm
        start), the twin, the controller, the expert's progress and the clock. The same actions
        after restore_state(state) give the same observations, bit for bit."""
        return self.core.save_state()

    def restore_state(self, state):
        """Goes back to a state this episode saved (reset() starts another episode, whose world
        refuses it); returns the observation of then."""
        self.core.restore_state(state)
        return self._observe(self.core.observation)

    @property
    def twin(self):
        """The episode's twin (raven_sim.Twin), valid until the next reset: what the robot itself
        reports besides the observation, e.g. `twin.raven_state()` (its motors' Tau and DAC
        counts) and `twin.measured_cf(raven_sim.Arm.LEFT)` (what the jaws push on)."""
        return self.core.twin

    def expert_action(self, from_state=False):
        """The main job's scripted operator's next step as an action of this environment's kind
        (joint targets for "pad"; call once per step). `from_state`: the operator first takes
        up the task from the state reached, as after steps someone else (a policy) decided."""
        return self.core.expert_action(from_state)

    def expert_jobs_finished(self):
        """Per arm (left first), how many of its three rings the operator has finished with,
        placed or given up after its re-grasps (3 once it is done)."""
        return np.array(self.core.expert_jobs_finished())


class VectorPegTransferEnv:
    """N peg-transfer environments stepped together, each on a worker thread (their steps
    release the GIL). No automatic reset: reset the ones that ended."""

    def __init__(self, n, **kwargs):
        self.envs = [PegTransferEnv(**kwargs) for _ in range(n)]
        self._pool = ThreadPoolExecutor(max_workers=n)

    def __len__(self):
        return len(self.envs)

    def reset(self, seeds):
        results = list(self._pool.map(lambda pair: pair[0].reset(seed=pair[1]),
                                      zip(self.envs, seeds)))
        return np.stack([r[0] for r in results]), [r[1] for r in results]

    def step(self, actions):
        results = list(self._pool.map(lambda pair: pair[0].step(pair[1]), zip(self.envs, actions)))
        observations, rewards, terminated, truncated, infos = zip(*results)
        return (np.stack(observations), np.array(rewards), np.array(terminated),
                np.array(truncated), list(infos))

    def expert_actions(self):
        return np.stack([env.expert_action() for env in self.envs])

    def close(self):
        self._pool.shutdown()
