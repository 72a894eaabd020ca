"""Pictures of a sweep: a map (2-D grid) or a line (1-D) of one measure, with the boundary the
analysis predicts drawn over it where it knows one.

Predictions (the heavy symmetric top, I1 = I2, centre of mass on axis 3, no damping; released
with rates α̇₀, γ̇₀ so that p_γ = I₃ ω̃₃ = I₃ (α̇₀ cos β₀ + γ̇₀)):

* sleeping-top threshold: the upright spin is stable when p_γ² > 4 M g l I₁, i.e. on the spin
  axis γ̇₀ = 2√(M g l I₁)/I₃ − α̇₀ cos β₀;
* steady precession at tilt β exists when p_γ² ≥ 4 M g l I₁ cos β (the discriminant of
  I₁ cos β α̇² − p_γ α̇ + M g l = 0), the curve γ̇₀ = 2√(M g l I₁ cos β)/I₃ − α̇₀ cos β (β < π/2).

The tennis racket (free asymmetric body, I1 < I2 < I3, spin about axis 2): the linearised
growth rate λ = ω̃₂ √((I₂ − I₁)(I₃ − I₂)/(I₁ I₃)) predicts the flip time's slope −1/λ against
ln ε of an off-axis rate ε; the line is drawn with that slope through the middle point.
"""
from __future__ import annotations

import math

import numpy as np

from derive.errors import SceneError


def _label(key: str) -> str:
    from derive.sweeps.keys import unit_of

    unit = unit_of(key)
    return f"{key} ({unit})" if unit else key


def _measure_label(name: str) -> str:
    from derive.sweeps.measures import REGISTRY

    m = REGISTRY.get(name)
    return f"{name} ({m.unit})" if m is not None and m.unit else name


def _heavy_top(scene):
    """(I1, I3, M g l, α̇₀) when the scene is a heavy symmetric top (a symmetric body whose
    effects are all conservative and axisymmetric, with M, g, l: the Lagrange top), else None."""
    from derive.sim.auto import has_routh

    if scene is None or not scene.initial.has_rates or not has_routh(scene.symmetric, scene.effects):
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


def plot_sweep(res, path_or_file, measure: str | None = None, fmt: str = "png") -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import LogNorm

    names = [m for m in res.measures if m != "nfev"] or list(res.measures)
    measure = measure or names[0]
    if measure not in res.measures:
        raise SceneError(f"--measure: {measure!r} is not a column of this sweep "
                         f"(one of {', '.join(res.measures)})")
    z = np.asarray(res.measures[measure], dtype=float)
    z = np.where(res.ok, z, np.nan)
    from derive.sim.plots import display_title

    title = display_title(res.title or res.source)
    fig, ax = plt.subplots(figsize=(7.5, 5.2), dpi=110)
    if res.shape is not None and len(res.shape) == 2:
        ky, kx = res.keys  # the first key is the slow one: rows
        y = res.params[ky].reshape(res.shape)[:, 0]
        x = res.params[kx].reshape(res.shape)[0, :]
        zz = z.reshape(res.shape)
        finite = zz[np.isfinite(zz)]
        norm = LogNorm(finite.min(), finite.max()) if _wide(finite) else None
        mesh = ax.pcolormesh(x, y, zz, shading="nearest", cmap="viridis", norm=norm)
        fig.colorbar(mesh, ax=ax, label=_measure_label(measure))
        ax.set_xlabel(_label(kx))
        ax.set_ylabel(_label(ky))
        keys = {kx: "x", ky: "y"}
        if set(keys) == {"initial.gamma_dot", "initial.beta"}:
            beta = np.linspace(y.min(), y.max(), 400) if keys["initial.beta"] == "y" else np.linspace(x.min(), x.max(), 400)
            for (label, spin), style in zip(_spin_curves(res, beta).items(), ("w-", "w--")):
                spin = np.broadcast_to(spin, beta.shape)
                xs, ys = (spin, beta) if keys["initial.beta"] == "y" else (beta, spin)
                ax.plot(xs, ys, style, lw=1.6, label=label)
            if ax.get_legend_handles_labels()[0]:
                ax.legend(loc="lower right", fontsize=8, framealpha=0.6)
            ax.set_xlim(x.min(), x.max())
            ax.set_ylim(y.min(), y.max())
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
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=8)
        ax.grid(True, alpha=0.3)
    ax.set_title(f"{title}\n{measure} over {len(z)} points ({int((~res.ok).sum())} failed)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path_or_file, format=fmt)
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
    import dataclasses

    from derive.symbolic.integrable import classify

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
        ax.axvline(v, color="k", ls=":", label=f"{case} case: {key} = {v:.4g}")


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
                ax.plot(x[ok], zm - np.log(x[ok] / xm) / lam, "k--",
                        label=f"linearised: slope −1/λ, λ = {lam:.3g} /s")
