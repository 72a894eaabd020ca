"""Plots of a simulated trajectory (matplotlib, headless Agg backend).

Three panels: β(t); the path of the symmetry axis ê₃ on the unit sphere, seen from above
(orthographic projection onto the x-y plane, upper hemisphere solid, lower dashed), where the
nutation loops, cusps and waves show; and the relative energy error |E(t) − E(0)|/|E(0)|.
"""
from __future__ import annotations

import numpy as np


def plot_result(res, fh) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6), constrained_layout=True)
    title = (res.scene.title if res.scene is not None and res.scene.title else "") or res.model
    fig.suptitle(f"{title} — {res.formulation}, {res.method}, {res.nfev} rhs evaluations")

    ax[0].plot(res.t, res.beta)
    ax[0].set_xlabel("t [s]")
    ax[0].set_ylabel("β [rad]")
    ax[0].set_title("tilt of the symmetry axis")

    x, y, z = res.axis.T
    upper = np.where(z >= 0, 1.0, np.nan)
    lower = np.where(z < 0, 1.0, np.nan)
    ax[1].plot(x * upper, y * upper, "-", lw=1, label="upper hemisphere")
    ax[1].plot(x * lower, y * lower, "--", lw=1, label="lower hemisphere")
    circle = np.linspace(0, 2 * np.pi, 361)
    ax[1].plot(np.cos(circle), np.sin(circle), color="0.7", lw=0.8)
    r = max(1e-12, float(np.max(np.hypot(x, y))))
    lim = min(1.05, 1.15 * r)
    ax[1].set_xlim(-lim, lim)
    ax[1].set_ylim(-lim, lim)
    ax[1].set_aspect("equal")
    ax[1].set_xlabel("ê₃ · x̂")
    ax[1].set_ylabel("ê₃ · ŷ")
    ax[1].set_title("axis path on the unit sphere (top view)")
    ax[1].legend(loc="upper right", fontsize=8)

    E0 = res.energy[0]
    scale = abs(E0) if E0 != 0 else max(1e-300, float(np.max(np.abs(res.energy))))
    err = np.abs(res.energy - E0) / scale
    ax[2].semilogy(res.t, np.maximum(err, 1e-17))
    ax[2].set_xlabel("t [s]")
    ax[2].set_ylabel("|E − E₀| / |E₀|")
    ax[2].set_title("relative energy error")
    fig.savefig(fh, format="png", dpi=110)
    plt.close(fig)
