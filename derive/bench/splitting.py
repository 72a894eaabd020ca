"""What the Lie–Poisson splittings cost against DOP853 and Gauss–Legendre at equal energy
error, on named bodies (:func:`bench_case`, :func:`bench_energy`): reported by the bench, never
asserted on time.
"""
from __future__ import annotations

import time

import numpy as np

from derive.methods.splitting import METHODS
from derive.runtime.splitter import Splitter, angular_momentum, body, energy, initial_state
from derive.reference.exact import euler_matrix, heavy_top
from derive.symbolic import models

#: (α, β, γ) at which the fast and slow Lagrange tops of :func:`bench_case` start (from rest
#: but for their spin); :func:`_reference` starts the exact solution there too.
_TOP_START = (0.0, 0.5, 0.0)


def bench_case(case: str):
    """(model, p, y0, period) of a named benchmark body:

    ``fast-top``    Lagrange top I₁ = 1, I₃ = 0.5, M g l = 1, released at β = 0.5 from rest
                    with p_γ = 1000, so p_γ²/(I₁ M g l) = 10⁶; period: the nutation period
                    2π I₁/p_γ.
    ``lagrange``    the same top with p_γ = 10 (p_γ²/(I₁ M g l) = 100, a slow top); period
                    2π I₁/p_γ.
    ``asymmetric``  I = (1, 1.5, 2) kg m², M g = 9.81 N, r_c = (0.05, 0.02, 0.1) m, started at
                    (α, β, γ) = (0.1, 0.6, 0.2) with ω̃ = (0.3, −0.2, 12) rad/s (three distinct
                    moments: the elliptic free flow); period 2π/|ω̃₀|.
    """
    if case in ("fast-top", "lagrange"):
        model = models.build("euler-poisson", True, ("gravity",))
        p_gamma = 1000.0 if case == "fast-top" else 10.0
        p = np.array([1.0, 0.5, 1.0, 9.81, 1.0 / 9.81])
        y0 = initial_state(model, p, (0.0, 0.0, p_gamma / p[1]), euler_matrix(*_TOP_START))
        return model, p, y0, 2 * np.pi * 1.0 / p_gamma
    if case == "asymmetric":
        model = models.build("euler-poisson", False, ("gravity_general",))
        p = np.array([1.0, 1.5, 2.0, 1.0, 9.81, 0.05, 0.02, 0.1])
        w0 = np.array([0.3, -0.2, 12.0])
        return (model, p, initial_state(model, p, w0, euler_matrix(0.1, 0.6, 0.2)),
                2 * np.pi / np.linalg.norm(w0))
    raise ValueError(f"unknown benchmark case {case!r}; known: fast-top, lagrange, asymmetric")


def _reference(case, model, p, y0, t, sp) -> np.ndarray:
    """(n, e) of the benchmark body at the times t, shape (len(t), 6): the exact Lagrange top
    (derive.reference.exact.heavy_top) for the symmetric cases, else DOP853 at rtol 1e-13."""
    if case in ("fast-top", "lagrange"):
        I1, I3, M, g, l = p
        w3 = float(angular_momentum(model, p, y0)[2]) / I3
        tr = heavy_top(I1, I3, M, g, l, *_TOP_START, 0.0, 0.0, w3, t)
        return np.concatenate([tr.R[:, 2, :], tr.R[:, 0, :]], axis=1)
    return sp.kernel.solve("dop853", y0, p, t, rtol=1e-13, atol=1e-15).y[:, 3:9]


def _axis(ne: np.ndarray) -> np.ndarray:
    """The body's axis 3 in space, R ê₃ = (e₃, (n × e)₃, n₃), from (n, e) rows."""
    n, e = ne[:, 0:3], ne[:, 3:6]
    return np.stack([e[:, 2], n[:, 0] * e[:, 1] - n[:, 1] * e[:, 0], n[:, 2]], axis=1)


def bench_energy(case: str = "asymmetric", periods: float = 1e4, target: float = 1e-8,
                 methods=("splitting4", "dop853", "gauss4"), repeat: int = 3,
                 samples: int = 997, budget: float = 60.0, measure: str = "energy") -> dict:
    """Cost of each method to keep the energy error below ``target`` over ``periods`` periods
    of a :func:`bench_case` body.

    Energy error: max over the run of |E(t) − E(0)| / (M g |r_c|) — relative to the scale of the
    potential energy, the part the integrators can get wrong (a fast top's E is dominated by the
    spin energy p_γ²/(2I₃), which would hide every error). Sampled at ``samples`` + 1 equally
    spaced times (a prime, so the output grid does not resonate with the nutation; fixed-step
    methods are not forced below the step they choose). Each method's setting — the step h
    (splitting, Gauss) or rtol (DOP853, atol = rtol/100) — is scanned from cheap to expensive
    on a grid of ratio 2^(1/2), and the first setting that meets the target and whose next
    grid value meets it too (no lucky resonance) is taken; its wall time is the best of
    ``repeat`` runs. A method whose scan exceeds ``budget`` seconds is reported as None.
    ``measure`` ``"axis"`` takes instead the error of the body's axis 3 in space, max |R ê₃ −
    (R ê₃)_ref| over the samples (precession and nutation: what a top's user watches), against
    the exact solution (Lagrange tops) or DOP853 at rtol 1e-13: the trajectory, which the energy
    alone does not judge (Gauss methods keep the quadratic energy of these variables exactly
    whatever their step).
    Returns {"case", "periods", "target", method: {"setting", "error", "seconds", "nfev"},
    "ratio_dop853"} with ratio_dop853 = seconds(dop853) / seconds(splitting4).
    """
    model, p, y0, period = bench_case(case)
    sp = Splitter(model)
    _, mg_rc = body(model, p)
    scale = float(np.linalg.norm(mg_rc)) or float(abs(energy(model, p, y0)))
    t = np.linspace(0.0, periods * period, int(samples) + 1)
    e0 = float(energy(model, p, y0))
    if measure not in ("energy", "axis"):
        raise ValueError(f"measure must be 'energy' or 'axis', not {measure!r}")
    ref = _reference(case, model, p, y0, t, sp) if measure != "energy" else None

    def run(method, setting):
        t0 = time.perf_counter()
        if method in METHODS:
            y, st = sp.solve(method, y0, p, t, setting)
            ok, nfev = st["status"] == 0, int(st["nfev"])
        else:
            kw = {"rtol": setting, "atol": setting * 1e-2} if method == "dop853" else {"h": setting}
            sol = sp.kernel.solve(method, y0, p, t, check=False, **kw)
            y, ok, nfev = sol.y, sol.success, sol.nfev
        dt = time.perf_counter() - t0
        if not ok:
            err = np.inf
        elif measure == "axis":
            err = float(np.max(np.linalg.norm(_axis(y[:, 3:9]) - _axis(ref), axis=1)))
        else:
            err = float(np.max(np.abs(energy(model, p, y) - e0)) / scale)
        return err, dt, nfev

    out: dict = {"case": case, "periods": periods, "target": target, "measure": measure}
    for method in methods:
        # Fixed steps start at the output spacing (a larger h would be cut to it anyway).
        start = 1e-3 if method == "dop853" else min(64 * period, float(t[1] - t[0]))
        grid = [start * 2.0 ** (-k / 2) for k in range(80)]
        spent, found, prev = 0.0, None, None
        for setting in grid:
            err, dt, _ = run(method, setting)
            spent += dt
            if err <= target:
                if prev is not None:
                    found = prev
                    break
                prev = setting
            else:
                prev = None
            if spent > budget:
                break
        if found is None:
            out[method] = None
            continue
        runs = [run(method, found) for _ in range(repeat)]
        out[method] = {"setting": found, "error": runs[0][0],
                       "seconds": min(r[1] for r in runs), "nfev": runs[0][2]}
    base = (out.get("splitting4") or {}).get("seconds")
    sec = (out.get("dop853") or {}).get("seconds")
    out["ratio_dop853"] = sec / base if base and sec else None
    return out
