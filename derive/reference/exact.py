"""Closed-form solutions of the lecture's rigid-body problems: references for the integrators.

Conventions (those of the whole package): z-y-z Euler angles, R = Rz(alpha) Ry(beta) Rz(gamma)
with active elementary rotations, R maps body components to inertial ones (v_in = R v_body);
omega = (w1, w2, w3) are body components; the symmetry axis e3 in inertial components is
R[:, 2] = (sin b cos a, sin b sin a, cos b); w1 = -a' sin b cos g + b' sin g,
w2 = a' sin b sin g + b' cos g, w3 = a' cos b + g'. Gravity g points along -z.

Three problems, each returning a ``Trajectory``:

* ``free_symmetric`` - torque-free body with I1 = I2 (lecture: w1 + i w2 = A e^{i(Omega t + phi)},
  Omega = w3 (I3 - I1)/I1) and its orientation;
* ``free_asymmetric`` - torque-free body with three moments, Jacobi elliptic functions in both
  regimes and on the separatrix, orientation from the invariable plane;
* ``heavy_top`` - symmetric top with a fixed point in uniform gravity, u = cos(beta) from the
  cubic of the notes, alpha and gamma in closed form with elliptic integrals of the third kind.

Continuous Euler angles. The heavy top's alpha, beta, gamma are continuous in t. When the axis
passes exactly through the vertical (p_alpha = p_gamma, so u = 1 is a root) beta changes sign
instead of alpha jumping by pi: (alpha, beta, gamma) and (alpha + pi, -beta, gamma + pi) are the
same orientation, and the Lagrangian is even in beta, so the smooth continuation is a solution.
Likewise through beta = pi (p_alpha = -p_gamma) beta continues past pi, and a top that goes over
the top (p_alpha = p_gamma = 0) has beta growing without bound. If p_alpha - p_gamma is not zero
but so small that the axis would pass within ~16 ulp (4e-15 rad) of the vertical, it is set to
zero: the orientation changes by less than that angle, and the angles stay smooth instead of
alpha and gamma jumping by +-pi within ~1e-15 s. A top that sleeps exactly (beta0 = 0,
beta-dot0 = 0) stays at beta = 0 whether or not p_gamma^2 >= 4 M g l I1 (an unstable equilibrium
is still an equilibrium); alpha and gamma then keep their initial rates, only their sum being
defined. The free-body solutions report Euler angles extracted from R (see ``euler_angles``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from types import MappingProxyType
from typing import Mapping

import numpy as np
from scipy import optimize

from derive.reference.elliptic import elliptic_f_from_jacobi, reduce_argument, sn2_rational_integral
from derive.reference.rotation import _rz, euler_angles, euler_matrix

__all__ = [
    "Trajectory",
    "free_symmetric",
    "free_asymmetric",
    "heavy_top",
    "euler_matrix",
    "euler_angles",
]

_EPS = float(np.finfo(float).eps)
# Closest approach to a pole (in rad) below which p_alpha -+ p_gamma is treated as zero.
_POLE_SNAP = 16 * _EPS


@dataclass(frozen=True)
class Trajectory:
    """Samples of an exact solution at the times t (n samples).

    omega (n, 3) body angular velocity; R (n, 3, 3) body -> inertial; axis (n, 3) = R[:, :, 2];
    alpha, beta, gamma (n,) z-y-z Euler angles (continuous, see the module docstring);
    energy = 1/2 sum I_i w_i^2 + M g l axis_z, p_alpha = (R I omega)_z (inertial z component of
    the angular momentum), p_gamma = I3 w3 - all three computed from the returned omega and R,
    so their constancy is a check of the solution, not an assumption.
    inertia = (I1, I2, I3), mgl = M g l (0 for free bodies); info holds solution parameters
    (regime, elliptic parameter, periods, roots) for inspection.
    """

    t: np.ndarray
    omega: np.ndarray
    R: np.ndarray
    axis: np.ndarray
    alpha: np.ndarray
    beta: np.ndarray
    gamma: np.ndarray
    energy: np.ndarray
    p_alpha: np.ndarray
    p_gamma: np.ndarray
    inertia: tuple[float, float, float]
    mgl: float
    info: Mapping[str, object]


# --------------------------------------------------------------------------------------------
# rotations: derive.reference.rotation (light, shared with the drawing of a motion)


def _axis_angle(n, theta):
    """Rotation by theta (array) about the unit vector n: I + sin th [n]x + 2 sin^2(th/2) [n]x^2."""
    n = np.asarray(n, dtype=float)
    K = np.array([[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]])
    th = np.asarray(theta, dtype=float)[..., None, None]
    return np.eye(3) + np.sin(th) * K + 2.0 * np.sin(0.5 * th) ** 2 * (K @ K)


# --------------------------------------------------------------------------------------------
# input handling and the result


def _positive(**kw):
    out = []
    for name, v in kw.items():
        v = float(v)
        if not (math.isfinite(v) and v > 0):
            raise ValueError(f"{name} must be positive and finite, got {v!r}")
        out.append(v)
    return out


def _finite(**kw):
    out = []
    for name, v in kw.items():
        v = float(v)
        if not math.isfinite(v):
            raise ValueError(f"{name} must be finite, got {v!r}")
        out.append(v)
    return out


def _times(t):
    t = np.atleast_1d(np.asarray(t, dtype=float))
    if t.ndim != 1 or not np.all(np.isfinite(t)):
        raise ValueError("t must be a finite scalar or 1-d array")
    return t


def _vector(w, name="omega0"):
    w = np.asarray(w, dtype=float)
    if w.shape != (3,) or not np.all(np.isfinite(w)):
        raise ValueError(f"{name} must be 3 finite numbers")
    return w


def _rotation_matrix(R0):
    if R0 is None:
        return np.eye(3)
    R0 = np.asarray(R0, dtype=float)
    if R0.shape != (3, 3) or not np.all(np.isfinite(R0)):
        raise ValueError("R0 must be a finite 3x3 matrix")
    if np.max(np.abs(R0.T @ R0 - np.eye(3))) > 1e-9 or np.linalg.det(R0) < 0:
        raise ValueError("R0 must be a rotation matrix (orthogonal, det +1)")
    return R0


def _trajectory(t, omega, R, inertia, mgl, info, angles=None):
    inertia = tuple(float(x) for x in inertia)
    Iw = omega * np.asarray(inertia)
    energy = 0.5 * np.sum(Iw * omega, axis=1) + mgl * R[:, 2, 2]
    p_alpha = np.einsum("nj,nj->n", R[:, 2, :], Iw)
    alpha, beta, gamma = euler_angles(R) if angles is None else angles
    return Trajectory(t=t, omega=omega, R=R, axis=R[:, :, 2].copy(), alpha=alpha, beta=beta,
                      gamma=gamma, energy=energy, p_alpha=p_alpha, p_gamma=Iw[:, 2].copy(),
                      inertia=inertia, mgl=float(mgl), info=MappingProxyType(dict(info)))


# --------------------------------------------------------------------------------------------
# torque-free symmetric body


def free_symmetric(I1, I3, omega0, t, R0=None):
    """Torque-free body with I1 = I2 (the lecture's solution) and its orientation.

    Body frame: w3 = const, w1 + i w2 = (w1(0) + i w2(0)) e^{i Omega t} (i.e. w1 = A cos(Omega t
    + phi), w2 = A sin(Omega t + phi)) with Omega = w3 (I3 - I1)/I1.
    Orientation: L = R I omega is fixed in inertial space, and
        R(t) = Rot(L_hat, |L| t / I1) R0 Rz(-Omega t),
    i.e. the body spins by -Omega t about e3 while the whole turns about L at the precession
    rate |L|/I1 (check: R^T R' = [Rz(Omega t) I omega0 / I1 - Omega e3]x = [omega(t)]x).
    """
    I1, I3 = _positive(I1=I1, I3=I3)
    w0 = _vector(omega0)
    t = _times(t)
    R0 = _rotation_matrix(R0)
    Omega = w0[2] * (I3 - I1) / I1
    c, s = np.cos(Omega * t), np.sin(Omega * t)
    omega = np.stack([w0[0] * c - w0[1] * s, w0[0] * s + w0[1] * c, np.full_like(t, w0[2])], 1)
    L_in = R0 @ (np.array([I1, I1, I3]) * w0)
    Lmag = float(np.linalg.norm(L_in))
    spin = _rz(-Omega * t)
    if Lmag == 0.0:
        R = R0 @ spin
    else:
        R = _axis_angle(L_in / Lmag, (Lmag / I1) * t) @ R0 @ spin
    info = {"regime": "symmetric", "Omega": Omega, "precession_rate": Lmag / I1, "L": Lmag}
    return _trajectory(t, omega, R, (I1, I1, I3), 0.0, info)


# --------------------------------------------------------------------------------------------
# torque-free asymmetric body


def _steady_rotation(I, w0, t, R0, info):
    """omega along a principal axis (or a spherical body): omega constant, R = R0 Rot(w_hat, |w| t)."""
    wmag = float(np.linalg.norm(w0))
    omega = np.tile(w0, (len(t), 1))
    R = np.broadcast_to(R0, (len(t), 3, 3)).copy() if wmag == 0 else R0 @ _axis_angle(w0 / wmag, wmag * t)
    return _trajectory(t, omega, R, I, 0.0, info)


def free_asymmetric(I1, I2, I3, omega0, t, R0=None):
    """Torque-free rigid body with principal moments I1, I2, I3 (any order) and its orientation.

    Invariants 2E = sum I_i w_i^2, L^2 = sum I_i^2 w_i^2. With the moments relabelled
    Ix, Iy, Iz so that Iy is the intermediate one and z is the axis the body circulates about
    (z = largest moment when L^2 > 2 E Iy, smallest when L^2 < 2 E Iy; a proper signed
    permutation of the body axes), Euler's equations are solved by (Landau-Lifshitz sec. 37)
        wx = sx Ax cn(tau), wy = sy Ay sn(tau), wz = sz Az dn(tau),  tau = lam t + tau0,
        Ax^2 = (2E Iz - L^2) / (Ix (Iz - Ix)),  Ay^2 = (2E Iz - L^2) / (Iy (Iz - Iy)),
        Az^2 = (L^2 - 2E Ix) / (Iz (Iz - Ix)),  lam^2 = (Iz - Iy)(L^2 - 2E Ix) / (Ix Iy Iz),
        m = (Iy - Ix)(2E Iz - L^2) / ((Iz - Iy)(L^2 - 2E Ix)),
        m1 = 1 - m = (Iz - Ix)(L^2 - 2E Iy) / ((Iz - Iy)(L^2 - 2E Ix)),
    signs sx = sign wx(0), sz = sign wz(0), sy = sx sz sign(Iz - Ix), tau0 = F(am | m) from the
    initial sn, cn. The differences L^2 - 2E Ij are formed as sums of I_i (I_i - Ij) w_i^2 in
    exact arithmetic, so m1 is correctly rounded for the given omega0 even at 1e-17;
    L^2 = 2E Iy is the separatrix (m = 1: sn = tanh, cn = dn = sech).

    Orientation: in an inertial frame with z along L, the z-y-z angles (phi, theta, psi) of the
    body satisfy (body components of L/|L|) = (-sin th cos psi, sin th sin psi, cos th)
    = (Ix wx, Iy wy, Iz wz)/|L|, which gives theta and psi algebraically, and
        phi' = |L| (Ix wx^2 + Iy wy^2) / (Ix^2 wx^2 + Iy^2 wy^2),
    a rational function of sn^2 integrated in closed form (elliptic integral of the third kind).
    Finally R(t) = R0 P M(0)^T Rz(phi(t)) M(t) P^T with M = Ry(theta) Rz(psi) and P the axis
    permutation, so R(0) = R0.

    Two equal moments are passed to ``free_symmetric`` (after a cyclic relabelling); omega0
    along a principal axis is steady rotation.
    """
    I = np.array(_positive(I1=I1, I2=I2, I3=I3))
    w0 = _vector(omega0)
    t = _times(t)
    R0 = _rotation_matrix(R0)

    if I[0] == I[1] == I[2] or np.count_nonzero(w0) <= 1:
        return _steady_rotation(I, w0, t, R0, {"regime": "steady"})
    for s in range(3):
        if I[(s + 1) % 3] == I[(s + 2) % 3]:
            # Relabel cyclically so the distinct moment is axis 3 (a proper rotation of the frame).
            P = np.eye(3)[:, [(s + 1) % 3, (s + 2) % 3, s]]
            sub = free_symmetric(I[(s + 1) % 3], I[s], P.T @ w0, t, R0 @ P)
            return _trajectory(t, sub.omega @ P.T, sub.R @ P.T, I, 0.0, sub.info)

    # The motion is homogeneous in omega: omega(t; s w) = s omega(s t; w), R(t; s w) = R(s t; w).
    # Solving for w = omega0/s keeps the squares below clear of underflow and overflow.
    scale = float(np.max(np.abs(w0)))
    sol = _free_asymmetric_core(I, w0 / scale, scale * t, R0)
    if sol is None:  # the components off one axis are below the range of their squares
        return _steady_rotation(I, w0, t, R0, {"regime": "steady"})
    omega, R, info = sol
    info["lam"] *= scale
    info["period"] /= scale
    info["L"] *= scale
    return _trajectory(t, omega * scale, R, I, 0.0, info)


def _free_asymmetric_core(I, w0, t, R0):
    ia, ib, ic = np.argsort(I)
    wa, wb, wc = w0[ia], w0[ib], w0[ic]
    # L^2 - 2E Ib without forming L^2 and 2E (the intermediate term drops out exactly).
    delta = _quad_form((I[ia], I[ia], I[ib], wa), (I[ic], I[ic], I[ib], wc))[1]
    perm = (ia, ib, ic) if delta >= 0 else (ic, ib, ia)
    P = np.zeros((3, 3))
    for k, i in enumerate(perm):
        P[i, k] = 1.0
    if np.linalg.det(P) < 0:
        P[:, 0] = -P[:, 0]
    Jx, Jy, Jz = I[list(perm)]
    wx, wy, wz = P.T @ w0

    # D_j = s_j^2 q_j: 2E Jz - L^2, L^2 - 2E Jx, L^2 - 2E Jy
    s_z, q_z = _quad_form((Jx, Jz, Jx, wx), (Jy, Jz, Jy, wy))
    s_x, q_x = _quad_form((Jy, Jy, Jx, wy), (Jz, Jz, Jx, wz))
    s_y, q_y = _quad_form((Jx, Jx, Jy, wx), (Jz, Jz, Jy, wz))
    if not (q_z / (Jz - Jx) > 0 and q_x / (Jz - Jx) > 0):
        return None
    Ax = s_z * math.sqrt(q_z / (Jx * (Jz - Jx)))
    Ay = s_z * math.sqrt(q_z / (Jy * (Jz - Jy)))
    Az = s_x * math.sqrt(q_x / (Jz * (Jz - Jx)))
    lam = s_x * math.sqrt((Jz - Jy) * q_x / (Jx * Jy * Jz))
    m1 = _clip_m1((Jz - Jx) * q_y / ((Jz - Jy) * q_x) * (s_y / s_x) ** 2)
    sx = 1.0 if wx >= 0 else -1.0
    sz = 1.0 if wz >= 0 else -1.0
    sy = sx * sz * math.copysign(1.0, Jz - Jx)

    sn0, cn0 = sy * wy / Ay, abs(wx) / Ax
    r = math.hypot(sn0, cn0)
    sn0, cn0 = sn0 / r, cn0 / r
    dn0 = math.sqrt(cn0 * cn0 + m1 * sn0 * sn0)
    tau0 = float(elliptic_f_from_jacobi(sn0, cn0, dn0, m1))
    arg = reduce_argument(lam * t + tau0, m1)
    arg0 = reduce_argument(np.array([tau0]), m1)
    sn, cn, dn, _ = arg.values()
    wf = np.stack([sx * Ax * cn, sy * Ay * sn, sz * Az * dn], 1)

    Lmag = math.sqrt(Jx * Jx * wx * wx + Jy * Jy * wy * wy + Jz * Jz * wz * wz)
    # phi' = |L| (A + B sn^2)/(C + D sn^2) once the common factor 2E Jz - L^2 of Ax^2 and Ay^2
    # is cleared: A = Jz - Jy, B = Jy - Jx, C = Jx (Jz - Jy), D = Jz (Jy - Jx), C + D = Jy (Jz - Jx).
    phi = Lmag * sn2_rational_integral(arg, arg0, lam, t, Jz - Jy, Jy - Jx, Jx * (Jz - Jy),
                                       Jz * (Jy - Jx), Jy * (Jz - Jx))
    M = _invariable_plane_matrix(Jx * wf[:, 0], Jy * wf[:, 1], Jz * wf[:, 2], Lmag)
    M0 = _invariable_plane_matrix(np.array([Jx * wx]), np.array([Jy * wy]), np.array([Jz * wz]), Lmag)[0]
    R = (R0 @ P @ M0.T) @ _rz(phi) @ M @ P.T
    omega = wf @ P.T
    K = arg.qp.K
    regime = "separatrix" if m1 == 0 else ("polar-largest" if delta > 0 else "polar-smallest")
    info = {"regime": regime,
            "m1": m1, "m": 1.0 - m1, "lam": lam, "tau0": tau0, "K": K,
            "period": 4 * K / lam if math.isfinite(K) else math.inf, "L": Lmag,
            "polar_axis": int(perm[2]) + 1}
    return omega, R, info


def _quad_form(*terms):
    """(s, q) with sum of J (Ja - Jb) w^2 over terms (J, Ja, Jb, w) equal to s^2 q, s = max |w|.

    Evaluated in exact rational arithmetic and rounded once: near the separatrix L^2 - 2E Iy is
    a small difference of O(1) terms, and m1, hence K ~ ln(4/sqrt(m1)) and the time of every
    flip, inherit its relative error; dividing by s keeps components ~1e-160 from being squared
    into the subnormal range."""
    s = max(abs(w) for *_, w in terms)
    if s == 0:
        return 0.0, 0.0
    S = Fraction(s)
    q = sum(Fraction(J) * (Fraction(a) - Fraction(b)) * (Fraction(w) / S) ** 2 for J, a, b, w in terms)
    return s, float(q)


def _clip_m1(m1):
    """m1 in [0, 1]; below 1e-150 (an orbit within ~1e-75 of a separatrix) it is taken as 0. The
    separatrix solution then agrees until the body has lingered 2K/lam >= 350/lam near the
    unstable equilibrium; beyond, R_J(0, m1, 1, .) ~ m1^(-3/2) would overflow in double."""
    m1 = min(max(float(m1), 0.0), 1.0)
    return 0.0 if m1 < 1e-150 else m1


def _invariable_plane_matrix(Lx, Ly, Lz, Lmag):
    """M = Ry(theta) Rz(psi) whose third row is the body components (Lx, Ly, Lz)/|L|, with
    sin th cos psi = -Lx/|L|, sin th sin psi = Ly/|L|, cos th = Lz/|L| (no angles formed)."""
    h = np.hypot(Lx, Ly)
    st, ct = h / Lmag, Lz / Lmag
    with np.errstate(invalid="ignore", divide="ignore"):
        cp = np.where(h > 0, -Lx / h, 1.0)
        sp = np.where(h > 0, Ly / h, 0.0)
    z = np.zeros_like(h)
    return np.stack([np.stack([ct * cp, -ct * sp, st], -1),
                     np.stack([sp, cp, z], -1),
                     np.stack([-st * cp, st * sp, ct], -1)], -2)


# --------------------------------------------------------------------------------------------
# heavy symmetric top


def heavy_top(I1, I3, M, g, l, alpha0, beta0, gamma0, alphadot0, betadot0, gammadot0, t):
    """Heavy symmetric top (I1 = I2 about the fixed point, centre of mass on body axis 3 at
    distance l, gravity g along -z) from the Lagrangian of the notes,
        L = 1/2 I1 (a'^2 sin^2 b + b'^2) + 1/2 I3 (a' cos b + g')^2 - M g l cos b.

    Constants: p_gamma = I3 (a' cos b + g'), p_alpha = I1 a' sin^2 b + p_gamma cos b,
    E' = E - p_gamma^2/(2 I3) = 1/2 I1 b'^2 + (p_alpha - p_gamma cos b)^2/(2 I1 sin^2 b) + M g l cos b.
    With u = cos b:  u'^2 = f(u) = (1 - u^2)(2/I1)(E' - M g l u) - ((p_alpha - p_gamma u)/I1)^2,
    a cubic with roots u1 <= u2 <= u3 (M g l > 0); the motion is
        u(t) = u1 + (u2 - u1) sn^2(lam (t - t0) | m),  m = (u2 - u1)/(u3 - u1),
        lam = sqrt(M g l (u3 - u1) / (2 I1)).
    It is computed in y = sin^2(b/2) = (1 - u)/2 (so b ~ 1e-8 keeps its digits), from the
    cubic re-centred at the initial point, whose coefficients are formed from the initial
    rates without cancellation; the root nearest a pole is refined on the polynomial centred
    at that pole, where its constant term -((p_alpha -+ p_gamma)/I1)^2/4 fixes it accurately.
    alpha and gamma follow from
        a' = (p_alpha - p_gamma u)/(I1 (1 - u^2))
           = (p_alpha - p_gamma)/(2 I1 (1 - u)) + (p_alpha + p_gamma)/(2 I1 (1 + u)),
        g' = p_gamma/I3 - a' u = p_gamma (1/I3 - 1/I1) - (p_alpha - p_gamma)/(2 I1 (1 - u))
             + (p_alpha + p_gamma)/(2 I1 (1 + u)),
    whose two terms integrate in closed form (elliptic integrals of the third kind), and a term
    whose coefficient is zero (axis through a pole) is absent - no 0/0. Any sign of M g l
    (hanging top, no gravity: then u is sinusoidal) and any beta0 are accepted; beta0 in
    (pi/2, pi] is solved as the mirrored problem (beta -> pi - beta, gamma -> -gamma,
    M g l -> -M g l) so the pole nearer the motion keeps full relative precision.

    See the module docstring for the continuous-angle conventions. Returns a ``Trajectory``
    with alpha, beta, gamma; omega from the Euler rates; info with p_alpha, p_gamma, the roots
    (y_roots in y, u_roots = 1 - 2 y; of the mirrored problem when info["mirrored"]), m1, lam,
    the nutation period 2K/lam, and through_pole (beta passes 0 or pi with a sign change).
    """
    I1, I3 = _positive(I1=I1, I3=I3)
    M, g, l, alpha0, beta0, gamma0, ad0, bd0, gd0 = _finite(
        M=M, g=g, l=l, alpha0=alpha0, beta0=beta0, gamma0=gamma0, alphadot0=alphadot0,
        betadot0=betadot0, gammadot0=gammadot0)
    t = _times(t)
    mgl = M * g * l
    p_gamma = I3 * (ad0 * math.cos(beta0) + gd0)

    # Reduce beta0 to [0, pi/2] with exact symmetries of the representation / the problem.
    turns = round(beta0 / (2 * math.pi))
    b = beta0 - 2 * math.pi * turns if turns else beta0
    bd, gd, k = bd0, gd0, mgl
    flipped = b < 0
    if flipped:  # (a, b, g) ~ (a + pi, -b, g + pi)
        b, bd = -b, -bd
    mirrored = b > 0.5 * math.pi
    if mirrored:  # beta -> pi - beta, gamma -> -gamma is the same top with M g l -> -M g l
        b, bd, gd, k = math.pi - b, -bd, -gd, -k

    # The core starts from alpha = gamma = 0 (they are cyclic); the initial values are added
    # back here, so the pi's of the symmetries above cancel exactly and alpha(0) = alpha0.
    sol = _heavy_top_core(I1, I3, k, b, ad0, bd, gd, t)
    dalpha, beta, dgamma, betadot, adsb = sol["alpha"], sol["beta"], sol["gamma"], sol["betadot"], sol["adsb"]
    if mirrored:
        beta, dgamma, betadot = math.pi - beta, -dgamma, -betadot
    if flipped:
        beta, betadot, adsb = -beta, -betadot, -adsb
    if turns:
        beta = beta + 2 * math.pi * turns
    alpha, gamma = alpha0 + dalpha, gamma0 + dgamma

    cg, sg = np.cos(gamma), np.sin(gamma)
    omega = np.stack([-adsb * cg + betadot * sg, adsb * sg + betadot * cg,
                      np.full_like(t, p_gamma / I3)], 1)
    R = euler_matrix(alpha, beta, gamma)
    info = dict(sol["info"])  # roots etc. of the mirrored problem when mirrored
    info.update(mirrored=mirrored, flipped=flipped, p_gamma=p_gamma,
                p_alpha=I1 * ad0 * math.sin(beta0) ** 2 + p_gamma * math.cos(beta0))
    return _trajectory(t, omega, R, (I1, I1, I3), mgl, info, angles=(alpha, beta, gamma))


def _poly(c, x):
    return c[0] + x * (c[1] + x * (c[2] + x * c[3]))


def _dpoly(c, x):
    return c[1] + x * (2 * c[2] + x * 3 * c[3])


def _far_root(c, side):
    """The real root of the cubic c0 + c1 x + c2 x^2 + c3 x^3 farthest towards side (-1 or +1).
    Newton from beyond the Cauchy bound converges monotonically: the cubic is convex (side -1,
    c3 < 0) or concave-up (side +1, c3 > 0) between the bound and its extreme root."""
    bound = 1.0 + max(abs(c[0]), abs(c[1]), abs(c[2])) / abs(c[3])
    x = side * bound
    for _ in range(2000):
        p = _poly(c, x)
        if p == 0 or (p < 0):
            break
        step = -p / _dpoly(c, x)
        x_new = x + step
        if side * (x - x_new) <= 0 or x_new == x:
            break
        x = x_new
    return x


def _straddling_roots(qa, qb, qc):
    """Roots x1 <= 0 <= x2 of qa x^2 + qb x + qc with qc/qa <= 0 (cancellation-free formula)."""
    disc = qb * qb - 4.0 * qa * qc
    sq = math.sqrt(max(disc, 0.0))
    q = -0.5 * (qb + math.copysign(sq, qb))
    if q == 0.0:
        return 0.0, 0.0
    r1, r2 = q / qa, qc / q
    return min(r1, r2), max(r1, r2)


def _pole_root(p, upper):
    """The root in (0, upper) of the pole-centred cubic p (p(0) < 0 < p(upper)), to full
    relative precision."""
    return optimize.brentq(lambda y: _poly(p, y), 0.0, upper, xtol=1e-300, rtol=4 * _EPS,
                           maxiter=1000)


def _heavy_top_core(I1, I3, mgl, b0, ad0, bd0, gd0, t):
    """The heavy top for 0 <= b0 <= pi/2, any sign of mgl, in y = sin^2(b/2), z = 1 - y;
    alpha and gamma are returned relative to their initial values.

    y'^2 = P(y) = y (1 - y)(A + 2 kap y) - (delta + 2 bb y)^2 / 4 with kap = 2 M g l / I1,
    bb = p_gamma/I1, delta = (p_alpha - p_gamma)/I1, A = 2 (E' - M g l)/I1; P(y0 + x) = c0 + c1 x
    + c2 x^2 + c3 x^3 with c0 = (sin b0 b0'/2)^2, c1 = cos b0 T0 + kap sin^2 b0 / 2 - bb q0,
    c2 = -T0 + 2 kap cos b0 - bb^2, c3 = -2 kap, T0 = b0'^2 + a0'^2 sin^2 b0, q0 = a0' sin^2 b0.
    Roots y1 <= y0 <= y2 of the motion, y3 the third (y3 <= 0 for kap > 0, >= 1 for kap < 0);
    y = y1 + (y2 - y1) P(w)^2 with P = cn (kap > 0) or sn (kap <= 0), w = lam t + w0.
    """
    sb, cb = math.sin(b0), math.cos(b0)
    sh, ch = math.sin(0.5 * b0), math.cos(0.5 * b0)
    y0, z0 = sh * sh, ch * ch
    pg = I3 * (ad0 * cb + gd0)
    bb = pg / I1
    q0 = ad0 * sb * sb  # (p_alpha - p_gamma cos b0)/I1
    delta = q0 - 2.0 * bb * y0  # (p_alpha - p_gamma)/I1
    sigma = q0 + 2.0 * bb * z0  # (p_alpha + p_gamma)/I1
    T0 = bd0 * bd0 + (ad0 * sb) ** 2
    kap = 2.0 * mgl / I1
    A = T0 - 2.0 * kap * y0
    spin = pg * (1.0 / I3 - 1.0 / I1)
    c = (
        (0.5 * sb * bd0) ** 2,
        cb * T0 + 0.5 * kap * sb * sb - bb * q0,
        -T0 + 2.0 * kap * cb - bb * bb,
        -2.0 * kap,
    )
    info = {"kappa": kap}

    if (b0 == 0.0 and bd0 == 0.0) or (c[0] == 0 and c[1] == 0 and c[2] == 0 and c[3] == 0):
        # Sleeping top (any spin) or a body at rest without gravity: an equilibrium.
        info.update(regime="equilibrium", m1=1.0, lam=0.0, nutation_period=math.inf)
        n = len(t)
        return {"alpha": ad0 * t, "beta": np.full(n, b0), "gamma": gd0 * t,
                "betadot": np.zeros(n), "adsb": np.full(n, ad0 * sb), "info": info}

    # --- roots, re-centred at y0 ---------------------------------------------------------
    if kap != 0.0:
        side = -1.0 if kap > 0 else 1.0
        if kap > 0 and delta == 0.0 and A <= 0.0:
            x3 = -y0  # y = 0 is the root and it is the far one
        else:
            x3 = _far_root(c, side)
        d0 = -c[0] / x3
        # Deflate x3 backward (stable for a large |x3|) or forward (for a small one), whichever
        # has the smaller rounding bound.
        scale1 = abs(cb * T0) + abs(0.5 * kap * sb * sb) + abs(bb * q0)
        scale2 = abs(T0) + abs(2 * kap * cb) + bb * bb
        err_back = (abs(d0) + scale1) / abs(x3)
        err_fwd = scale2 + abs(c[3] * x3)
        d1 = (d0 - c[1]) / x3 if err_back <= err_fwd else c[2] + c[3] * x3
        x1, x2 = _straddling_roots(c[3], d1, d0)
    else:
        x3 = math.inf
        x1, x2 = _straddling_roots(c[2], c[1], c[0])
    dy = x2 - x1
    y1, y2, z1, z2 = y0 + x1, y0 + x2, z0 - x1, z0 - x2
    ym, yp = -x1, x2  # y0 - y1, y2 - y0

    # --- refine the root next to each pole on the pole-centred cubic -----------------------
    y1_refined = z2_refined = False
    if y1 < 0.5 * y0:
        p = (-0.25 * delta * delta, A - bb * delta, 2 * kap - A - bb * bb, -2 * kap)
        if delta == 0.0:
            y1 = 0.0 if A > 0 else max(y1, 0.0)
        elif dy > 0 and _poly(p, y0 + 0.5 * (x1 + x2)) > 0:
            y1 = _pole_root(p, y0 + 0.5 * (x1 + x2))
        y1 = max(y1, 0.0)
        if 2.0 * math.sqrt(y1) < _POLE_SNAP:
            delta, y1 = 0.0, 0.0
        y1_refined = True
        ym, z1 = y0 - y1, 1.0 - y1
        dy = y2 - y1
    if z2 < 0.5 * z0:
        Az = A + 2 * kap
        p = (-0.25 * sigma * sigma, Az + bb * sigma, -Az - 2 * kap - bb * bb, 2 * kap)
        if sigma == 0.0:
            z2 = 0.0 if Az > 0 else max(z2, 0.0)
        elif dy > 0 and _poly(p, z0 - 0.5 * (x1 + x2)) > 0:
            z2 = _pole_root(p, z0 - 0.5 * (x1 + x2))
        z2 = max(z2, 0.0)
        if 2.0 * math.sqrt(z2) < _POLE_SNAP:
            sigma, z2 = 0.0, 0.0
        z2_refined = True
        yp, y2 = z0 - z2, 1.0 - z2
        dy = z1 - z2

    # --- elliptic parameter and rate --------------------------------------------------------
    if kap > 0:
        y3 = y0 + x3
        far = x2 - x3
        near = (y1 - y3) if y1_refined else (x1 - x3)
        lam = math.sqrt(0.5 * kap * far)
    elif kap < 0:
        y3 = y0 + x3
        far = x3 - x1
        near = (z2 + (x3 - z0)) if z2_refined else (x3 - x2)
        lam = math.sqrt(-0.5 * kap * far)
    else:
        y3, far, near = math.inf, math.inf, 1.0
        lam = 0.5 * math.sqrt(-c[2])
    m1 = 1.0 if kap == 0 else _clip_m1(near / far)

    # --- phase at t = 0 --------------------------------------------------------------------
    sig_signed = delta == 0.0 and y1 == 0.0
    chi_signed = sigma == 0.0 and z2 == 0.0
    if dy > 0:
        P0, Q0 = math.sqrt(max(ym, 0.0) / dy), math.sqrt(max(yp, 0.0) / dy)
        r = math.hypot(P0, Q0)
        P0, Q0 = P0 / r, Q0 / r
    else:
        P0, Q0 = 1.0, 0.0
    eps_P = -1.0 if kap > 0 else 1.0  # y' = 2 eps_P dy lam P Q dn
    s_dir = eps_P * (1.0 if bd0 >= 0 else -1.0)
    if chi_signed and not sig_signed:
        P0 *= s_dir
    else:
        Q0 *= s_dir
    sn0, cn0 = (Q0, P0) if kap > 0 else (P0, Q0)
    dn0 = math.sqrt(cn0 * cn0 + m1 * sn0 * sn0)
    w0 = float(elliptic_f_from_jacobi(sn0, cn0, dn0, m1))

    # --- evaluate ---------------------------------------------------------------------------
    arg = reduce_argument(lam * t + w0, m1)
    arg0 = reduce_argument(np.array([w0]), m1)
    sn, cn, dn, am = arg.values()
    Pw, Qw = (cn, sn) if kap > 0 else (sn, cn)
    rdy = math.sqrt(dy)
    sig = rdy * Pw if sig_signed else np.sqrt(y1 + dy * Pw * Pw)
    chi = rdy * Qw if chi_signed else np.sqrt(z2 + dy * Qw * Qw)
    if sig_signed and chi_signed:
        # Over the top (p_alpha = p_gamma = 0): sin(b/2) = P(w), cos(b/2) = s_dir Q(w), so
        # b' = 2 sign(b0') lam dn and b = b0 + 2 sign(b0') (am w - am w0), growing without bound.
        chi = s_dir * chi
        am0 = arg0.values()[3]
        beta = b0 + 2.0 * (1.0 if bd0 >= 0 else -1.0) * (am - am0)
    else:
        beta = 2.0 * np.arctan2(sig, chi)
    # b' = y'/(sin(b/2) cos(b/2)) with y' = 2 eps_P dy lam P Q dn; a signed sin or cos cancels
    # its P or Q (no 0/0 at the pole).
    with np.errstate(invalid="ignore", divide="ignore"):
        fP = np.ones_like(t) if sig_signed else np.where(sig > 0, rdy * Pw / sig, 0.0)
        fQ = np.full_like(t, s_dir) if (sig_signed and chi_signed) else (
            np.ones_like(t) if chi_signed else np.where(chi > 0, rdy * Qw / chi, 0.0))
    betadot = 2.0 * eps_P * lam * dn * fP * fQ

    adsb = np.zeros_like(t)
    Jy = Jz = 0.0
    if delta != 0.0:
        adsb = adsb + 0.5 * delta * chi / sig
        if kap > 0:
            Jy = sn2_rational_integral(arg, arg0, lam, t, 1.0, 0.0, y2, -dy, y1)
        else:
            Jy = sn2_rational_integral(arg, arg0, lam, t, 1.0, 0.0, y1, dy, y2)
    if sigma != 0.0:
        adsb = adsb + 0.5 * sigma * sig / chi
        if kap > 0:
            Jz = sn2_rational_integral(arg, arg0, lam, t, 1.0, 0.0, z2, dy, z1)
        else:
            Jz = sn2_rational_integral(arg, arg0, lam, t, 1.0, 0.0, z1, -dy, z2)
    alpha = 0.25 * delta * Jy + 0.25 * sigma * Jz
    gamma = spin * t - 0.25 * delta * Jy + 0.25 * sigma * Jz
    alpha = alpha + np.zeros_like(t)
    gamma = gamma + np.zeros_like(t)

    K = arg.qp.K
    info.update(
        regime="nutation",
        u_roots=(1.0 - 2.0 * y2, 1.0 - 2.0 * y1, 1.0 - 2.0 * y3 if math.isfinite(y3) else math.nan),
        y_roots=(y1, y2, y3), m1=m1, lam=lam, w0=w0,
        nutation_period=(2.0 * K / lam) if math.isfinite(K) else math.inf,
        through_pole=bool(sig_signed or chi_signed),
    )
    return {"alpha": alpha, "beta": beta, "gamma": gamma, "betadot": betadot, "adsb": adsb,
            "info": info}
