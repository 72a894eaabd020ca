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

import numpy as np
from scipy import optimize

from derive.reference.elliptic import elliptic_f_from_jacobi, reduce_argument, sn2_rational_integral
from derive.reference.free_body import _clip_m1, free_asymmetric, free_symmetric
from derive.reference.rotation import euler_angles, euler_matrix
from derive.reference.trajectory import _EPS, _POLE_SNAP, Trajectory, _finite, _positive, _times, _trajectory

__all__ = [
    "Trajectory",
    "free_symmetric",
    "free_asymmetric",
    "heavy_top",
    "euler_matrix",
    "euler_angles",
]


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


def _near_pole(p, gap, A, root, moves, mid):
    """(gap, root): the root next to a pole (y1 or z2, with the pole's δ or σ and A) refined on
    the pole-centred cubic ``p`` below ``mid``; both 0 when the approach is below ``_POLE_SNAP``."""
    if gap == 0.0:
        root = 0.0 if A > 0 else max(root, 0.0)
    elif moves and _poly(p, mid) > 0:
        root = _pole_root(p, mid)
    root = max(root, 0.0)
    return (0.0, 0.0) if 2.0 * math.sqrt(root) < _POLE_SNAP else (gap, root)


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
        delta, y1 = _near_pole(p, delta, A, y1, dy > 0, y0 + 0.5 * (x1 + x2))
        y1_refined = True
        ym, z1 = y0 - y1, 1.0 - y1
        dy = y2 - y1
    if z2 < 0.5 * z0:
        Az = A + 2 * kap
        p = (-0.25 * sigma * sigma, Az + bb * sigma, -Az - 2 * kap - bb * bb, 2 * kap)
        sigma, z2 = _near_pole(p, sigma, Az, z2, dy > 0, z0 - 0.5 * (x1 + x2))
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
