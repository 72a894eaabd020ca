"""What an animation shows, as numbers: the body's shape, and the motion sampled at the frames.

The body is drawn as what its moments make it (:func:`body_mesh`):

* a symmetric body (I1 = I2) is a top: a uniform disc (a cylinder of radius r and thickness H)
  on a spindle along ê₃. A uniform cylinder of mass M has I3 = M r²/2 and, about its centre,
  I1c = M (r²/4 + H²/12), so r = √(2 I3 / M) and H = r √(6 (I1c/I3 − 1/2)). With gravity and
  the centre of mass on the axis at height l, the disc sits at l and I1c = I1 − M l² (the
  parallel-axis theorem: I1 is about the pivot); otherwise the disc is centred on the pivot
  (the centre of mass of a free body) with I1c = I1. A disc thinner than what the moments
  allow is drawn with a visible thickness (:data:`MIN_THICKNESS` r).
* an asymmetric body is the uniform box with those principal moments: half-widths
  bᵢ = √(3 (I_j + I_k − I_i) / (2 M)), centred on the centre of mass (on the pivot when free),
  with a rod along ê₃ out to the unit sphere.

The drawing is scaled so that the tip of ê₃'s spindle lies on the unit sphere, where the trace
of the axis is drawn. An off-axis centre of mass (a Kovalevskaya top) is marked with a dot.

The motion at a frame time (:func:`frames`) is R(t) between two samples tₖ < t < tₖ₊₁ of the
result, each R from the result's z-y-z angles (:func:`derive.reference.rotation.euler_matrix`):
turned forward from Rₖ and back from Rₖ₊₁ by the body angular velocity, taken linear between
the samples (Ṙ = R[ω̃]ₓ, so R(t) ≈ Rₖ exp([∫ₜₖᵗ ω̃ ds]ₓ), the Magnus series to second order),
the two blended in proportion to the time from each and made orthogonal again.
A spin of several turns between samples is followed (the angular velocity says how far the
body turned), which interpolating the angles or a shortest-path slerp would not; at a sample
time the frame is the sample's rotation exactly.

Fast spins (:func:`spin_note`): when the body turns more than :data:`STROBE_TURN` of a turn
about its axis between two frames, no frame rate shows the spin; the stripe on the disc is then
drawn where it truly is at each frame, like a stroboscope flashing at the frame rate, and the
caption says so (its apparent turning is aliasing, not the spin).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from derive.errors import SceneError
from derive.reference.rotation import euler_angles, euler_matrix
from derive.symbolic import effects as fx

#: Above this much of a turn about ê₃ between frames the spin is drawn stroboscopically: at half
#: a turn a single stripe's direction of turning cannot be told, and well before that it jumps.
STROBE_TURN = 0.25
#: Thinnest disc drawn, as a fraction of its radius (a thin disc would vanish edge-on).
MIN_THICKNESS = 0.08
#: Default frames per second (a GIF's frame delay is in hundredths of a second: 5 of them).
DEFAULT_FPS = 20
#: The largest frame rate (GIF viewers slow down delays under two hundredths of a second).
MAX_FPS = 50
#: The most frames one animation may hold.
MAX_FRAMES = 3000
#: The default time scale makes the symmetry axis turn about this fast on screen, rad/s ...
AXIS_RATE_ON_SCREEN = 1.0
#: ... within these bounds on the animation's length, s.
WALL_SECONDS = (4.0, 12.0)
#: Sides of the disc's cylinder (and sectors of its faces).
SIDES = 24
#: The stripe covers this many sectors of the disc.
STRIPE_SECTORS = 2

BODY = (0.85, 0.47, 0.16)     # orange
STRIPE = (0.10, 0.20, 0.55)   # dark blue
SPINDLE = (0.35, 0.35, 0.38)  # grey
AXIS_FACES = (0.20, 0.45, 0.75)  # the box's ±ê₃ faces


@dataclass
class Mesh:
    """A body as flat faces in body axes: ``verts`` (m, 3), ``faces`` (a list of index lists,
    counter-clockwise seen from outside), ``colors`` (one RGB per face), ``layers`` (per face:
    −1 the spindle below the body, 0 the body, +1 the spindle above it, along ê₃), ``com`` (the
    centre of mass to mark, or None), ``kind`` ("top" or "box") and ``shape`` (what the shape
    was made from, in words).

    The layers order what a painter's sort by depth gets wrong: seen from the +ê₃ side, the
    spindle below the body is behind it and the part above in front; from the −ê₃ side the
    other way round (:meth:`order`)."""

    verts: np.ndarray
    faces: list
    colors: list
    layers: list
    com: np.ndarray | None
    kind: str
    shape: str

    def order(self, depth: np.ndarray, toward_viewer: float) -> np.ndarray:
        """Indices of faces far to near: by layer (signed by which side of the body ê₃ shows,
        ``toward_viewer`` = ê₃ · direction to the viewer), then by ``depth`` (toward the viewer)."""
        side = 1.0 if toward_viewer >= 0 else -1.0
        return np.lexsort((depth, side * np.asarray(self.layers, dtype=float)))

    def normals(self) -> np.ndarray:
        """Outward unit normals (f, 3), from each face's first three vertices."""
        a, b, c = self.verts[np.array([f[:3] for f in self.faces])].transpose(1, 0, 2)
        n = np.cross(b - a, c - a)
        norm = np.linalg.norm(n, axis=1, keepdims=True)
        return n / np.where(norm > 0, norm, 1.0)


def _gravity(scene):
    g = scene.tables.get(fx.GRAVITY_TABLE.name) if scene is not None else None
    if g is None:
        return None, None
    return float(g["M"]), np.asarray(g["com"], dtype=float)


def body_mesh(scene) -> Mesh:
    """The body drawn for a scene, scaled so that the tip of ê₃'s spindle is at distance 1.

    Parameters
    ----------
    scene : derive.sim.scene.Scene
        Its ``body`` (I1, I2, I3) and, if present, its gravity table (M, com).

    Returns
    -------
    Mesh
        A top for a symmetric body, a box for an asymmetric one (see the module docstring).
    """
    I1, I2, I3 = scene.body.moments
    M, com = _gravity(scene)
    if scene.symmetric:
        return _top(I1, I3, M, com)
    return _box(I1, I2, I3, M, com)


def _top(I1, I3, M, com) -> Mesh:
    on_axis = com is not None and abs(com[0]) + abs(com[1]) <= 1e-12 * max(abs(com[2]), 1e-300)
    r = math.sqrt(2.0 * I3 / M) if M else 1.0
    if on_axis and com[2] != 0:
        centre, I1c, where = float(com[2]), I1 - M * com[2] ** 2, "at the centre of mass, l along ê₃ from the pivot"
    else:
        centre, I1c, where = 0.0, I1, "centred on the pivot" if com is not None else "centred on the centre of mass"
    H = r * math.sqrt(max(6.0 * (I1c / I3 - 0.5), 0.0))
    thin = H < MIN_THICKNESS * r
    H = max(H, MIN_THICKNESS * r)
    end = H / 2 + 0.6 * r  # the spindle's reach beyond the disc's centre
    lo = min(0.0, centre - end) if centre <= 0 else 0.0  # a top on its tip: the spindle starts at the pivot
    hi = centre + end if centre >= 0 else 0.0
    s = 1.0 / max(hi, -lo)
    verts, faces, colors, layers = [], [], [], []
    bottom, top = s * (centre - H / 2), s * (centre + H / 2)
    _cylinder(verts, faces, colors, s * r, bottom, top, SIDES, BODY, stripe=True)
    layers += [0] * len(faces)
    _spindle(verts, faces, colors, layers, 0.035, s * lo, bottom, top, 1.0)  # its tip on the unit sphere
    mark = None if com is None or on_axis else s * com
    shape = (f"a top: a uniform disc {where}, radius and thickness from I3 and I1 "
             f"(r = sqrt(2 I3/M), H = r sqrt(6 (I1c/I3 - 1/2))){', drawn thicker than its moments say' if thin else ''}"
             + ("" if M else "; no mass given: proportions only"))
    return Mesh(np.array(verts), faces, colors, layers, mark, "top", shape)


def _spindle(verts, faces, colors, layers, r, z0, bottom, top, z1):
    """A rod along ê₃ from z0 to z1 outside the body's span [bottom, top]: the part below (layer
    −1) and the part above (+1)."""
    for lo, hi, layer in ((z0, min(bottom, z1), -1), (max(top, z0), z1, 1)):
        if hi - lo > 1e-9:
            before = len(faces)
            _cylinder(verts, faces, colors, r, lo, hi, 6, SPINDLE, stripe=False,
                      segments=max(1, int(round(6 * (hi - lo)))))
            layers += [layer] * (len(faces) - before)


def _cylinder(verts, faces, colors, r, z0, z1, n, color, stripe, segments=1):
    """Append a closed cylinder about ê₃ from z0 to z1 (``segments`` rings along it, so that a
    long spindle sorts well against the disc); ``stripe`` colours sectors 0.. of it."""
    k0 = len(verts)
    rings = np.linspace(z0, z1, segments + 1)
    ang = 2 * np.pi * (np.arange(n) + 0.5) / n
    for z in rings:
        verts.extend([r * math.cos(a), r * math.sin(a), z] for a in ang)
    for j in range(segments):
        for i in range(n):
            a, b = k0 + j * n + i, k0 + j * n + (i + 1) % n
            faces.append([a, b, b + n, a + n])
            colors.append(STRIPE if stripe and i < STRIPE_SECTORS else color)
    bottom, top = len(verts), len(verts) + 1
    verts.extend([[0.0, 0.0, z0], [0.0, 0.0, z1]])
    last = k0 + segments * n
    for i in range(n):
        a, b = k0 + i, k0 + (i + 1) % n
        faces.append([bottom, b, a])
        colors.append(color)
        a, b = last + i, last + (i + 1) % n
        faces.append([top, a, b])
        colors.append(STRIPE if stripe and i < STRIPE_SECTORS else color)


def _box(I1, I2, I3, M, com) -> Mesh:
    mass = M or 1.0
    half = np.sqrt(np.maximum(3.0 * (np.array([I2 + I3 - I1, I1 + I3 - I2, I1 + I2 - I3])) / (2.0 * mass),
                              1e-6 * max(I1, I2, I3) / mass))
    centre = com if com is not None else np.zeros(3)
    reach = float(np.linalg.norm(centre) + np.linalg.norm(half))
    s = 0.65 / reach  # (room on the unit sphere for the path of ê₃ around it)
    c, h = s * centre, s * half
    verts = [c + h * np.array([x, y, z]) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    faces = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
    colors = [BODY, BODY, BODY, BODY, AXIS_FACES, AXIS_FACES]
    verts, layers = [list(v) for v in verts], [0] * len(faces)
    _spindle(verts, faces, colors, layers, 0.03, 0.0, c[2] - h[2], c[2] + h[2], 1.0)
    shape = ("a box: the uniform box with the body's principal moments, half-widths "
             "b_i = sqrt(3 (I_j + I_k - I_i) / (2 M)); its ±ê₃ faces blue; a rod along ê₃"
             + ("" if M else "; no mass given: proportions only"))
    return Mesh(np.array(verts), faces, colors, layers, None if com is None else c, "box", shape)


# ---------------------------------------------------------------------------------------------
# the motion at the frames


@dataclass
class Frames:
    """The motion at the animation's frames: ``t`` (k,) simulated times, ``R`` (k, 3, 3) body →
    inertial, ``angles`` (k, 3) z-y-z angles of R (rad; α, γ wrapped to (−π, π]), ``L`` (k, 3)
    the angular momentum in inertial axes divided by max |L|; ``fps`` and ``speed`` (simulated
    seconds per wall second); ``trace_t`` and ``trace`` the result's samples of ê₃ (for the path
    drawn up to each frame); ``spin_turns`` the largest turn of the body between two frames (in
    turns: about ê₃ for a top, in all for a box); ``title`` and ``notes`` (what the caption
    says: the time scale, how the spin is drawn)."""

    t: np.ndarray
    R: np.ndarray
    angles: np.ndarray
    L: np.ndarray
    fps: int
    speed: float
    trace_t: np.ndarray
    trace: np.ndarray
    spin_turns: float
    title: str
    notes: list

    @property
    def axis(self) -> np.ndarray:
        """ê₃ in inertial axes at each frame, (k, 3): the third column of R."""
        return self.R[:, :, 2]

    @property
    def strobe(self) -> bool:
        """Whether the spin is drawn stroboscopically (:data:`STROBE_TURN`)."""
        return self.spin_turns > STROBE_TURN


def check_settings(fps, speed, names=("fps", "speed")) -> None:
    """SceneError naming the key (``names``: how the caller calls them, ``--fps`` on the command
    line) for a frame rate or a time scale no animation can have."""
    if fps is not None and (isinstance(fps, bool) or not isinstance(fps, (int, float)) or not math.isfinite(fps)
                            or not float(fps).is_integer() or not 1 <= fps <= MAX_FPS):
        raise SceneError(f"animate: {names[0]}: must be a whole number from 1 to {MAX_FPS} (got {fps!r})")
    if speed is not None and (isinstance(speed, bool) or not isinstance(speed, (int, float))
                              or not math.isfinite(speed) or speed <= 0):
        raise SceneError(f"animate: {names[1]}: must be a positive number of simulated seconds per second "
                         f"(got {speed!r})")


def default_speed(res) -> float:
    """Simulated seconds per wall second when none is given: the symmetry axis turns at about
    :data:`AXIS_RATE_ON_SCREEN` rad/s on screen (its 90th-percentile rate |dê₃/dt|, where
    nutation and precession show), within an animation of :data:`WALL_SECONDS`."""
    t = np.asarray(res.t, dtype=float)
    span = float(t[-1] - t[0])
    if span <= 0:
        return 1.0
    rate = np.linalg.norm(np.diff(res.axis, axis=0), axis=1) / np.diff(t)
    fast = float(np.percentile(rate, 90)) if rate.size else 0.0
    speed = AXIS_RATE_ON_SCREEN / fast if fast > 0 else math.inf
    lo, hi = WALL_SECONDS
    return float(min(max(speed, span / hi), span / lo))


def _exp(w: np.ndarray) -> np.ndarray:
    """exp([w]ₓ) for rotation vectors w (k, 3): the rotation by |w| about w."""
    from scipy.spatial.transform import Rotation

    return Rotation.from_rotvec(w).as_matrix()


def _orthogonal(M: np.ndarray) -> np.ndarray:
    """The rotation nearest each matrix (..., 3, 3) (the polar factor U Vᵀ of its SVD)."""
    U, _, Vt = np.linalg.svd(M)
    return U @ Vt


def rotation_at(res, t: np.ndarray) -> np.ndarray:
    """R(t) (k, 3, 3) at times within the run, from the samples of ``res`` (module docstring)."""
    ts = np.asarray(res.t, dtype=float)
    Rs = euler_matrix(res.alpha, res.beta, res.gamma)
    w = np.asarray(res.omega, dtype=float)
    k = np.clip(np.searchsorted(ts, t, side="right") - 1, 0, max(len(ts) - 2, 0))
    if len(ts) < 2:
        return np.repeat(Rs[:1], len(t), axis=0)
    h = ts[k + 1] - ts[k]
    tau = np.clip(t - ts[k], 0.0, h)
    # ω̃ linear between the samples: ∫ω̃ from tₖ to t and from t to tₖ₊₁
    slope = (w[k + 1] - w[k]) / np.where(h > 0, h, 1.0)[:, None]
    back = (h - tau)[:, None]
    A = Rs[k] @ _exp(w[k] * tau[:, None] + slope * (tau ** 2 / 2)[:, None])
    B = Rs[k + 1] @ _exp(-(w[k + 1] * back - slope * back ** 2 / 2))
    s = np.where(h > 0, tau / np.where(h > 0, h, 1.0), 0.0)[:, None, None]
    R = _orthogonal((1 - s) * A + s * B)
    # at a sample (up to the round-off of the frame times): the sample's own rotation, bit for bit
    near = np.where(tau <= 0.5 * h, k, k + 1)
    at = np.abs(t - ts[near]) <= 1e-9 * h
    R[at] = Rs[near[at]]
    return R


def _interp(ts, values, t):
    return np.stack([np.interp(t, ts, values[:, j]) for j in range(values.shape[1])], axis=1)


def frame_times(res, fps, speed) -> tuple[int, float, np.ndarray, np.ndarray]:
    """(fps, speed, the result's times, the frame times t₀ + k·speed/fps up to its end), the
    defaults filled in; SceneError for settings no animation can have or too many frames."""
    check_settings(fps, speed)
    fps = int(fps or DEFAULT_FPS)
    speed = float(speed or default_speed(res))
    ts = np.asarray(res.t, dtype=float)
    count = int(math.floor((ts[-1] - ts[0]) * fps / speed * (1 + 1e-12))) + 1
    if count > MAX_FRAMES:
        raise SceneError(f"animate: speed: {count} frames at {fps} frames per second and {speed:g} simulated "
                         f"seconds per second; at most {MAX_FRAMES} (raise the speed, --speed, or lower fps, --fps)")
    return fps, speed, ts, ts[0] + np.arange(count) * (speed / fps)


def frames(res, fps: int | None = None, speed: float | None = None, title: str = "") -> Frames:
    """The motion of ``res`` at the frames of an animation.

    Parameters
    ----------
    res : derive.sim.simulation.Result
        The arrays ``t``, ``alpha``, ``beta``, ``gamma``, ``omega``, ``axis``, ``L``.
    fps : int, optional
        Frames per wall second (default :data:`DEFAULT_FPS`).
    speed : float, optional
        Simulated seconds per wall second (default :func:`default_speed`).
    title : str
        The caption's title.

    Returns
    -------
    Frames
        Frame k at simulated time t₀ + k·speed/fps, up to the end of the run: ⌊(t_end − t₀)·
        fps/speed⌋ + 1 frames.
    """
    fps, speed, ts, t = frame_times(res, fps, speed)
    R = rotation_at(res, t)
    a, b, g = euler_angles(R, unwrap=False)
    Lb = _interp(ts, np.asarray(res.L, dtype=float), t)
    L = np.einsum("kij,kj->ki", R, Lb)
    big = float(np.max(np.linalg.norm(res.L, axis=1))) or 1.0
    w = np.asarray(res.omega, dtype=float)
    dt = speed / fps
    symmetric = res.scene is None or res.scene.symmetric
    rate = np.abs(w[:, 2]) if symmetric else np.linalg.norm(w, axis=1)
    spin = float(rate.max()) * dt / (2 * np.pi)
    fr = Frames(t, R, np.stack([a, b, g], axis=1), L / big, fps, speed, ts, np.asarray(res.axis, dtype=float),
                spin, title, [])
    fr.notes = [time_note(fr), spin_note(fr, float(rate.max()), symmetric)]
    return fr


def time_note(fr: Frames) -> str:
    """The time scale in words."""
    if fr.speed >= 1:
        scale = f"time ×{fr.speed:.3g}: 1 s on screen is {fr.speed:.3g} s of the motion"
    else:
        scale = f"slowed ×{1 / fr.speed:.3g}: 1 s on screen is {fr.speed * 1e3:.3g} ms of the motion"
    return f"{scale}; {fr.fps} frames/s, one every {fr.speed / fr.fps * 1e3:.3g} ms"


def spin_note(fr: Frames, rate: float, symmetric: bool) -> str:
    """How the spin is drawn: frame by frame, or (above :data:`STROBE_TURN` of a turn between
    frames) stroboscopically."""
    what = "spin about ê₃" if symmetric else "rotation"
    hz = rate / (2 * np.pi)
    if fr.strobe:
        return (f"{what} up to {rate:.3g} rad/s ({hz:.3g} turns/s), {fr.spin_turns:.3g} turns between frames: "
                f"too fast to show; the {'stripe' if symmetric else 'body'} is drawn where it is at each "
                f"frame (stroboscopic), its apparent turning is not the spin")
    return f"{what} up to {rate:.3g} rad/s, at most {fr.spin_turns:.2g} turns between frames: drawn as it turns"
