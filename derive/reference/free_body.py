"""The torque-free body in closed form: symmetric (the lecture's rotating ω̃ in the body) and
asymmetric (Jacobi elliptic functions in both regimes and on the separatrix, the orientation from
the invariable plane). Conventions: :mod:`derive.reference.exact`.
"""
from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from derive.reference.elliptic import elliptic_f_from_jacobi, reduce_argument, sn2_rational_integral
from derive.reference.rotation import _rz
from derive.reference.trajectory import _axis_angle, _positive, _rotation_matrix, _times, _trajectory, _vector


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
    wa, wc = w0[ia], w0[ic]
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
