"""Figures of a simulated trajectory (matplotlib, headless Agg backend).

`figure(res)` builds the figure and returns it (tests inspect it); `plot_result(res, fh, fmt)`
writes it as PNG, PDF or SVG. Panels, three to a row:

* ``beta``: β(t), the tilt of body axis ê₃ from the vertical (the symmetry axis of a symmetric
  body). When β hardly moves (relative spread < 1e-6) the panel shows β − β(0) instead and
  says what β(0) is, rather than printing ticks that differ in the 12th digit.
* ``omega``: the body components ω̃₁, ω̃₂, ω̃₃(t); ω̃₃ on its own right-hand axis when it is
  more than ten times the others (a fast top), both axes symmetric about a common zero so that
  a nearly constant ω̃₃ is drawn as the flat line it is (the legend says within how much). For
  an asymmetric body this is where the flip about the intermediate axis shows.
* ``energy``: without damping, the signed relative energy error (E(t) − E(0))/|E(0)| on a
  symlog axis, linear within ±ε (machine epsilon), so an exact zero is drawn as 0. With a
  damping torque −c ω̃ the energy loss is physics, not error: the panel shows E(t), the work
  done against damping W(t) = ∫₀ᵗ c |ω̃|² dt′ (trapezoid rule on the output samples) and their
  sum, which stays at E(0);
* ``balance`` (damped scenes): (E + W − E(0))/|E(0)| on a symlog axis — the trapezoid rule's
  error on the output grid plus the integration error;
* ``momenta`` (undamped): relative deviation of what the motion conserves (p_α, p_γ, the
  integrable case's integral);
* ``top`` (symmetric heavy tops): the path of ê₃ seen from above (orthographic projection on
  the x-y plane, upper hemisphere solid, lower dashed), where loops, cusps and waves show;
* ``sphere``: the textbook figure, the path of ê₃ on the unit sphere in 3-D;
* ``polhode`` (free and asymmetric bodies, instead of ``top``): the angular momentum in body
  axes, L̃ = (I1 ω̃₁, I2 ω̃₂, I3 ω̃₃), on the momentum sphere |L̃| = const (for a free body; for a
  heavy one its direction L̃/|L̃|): a free body's runs along the intersection with the energy
  ellipsoid, and a flip is the path going from one side of the intermediate axis ê₂ to the other.

A quantity that is exactly conserved (every sample equal to the first: p_γ of a formulation
that holds it as a parameter) is said to be so in words; it is not drawn as a row of zeros. A
run whose energy the physics does not conserve (damping, a user's torque) shows E(t) − E(0) as
the work done, never as an error. The grid holds six panels, none empty.

The title names the scene, the formulation, the method and its tolerances (or its step).
Tick labels never use matplotlib's offset notation: `PlainFormatter` prints every tick in
full with just the digits that tell neighbouring ticks apart.
"""
from __future__ import annotations

import functools
import math

import numpy as np

from derive.sim.scene_types import FIXED_STEP_METHODS
from derive.symbolic import effects

#: Relative spread of β below which the β panel shows β − β(0).
FLAT_BETA = 1e-6
#: ω̃₃ gets its own axis when it exceeds the transverse components by this factor.
SPIN_AXIS_RATIO = 10.0
EPS = float(np.finfo(float).eps)


def _matplotlib():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import ticker

    return plt, ticker


def _plain_label(x: float, ticks) -> str:
    """The label of tick ``x`` among ``ticks``: in full, the fewest digits that tell them apart."""
    locs = [float(v) for v in ticks if np.isfinite(v)] or [x]
    steps = np.diff(sorted(set(locs)))
    step = float(np.min(steps)) if steps.size else abs(x) or 1.0
    if x == 0 or abs(x) < 1e-9 * step:  # a tick at zero (up to round-off of the locator)
        return "0"
    big = max(abs(v) for v in locs)
    fixed = 1e-3 <= big < 1e5
    lead = -math.floor(math.log10(step) + 1e-9)  # decimals of the tick spacing's first digit
    if not fixed:
        lead += math.floor(math.log10(big))
    # The fewest digits that print every tick exactly (a spacing of 2.5 needs one decimal).
    for digits in range(max(0, lead), max(0, lead) + 6):
        fmt = f"{{:.{digits}{'f' if fixed else 'e'}}}"
        if all(abs(float(fmt.format(v)) - v) <= 1e-3 * step for v in locs):
            break
    text = fmt.format(x)
    if not fixed:
        mant, exp = text.split("e")
        text = f"{mant}e{int(exp)}"
    return text


def plain_formatter():
    """A tick formatter without offset or common multiplier: every label is the full number."""
    _, ticker = _matplotlib()

    class PlainFormatter(ticker.Formatter):
        def set_locs(self, locs):  # (kept here: Formatter.locs is deprecated)
            self.ticks = list(locs)

        def __call__(self, x, pos=None):
            return _plain_label(x, getattr(self, "ticks", []))

    return PlainFormatter()


def _plain(ax, axes="xy"):
    for name in axes:
        getattr(ax, f"{name}axis").set_major_formatter(plain_formatter())


def _legend_outside(ax, **kw):
    """Legend to the right of the axes, never over the data."""
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, fontsize=8,
              frameon=False, **kw)


def _symlog(ax, values, what: str, linthresh: float):
    """A non-negative deviation on a symlog axis: logarithmic above ``linthresh``, linear from
    0 to it, so an exact zero is drawn at 0 (not at an invented 1e-17). For relative deviations
    ``linthresh`` = 1e-16 lies below the smallest non-zero relative difference of two doubles
    (ε/2 ≈ 1.1e-16), so the linear part holds only the exact zeros."""
    ax.set_yscale("symlog", linthresh=linthresh, linscale=1.0)
    top = float(np.max(values)) if values.size else 0.0
    ax.set_ylim(0.0, 10.0 ** math.ceil(math.log10(max(top, 10 * linthresh)) + 1e-9))
    ax.set_ylabel(what + "\n(symlog: linear from 0 to " + f"{linthresh:.3g})")


def _say(ax, title: str, text: str):
    """A panel of words: what an exactly conserved quantity would draw as a row of zeros."""
    ax.set_axis_off()
    ax.set_title(title, fontsize=10)
    ax.text(0.5, 0.5, text, ha="center", va="center", fontsize=10, transform=ax.transAxes, wrap=True)


def _zeros_note(values: np.ndarray) -> str:
    zeros = int(np.count_nonzero(values == 0))
    return f"\n{zeros} of {values.size} samples exactly 0" if zeros else ""


def _plot_deviation(ax, t, values, **kw):
    """Round-off takes few distinct values (multiples of ε/2): dots show them, a line through
    them would only fill the area between 0 and ε. Anything smoother is drawn as a line."""
    if np.unique(values).size < 50:
        return ax.plot(t, values, ".", ms=2.5, **kw)
    return ax.plot(t, values, lw=0.8, **kw)


def _deviation(x: np.ndarray) -> tuple[np.ndarray, str, float]:
    """|x − x(0)| / |x(0)|, or |x − x(0)| when x(0) = 0 (said in the label); and the symlog
    threshold that suits it."""
    x0 = float(x[0])
    if x0 != 0.0:
        return np.abs(x - x0) / abs(x0), "/ |{0}(0)|", 1e-16
    return np.abs(x - x0), "(absolute: {0}(0) = 0)", max(EPS * float(np.max(np.abs(x))), 1e-300)


def _is_symmetric(res) -> bool:
    sc = res.scene
    return sc is None or sc.body.I1 == sc.body.I2


def _damping_c(res) -> float:
    sc = res.scene
    return float(sc.damping.c) if sc is not None and sc.damping is not None else 0.0


def work_against_damping(res) -> np.ndarray:
    """W(t) = ∫₀ᵗ c |ω̃|² dt′ by the trapezoid rule on the output samples (the power a
    viscous torque −c ω̃ takes out is c |ω̃|², the same in body and inertial components)."""
    power = _damping_c(res) * np.sum(np.asarray(res.omega) ** 2, axis=1)
    steps = np.diff(res.t) * 0.5 * (power[1:] + power[:-1])
    return np.concatenate(([0.0], np.cumsum(steps)))


#: Longest scene title drawn on a plot, in characters (longer ones are cut with "…"): text
#: layout costs matplotlib time in proportion to its length (a 1 MB title took 90 s).
TITLE_DISPLAY_LIMIT = 100


def display_title(text: str, limit: int = TITLE_DISPLAY_LIMIT) -> str:
    """``text`` as a plot shows it: one line (runs of whitespace, newlines too, become one
    space), at most ``limit`` characters (cut with "…"), and ``$`` literal (matplotlib would
    read text between two of them as mathtext, which can fail to parse).

    Parameters
    ----------
    text : str
        A scene's or sweep's title (any length: a scene file may hold up to 1 MiB).
    limit : int
        The most characters kept.

    Returns
    -------
    str
        The title to draw.
    """
    # Cut before splitting: whitespace-collapsing a megabyte would cost more than the rest.
    line = " ".join(text[:4 * limit].split())
    if len(line) > limit:
        line = line[:limit - 1].rstrip() + "…"
    return line.replace("$", r"\$")


def _title(res) -> str:
    sc = res.scene
    name = display_title(sc.title if sc is not None and sc.title else "") or res.model or "simulation"
    parts = [f"formulation {res.formulation}", f"method {res.method}"]
    if sc is not None:
        s = sc.simulate
        if res.method in FIXED_STEP_METHODS:
            parts.append(f"h = {s.h:g} s" if s.h is not None else "default step h")
        else:
            parts.append(f"rtol = {s.rtol:g}, atol = {s.atol:g}")
    parts.append(f"{res.nfev} rhs evaluations")
    return f"{name}\n" + ", ".join(parts)


# ---------------------------------------------------------------------------------------------
# panels: each draws into its axes and sets its own title


def _panel_beta(ax, res):
    axis = "symmetry axis" if _is_symmetric(res) else "body axis"
    beta = np.asarray(res.beta)
    b0 = float(beta[0])
    spread = float(np.ptp(beta))
    if spread <= FLAT_BETA * max(abs(b0), EPS):
        ax.plot(res.t, beta - b0)
        ax.set_ylabel(f"β − β(0) [rad]\nβ(0) = {b0:.12g}")
        ax.set_title(f"tilt of the {axis} ê₃ (nearly constant)")
    else:
        ax.plot(res.t, beta)
        ax.set_ylabel("β [rad]")
        ax.set_title(f"tilt β of the {axis} ê₃")
    _plain(ax)


def _unresolved(w: np.ndarray) -> bool:
    """True when ω̃₁ or ω̃₂ changes sign at more than one sample in eight: the output grid
    does not resolve their rotation, and a line through the samples would be aliasing."""
    flips = [np.count_nonzero(np.diff(np.sign(w[:, k])) != 0) for k in (0, 1)]
    return max(flips) > len(w) / 8


def _panel_omega(ax, res):
    w = np.asarray(res.omega)
    colors = ("C0", "C1", "C2")
    fast = _unresolved(w)
    if fast:
        series = [(np.hypot(w[:, 0], w[:, 1]), "|ω̃⊥| = √(ω̃₁² + ω̃₂²)", colors[0])]
    else:
        series = [(w[:, 0], "ω̃₁", colors[0]), (w[:, 1], "ω̃₂", colors[1])]
    transverse = max(float(np.max(np.abs(y))) for y, _, _ in series)
    spin = float(np.max(np.abs(w[:, 2])))
    separate = spin > SPIN_AXIS_RATIO * transverse and transverse > 0
    if not separate:
        series.append((w[:, 2], "ω̃₃", colors[2]))
    lines = [ax.plot(res.t, y, color=c, lw=1, label=name)[0] for y, name, c in series]
    ax.set_ylabel(("|ω̃⊥|" if fast else "ω̃₁, ω̃₂") + " [rad/s]" if separate else "ω̃ [rad/s]")
    _plain(ax)
    if separate:
        # ω̃₃ itself on its own axis, both axes symmetric about a common zero: heights on either
        # side mean what they say. Not its deviation from ω̃₃(0): a round-off wobble of 1e-10
        # drawn as tall as ω̃₁, ω̃₂ reads as order one. A nearly constant ω̃₃ is a flat line,
        # and the legend states how constant.
        right = ax.twinx()
        w3, w30 = w[:, 2], float(w[0, 2])
        dev = float(np.max(np.abs(w3 - w30)))
        label = "ω̃₃ (right axis)"
        if dev == 0.0:
            label += ", constant exactly"
        elif dev <= FLAT_BETA * abs(w30):
            label += f", constant within {dev:.1e} rad/s"
        lines.append(right.plot(res.t, w3, color=colors[2], lw=1, label=label)[0])
        # ω̃₁, ω̃₂ get the more headroom, so that they mostly stay below the ω̃₃ line.
        left_lim, right_lim = _zero_aligned([y for y, _, _ in series], w3, (1.3, 1.1))
        ax.set_ylim(*left_lim)
        right.set_ylim(*right_lim)
        right.set_ylabel("ω̃₃ [rad/s]", color=colors[2])
        right.tick_params(axis="y", colors=colors[2])
        _plain(right, "y")
    # Above the axes, one row: clear of the data and of the tick labels on either side.
    ax.legend(lines, [ln.get_label() for ln in lines], loc="lower left", bbox_to_anchor=(0.0, 1.0),
              ncol=len(lines), borderaxespad=0.2, fontsize=8, frameon=False, handlelength=1.5)
    ax.set_title("angular velocity, body frame" + ("\n(ω̃₁, ω̃₂ turn faster than the samples resolve)"
                                                   if fast else ""), fontsize=10, pad=18)


def _zero_aligned(left: list, right: np.ndarray, margins=(1.1, 1.1)):
    """y-limits of two twin axes on which 0 sits at the same height: each axis spans its data
    and zero, scaled by its margin; the part below zero is the larger of the two axes' (as a
    fraction of each axis's largest magnitude), so that a curve's height above the common
    zero line means the same on either side."""
    spans = []
    for data in (np.concatenate([np.ravel(d) for d in left]), np.ravel(right)):
        lo, hi = min(0.0, float(np.min(data))), max(0.0, float(np.max(data)))
        spans.append((lo, hi, max(-lo, hi) or 1.0))
    below = max(-lo / size for lo, _, size in spans) + 0.05
    above = max(hi / size for _, hi, size in spans) + 0.05
    return tuple((-below * size * m, above * size * m) for (_, _, size), m in zip(spans, margins))


def _user_symmetries(res) -> dict | None:
    """For a scene with terms written by the user, what their symmetry conserves
    (``derive.symbolic.symmetries.symmetries``: checked symbolically, so SymPy is imported here, for
    such a scene only); None for any other scene."""
    sc = res.scene
    if sc is None or not getattr(sc, "terms", ()):
        return None
    labels = {t.effect: f"{t.kind} {t.name!r}" for t in sc.terms}
    return _symmetries(sc.effects, sc.symmetric, tuple(sorted(labels.items())))


@functools.lru_cache(maxsize=32)
def _symmetries(effect_names, symmetric, labels) -> dict:
    # SymPy decides the invariances; a plot of a scene without user terms never loads it.
    from derive.symbolic.symmetries import symmetries

    return symmetries(effect_names, symmetric, dict(labels))


def _panel_energy_error(ax, res):
    found = _user_symmetries(res)
    if found is not None and not found["energy"]:
        # A user's torque does work: E(t) − E(0) is that work, not an error.
        E = np.asarray(res.energy, dtype=float)
        ax.plot(res.t, E - E[0], lw=1)
        ax.set_ylabel("E(t) − E(0) [J]")
        ax.set_title(f"work done on the body, E(t) − E(0)\n(energy not conserved: {found['why']['energy']})",
                     fontsize=10)
        _plain(ax)
        return
    E = np.asarray(res.energy, dtype=float)
    if np.all(E == E[0]):
        return _say(ax, "energy error (no damping: E is conserved)",
                    f"E is conserved exactly:\nE(t) = E(0) = {E[0]:.10g} J\nat every one of the {E.size} samples")
    rel, how, lin = _deviation(E)
    _plot_deviation(ax, res.t, rel)
    _symlog(ax, rel, "|E − E(0)| " + how.format("E"), lin)
    ax.set_title("energy error (no damping: E is conserved)" + _zeros_note(rel), fontsize=10)
    _plain(ax, "x")


def _panel_energy_damped(ax, res):
    E = np.asarray(res.energy, dtype=float)
    W = work_against_damping(res)
    ax.plot(res.t, E, label="E(t) = T + V")
    ax.plot(res.t, W, label="W(t) = ∫₀ᵗ c|ω̃|² dt′\n(trapezoid rule on\nthe output samples)")
    ax.plot(res.t, E + W, "--", color="k", lw=1, label="E + W (= E(0))")
    ax.set_ylabel("energy [J]")
    ax.set_title(f"energy and work done by damping (c = {_damping_c(res):g} N m s)")
    _plain(ax)
    _legend_outside(ax)


def _panel_balance(ax, res):
    E = np.asarray(res.energy, dtype=float)
    total = E + work_against_damping(res)
    rel, how, lin = _deviation(total)
    _plot_deviation(ax, res.t, rel)
    _symlog(ax, rel, "|E + W − E(0)| " + how.format("E"), lin)
    ax.set_title("energy balance residual: trapezoid rule on the\noutput grid + integration error"
                 + _zeros_note(rel), fontsize=10)
    _plain(ax, "x")


def _conserved(res) -> list[tuple[str, np.ndarray]]:
    """What the undamped motion conserves besides the energy: p_α always (the vertical is a
    symmetry axis of gravity); p_γ when the body is symmetric and every effect axisymmetric
    (not for a centre of mass off axis 3: the Kovalevskaya top); the integrable case's integral."""
    found = _user_symmetries(res)
    if found is not None:  # a body with user terms: what their symmetry leaves, and only that
        return [(name, np.asarray(getattr(res, key), dtype=float))
                for name, key in (("p_α", "p_alpha"), ("p_γ", "p_gamma")) if found[key]]
    out = [("p_α", np.asarray(res.p_alpha, dtype=float))]
    sc = res.scene
    axisymmetric = sc is None or all(e.axisymmetric for e in effects.lookup(sc.effects))
    if _is_symmetric(res) and axisymmetric:
        out.append(("p_γ", np.asarray(res.p_gamma, dtype=float)))
    for name, values in getattr(res, "integrals", {}).items():
        values = np.asarray(values, dtype=float)
        if len(out) > 1 and np.array_equal(values, out[1][1]):
            continue  # the Lagrange top's integral is p_γ itself: not shown twice
        out.append((name, values))
    return out


def _panel_momenta(ax, res):
    conserved = _conserved(res)
    if not conserved:  # a body with user terms that conserve neither momentum
        why = _user_symmetries(res)["why"]
        for name, key in (("p_α", "p_alpha"), ("p_γ", "p_gamma")):
            ax.plot(res.t, np.asarray(getattr(res, key), dtype=float), lw=1, label=name)
        ax.set_ylabel("kg m²/s")
        ax.set_title(f"p_α, p_γ (not conserved: {why['p_alpha']};\n{why['p_gamma']})",
                     fontsize=10)
        _plain(ax, "x")
        _legend_outside(ax)
        return
    exact = [(sym, v) for sym, v in conserved if np.all(v == v[0])]
    said = ", ".join(f"{sym} = {v[0]:.10g}" for sym, v in exact)
    if len(exact) == len(conserved):
        return _say(ax, "conserved: " + ", ".join(sym for sym, _ in exact),
                    f"conserved exactly, every one of the {res.t.size} samples\nequal to the first:\n{said}")
    devs, lins, names = [], [], []
    for sym, values in conserved:
        if any(sym == e for e, _ in exact):
            continue
        rel, how, lin = _deviation(values)
        _plot_deviation(ax, res.t, rel, label=f"|{sym} − {sym}(0)| {how.format(sym)}")
        devs.append(rel)
        lins.append(lin)
        names.append(sym)
    _symlog(ax, np.concatenate(devs), "deviation", min(lins))
    ax.set_title("conserved: " + ", ".join(names) + _zeros_note(np.concatenate(devs))
                 + (f"\nexactly constant (not drawn): {said}" if exact else ""), fontsize=10)
    _plain(ax, "x")
    _legend_outside(ax)


def _panel_top(ax, res):
    x, y, z = np.asarray(res.axis).T
    upper = np.where(z >= 0, 1.0, np.nan)
    lower = np.where(z < 0, 1.0, np.nan)
    ax.plot(x * upper, y * upper, "-", lw=1, color="C0", label="upper hemisphere")
    if np.any(z < 0):
        ax.plot(x * lower, y * lower, "--", lw=1, color="C3", label="lower hemisphere")
    ax.plot(x[:1], y[:1], "o", color="k", ms=4, label="start")
    circle = np.linspace(0, 2 * np.pi, 361)
    ax.plot(np.cos(circle), np.sin(circle), color="0.7", lw=0.8)
    # Square window around the path (the whole disc when the path reaches far out).
    cx, cy = 0.5 * (np.nanmax(x) + np.nanmin(x)), 0.5 * (np.nanmax(y) + np.nanmin(y))
    half = 0.55 * max(float(np.ptp(x)), float(np.ptp(y)), 1e-9)
    if half > 0.5:
        cx, cy, half = 0.0, 0.0, 1.05
    ax.set_xlim(cx - half, cx + half)
    ax.set_ylim(cy - half, cy + half)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel("ê₃ · x̂")
    ax.set_ylabel("ê₃ · ŷ")
    ax.set_title("path of ê₃, seen from above")
    _plain(ax)
    ax.xaxis.set_major_locator(_matplotlib()[1].MaxNLocator(5))
    _legend_outside(ax)


def _sphere(ax, labels):
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 37), np.linspace(0, np.pi, 19))
    ax.plot_wireframe(np.cos(u) * np.sin(v), np.sin(u) * np.sin(v), np.cos(v), color="0.85", lw=0.4)
    for k, (vec, name) in enumerate(zip(np.eye(3), labels)):
        ax.plot(*np.vstack([-vec, vec]).T * 1.15, color="0.5", lw=0.6)
        ax.text(*(vec * 1.25), name, color="0.3", fontsize=9)
    ax.set_box_aspect((1, 1, 1))
    for set_lim in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        set_lim(-1.05, 1.05)
    ticks = [-1, 0, 1]
    ax.set_xticks(ticks)
    ax.set_yticks(ticks)
    ax.set_zticks(ticks)
    ax.tick_params(labelsize=7, pad=0)
    ax.view_init(elev=22, azim=-55)


def _path3d(ax, P, label):
    ax.plot(P[:, 0], P[:, 1], P[:, 2], color="C0", lw=1.0, label=label)
    ax.scatter(*P[0], color="k", s=12, depthshade=False, label="start")
    ax.scatter(*P[-1], color="C3", s=12, depthshade=False, label="end")


def _panel_sphere(ax, res):
    _sphere(ax, ("x̂", "ŷ", "ẑ"))
    P = np.asarray(res.axis)
    P = P / np.linalg.norm(P, axis=1, keepdims=True)
    _path3d(ax, P, "ê₃(t)")
    which = "symmetry axis" if _is_symmetric(res) else "body axis"
    # A path too small to see on the whole sphere (a sleeping top) is said to be so.
    centre = P.mean(axis=0)
    centre /= max(np.linalg.norm(centre), 1e-300)
    spread = float(np.degrees(np.max(np.arccos(np.clip(P @ centre, -1.0, 1.0)))))
    note = f", within {spread:.2g}° of one point" if spread < 2.0 else ""
    if note and "top" in panels(res):
        note += ":\nthe top view shows its shape"
    ax.set_title(f"{which} ê₃ on the unit sphere\n(inertial frame{note})", fontsize=10)
    ax.legend(loc="upper left", bbox_to_anchor=(0.0, 1.0), fontsize=7, frameon=False)


def _panel_polhode(ax, res):
    I = np.array(res.scene.body.moments) if res.scene is not None else np.ones(3)
    L = getattr(res, "L", None)
    L = np.asarray(L) if L is not None else np.asarray(res.omega) * I
    _sphere(ax, ("ê₁", "ê₂", "ê₃"))
    size = np.linalg.norm(L, axis=1)
    _path3d(ax, L / size[:, None], "L̃/|L̃|")
    flip = "" if _is_symmetric(res) else "; ê₂: intermediate axis,\na flip crosses from one side of it to the other"
    if _free(res):
        ax.set_title(f"polhode: L̃ in body axes on the momentum sphere\n|L̃| = {np.median(size):.4g} kg m²/s"
                     + flip, fontsize=10)
    else:
        ax.set_title("direction of L̃ in body axes" + flip, fontsize=10)
    ax.legend(loc="upper left", bbox_to_anchor=(0.0, 1.0), fontsize=7, frameon=False)


def panels(res) -> list[str]:
    """The panel names `figure` draws for this result, in order."""
    names = ["beta", "omega", "energy", "balance" if _damping_c(res) != 0.0 else "momenta"]
    # a symmetric heavy top's loops and cusps show from above; a free or asymmetric body's
    # motion is read in its own axes (the polhode)
    names += ["top", "sphere"] if _is_symmetric(res) and not _free(res) else ["sphere", "polhode"]
    return names


def _free(res) -> bool:
    """No force field acts (no effect with a potential): the motion is read in the body's axes."""
    return all(e.potential is None for e in effects.lookup(getattr(res, "effects", ())))


def _panel_energy(ax, res):
    (_panel_energy_damped if _damping_c(res) != 0.0 else _panel_energy_error)(ax, res)


_DRAW = {"beta": _panel_beta, "omega": _panel_omega, "energy": _panel_energy, "balance": _panel_balance,
         "momenta": _panel_momenta, "top": _panel_top, "sphere": _panel_sphere, "polhode": _panel_polhode}
_3D = ("sphere", "polhode")
_OF_TIME = ("beta", "omega", "energy", "balance", "momenta")  # panels over t: their x axis is t [s]
COLUMNS = 3


def figure(res):
    """The figure of a result (matplotlib Figure, not saved). Each axes carries its panel name
    as its label (``ax.get_label()``); twin axes are labelled ``<panel>:twin``."""
    plt, _ = _matplotlib()
    names = panels(res)
    columns = COLUMNS if len(names) % COLUMNS == 0 or len(names) % 2 else 2  # no empty cell
    rows = -(-len(names) // columns)
    fig = plt.figure(figsize=(6.2 * columns, 4.6 * rows + 0.8), layout="constrained")
    fig.get_layout_engine().set(w_pad=0.12, h_pad=0.12, wspace=0.06, hspace=0.06)
    for k, name in enumerate(names):
        ax = fig.add_subplot(rows, columns, k + 1, projection="3d" if name in _3D else None, label=name)
        before = set(fig.axes)
        if name in _OF_TIME:
            ax.set_xlabel("t [s]")
        _DRAW[name](ax, res)
        for extra in set(fig.axes) - before:
            extra.set_label(f"{name}:twin")
    fig.suptitle(_title(res), fontsize=12)
    return fig


def plot_result(res, fh, fmt: str = "png") -> None:
    """Write the figure of ``res`` to the open binary file ``fh``.

    Parameters
    ----------
    res : Result
        What `derive.simulate` returned.
    fh : binary file object
        Where the figure goes.
    fmt : {"png", "pdf", "svg"}
        The file format (matplotlib's ``savefig`` format); PNG at 100 dpi.
    """
    plt, _ = _matplotlib()
    fig = figure(res)
    try:
        fig.savefig(fh, format=fmt, dpi=100)
    finally:
        plt.close(fig)
