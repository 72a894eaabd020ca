"""A compiled Euler–Poisson model with its Lie–Poisson splitting solvers, and the NumPy maps
between the body's state and (ω̃, R) used to start and read them.

The state is the model's own: (ω̃, n, e) or (L, n, e) with L = I ω̃ about the pivot, n = Rᵀẑ
and e = Rᵀx̂ in body axes (:mod:`derive.methods.splitting`).
"""
from __future__ import annotations

import numpy as np

from derive.codegen.sources import model_sources
from derive.codegen.splitting import _omega_state, render_splitting
from derive.runtime.cbuild import DEFAULT_FLAGS, compile_library
from derive.runtime.kernel import Kernel
from derive.runtime.records import STATS_DTYPE, saveat


def sources(model, methods: list[str] | None = None) -> tuple[dict[str, str], str]:
    """Every C file of the model, its registered solvers and its splitting solvers, and the
    name of the one translation unit that includes the .c files."""
    files = {k[2:]: v for k, v in model_sources(model).items() if k.startswith("c/")}
    files.update(render_splitting(model, methods))
    unity = f"{model.name}_split_unity.c"
    files[unity] = "".join(f'#include "{n}"\n' for n in
                           (f"{model.name}.c", f"{model.name}_solvers.c", f"{model.name}_splitting.c"))
    return files, unity


class Splitter:
    """A compiled Euler–Poisson model with its splitting solvers (``solve``: their run drivers,
    arguments unchecked, so the C checks answer) and, as ``kernel``
    (:class:`derive.runtime.kernel.Kernel`), the registered ones (dop853, gauss4, …)."""

    def __init__(self, model, flags=None):
        files, unity = sources(model)
        self.model = model
        self.lib = compile_library(f"{model.name}_split", files, unity,
                                   DEFAULT_FLAGS if flags is None else flags)
        self.kernel = Kernel(self.lib, model.name)

    def solve(self, method: str, y0, p, t_out, h: float):
        """(y at every t_out, the derive_stats record) for one trajectory."""
        y, st = self.solve_batch(method, np.reshape(y0, (1, -1)), p, t_out, h)
        return y[0], st[0]

    def solve_batch(self, method: str, y0s, ps, t_out, h: float):
        """(y[b, k], stats[b]) for n_batch trajectories (``ps``: one per trajectory, or shared)."""
        t = np.ascontiguousarray(t_out, dtype=np.float64)
        y0s = np.ascontiguousarray(y0s, dtype=np.float64)
        n = y0s.shape[0]
        ps = np.ascontiguousarray(np.broadcast_to(np.asarray(ps, dtype=np.float64),
                                                  (n, len(self.model.params))))
        y = np.full((n, t.size, 9), np.nan)
        st = np.zeros(max(n, 1), dtype=STATS_DTYPE)
        self.kernel.driver(method)(saveat(t, outputs=False), n, y0s, ps, [float(h)], y, None, st)
        return y, st[:n]


def body(model, p) -> tuple[np.ndarray, np.ndarray]:
    """(I₁, I₂, I₃) and M g r_c of an Euler–Poisson model's parameter vector p."""
    pn, p = model.param_names, np.asarray(p, dtype=float)
    inertia = np.array([p[pn.index("I1")], p[pn.index("I2" if "I2" in pn else "I1")],
                        p[pn.index("I3")]])
    if "cx" in pn:
        rc = np.array([p[pn.index(k)] for k in ("cx", "cy", "cz")])
    elif "l" in pn:
        rc = np.array([0.0, 0.0, p[pn.index("l")]])
    else:
        rc = np.zeros(3)
    mg = p[pn.index("M")] * p[pn.index("g")] if "M" in pn else 0.0
    return inertia, mg * rc


def initial_state(model, p, omega, R) -> np.ndarray:
    """The model's state from ω̃ (body axes) and R (body → inertial): (ω̃ or L = I ω̃, n, e) with
    n = Rᵀẑ (third row of R), e = Rᵀx̂ (first row)."""
    R = np.asarray(R, dtype=float)
    w = np.asarray(omega, dtype=float)
    head = w if _omega_state(model) else body(model, p)[0] * w
    return np.concatenate([head, R[2], R[0]])


def angular_momentum(model, p, y) -> np.ndarray:
    """L = I ω̃ along y[..., 9]."""
    y = np.asarray(y)
    return y[..., 0:3] * body(model, p)[0] if _omega_state(model) else y[..., 0:3]


def energy(model, p, y) -> np.ndarray:
    """H = Σ L_i²/(2 I_i) + M g n·r_c along y[..., 9]."""
    inertia, mg_rc = body(model, p)
    L = angular_momentum(model, p, y)
    return 0.5 * np.sum(L**2 / inertia, axis=-1) + np.asarray(y)[..., 3:6] @ mg_rc
