"""Pictures of a sweep: a map (2-D grid) or a line (1-D) of one measure, with the boundary the
analysis predicts drawn over it where it knows one.

Predictions (a top on a table: the tippe top's inversion condition, :func:`_contact_lines`;
the heavy symmetric top, I1 = I2, centre of mass on axis 3, no damping; released
with rates α̇₀, γ̇₀ so that p_γ = I₃ ω̃₃ = I₃ (α̇₀ cos β₀ + γ̇₀)):

* sleeping-top threshold: the upright spin is stable when p_γ² > 4 M g l I₁, i.e. on the spin
  axis γ̇₀ = 2√(M g l I₁)/I₃ − α̇₀ cos β₀;
* steady precession at tilt β exists when p_γ² ≥ 4 M g l I₁ cos β (the discriminant of
  I₁ cos β α̇² − p_γ α̇ + M g l = 0), the curve γ̇₀ = 2√(M g l I₁ cos β)/I₃ − α̇₀ cos β (β < π/2).

The tennis racket (free asymmetric body, I1 < I2 < I3, spin about axis 2): the linearised
growth rate λ = ω̃₂ √((I₂ − I₁)(I₃ − I₂)/(I₁ I₃)) predicts the flip time's slope −1/λ against
ln ε of an off-axis rate ε, i.e. −ln 10/λ per decade on the log₁₀ axis the map uses; the line
is drawn with that slope through the middle point.

What a reader sees is said on the figure: the title names the measure and the varied keys (a
map spans many scenes; the base scene's own title is shown as such); axes carry the physical
symbol (ω̃₁(0), not the zero-based ``initial.omega.0``) and unit; points without a value are
marked, with a count in the legend: a measure that is NaN for a run that went fine ("never
tilted" within t_end) in grey, failed points in red. :func:`sweep_figure` returns the figure.
"""
from __future__ import annotations

import dataclasses
import math
import re

import numpy as np

from derive.errors import SceneError
from derive.sim.plots import display_title
from derive.sweeps.keys import unit_of
from derive.sweeps.measures import REGISTRY
from derive.sim.auto import has_routh
from derive.symbolic.integrable import classify


#: The physical symbol of a varied scene key (initial values with a subscript 0).
SYMBOLS = {"initial.alpha": "α₀", "initial.beta": "β₀", "initial.gamma": "γ₀",
           "initial.alpha_dot": "α̇₀", "initial.beta_dot": "β̇₀", "initial.gamma_dot": "γ̇₀",
           "initial.omega.0": "ω̃₁(0)", "initial.omega.1": "ω̃₂(0)", "initial.omega.2": "ω̃₃(0)",
           "body.I1": "I₁", "body.I2": "I₂", "body.I3": "I₃",
           "gravity.M": "M", "gravity.g": "g", "gravity.l": "l", "damping.c": "c",
           "contact.radius": "r", "contact.offset": "s", "contact.mu": "μ",
           "contact.regularization": "ε", "contact.restitution": "e",
           "initial.vx": "v_x(0)", "initial.vy": "v_y(0)"}


def symbol(key: str) -> str:
    """The symbol of a varied key; an unknown key as written, but a trailing vector index made
    1-based and said to be a component (``x.y.0`` -> ``x.y component 1``)."""
    if key in SYMBOLS:
        return SYMBOLS[key]
    head, _, last = key.rpartition(".")
    return f"{head} component {int(last) + 1}" if head and last.isdigit() else key


def _label(key: str) -> str:
    """Axis label of a varied key: symbol, what it is (the key, unless that is a zero-based
    vector component) and unit."""
    unit = unit_of(key)
    sym = symbol(key)
    if key.startswith("initial.omega."):
        what = f"{sym}, body frame"
    elif sym != key:
        what = f"{sym} ({key})"
    else:
        what = sym
    return f"{what} [{unit}]" if unit else what


def _measure_label(name: str) -> str:
    m = REGISTRY.get(name)
    return f"{name} [{m.unit}]" if m is not None and m.unit else name


def _nan_meaning(name: str) -> str:
    """What NaN means for a measure, from its documentation ("... (NaN: never)"), or ""."""
    m = REGISTRY.get(name)
    found = re.search(r"\(NaN: ([^)]*)\)", m.doc) if m is not None else None
    return found.group(1) if found else ""


def _points(n) -> str:
    return f"{int(n)} point" + ("" if int(n) == 1 else "s")


def _title(res, measure: str, n: int, failed: int) -> str:
    """Line 1: the sweep (measure over the varied keys, how many points); line 2: the base
    scene's title, labelled as such (it describes one scene, not the map)."""
    over = " × ".join(symbol(k) for k in res.keys)
    head = f"{measure} over {over}: {n} points ({failed} failed)"
    # one line, cut for display (a huge title would take the figure long to lay out)
    base = display_title(res.title) if res.title else ""
    return f"{head}\nbase scene: {base}" if base else head


def _heavy_top(scene):
    """(I1, I3, M g l, α̇₀) when the scene is a heavy symmetric top (a symmetric body whose
    effects are all conservative and axisymmetric, with M, g, l: the Lagrange top), else None."""
    if scene is None or not hasattr(scene, "initial"):  # a top on a table: _contact_lines
        return None
    if not scene.initial.has_rates or not has_routh(scene.symmetric, scene.effects):
        return None
    v = scene.param_values()
    if not {"M", "g", "l"} <= set(v):
        return None
    return scene.body.I1, scene.body.I3, v["M"] * v["g"] * v["l"], scene.initial.alpha_dot


def _spin_curves(res, beta):
    """{label: γ̇₀(β)} of the heavy-top predictions, or {} when they do not apply."""
    top = _heavy_top(res.scene)
    if top is None or top[2] <= 0:
        return {}
    I1, I3, mgl, ad = top
    cb = np.cos(beta)
    curves = {"sleeping threshold p_γ² = 4MglI₁": 2 * math.sqrt(mgl * I1) / I3 - ad * cb}
    with np.errstate(invalid="ignore"):
        steady = np.where(cb > 0, 2 * np.sqrt(mgl * I1 * cb) / I3 - ad * cb, np.nan)
    curves["steady precession exists: p_γ² = 4MglI₁cos β"] = steady
    return curves


def _contact_lines(ax, res, keys: dict) -> None:
    """The tippe top's inversion condition over a map that varies the ball's offset s = αr (and
    not its radius or moments): Jellett's integral lets an axisymmetric body on a ball turn
    over only when 1 − α < I₁/I₃ < 1 + α, i.e. beyond s = r |I₁/I₃ − 1| (white line)."""
    sc = res.scene
    if (sc is None or not hasattr(sc, "shape") or sc.shape != "sphere" or not sc.symmetric
            or "contact.offset" not in keys or {"contact.radius", "body.I1", "body.I3"} & set(keys)):
        return
    s = sc.radius * abs(sc.I1 / sc.I3 - 1)
    label = f"inversion possible beyond s = r|I₁/I₃ − 1| = {s:.4g} m"
    (ax.axvline if keys["contact.offset"] == "x" else ax.axhline)(s, color="w", ls="-", lw=1.6,
                                                                   label=label)


def sweep_figure(res, measure: str | None = None):
    """The figure of a sweep (matplotlib Figure, not saved): a map of one measure over a 2-D
    grid, or a line over a 1-D sweep, with the predictions where the analysis has them.

    Parameters
    ----------
    res : SweepResult
        What `derive.sweep` returned.
    measure : str, optional
        The column to draw (default: the first measure other than nfev).

    Returns
    -------
    matplotlib.figure.Figure
        Its data axes is labelled ``"sweep"``; the points without a value are drawn by artists
        with gid ``"nan"`` (the measure is NaN) and ``"failed"``, with legend entries giving
        their counts.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap, LogNorm
    from matplotlib.patches import Patch

    names = [m for m in res.measures if m != "nfev"] or list(res.measures)
    measure = measure or names[0]
    if measure not in res.measures:
        raise SceneError(f"--measure: {measure!r} is not a column of this sweep "
                         f"(one of {', '.join(res.measures)})")
    raw = np.asarray(res.measures[measure], dtype=float)
    failed = ~np.asarray(res.ok)
    z = np.where(failed, np.nan, raw)
    novalue = ~failed & ~np.isfinite(raw)  # the run went fine; the measure has no value
    meaning = _nan_meaning(measure)
    if meaning and measure.startswith("time_to") and res.scene is not None:
        meaning += f" within t_end = {res.scene.simulate.t_end:g} s"  # "never", up to t_end
    # (gid of the marking artist, legend text)
    nan_label = ("nan", f"{measure} = NaN ({meaning}): {_points(novalue.sum())}" if meaning
                 else f"{measure} has no value (NaN): {_points(novalue.sum())}")
    failed_label = ("failed", f"failed: {_points(failed.sum())} (see the status column)")
    fig, ax = plt.subplots(figsize=(7.5, 5.2), dpi=110)
    ax.set_label("sweep")
    if res.shape is not None and len(res.shape) == 2:
        ky, kx = res.keys  # the first key is the slow one: rows
        y = res.params[ky].reshape(res.shape)[:, 0]
        x = res.params[kx].reshape(res.shape)[0, :]
        zz = z.reshape(res.shape)
        finite = zz[np.isfinite(zz)]
        norm = LogNorm(finite.min(), finite.max()) if _wide(finite) else None
        mesh = ax.pcolormesh(x, y, zz, shading="nearest", cmap="viridis", norm=norm)
        fig.colorbar(mesh, ax=ax, label=_measure_label(measure))
        # Cells without a value would be left blank (the background): paint them in colours
        # outside the colour map, so that "never" and "failed" are seen and counted.
        marks = []  # legend patches of the painted cells
        for mask, colour, label in ((novalue, "0.6", nan_label), (failed, "tab:red", failed_label)):
            if mask.any():
                cells = np.ma.masked_where(~mask.reshape(res.shape), np.ones(res.shape))
                painted = ax.pcolormesh(x, y, cells, shading="nearest",
                                        cmap=ListedColormap([colour]))
                gid, text = label
                painted.set_gid(gid)
                marks.append(Patch(facecolor=colour, edgecolor="white", label=text))
        ax.set_xlabel(_label(kx))
        ax.set_ylabel(_label(ky))
        keys = {kx: "x", ky: "y"}
        if set(keys) == {"initial.gamma_dot", "initial.beta"}:
            beta = np.linspace(y.min(), y.max(), 400) if keys["initial.beta"] == "y" else np.linspace(x.min(), x.max(), 400)
            for (label, spin), style in zip(_spin_curves(res, beta).items(), ("w-", "w--")):
                spin = np.broadcast_to(spin, beta.shape)
                xs, ys = (spin, beta) if keys["initial.beta"] == "y" else (beta, spin)
                ax.plot(xs, ys, style, lw=1.6, label=label)
            ax.set_xlim(x.min(), x.max())
            ax.set_ylim(y.min(), y.max())
        _contact_lines(ax, res, keys)
        handles, labels = ax.get_legend_handles_labels()
        if handles or marks:
            # A dark box: the predicted curves are white (they are drawn over the colour map).
            ax.legend(handles + marks, labels + [m.get_label() for m in marks], loc="lower right",
                      fontsize=8, framealpha=0.85, facecolor="0.25", edgecolor="0.25",
                      labelcolor="white")
    else:
        k = res.keys[0]
        x = res.params[k]
        order = np.argsort(x)
        ax.plot(x[order], z[order], "o-", ms=3, label=f"{measure} (simulated)")
        ax.set_xlabel(_label(k))
        ax.set_ylabel(_measure_label(measure))
        if _wide(z[np.isfinite(z)]):
            ax.set_yscale("log")
        _line_prediction(ax, res, k, x[order], z[order], measure)
        # Points without a value, on the bottom edge of the axes at their x (a line through
        # the others would just skip them).
        edge = ax.get_xaxis_transform()
        for mask, style, label in ((novalue, dict(marker="v", color="0.45"), nan_label),
                                   (failed, dict(marker="x", color="tab:red"), failed_label)):
            if mask.any():
                gid, text = label
                ax.plot(x[mask], np.full(int(mask.sum()), 0.03), ls="none", ms=7, clip_on=False,
                        transform=edge, gid=gid, label=text, **style)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=8)
        ax.grid(True, alpha=0.3)
    ax.set_title(_title(res, measure, len(z), int(failed.sum())), fontsize=10)
    fig.tight_layout()
    return fig


def plot_sweep(res, path_or_file, measure: str | None = None, fmt: str = "png") -> None:
    """Write :func:`sweep_figure` to ``path_or_file`` in the format ``fmt`` (png, pdf, svg)."""
    import matplotlib.pyplot as plt

    fig = sweep_figure(res, measure)
    try:
        fig.savefig(path_or_file, format=fmt)
    finally:
        plt.close(fig)


def _wide(finite: np.ndarray) -> bool:
    """Positive values spanning more than two decades: drawn on a log scale."""
    return bool(finite.size) and finite.min() > 0 and finite.max() / finite.min() > 100


#: Moment ratios at which a body can become an integrable case (Lagrange 1, Kovalevskaya 2,
#: Goryachev–Chaplygin 4), tried against each other moment when a sweep varies one.
_RATIOS = (0.25, 0.5, 1.0, 2.0, 4.0)


def _integrable_moments(ax, sc, key, x) -> None:
    """Where the swept moment makes the scene's body an integrable case, the other numbers as
    the scene has them (``derive.symbolic.integrable.classify``): a dotted line labelled with the case."""
    i = ("body.I1", "body.I2", "body.I3").index(key)
    moments = list(sc.body.moments)
    found = {}
    for j, other in enumerate(moments):
        if j == i:
            continue
        for r in _RATIOS:
            v = other * r
            if not (x.min() <= v <= x.max()):
                continue
            trial = list(moments)
            trial[i] = v
            case = classify(dataclasses.replace(sc, body=type(sc.body)(*trial))).case
            if case != "general":
                found.setdefault(v, case)
    for v, case in sorted(found.items()):
        ax.axvline(v, color="k", ls=":", label=f"{case} case: {symbol(key)} = {v:.4g}")


def _line_prediction(ax, res, key, x, z, measure):
    sc = res.scene
    if sc is None:
        return
    if measure == "integral_drift" and key in ("body.I1", "body.I2", "body.I3"):
        _integrable_moments(ax, sc, key, x)
        return
    if key == "initial.gamma_dot" and measure.startswith("beta"):
        top = _heavy_top(sc)
        if top is not None and top[2] > 0:
            for label, spin in _spin_curves(res, np.array([sc.initial.beta])).items():
                if "sleeping" in label:
                    ax.axvline(float(np.ravel(spin)[0]), color="k", ls="--", label=label)
        return
    if (key.startswith("initial.omega.") and measure == "time_to_flip" and not sc.effects
            and not sc.initial.has_rates):
        I1, I2, I3 = sc.body.moments
        w2 = sc.initial.omega[1]
        if (I2 - I1) * (I3 - I2) > 0:
            lam = abs(w2) * math.sqrt((I2 - I1) * (I3 - I2) / (I1 * I3))
            ok = np.isfinite(z) & (x > 0)
            if ok.sum() >= 2:
                ax.set_xscale("log")
                xm = math.exp(np.mean(np.log(x[ok])))
                zm = float(np.interp(math.log(xm), np.log(x[ok]), z[ok]))
                # The axis is log10: per decade of ε the flip comes ln(10)/λ earlier.
                ax.plot(x[ok], zm - np.log(x[ok] / xm) / lam, "k--",
                        label=f"linearised: slope −ln 10/λ = −{math.log(10) / lam:.3g} s per "
                              f"decade of {symbol(key)} (λ = {lam:.3g} /s)")
