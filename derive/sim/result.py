"""The Result of a run: the C call's output rows as arrays, the integrals of an integrable case,
the checks of a finished run (non-finite outputs, the Euler angles' pole), what a SaveAt keeps
(:func:`kept`), and the one-line message of a failed run (:func:`_explain`).

Takes: the output rows of a C call. Gives: :class:`Result`.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from derive.errors import IntegrationError, SceneError
from derive.methods.status import Status
from derive.methods.status import message as status_message
from derive.sim import animate as views
from derive.sim import plan
from derive.sim.saveat import SaveAt
from derive.sim.scene import Scene
from derive.symbolic.formulations import OUTPUTS, REGISTRY


@dataclass
class Result:
    """One simulated motion: the arrays of the output file, as attributes.

    Attributes
    ----------
    t : ndarray, shape (n,)
        Output times, s (uniform from 0 to ``t_end``).
    alpha, beta, gamma : ndarray, shape (n,)
        z-y-z Euler angles, rad: β ∈ [0, π]; α and γ continuous (not wrapped to ±π).
    omega : ndarray, shape (n, 3)
        Angular velocity in body axes (ω̃₁, ω̃₂, ω̃₃), rad/s.
    axis : ndarray, shape (n, 3)
        Inertial components of the body axis ê₃.
    energy : ndarray, shape (n,)
        Total energy T + V, J (conserved without damping).
    p_alpha, p_gamma : ndarray, shape (n,)
        Momenta conjugate to α and γ, kg m²/s (conserved for a symmetric top without damping).
    n, L : ndarray, shape (n, 3)
        The upward vertical, and the angular momentum about the pivot (kg m²/s), in body axes.
    integrals : dict
        ``{name: (n,) array}``: the extra integral of an integrable case (also readable as
        ``res.integral_<name>``); empty for a general body.
    method, formulation : str
        What actually ran.
    nfev : int
        Right-hand-side evaluations.
    model : str
        The generated model's name (its C prefix).
    """

    t: np.ndarray
    alpha: np.ndarray
    beta: np.ndarray
    gamma: np.ndarray
    omega: np.ndarray
    axis: np.ndarray
    energy: np.ndarray
    p_alpha: np.ndarray
    p_gamma: np.ndarray
    n: np.ndarray
    L: np.ndarray
    method: str
    formulation: str
    nfev: int
    model: str = ""
    #: The effects in the model that ran (registry names): a table whose values make its effect
    #: vanish (``[damping] c = 0``) is absent here, and ``model`` names the kernel without it.
    effects: tuple = ()
    integrals: dict = field(default_factory=dict)
    state: np.ndarray | None = field(default=None, repr=False)
    scene: Scene | None = field(default=None, repr=False)

    def arrays(self) -> dict:
        """Everything the output file holds, by name (``integral_<name>`` for the integrals,
        ``method``, ``formulation`` and ``nfev`` as 0-d arrays)."""
        out = {name: getattr(self, name) for name, _ in OUTPUTS if getattr(self, name) is not None}
        out["t"] = self.t
        out.update({f"integral_{k}": v for k, v in self.integrals.items()})
        out.update(method=np.array(self.method), formulation=np.array(self.formulation),
                   nfev=np.array(self.nfev, dtype=np.int64))
        return out

    def __getattr__(self, name):
        # (called only for a name the instance does not hold yet)
        d = self.__dict__
        row = _VIEWS.get(name)
        if row is not None and name not in d.get("_kept", (name,)):
            return None  # not kept (SaveAt.outputs)
        if row is not None and "_out" in d:  # an output of the C call's buffer: its view, once
            value = d[name] = _view(d["_out"], *row)
            return value
        if name.startswith("integral_") and name[9:] in d.get("integrals", {}):
            return self.integrals[name[9:]]
        raise AttributeError(name)

    def animate(self, path=None, *, fps=None, speed=None):
        """The motion drawn in 3-D: the body turning, the path of ê₃ on the unit sphere, L, the
        vertical, the time and the angles (:mod:`derive.sim.animate`; ``derive animate``).

        Parameters
        ----------
        path : str or os.PathLike, optional
            ``.gif``, ``.mp4`` (needs ffmpeg) or ``.html`` (self-contained): written all or
            nothing. None: return the player for Jupyter to show inline.
        fps : int, optional
            Frames per second (default 20).
        speed : float, optional
            Simulated seconds per wall second (default: chosen from the motion).

        Returns
        -------
        str or os.PathLike, or derive.sim.animate.page.Animation
            ``path`` when given, else an object with ``_repr_html_`` (and ``save``).
        """
        return views.animate(self, path, fps, speed)

    def _repr_html_(self) -> str:
        """A short summary table for Jupyter (scene, method, t range, samples, energy drift)."""
        return views.summary_html(self)


def _explain(desc, stats, max_steps) -> str:
    """The solver's one-line failure message; for a domain error, what the domain is."""
    status = int(stats["status"])
    if status == Status.DOMAIN and desc.domain_note:
        return f"t = {float(stats['t_fail']):.8g}: {desc.domain_note}"
    if status == Status.NONFINITE_OUTPUT and 0 <= int(stats["fail_index"]) < len(_COLUMN_OUTPUT):
        return (f"t = {float(stats['t_fail']):.6g}: non-finite {_COLUMN_OUTPUT[int(stats['fail_index'])]} "
                f"in the output")
    return status_message(stats, desc.states, max_steps)


#: output -> (its rows of out (NOBS, n), wide: its rows transposed to (n, width)).
_VIEWS = {name: (k if w == 1 else slice(k, k + w), w > 1)
          for k, (name, w) in zip(np.cumsum([0] + [w for _, w in OUTPUTS]).tolist(), OUTPUTS)}
_L_ROWS, _N_ROWS = _VIEWS["L"][0], _VIEWS["n"][0]  # the rows of out holding L and n
_COLUMN_OUTPUT = tuple(name for name, width in OUTPUTS for _ in range(width))  # column -> output
_EPS = float(np.finfo(float).eps)


def _result(desc, out, y, t, scene, method, nfev, finite: bool = False, integrals=None) -> Result:
    """The Result of one trajectory's outputs ``out`` (NOBS, n), each output's view made when
    first read (:meth:`Result.__getattr__`: a batch of 1000 would otherwise make 10 000 views);
    ``finite``: the caller has checked them already (a batch checks all trajectories at once);
    ``integrals``: the scene's integral formulas when the caller has them
    (:attr:`derive.sim.plan.Plan.integral_rows`)."""
    if not finite and not np.isfinite(out).all():  # find where only when something is wrong
        for name, (rows, wide) in _VIEWS.items():
            bad = ~np.isfinite(_view(out, rows, wide))
            if bad.any():
                j = int(np.argwhere(bad)[0][0])
                raise IntegrationError(f"t = {t[j]:.6g}: non-finite {name} in the output")
    rows = plan.integral_rows_of(scene) if integrals is None else integrals
    return _filled(t, method, desc.formulation, desc.name, desc.effects, out, y, int(nfev),
                   _integral_arrays(rows, out, t), scene)


def _view(out: np.ndarray, rows, wide: bool) -> np.ndarray:
    """An output's view of ``out`` (NOBS, n): its row, or its rows transposed to (n, width)."""
    return out[rows].T if wide else out[rows]


def _filled(t, method, formulation, model, effects, out, y, nfev, integrals, scene) -> Result:
    """A Result whose outputs are the rows of ``out``, made when first read."""
    res = object.__new__(Result)  # every other field is given: what Result(**fields) would make
    res.__dict__.update(t=t, method=method, formulation=formulation, model=model, effects=effects,
                        _out=out, state=y, nfev=nfev, integrals=integrals, scene=scene)
    return res


def _integral_arrays(rows, out: np.ndarray, t: np.ndarray) -> dict:
    """``integral_<name>`` arrays of the scene's integrable case (none for a general body) from
    its formulas ``rows`` (:func:`derive.sim.plan.integral_rows_of`) on the L and n rows of the
    outputs ``out`` (NOBS, n), the formulas' own layout, with NumPy's floating-point errors
    ignored (absurd numbers may overflow there); IntegrationError naming the first non-finite
    value."""
    L, n = out[_L_ROWS], out[_N_ROWS]
    found = {}
    for name, formula, values, component in rows:
        if component is not None:  # L's own component: a copy of the row, finite as L was checked
            found[name] = L[component].copy()
            continue
        with np.errstate(all="ignore"):
            found[name] = values = np.asarray(formula(L, n, values), dtype=float)
        if not np.isfinite(values).all():
            j = int(np.argwhere(~np.isfinite(values))[0][0])
            raise IntegrationError(f"t = {t[j]:.6g}: non-finite integral_{name} in the output "
                                   f"(overflow: the scene's numbers are out of range)")
    return found


def _clear_of_pole(sin_beta, rtol):
    """The rule: eps/sin²β, the relative error of q̈ there, within the tolerance (scalars or
    arrays)."""
    return sin_beta * sin_beta >= _EPS / rtol


def _check_pole(desc, t, beta, rtol):
    """The Euler-angle equations divide by sin β: q̈ has relative error ~ eps/sin²β. Refuse a
    trajectory whose closest approach to a pole made that larger than the tolerance.

    The output β is canonical, in [0, π], where sin is concave: the smallest sin β over the
    samples is at the smallest or the largest β (two reductions, not a sine per sample)."""
    if not REGISTRY[desc.formulation].pole_loss:
        return
    lo, hi = float(beta.min()), float(beta.max())
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return  # _result names the non-finite output
    if _clear_of_pole(min(math.sin(lo), math.sin(hi)), rtol):
        return
    s = np.abs(np.sin(beta))
    k = int(s.argmin())
    if not _clear_of_pole(s[k], rtol):
        raise IntegrationError(f"t = {t[k]:.6g}: coordinate singularity of the Euler-angle formulation "
                               f"(|sin beta| = {s[k]:.3g}); use formulation = \"quaternion\" or \"auto\"")


def _pole_suspects(desc, betas: np.ndarray, rtol: float) -> np.ndarray:
    """Per trajectory (rows of canonical β), whether ``_check_pole`` could object: the smallest
    sin β is at the smallest or the largest β (sin is concave on [0, π]). The outputs are finite
    here (the C call checked them; a NaN would make its row a suspect anyway)."""
    if not REGISTRY[desc.formulation].pole_loss:
        return np.zeros(len(betas), dtype=bool)
    return ~_clear_of_pole(np.minimum(np.sin(betas.min(axis=1)), np.sin(betas.max(axis=1))), rtol)


def _quiet(fn):
    """Run ``fn`` with NumPy's floating-point warnings off: absurd but finite inputs overflow on
    the way, and what counts is the result, which is checked (a non-finite state or output is
    an IntegrationError); a warning printed before that error line would only confuse."""
    @functools.wraps(fn)
    def quiet(*args, **kwargs):
        with np.errstate(all="ignore"):
            return fn(*args, **kwargs)
    return quiet


#: What a SaveAt may name: the outputs of the output file and the integrator's state.
KNOWN = tuple(name for name, _ in OUTPUTS) + ("state",)


def selection(saveat: SaveAt) -> tuple[bool, tuple[str, ...]]:
    """(final, names) of a :class:`~derive.sim.saveat.SaveAt`: whether only t_end is kept, and
    the outputs kept (every one and the state when it names none); SceneError naming
    ``outputs`` for a name that is not an output."""
    names = saveat.outputs or KNOWN
    for n in names:
        if n not in KNOWN:
            raise SceneError(f"<saveat>: outputs: unknown output {n!r} (the outputs: {', '.join(KNOWN)})")
    return saveat.final, names


def kept(res: Result, saveat: SaveAt | None) -> Result:
    """``res`` as ``saveat`` keeps it: with ``t="final"`` every array at t_end alone (length 1
    along time), with ``outputs`` only those outputs (the others None; ``arrays()`` leaves them
    out). The default SaveAt keeps ``res`` as it is."""
    if saveat is None or saveat.everything:
        return res
    final, names = selection(saveat)
    d = res.__dict__
    out, y, t = d["_out"], res.state, res.t
    integrals = res.integrals
    if final:
        out, y, t = out[:, -1:], y[-1:], t[-1:]
        integrals = {k: v[-1:] for k, v in integrals.items()}
    new = _filled(t, res.method, res.formulation, res.model, res.effects, out,
                  y if "state" in names else None, res.nfev, integrals, res.scene)
    if saveat.outputs is not None:
        new.__dict__["_kept"] = frozenset(names)
    return new
