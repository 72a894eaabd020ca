"""`derive analyze` for a body with terms written by the user (``[[potential]]``, ``[[torque]]``).

Everything is derived from the scene's effects (built-in and the user's) as for the shipped ones:

1. T, V and L = T − V in z-y-z Euler angles (ΣV of every conservative effect);
2. the Euler–Poisson equations (``models.euler_poisson``): ω̃̇, ṅ = n × ω̃ and ė = e × ω̃ (a user's
   V may depend on all of R, whose rows are e, n × e, n);
3. the integrals their symmetry leaves (:func:`derive.symbolic.symmetries.symmetries`): the energy
   without torques, p_α = L·n when V is invariant about the vertical and no torque has a
   vertical component, p_γ = I₃ω̃₃ for a symmetric body when V is invariant about axis 3 and no
   torque acts along it, and |n|² = 1 always;
4. for a conservative body, the rest equilibria: ω̃ = 0 at the critical points of V on SO(3),
   found numerically from many starting orientations (Newton on the torque of V), each with the
   Hessian H of V under body rotations R → R exp([ε]ₓ) and the linearisation
   I δθ̈ = −H δθ, λ² = −eig(I⁻¹H). Verdict: stable (True) when every eigenvalue of I⁻¹H is
   positive (a strict minimum: Lagrange–Dirichlet), or positive apart from directions along
   which V is exactly constant (a family of equilibria, stable as a set); unstable (False) when
   one is negative (a real λ > 0); None otherwise (degenerate). Steady rotations are not
   searched for.

Parameters of a term are shown with the term's name as a subscript (μ_magnet).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from derive.symbolic import effect_sums as sums
from derive.symbolic import effects as fx
from derive.symbolic import models
from derive.symbolic.lagrangian import I1, I2, I3, kinetic_energy
from derive.symbolic.rotations import ZYZ, skew, trig_reduce
from derive.symbolic.symmetries import symmetries

#: Relative size of a torque below which a point counts as a critical point of V.
CRITICAL_TOLERANCE = 1e-10
#: Relative size of an eigenvalue of I⁻¹H below which it counts as zero.
ZERO_TOLERANCE = 1e-8
#: Starting orientations of the search for critical points (deterministic).
STARTS = 48


@dataclass
class Rest:
    """A rest equilibrium (ω̃ = 0 at a critical point of V): V there, the upward vertical n in
    body axes, the Hessian's eigenvalues, the linearisation's eigenvalues and the verdict."""

    V: float
    n: tuple
    hessian: list
    eigenvalues: list
    stable: bool | None
    family: int  # directions along which V is constant (0: an isolated equilibrium)

    @property
    def description(self) -> str:
        kind = {True: "minimum", False: "saddle or maximum", None: "degenerate critical point"}
        text = f"rest at a {kind[self.stable]} of V"
        if self.family:
            text += (f", one of a family ({self.family} direction{'s' if self.family > 1 else ''} "
                     f"along which V is constant)")
        return text

    def to_json(self) -> dict:
        return {"kind": "rest", "axis": None,
                "condition": "omega = 0 and the torque of V vanishes (dV = 0 on SO(3))",
                "stable": self.stable, "description": self.description,
                "method": "Hessian of V under body rotations; linearisation I dtheta'' = -H dtheta",
                "values": {"V": self.V, "n": list(self.n), "hessian_eigenvalues": self.hessian,
                           "family": self.family},
                "units": {"V": "J", "hessian_eigenvalues": "J rad^-2", "eigenvalues": "s^-1"},
                "eigenvalues": [[float(z.real), float(z.imag)] for z in self.eigenvalues]}


@dataclass
class OwnBodyAnalysis:
    """The analysis of a scene with user terms; ``to_json`` and ``to_markdown`` as
    :class:`derive.lecture.analysis.Analysis`."""

    scene: object
    integrals: dict  # symmetries(...)
    equilibria: list = field(default_factory=list)
    searched: bool = False  # rest equilibria searched (a conservative body)

    @property
    def reason(self) -> str:
        return ("the scene has terms written by the user: the integrals are those their "
                "symmetry leaves, derived below")

    def integral_records(self) -> list[dict]:
        sym = self.integrals
        out = [
            {"name": "energy", "expression": "T + V", "unit": "J", "conserved": sym["energy"]},
            {"name": "p_alpha", "expression": "L.n", "unit": "kg m^2 s^-1",
             "conserved": sym["p_alpha"]},
            {"name": "p_gamma", "expression": "I3*omega3", "unit": "kg m^2 s^-1",
             "conserved": sym["p_gamma"]},
            {"name": "n_squared", "expression": "n.n", "unit": "", "conserved": True},
        ]
        for rec in out:
            rec["proved"] = rec["conserved"]
            why = sym["why"].get(rec["name"])
            rec["why"] = why or ("a Casimir of the Euler-Poisson equations" if rec["name"] ==
                                 "n_squared" else "invariance checked symbolically")
        return out

    def to_json(self) -> dict:
        sc = self.scene
        dissipative = not self.integrals["energy"]
        return {
            "case": "general", "reason": self.reason, "dissipative": dissipative,
            "terms": [t.given() | {"kind": t.kind} for t in sc.terms],
            # The contract's integrals are the conserved quantities; the others, with the
            # effect that breaks each, are listed apart.
            "integrals": [{"name": r["name"], "expression": r["expression"], "unit": r["unit"],
                           "proved": r["proved"], "why": r["why"]}
                          for r in self.integral_records() if r["conserved"]],
            "not_conserved": [{"name": r["name"], "expression": r["expression"],
                               "why": r["why"]}
                              for r in self.integral_records() if not r["conserved"]],
            "equilibria": [e.to_json() for e in self.equilibria],
        }

    def to_markdown(self) -> str:
        sc = self.scene
        title = sc.title or sc.source
        b = sc.body
        T, V = _energies(sc)
        m = _ep(sc)
        show = _display_symbols(sc)
        out = [f"# Analysis: {title}", "",
               f"Scene `{sc.source}`. Every formula is derived by `derive` (SymPy) from the scene's "
               "effects, the terms written by the user among them. Conventions: z-y-z Euler "
               "angles, body principal axes (tilde), n = Rᵀẑ the upward vertical and e = Rᵀx̂ in "
               "body axes; a term's params carry its name as a subscript.", "",
               "## Body and terms", "",
               f"Principal moments about the pivot: I1 = {b.I1:g}, I2 = {b.I2:g}, I3 = {b.I3:g} "
               "kg m²" + (" (symmetric about axis 3)." if sc.symmetric else "."), ""]
        for name in sc.tables:
            out.append(f"- [{name}] " + ", ".join(f"{k} = {v}" for k, v in
                                                  sc.tables[name].given().items()))
        for t in sc.terms:
            what = (f"V = `{t.exprs[0]}` (J)" if t.kind == "potential" else
                    f"τ = ({', '.join(f'`{e}`' for e in t.exprs)}) (N m, {t.frame} frame)")
            params = ", ".join(f"{p} = {v:g}" for p, v in t.params)
            out.append(f"- {t.kind} `{t.name}`: {what}" + (f"; {params}" if params else ""))
        out += ["", "**Case: general** — " + self.reason + ".", "",
                "## Kinetic and potential energy, Lagrangian", "",
                rf"$$ T = {sp.latex(T)} $$", "", rf"$$ V = {sp.latex(V.subs(show))} $$", "",
                r"$$ L = T - V $$", "",
                "## Equations of motion", "",
                "Euler–Poisson (L = I ω̃ about the pivot), the torques of the potentials by virtual "
                "rotation, derived from the effects:", ""]
        names = (r"\dot{\tilde\omega}", r"\dot{\tilde n}", r"\dot{\tilde e}")
        for k, lhs in enumerate(names):
            rhs = sp.Matrix(m.rhs[3 * k:3 * k + 3]).subs(show)
            out += [rf"$$ {lhs} = {sp.latex(rhs)} $$", ""]
        out += ["## Integrals of the motion", "",
                "Found by symmetry (the invariances checked symbolically), not by name:", ""]
        for r in self.integral_records():
            out.append(f"- `{r['name']}` = {r['expression']}: "
                       + ("**conserved**" if r["conserved"] else "not conserved")
                       + f" ({r['why']}).")
        out += ["", "## Relative equilibria and their stability", ""]
        if not self.searched:
            out.append("Not searched: a torque acts (no potential energy to be critical).")
        elif not self.equilibria:
            out.append("None found (V has no critical point the search reached).")
        verdict = {True: "stable", False: "unstable", None: "undecided / degenerate"}
        for e in self.equilibria:
            out += [f"### {e.description}", "",
                    f"V = {e.V:.6g} J, n = ({', '.join(f'{x:.6g}' for x in e.n)}); eigenvalues of "
                    f"the Hessian of V: {', '.join(f'{h:.6g}' for h in e.hessian)} J rad⁻²; "
                    f"linearisation eigenvalues: "
                    + ", ".join(f"{z.real + 0.0:.4g}{z.imag + 0.0:+.4g}i" for z in e.eigenvalues)
                    + f" s⁻¹. **{verdict[e.stable]}**.", ""]
        return "\n".join(out).rstrip() + "\n"


def analyze(sc) -> OwnBodyAnalysis:
    """The analysis of a validated scene with user terms (see the module docstring)."""
    labels = {t.effect: f"{t.kind} {t.name!r}" for t in sc.terms}
    found = symmetries(sc.effects, sc.symmetric, labels)
    conservative = found["energy"]
    eqs = _rest_equilibria(sc) if conservative else []
    return OwnBodyAnalysis(sc, found, eqs, searched=conservative)


def _display_symbols(sc) -> dict:
    """{model parameter symbol: display symbol}: μ_magnet for the term magnet's μ."""
    out = {}
    for t in sc.terms:
        for p, _ in t.params:
            out[sp.Symbol(t.model_param(p), real=True)] = sp.Symbol(f"{p}_{{{t.name}}}", real=True)
    return out


@functools.lru_cache(maxsize=32)
def _ep_cached(symmetric, effects):
    return models.euler_poisson(symmetric, fx.lookup(effects))


def _ep(sc):
    return _ep_cached(sc.symmetric, sc.effects)


def _energies(sc):
    """(T, V) in z-y-z angles: T of the body, V the sum over the conservative effects."""
    effs = fx.lookup(sc.effects)
    moments = (I1, I1, I3) if sc.symmetric else (I1, I2, I3)
    T = trig_reduce(kinetic_energy(moments))
    V = trig_reduce(sums.potential(effs, ZYZ.matrix(), sums.Symbols(effs)))
    return T, V


# ---------------------------------------------------------------------------------------------
# rest equilibria: critical points of V on SO(3)


def _potential_functions(sc):
    """(V(R), grad(R), H(R)) as NumPy functions of the 3×3 matrix R at the scene's numbers:
    grad_k = ∂/∂ε_k V(R exp([ε]ₓ)) and H_jk = ∂²/∂ε_j∂ε_k at ε = 0 (body-frame rotations)."""
    effs = fx.lookup(sc.effects)
    sym = sums.Symbols(effs)
    r = sp.Matrix(3, 3, sp.symbols("r0:9", real=True))
    eps = sp.Matrix(sp.symbols("eps0:3", real=True))
    S = skew(eps)
    values = sc.param_values()
    at = {sym(p.name): values[p.name] for e in effs for p in e.params}
    Vp = sums.potential(effs, r * (sp.eye(3) + S + S * S / 2), sym).subs(at)
    zero = {e: 0 for e in eps}
    grad = [sp.diff(Vp, e).subs(zero) for e in eps]
    H = [[sp.diff(Vp, a, b).subs(zero) for b in eps] for a in eps]
    V = Vp.subs(zero)
    args = list(r)
    fV = sp.lambdify(args, V, "numpy")
    fg = sp.lambdify(args, grad, "numpy")
    fH = sp.lambdify(args, H, "numpy")

    def call(f, R):
        return np.asarray(f(*np.asarray(R, dtype=float).ravel()), dtype=float)

    return (lambda R: float(call(fV, R)), lambda R: call(fg, R), lambda R: call(fH, R))


def _expm(theta) -> np.ndarray:
    """exp([θ]ₓ) by Rodrigues' formula."""
    a = float(np.linalg.norm(theta))
    K = np.array([[0, -theta[2], theta[1]], [theta[2], 0, -theta[0]], [-theta[1], theta[0], 0]])
    if a < 1e-12:
        return np.eye(3) + K
    return np.eye(3) + math.sin(a) / a * K + (1 - math.cos(a)) / a**2 * (K @ K)


def _starts() -> list:
    """Deterministic starting orientations: the 24 rotations of the cube, then random ones."""
    out = []
    for perm in ((0, 1, 2), (1, 2, 0), (2, 0, 1), (1, 0, 2), (0, 2, 1), (2, 1, 0)):
        for signs in ((1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1),
                      (-1, 1, 1), (1, -1, 1), (1, 1, -1), (-1, -1, -1)):
            R = np.zeros((3, 3))
            for i, (j, s) in enumerate(zip(perm, signs)):
                R[i, j] = s
            if np.linalg.det(R) > 0:
                out.append(R)
    rng = np.random.default_rng(0)
    while len(out) < STARTS:
        q = rng.normal(size=4)
        q /= np.linalg.norm(q)
        w, x, y, z = q
        out.append(np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                             [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                             [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]))
    return out


def _rest_equilibria(sc) -> list[Rest]:
    """The rest equilibria (see the module docstring), one per value of V and signature."""
    from scipy.optimize import least_squares

    fV, fg, fH = _potential_functions(sc)
    starts = _starts()
    with np.errstate(all="ignore"):
        scale = max(abs(fV(R)) for R in starts) + max(float(np.linalg.norm(fg(R))) for R in starts)
    if not math.isfinite(scale) or scale == 0:
        return []
    I = np.array(sc.body.moments)
    found: dict = {}
    for R0 in starts:
        with np.errstate(all="ignore"):
            sol = least_squares(lambda th: fg(R0 @ _expm(th)), np.zeros(3), xtol=1e-15,
                                ftol=1e-15, gtol=1e-15, max_nfev=200)
            R = R0 @ _expm(sol.x)
            g = fg(R)
        if not np.all(np.isfinite(g)) or np.linalg.norm(g) > CRITICAL_TOLERANCE * scale:
            continue
        rest = _classify(R, fV, fH, I, scale)
        if rest is None:
            continue
        key = (round(rest.V / scale, 7), rest.stable, rest.family)
        found.setdefault(key, rest)
    return [found[k] for k in sorted(found, key=lambda k: k[0])]


def _classify(R, fV, fH, I, scale) -> Rest | None:
    H = fH(R)
    if not np.all(np.isfinite(H)):
        return None
    H = (H + H.T) / 2
    h = np.linalg.eigvalsh(H)
    # I δθ̈ = −H δθ: I⁻¹H is similar to the symmetric I^{-1/2} H I^{-1/2} (real eigenvalues).
    Is = 1 / np.sqrt(I)
    mu, vecs = np.linalg.eigh(Is[:, None] * H * Is[None, :])
    tol = ZERO_TOLERANCE * max(float(np.max(np.abs(mu))), scale / float(np.max(I)))
    lam = [complex(l) for m in mu for l in (np.sqrt(complex(-m)), -np.sqrt(complex(-m)))]
    zero = [k for k, m in enumerate(mu) if abs(m) <= tol]
    # A zero mode along which V is exactly constant: a family of equilibria (a symmetry of V).
    family = 0
    V0 = fV(R)
    for k in zero:
        v = Is * vecs[:, k]
        v = v / np.linalg.norm(v)
        if all(abs(fV(R @ _expm(s * v)) - V0) <= 1e-10 * scale for s in (0.3, 1.1, 2.5)):
            family += 1
    if any(m < -tol for m in mu):
        stable = False
    elif len(zero) == family:
        stable = True
    else:
        stable = None
    return Rest(V0, tuple(float(x) for x in R[2, :]), [float(x) for x in h], lam, stable, family)
