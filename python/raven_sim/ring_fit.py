"""Rings found in an RGB-D camera by fitting the ring's known shape to the points the camera
sees of it: the classical way a robot locates a known object with a calibrated depth camera
(a model fit, as ICP is), where vision.RingLocator learns it from images.

Each task camera (left-task, right-task) gives a colour image and a depth image (m along its
axis). A ring's pixels are told by their colour (red: well above green and blue, under any light
or tint of the shipped looks), taken back into the world through the camera's pose and field of
view (its calibration), and a ring's surface is fitted to them by least squares: its centre and,
for a ring that is lifted or tipped, its axis. The surface is the design's ring (a tube of
elliptical section around a centre line) as the camera sees it: a twin's ring is drawn as a
polygon mesh whose faces lie inside the smooth surface, so each radius is scaled by the mean
distance of a polygon's sides (`facet_scale`); a real ring is smooth (scale 1).

Each arm's tracker keeps its three rings from one image to the next: a ring's points are the
coloured points nearest its last estimate, and its fit starts from that estimate, from the
points' centroid and from the nearest post (a ring that dropped onto a post, or was pushed,
would leave a fit from the last estimate in a wrong minimum). A ring with no points near its
estimate while coloured points lie apart from every ring has left it faster than a step moves
(slipped from the jaws and fallen): it is taken up from the nearest such group of points. A ring
the camera cannot see at all (the tool in front of it) keeps its last estimate.
"""

import math

import numpy as np

# A ring's points: within this of its last estimate (m); a ring moves far less between steps.
GATE = 0.015
MOST_POINTS_MISSING = 8  # fewer points than this: the ring is not seen, its estimate is kept
ABOVE_POST = 0.012  # m: a fit also starts on the nearest post within this of the ring
FRONT_HALF = 0.004  # m: a ring's centre lies this far behind the centroid of its visible half
ROBUST_SCALE = 0.0005  # m: residuals beyond this count less (soft L1): a stray pixel
# A fit whose points lie this near its surface (root mean square, m) is taken without trying
# other starts: the twin's rendered rings fit to 0.02-0.08 mm, a wrong minimum to 0.6 mm.
GOOD_FIT = 0.00025


def facet_scale(sides):
    """The mean distance from the centre of a regular polygon's sides (sides > 2) to its
    circumradius: cos(t) atanh(sin t) / t with t = pi / sides; 1 for a smooth outline (0)."""
    if sides <= 0:
        return 1.0
    t = math.pi / sides
    return math.cos(t) * math.atanh(math.sin(t)) / t


class RingShape:
    """The ring's surface as a camera sees it: centre-line radius, and the tube's radial and
    axial semi-axes (m)."""

    def __init__(self, major_radius, tube_half_width, half_height, stations=0, tube_stations=0):
        around, section = facet_scale(stations), facet_scale(tube_stations)
        self.radius = around * major_radius
        self.radial = around * section * tube_half_width
        self.axial = section * half_height

    @staticmethod
    def of_layout(layout):
        """The twin's ring as drawn (raven_sim.peg_layout())."""
        return RingShape(layout["ring_radius"], layout["ring_tube_half_width"],
                         layout["ring_height"] / 2, layout["ring_stations"],
                         layout["ring_tube_stations"])

    def distances(self, points, centre, axis):
        """Each point's distance from the surface (m, outside positive; first order)."""
        axis = axis / np.linalg.norm(axis)
        offset = points - centre
        along = offset @ axis
        radial = np.linalg.norm(offset - np.outer(along, axis), axis=1)
        p = (radial - self.radius) / self.radial
        q = along / self.axial
        level = np.sqrt(p * p + q * q) + 1e-12
        slope = np.sqrt((p / self.radial) ** 2 + (q / self.axial) ** 2) / level + 1e-12
        return (level - 1.0) / slope


def fit_ring(shape, points, start):
    """The ring's centre (3,) fitted to `points` (N, 3) from `start`, its axis free to tip, and
    the fit's cost (half the sum of the robust squared residuals)."""
    from scipy.optimize import least_squares

    def residuals(x):
        return shape.distances(points, x[:3], np.array([x[3], x[4], 1.0]))

    fit = least_squares(residuals, np.concatenate([start, [0.0, 0.0]]), loss="soft_l1",
                        f_scale=ROBUST_SCALE, max_nfev=60)
    return fit.x[:3], fit.cost


class TaskCamera:
    """A calibrated camera: its eye, where it looks and its vertical field of view (the twin's
    raven_sim.task_camera(name), or a real camera's calibration)."""

    def __init__(self, eye, target, fov_y, depth_scale=1.0):
        """`depth_scale`: what its depth reads per metre (an RGB-D camera's depth bias)."""
        self.depth_scale = float(depth_scale)
        self.eye = np.asarray(eye, dtype=np.float64)
        self.target = np.asarray(target, dtype=np.float64)
        forward = self.target - self.eye
        self.forward = forward / np.linalg.norm(forward)
        side = np.cross(self.forward, [0.0, 0.0, 1.0])
        self.side = side / np.linalg.norm(side)
        self.up = np.cross(self.side, self.forward)
        self.fov_y = float(fov_y)

    def points(self, depth, mask):
        """The world points (N, 3) of the pixels in `mask` with a finite depth (m along the
        axis), rows top first."""
        height, width = depth.shape
        rows, cols = np.nonzero(mask & np.isfinite(depth))
        along = depth[rows, cols].astype(np.float64) / self.depth_scale
        half = math.tan(self.fov_y / 2)
        right = (2 * (cols + 0.5) / width - 1) * half * width / height * along
        up = (1 - 2 * (rows + 0.5) / height) * half * along
        return (self.eye + np.outer(right, self.side) + np.outer(up, self.up)
                + np.outer(along, self.forward))


def ring_pixels(rgb):
    """The pixels of a ring's colour: red well above green and blue (H, W bool)."""
    c = np.asarray(rgb, dtype=np.float64) + 1.0
    red, green, blue = c[..., 0], c[..., 1], c[..., 2]
    return (red > 1.6 * green) & (red > 1.6 * blue) & (red > 40.0)


class RingTracker:
    """One camera's rings, kept from image to image."""

    def __init__(self, camera, shape, starts, posts):
        """`starts` (K, 3): where the rings are before the first image; `posts` (P, 2): the
        posts' x, y."""
        self.camera, self.shape = camera, shape
        self.estimates = np.array(starts, dtype=np.float64)
        self.posts = np.asarray(posts, dtype=np.float64).reshape(-1, 2)
        self.fitted_to = [None] * len(self.estimates)  # the points each estimate was fitted to
        # Away from the camera in the board's plane: a ring's centre lies behind its visible half.
        away = np.array([camera.forward[0], camera.forward[1], 0.0])
        self.behind = FRONT_HALF * away / np.linalg.norm(away)

    def update(self, rgb, depth):
        """The rings (K, 3) after this image pair."""
        points = self.camera.points(np.asarray(depth, dtype=np.float64), ring_pixels(rgb))
        if len(points) == 0:
            return self.estimates.copy()
        distance = np.stack([np.linalg.norm(points - e, axis=1) for e in self.estimates])
        owner = distance.argmin(axis=0)
        near = distance.min(axis=0) < GATE
        for ring in range(len(self.estimates)):
            mine = points[(owner == ring) & near]
            if len(mine) < MOST_POINTS_MISSING:
                mine = self.fallen(points[~near], ring)
            same = self.fitted_to[ring] is not None and np.array_equal(mine, self.fitted_to[ring])
            if len(mine) >= MOST_POINTS_MISSING and not same:  # a still scene: the same fit
                self.estimates[ring] = self.best_fit(mine, self.estimates[ring])
                self.fitted_to[ring] = mine
        return self.estimates.copy()

    def fallen(self, apart, ring):
        """The points of one ring's size (any of its points within its diameter of the one
        nearest `ring`'s estimate) among those `apart` from every ring: where a ring that left
        its estimate lies; none if too few."""
        if len(apart) < MOST_POINTS_MISSING:
            return apart[:0]
        nearest = apart[np.linalg.norm(apart - self.estimates[ring], axis=1).argmin()]
        across = 2.0 * (self.shape.radius + self.shape.radial)
        return apart[np.linalg.norm(apart - nearest, axis=1) < across]

    def best_fit(self, points, last):
        """The fit from the last estimate if it is good, else the lowest-cost fit over that and
        two more starts: behind the visible half's centroid, and the nearest post at the last
        height."""
        fits = [fit_ring(self.shape, points, last)]
        if math.sqrt(2.0 * fits[0][1] / len(points)) <= GOOD_FIT:
            return fits[0][0]
        starts = [points.mean(axis=0) + self.behind]
        to_post = np.linalg.norm(self.posts - last[:2], axis=1)
        if len(to_post) and to_post.min() < ABOVE_POST:
            starts.append(np.array([*self.posts[to_post.argmin()], last[2]]))
        fits += [fit_ring(self.shape, points, start) for start in starts]
        return min(fits, key=lambda fit: fit[1])[0]
