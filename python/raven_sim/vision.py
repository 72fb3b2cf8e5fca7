"""The image policy: each arm sees its rings through its own task camera, and the state policy's
network acts on what it saw.

A RingLocator (a small convolutional network with a spatial softmax, Levine et al. 2016) reads one
arm's task-camera image ("left-task" or "right-task") and gives where the arm's three rings are.
ImagePolicy puts those in place of the rings in the state and lets a cloned state policy
(imitation.Policy) act: the only things it reads of the state are the arm's own (its joint
targets, the tool point they give, its grasp wrench) and the rings, and the rings it now has from
the images. Nothing else of the world is seen.

The locator sees the image alone, not the arm's joints: given them, it learnt that a ring follows
the jaws once they closed on it (in the demonstrations it nearly always does), and when a grasp
slipped it saw the ring carried to its target post while it lay on the start post.

The right arm's scene is the left's mirrored about the board's centre line (x = 0), so one locator
serves both: the right arm's image is flipped left to right, and what it sees is mirrored back.
The locator learns from the demonstrations' images with their recorded ring centres; the state
policy from the same demonstrations' states (behaviour cloning, imitation.fit).
"""

import numpy as np

from .demos import expert_jobs_of, stored
from .imitation import LAYOUT, REST_Z, RINGS, Policy, train_network

CAMERAS = ("left-task", "right-task")  # per arm, left first
KIND = "image policy: RingLocator on each arm's task camera + imitation.Policy"
# Per arm: each of its rings relative to where it starts (its start post, lying on the board).
ORIGINS = [np.array([[*j["from"], REST_Z] for j in LAYOUT["jobs"] if j["arm"] == arm])
           for arm in (0, 1)]
RING_ROWS = [[LAYOUT["jobs"].index(j) for j in LAYOUT["jobs"] if j["arm"] == arm]
             for arm in (0, 1)]
MIRROR = np.array([-1.0, 1.0, 1.0])  # x about the centre line
MM = 1000.0
FRAME_STRIDE = 2  # the locator learns from every other step: the next one looks the same
WORKSPACE = 0.2  # m: a ring farther than this from where it starts has left the board


def image_key(arm):
    return f"{CAMERAS[arm]}/rgb"


def seen_image(images, arm):
    """An arm's camera image (H, W, 3), or images (N, H, W, 3), as the locator sees them:
    channels first, the right arm's flipped left to right."""
    images = np.asarray(images)
    if arm == 1:
        images = images[..., ::-1, :]
    return np.ascontiguousarray(np.moveaxis(images, -1, -3))


def rings_seen(rings, arm):
    """The arm's rings (3, 3) in the world -> what the locator gives: their offsets from where
    they start, mirrored for the right arm, in mm (9 values)."""
    offsets = (rings - ORIGINS[arm]) * (MIRROR if arm else 1.0)
    return offsets.ravel() * MM


def rings_in_world(seen, arm):
    """What the locator gave (9 values, or N x 9) -> the arm's rings in the world ((N,) 3, 3)."""
    seen = np.asarray(seen, dtype=np.float64)
    return seen.reshape(*seen.shape[:-1], 3, 3) / MM * (MIRROR if arm else 1.0) + ORIGINS[arm]


def make_locator(channels=16, keypoints=32, hidden=256):
    """Image (3, H, W) uint8 -> the arm's rings (9, mm). The image is
    averaged down 2 x 2 first (128 x 96 -> 64 x 48: a ring is still 7 pixels wide), the keypoints
    found at a quarter of the image's resolution."""
    import torch
    from torch import nn

    class SpatialSoftmax(nn.Module):
        """Per channel the expected image position (x, y in [-1, 1]) of its softmax."""

        def forward(self, x):
            n, c, h, w = x.shape
            weights = torch.softmax(x.reshape(n, c, h * w), dim=-1).reshape(n, c, h, w)
            ys = torch.linspace(-1.0, 1.0, h, device=x.device)
            xs = torch.linspace(-1.0, 1.0, w, device=x.device)
            return torch.cat([(weights.sum(2) * xs).sum(-1), (weights.sum(3) * ys).sum(-1)], 1)

    class RingLocator(nn.Module):
        """Convolutions to keypoints, keypoints to rings."""

        def __init__(self):
            super().__init__()
            self.convolutions = nn.Sequential(
                nn.AvgPool2d(2),
                nn.Conv2d(3, channels, 5, stride=2, padding=2), nn.ReLU(),
                nn.Conv2d(channels, channels, 3, padding=1), nn.ReLU(),
                nn.Conv2d(channels, channels, 3, padding=1), nn.ReLU(),
                nn.Conv2d(channels, keypoints, 3, padding=1))
            self.keypoints = SpatialSoftmax()
            self.head = nn.Sequential(nn.Linear(2 * keypoints, hidden), nn.ReLU(),
                                      nn.Linear(hidden, hidden), nn.ReLU(), nn.Linear(hidden, 9))

        def forward(self, images):
            return self.head(self.keypoints(self.convolutions(images.float() / 127.5 - 1.0)))

    return RingLocator()


class SeeingPolicy:
    """A state policy acting on the rings a subclass's `locate(observation)` sees (the 18 ring
    values of a state), never on the true ones; `policy` is the state policy."""

    def reset(self):
        self.policy.reset()

    def act(self, observation):
        state = np.array(observation["state"], dtype=np.float64)
        state[RINGS] = self.locate(observation)  # the true rings are not seen
        return self.policy.act(state)


class ImagePolicy(SeeingPolicy):
    """Rings located from each arm's task camera, then a state policy acting on them."""

    def __init__(self, locator, policy, image_size):
        self.locator, self.policy, self.image_size = locator, policy, tuple(image_size)

    @property
    def env_kwargs(self):
        """The observations this policy needs of PegTransferEnv."""
        return {"obs": ("state", "rgb"), "camera": list(CAMERAS), "image_size": self.image_size}

    def fresh(self):
        return ImagePolicy(self.locator, self.policy.fresh(), self.image_size)

    def locate(self, observation):
        """Each arm's rings as its camera sees them: the 18 ring values of a state."""
        import torch
        images = torch.as_tensor(np.stack([seen_image(observation[image_key(a)], a)
                                           for a in (0, 1)]))
        with torch.no_grad():
            seen = self.locator(images).numpy().astype(np.float64)
        rings = np.zeros((6, 3))
        for arm in (0, 1):
            rings[RING_ROWS[arm]] = rings_in_world(seen[arm], arm)
        return rings.ravel()

    def save(self, path, **about):
        import torch
        torch.save({"kind": KIND, "locator": self.locator.state_dict(),
                    "image_size": list(self.image_size), "policy": self.policy.checkpoint(),
                    **about}, path)

    @staticmethod
    def from_checkpoint(saved, path):
        return ImagePolicy(locator_of(saved), Policy.from_checkpoint(saved["policy"], path),
                           saved["image_size"])


def locator_of(saved):
    """The ring locator an image policy's checkpoint holds (whatever its state policy)."""
    locator = make_locator()
    locator.load_state_dict(saved["locator"])
    locator.eval()
    return locator


def load_policy(path):
    """A state policy (imitation.Policy) or an image policy (vision.ImagePolicy or
    rgbd_policy.RgbdPolicy), whichever the file holds."""
    import torch

    from . import rgbd_policy
    saved = torch.load(path)
    if saved.get("kind") == KIND:
        return ImagePolicy.from_checkpoint(saved, path)
    if saved.get("kind") == rgbd_policy.KIND:
        return rgbd_policy.RgbdPolicy.from_checkpoint(saved, path)
    return Policy.from_checkpoint(saved, path)


def locator_samples(demo):
    """One demo's (images, rings seen) per arm, stacked: the locator's training rows.
    Every FRAME_STRIDE-th step; not those where one of the arm's rings is beyond WORKSPACE of
    where it starts (thrown off the board: nothing to see)."""
    states = np.asarray(demo["obs/state"])[::FRAME_STRIDE]
    images, rings = [], []
    for arm in (0, 1):
        seen = np.array([rings_seen(s[RINGS].reshape(6, 3)[RING_ROWS[arm]], arm) for s in states])
        kept = np.abs(seen).max(axis=1) < WORKSPACE * MM
        frames = demo[stored(image_key(arm))][()][::FRAME_STRIDE]
        images.append(seen_image(frames[kept], arm))
        rings.append(seen[kept])
    return np.concatenate(images), np.concatenate(rings)


def image_demos(paths):
    """Each demo of the files, in order, open while it is used; one without both task cameras'
    images is an error naming the file and the demo."""
    import h5py
    for path in paths:
        with h5py.File(path, "r") as f:
            for k in sorted(f["data"].keys(), key=lambda k: int(k[5:])):
                if stored(image_key(0)) not in f["data"][k]:
                    raise ValueError(f"{path}: {k} has no {CAMERAS} images (record with --obs "
                                     f"state,rgb --camera {','.join(CAMERAS)})")
                yield f["data"][k]


def load_locator_samples(paths):
    parts = [locator_samples(demo) for demo in image_demos(paths)]
    return tuple(np.concatenate([p[i] for p in parts]) for i in range(2))


def with_located_rings(demo, locator, batch=256):
    """One demo's states with the rings its task cameras show (the locator's reading of each
    step's images) in place of the recorded ones: what an image policy's acting part is given."""
    import torch
    states = np.array(demo["obs/state"], dtype=np.float64)
    rings = states[:, RINGS].reshape(len(states), 6, 3)
    for arm in (0, 1):
        frames = demo[stored(image_key(arm))]
        with torch.no_grad():
            seen = np.concatenate([locator(torch.as_tensor(seen_image(frames[i:i + batch], arm)))
                                   .numpy() for i in range(0, len(states), batch)])
        rings[:, RING_ROWS[arm]] = rings_in_world(seen, arm)
    states[:, RINGS] = rings.reshape(len(states), -1)
    return states


def load_located(paths, locator):
    """Every demo of the files: its states with located rings (with_located_rings), its
    waypoints and the operator's jobs, as demos.load_all gives them with the recorded rings."""
    states, waypoints, jobs = [], [], []
    for demo in image_demos(paths):
        states.append(with_located_rings(demo, locator))
        waypoints.append(np.asarray(demo["waypoints"]))
        jobs.append(expert_jobs_of(demo))
    return states, waypoints, jobs


def fit_locator(images, rings, epochs, batch=128, lr=1e-3, seed=0, log=print, start=None):
    """Trains a RingLocator (a new one, or on from `start`): mean squared error in mm, Adam with
    a cosine schedule. Returns it, with its mean error (mm) on the last epoch's batches and the
    seconds it took."""
    import torch
    torch.manual_seed(seed)
    locator = make_locator() if start is None else start.train()
    images = torch.as_tensor(images)
    rings = torch.as_tensor(rings, dtype=torch.float32)

    def ring_error(predicted, target, _):  # summed over the batch's rings, mm
        return (predicted - target).reshape(-1, 3, 3).norm(dim=2).sum().item()

    def log_epoch(epoch, total, seconds):
        log(f"epoch {epoch}: ring error {total / (3 * len(images)):.2f} mm ({seconds:.0f} s)")

    total, seconds = train_network(locator, images, rings, epochs, batch, lr, seed,
                                   ring_error, log_epoch)
    return locator, total / (3 * len(images)), seconds
