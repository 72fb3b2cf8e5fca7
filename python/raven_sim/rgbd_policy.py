"""The RGB-D image policy: each arm's rings fitted in its own task camera's colour and depth
images (ring_fit), then the state policy's network acting on them.

It sees what vision.ImagePolicy sees, each arm's task camera and the arm's own joints, with the
depth image beside the colour one (an RGB-D camera, or a stereo pair's depth), and it knows the
camera's calibration (raven_sim.task_camera), the board's and the ring's shapes
(raven_sim.peg_layout), as a robot's perception of known objects does. From each episode's first
images it finds where each camera really is from the board it sees (board_calibration: a camera
mounted again sits millimetres from its calibration). Nothing of the world's state is read: a
test gives it rings a kilometre away in the state and it acts the same.
"""

import numpy as np

from ._raven_sim import task_camera
from .board_calibration import calibrate
from .imitation import LAYOUT, REST_Z, Policy
from .ring_fit import RingShape, RingTracker, TaskCamera
from .vision import CAMERAS, RING_ROWS, SeeingPolicy, image_key

KIND = "image policy: rings fitted in each arm's RGB-D task camera + imitation.Policy"
POSTS = np.array([p for j in LAYOUT["jobs"] for p in (j["from"], j["to"])])


def depth_key(arm):
    return f"{CAMERAS[arm]}/depth"


class RgbdPolicy(SeeingPolicy):
    """Rings fitted in each arm's RGB-D task camera, then a state policy acting on them."""

    def __init__(self, policy, image_size=(128, 96)):
        self.policy, self.image_size = policy, tuple(image_size)
        self.shape = RingShape.of_layout(LAYOUT)
        self.cameras = [TaskCamera(**task_camera(arm)) for arm in (0, 1)]  # as calibrated
        self.reset()

    @property
    def env_kwargs(self):
        """The observations this policy needs of PegTransferEnv."""
        return {"obs": ("state", "rgb", "depth"), "camera": list(CAMERAS),
                "image_size": self.image_size}

    def reset(self):
        """A new episode: the cameras to be found again from its first images."""
        super().reset()
        self.trackers = None

    def start(self, observation):
        """Each camera found from the board in its first images, and its rings lying on their
        start posts until the images say otherwise."""
        self.trackers = []
        for arm in (0, 1):
            camera = calibrate(self.cameras[arm], observation[image_key(arm)],
                               observation[depth_key(arm)], LAYOUT, POSTS)
            starts = [[*LAYOUT["jobs"][i]["from"], REST_Z] for i in RING_ROWS[arm]]
            self.trackers.append(RingTracker(camera, self.shape, starts, POSTS))

    def fresh(self):
        return RgbdPolicy(self.policy.fresh(), self.image_size)

    def locate(self, observation):
        """Each arm's rings as its camera sees them: the 18 ring values of a state."""
        if self.trackers is None:
            self.start(observation)
        rings = np.zeros((6, 3))
        for arm in (0, 1):
            rings[RING_ROWS[arm]] = self.trackers[arm].update(observation[image_key(arm)],
                                                              observation[depth_key(arm)])
        return rings.ravel()

    def save(self, path, **about):
        import torch
        torch.save({"kind": KIND, "image_size": list(self.image_size),
                    "policy": self.policy.checkpoint(), **about}, path)

    @staticmethod
    def from_checkpoint(saved, path):
        return RgbdPolicy(Policy.from_checkpoint(saved["policy"], path), saved["image_size"])
