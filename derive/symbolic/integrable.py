"""The integrable cases of a heavy rigid body about a fixed point: detected, their integrals
stated once, and proved along the derived Euler–Poisson equations.

Equations (`models.euler_poisson`, body principal axes, ω̃ = I⁻¹L, n = Rᵀẑ the upward vertical,
r_c = (c_x, c_y, c_z) the centre of mass from the pivot):

    L̇ = L × ω̃ + M g n × r_c,    ṅ = n × ω̃,    E = ½ L·ω̃ + M g n·r_c.

Every such body conserves E, the area integral L·n (= p_α) and the Casimir |n|² = 1. A fourth
integral, which makes the flow integrable, exists in these cases (written with axis 3 as the
symmetry axis, the scene's convention; a body symmetric about axis 1 or 2 is recognised by a
cyclic relabelling of its axes, ``RELABELLINGS``):

* ``euler``   no gravity torque (no [gravity] table, r_c = 0 or g = 0):  |L|² (``L_squared``).
* ``lagrange`` I₁ = I₂, r_c on axis 3:  L₃ = I₃ω̃₃ (= p_γ; ``L_3``, or ``L_1``/``L_2`` for a body
  symmetric about axis 1/2); a spherical body (I₁ = I₂ = I₃) with r_c anywhere:  L·r_c
  (``L_dot_rc``: its axis through r_c is a symmetry axis).
* ``kovalevskaya`` I₁ = I₂ = 2I₃, r_c in the equatorial plane (any azimuth φ, c_x + i c_y =
  |r_c| e^{iφ}):  K = |(ω̃₁ + iω̃₂)² − (M g/I₃)(c_x + i c_y)(n₁ + i n₂)|². With the body turned
  about axis 3 so that r_c = (x_c, 0, 0) this is the classical (ω̃₁² − ω̃₂² − k n₁)² +
  (2ω̃₁ω̃₂ − k n₂)², k = M g x_c/I₃ (the turn multiplies both complex numbers by e^{−2iφ}).
* ``goryachev-chaplygin`` I₁ = I₂ = 4I₃, r_c in the equatorial plane: on the level L·n = 0,
  G = ω̃₃(ω̃₁² + ω̃₂²) − (M g/I₃)(c_x ω̃₁ + c_y ω̃₂) n₃; along the flow
  dG/dt = −(M g/(4 I₃²)) (c_x ω̃₂ − c_y ω̃₁) (L·n). A scene whose initial state is off that level
  (|L·n| > TOLERANCE·|L||n|) is classified ``general`` (``classify``; its ``body_case`` keeps
  "goryachev-chaplygin"): G is then not an integral of its motion.
* ``general`` anything else; also any scene with a dissipative torque (damping c > 0), which
  conserves none of these.

Names. Each quantity has one name, used for the JSON of ``derive analyze``, the simulation's
arrays ``integral_<name>`` and ``Result.integrals``, the plots, the sweeps' ``integral_drift``
option and the generated ``outputs.md``: ``energy``, ``p_alpha`` (L·n), ``n_squared`` (|n|²),
``L_squared`` (|L|², never a component), ``L_1``/``L_2``/``L_3`` (the component of L along
that body axis), ``L_dot_rc``, ``kovalevskaya``, ``goryachev_chaplygin``.

Each formula is written once (``Integral.formula``), as arithmetic on three L components, three
n components and a parameter mapping, so the same code evaluates it on NumPy arrays (the
simulation's observables, ``integrals_for``) and on SymPy symbols (the proofs, which live in
:mod:`derive.symbolic.integral_proofs`). SymPy is imported only inside ``c_code``.
"""
from __future__ import annotations

import dataclasses
import math
import re
from dataclasses import dataclass
from typing import Callable

import numpy as np

#: THE tolerance of the classification (relative): two moments are equal when
#: |a − b| ≤ TOLERANCE · max(|a|, |b|); the centre of mass is on axis 3 when
#: √(c_x² + c_y²) ≤ TOLERANCE · |r_c|, in the equatorial plane when |c_z| ≤ TOLERANCE · |r_c|;
#: and there is no gravity torque when g = 0 or |r_c| ≤ TOLERANCE · √(I_max / M) (the body's
#: radius of gyration is the length scale).
TOLERANCE = 1e-9

CASES = ("euler", "lagrange", "kovalevskaya", "goryachev-chaplygin", "general")

#: The case relations among the parameters, as substitutions into the general Euler–Poisson
#: model (I₁, I₂, I₃, M, g, c_x, c_y, c_z); the names are those of the model's parameters.
RELATIONS = {
    "euler": {"cx": 0, "cy": 0, "cz": 0},
    "lagrange": {"I2": "I1", "cx": 0, "cy": 0},
    "kovalevskaya": {"I1": "2*I3", "I2": "2*I3", "cz": 0},
    "goryachev-chaplygin": {"I1": "4*I3", "I2": "4*I3", "cz": 0},
    "general": {},
}


# ---------------------------------------------------------------------------------------------
# the integrals, each written once


def _omega(L, p):
    return L[0] / p["I1"], L[1] / p["I2"], L[2] / p["I3"]


def _energy(L, n, p):
    w = _omega(L, p)
    return (L[0] * w[0] + L[1] * w[1] + L[2] * w[2]) / 2 + p["M"] * p["g"] * (
        n[0] * p["cx"] + n[1] * p["cy"] + n[2] * p["cz"])


def _area(L, n, p):
    return L[0] * n[0] + L[1] * n[1] + L[2] * n[2]


def _n_squared(L, n, p):
    return n[0] ** 2 + n[1] ** 2 + n[2] ** 2


def _L_squared(L, n, p):
    return L[0] ** 2 + L[1] ** 2 + L[2] ** 2


def _L_dot_rc(L, n, p):
    return L[0] * p["cx"] + L[1] * p["cy"] + L[2] * p["cz"]


def _L3(L, n, p):
    return L[2] * (L[0] ** 0)  # times 1 of L's type: a NumPy column stays an array


def _kovalevskaya(L, n, p):
    w1, w2, _ = _omega(L, p)
    k = p["M"] * p["g"] / p["I3"]
    re = w1 ** 2 - w2 ** 2 - k * (p["cx"] * n[0] - p["cy"] * n[1])
    im = 2 * w1 * w2 - k * (p["cx"] * n[1] + p["cy"] * n[0])
    return re ** 2 + im ** 2


def _goryachev_chaplygin(L, n, p):
    w1, w2, w3 = _omega(L, p)
    k = p["M"] * p["g"] / p["I3"]
    return w3 * (w1 ** 2 + w2 ** 2) - k * (p["cx"] * w1 + p["cy"] * w2) * n[2]


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def pretty_unit(unit: str) -> str:
    """An ASCII unit ("kg m^2 s^-1") with superscripts ("kg m² s⁻¹") for Markdown; "1"
    (dimensionless) gives ""."""
    if unit == "1":
        return ""
    return re.sub(r"\^(-?\d+)", lambda m: m.group(1).translate(_SUPERSCRIPT), unit)


def _lagrange_meaning(k: int) -> str:
    return (f"L_{k} = I{k} ω̃{k}, the component of L along body axis {k}, the symmetry axis of a "
            f"Lagrange top" + (" (= p_γ)" if k == 3 else ""))


@dataclass(frozen=True)
class Integral:
    """A first integral: ``name`` (the npz key is ``integral_<name>``), a plain-text
    ``expression`` (the JSON contract's), its LaTeX, and ``formula(L, n, p)``; ``on`` names the
    level set it is conserved on ("L.n = 0"), if any; ``relations`` the parameter relations of
    its proof when they are not its case's; ``unit`` its SI unit (ASCII, "1" dimensionless);
    ``meaning`` what it is, in words (the generated outputs.md); ``component`` k when the
    integral is L's component k (0-based, the formulas' axes) and nothing else, so that a run
    takes it from its L output, already computed and checked, without evaluating ``formula``."""

    name: str
    expression: str
    latex: str
    formula: Callable
    on: str | None = None
    relations: dict | None = None  # for its proof, instead of its case's RELATIONS
    unit: str = "1"
    meaning: str = ""
    component: int | None = None


ENERGY = Integral("energy", "E = (L1^2/I1 + L2^2/I2 + L3^2/I3)/2 + M g (n . r_c)",
                  r"E = \tfrac12\left(\frac{L_1^2}{I_1} + \frac{L_2^2}{I_2} + \frac{L_3^2}{I_3}\right)"
                  r" + M g\,\tilde n\cdot\tilde r_c", _energy, unit="J",
                  meaning="the total energy T + V")
AREA = Integral("p_alpha", "p_alpha = L . n = L1 n1 + L2 n2 + L3 n3",
                r"p_\alpha = \tilde L\cdot\tilde n", _area, unit="kg m^2 s^-1",
                meaning="the vertical component of the angular momentum, L·n")
CASIMIR = Integral("n_squared", "|n|^2 = n1^2 + n2^2 + n3^2 = 1",
                   r"|\tilde n|^2 = n_1^2 + n_2^2 + n_3^2 = 1", _n_squared,
                   meaning="the squared length of the vertical n (1: a Casimir)")

#: The Lagrange case of a spherical body (I₁ = I₂ = I₃): every axis is a symmetry axis, the one
#: through r_c included, wherever r_c is.
SPHERE = Integral("L_dot_rc", "L . r_c = L1 cx + L2 cy + L3 cz (spherical body: I1 = I2 = I3)",
                  r"\tilde L\cdot\tilde r_c = L_1 c_x + L_2 c_y + L_3 c_z\quad(I_1 = I_2 = I_3)",
                  _L_dot_rc, relations={"I2": "I1", "I3": "I1"}, unit="kg m^3 s^-1",
                  meaning="L·r_c, |r_c| times the component of L along the centre of mass (spherical "
                          "body I1 = I2 = I3, case lagrange)")

#: The extra integral of each case.
EXTRA = {
    "euler": Integral("L_squared", "|L|^2 = L1^2 + L2^2 + L3^2",
                      r"|\tilde L|^2 = L_1^2 + L_2^2 + L_3^2", _L_squared, unit="kg^2 m^4 s^-2",
                      meaning="|L|², the squared length of the angular momentum (free body, "
                              "case euler); never a component"),
    "lagrange": Integral("L_3", "L3 = I3 omega3 = p_gamma",
                         r"L_3 = I_3\tilde\omega_3 = p_\gamma", _L3, unit="kg m^2 s^-1",
                         meaning=_lagrange_meaning(3), component=2),
    "kovalevskaya": Integral(
        "kovalevskaya",
        "K = (w1^2 - w2^2 - (M g/I3)(cx n1 - cy n2))^2 + (2 w1 w2 - (M g/I3)(cx n2 + cy n1))^2, "
        "w = L/I",
        r"K = \left|(\tilde\omega_1 + i\tilde\omega_2)^2 - \frac{M g}{I_3}(c_x + i c_y)(n_1 + i n_2)\right|^2"
        r" = \left(\tilde\omega_1^2 - \tilde\omega_2^2 - \frac{Mg}{I_3}(c_x n_1 - c_y n_2)\right)^2"
        r" + \left(2\tilde\omega_1\tilde\omega_2 - \frac{Mg}{I_3}(c_x n_2 + c_y n_1)\right)^2",
        _kovalevskaya, unit="s^-4",
        meaning="Kovalevskaya's quartic integral K (I1 = I2 = 2 I3, r_c equatorial)"),
    "goryachev-chaplygin": Integral(
        "goryachev_chaplygin",
        "G = w3 (w1^2 + w2^2) - (M g/I3)(cx w1 + cy w2) n3, w = L/I (conserved on L . n = 0)",
        r"G = \tilde\omega_3(\tilde\omega_1^2 + \tilde\omega_2^2) - \frac{M g}{I_3}"
        r"(c_x\tilde\omega_1 + c_y\tilde\omega_2)\,n_3\quad(\text{on } \tilde L\cdot\tilde n = 0)",
        _goryachev_chaplygin, on="L.n = 0", unit="s^-3",
        meaning="the Goryachev-Chaplygin integral G (I1 = I2 = 4 I3, r_c equatorial), written "
                "only for a state on L·n = 0"),
}


# ---------------------------------------------------------------------------------------------
# classification from the scene's numbers


#: The cyclic relabellings of the body axes (0-based), identity first: ``axes[j]`` is the body
#: axis that plays axis j + 1 of the formulas. Cyclic, so the relabelled frame is right-handed
#: and the Euler–Poisson equations keep their form: a body symmetric about axis 1 (I₂ = I₃) is
#: the formulas' body with axes (2, 3, 1).
RELABELLINGS = ((0, 1, 2), (1, 2, 0), (2, 0, 1))
_COM = ("cx", "cy", "cz")


def relabel_params(p: dict, axes) -> dict:
    """The formulas' parameters from the body's: I_{j+1} ← I_{axes[j]+1}, c ← c likewise."""
    q = dict(p)
    for j, a in enumerate(axes):
        q[f"I{j + 1}"] = p[f"I{a + 1}"]
        q[_COM[j]] = p[_COM[a]]
    return q


def relabelled(integral: Integral, axes) -> Integral:
    """The integral in the body's own axes when the formulas' axes (1, 2, 3) are body axes
    ``axes`` (+1): its formula permutes L, n and the parameters first; the Lagrange integral
    is renamed after the body axis it is about (L_3 → L_1 for a body symmetric about axis 1)."""
    if tuple(axes) == RELABELLINGS[0]:
        return integral
    formula = integral.formula

    def f(L, n, p, _axes=tuple(axes)):
        return formula(tuple(L[a] for a in _axes), tuple(n[a] for a in _axes), relabel_params(p, _axes))

    body = ", ".join(str(a + 1) for a in axes)
    lagrange = integral.name == EXTRA["lagrange"].name
    name = f"L_{axes[2] + 1}" if lagrange else integral.name
    meaning = _lagrange_meaning(axes[2] + 1) if lagrange else integral.meaning
    return Integral(name, f"{integral.expression} [axes 1, 2, 3 of this formula = body axes {body}]",
                    rf"{integral.latex}\quad[(1, 2, 3) \to \text{{body axes }} ({body})]", f,
                    on=integral.on, relations=integral.relations, unit=integral.unit,
                    meaning=meaning,
                    component=None if integral.component is None else axes[integral.component])


@dataclass(frozen=True)
class Classification:
    """The case of a scene and why (one sentence); ``axes`` the body axes (0-based) that play
    the formulas' axes 1, 2, 3 (the symmetry axis of the case is body axis axes[2] + 1);
    ``body_case`` the case of the body's numbers when the scene's state rules it out (a
    Goryachev–Chaplygin body off the level L·n = 0: ``case`` is then "general")."""

    case: str
    reason: str
    dissipative: bool = False
    integral: str | None = None  # the extra integral's name when it is not EXTRA[case]'s
    axes: tuple = RELABELLINGS[0]
    body_case: str | None = None

    @property
    def canonical_extra(self) -> Integral | None:
        """The case's extra integral in the formulas' axes (None: general or dissipative)."""
        if self.dissipative:
            return None
        if self.integral == SPHERE.name:
            return SPHERE
        return EXTRA.get(self.case)

    @property
    def extra(self) -> Integral | None:
        """The extra integral in the body's own axes."""
        c = self.canonical_extra
        return None if c is None else relabelled(c, self.axes)


def _equal(a: float, b: float) -> bool:
    return abs(a - b) <= TOLERANCE * max(abs(a), abs(b))


def parameters(scene) -> dict[str, float]:
    """The general Euler–Poisson model's parameters from a scene: I₁, I₂, I₃, M, g and the centre
    of mass (c_x, c_y, c_z); a scene without gravity has M = g = 0 and r_c = 0."""
    b = scene.body
    p = {"I1": b.I1, "I2": b.I2, "I3": b.I3, "M": 0.0, "g": 0.0, "cx": 0.0, "cy": 0.0, "cz": 0.0}
    grav = scene.gravity
    if grav is not None:
        p.update(M=float(grav.M), g=float(grav.g))
        p.update(zip(("cx", "cy", "cz"), (float(c) for c in grav.com)))
    return p


def classify_values(I1, I2, I3, M=0.0, g=0.0, com=(0.0, 0.0, 0.0), damping=0.0) -> Classification:
    """The integrable case from numbers (see the module docstring and ``TOLERANCE``). The
    classical cases take axis 3 as the symmetry axis (the scene convention); a body symmetric
    about axis 1 or 2 is recognised through a cyclic relabelling of its axes (``RELABELLINGS``)."""
    I, c = (I1, I2, I3), tuple(float(x) for x in com)
    first = None
    for axes in RELABELLINGS:
        found = _classify(*(I[a] for a in axes), M, g, tuple(c[a] for a in axes), damping)
        if axes == RELABELLINGS[0]:
            first = found
        if found.case != "general" or found.dissipative:
            if axes == RELABELLINGS[0]:
                return found
            return dataclasses.replace(found, axes=axes, reason=(
                f"{found.reason}, with body axis {axes[2] + 1} as the symmetry axis (the formulas' "
                f"axes 1, 2, 3 are body axes {axes[0] + 1}, {axes[1] + 1}, {axes[2] + 1})"))
    return first


def _classify(I1, I2, I3, M, g, com, damping) -> Classification:
    """The classification with axis 3 as the symmetry axis."""
    cx, cy, cz = com
    r = math.hypot(cx, cy, cz)  # scaled: |r_c| = 1e300 is not an overflow
    if damping > 0:
        return Classification("general", f"dissipative: the damping torque -c omega (c = {damping:g}) "
                                         "conserves neither the energy nor L.n", dissipative=True)
    scale = math.sqrt(max(I1, I2, I3) / M) if M > 0 else math.inf
    if g == 0 or M == 0 or r <= TOLERANCE * scale:
        return Classification("euler", "no gravity torque (r_c = 0 or g = 0): Euler's free body")
    if _equal(I1, I2) and _equal(I2, I3) and math.hypot(cx, cy) > TOLERANCE * r:
        return Classification("lagrange", "spherical body (I1 = I2 = I3): the axis through the centre "
                                          "of mass is a symmetry axis, so L.r_c is conserved",
                              integral=SPHERE.name)
    if not _equal(I1, I2):
        return Classification("general", "no two equal moments with the centre of mass placed as an "
                                         "integrable case needs, and a gravity torque: no known "
                                         "integrable case")
    if math.hypot(cx, cy) <= TOLERANCE * r:
        return Classification("lagrange", "I1 = I2 and the centre of mass on the symmetry axis 3")
    if abs(cz) <= TOLERANCE * r:
        if _equal(I1, 2 * I3):
            return Classification("kovalevskaya", "I1 = I2 = 2 I3 and the centre of mass in the "
                                                  "equatorial plane")
        if _equal(I1, 4 * I3):
            return Classification("goryachev-chaplygin", "I1 = I2 = 4 I3 and the centre of mass in "
                                                         "the equatorial plane (integrable on L.n = 0)")
    return Classification("general", "symmetric body (I1 = I2) with the centre of mass off the "
                                     "symmetry axis, not a Kovalevskaya or Goryachev-Chaplygin ratio")


def area_level(scene) -> tuple[float, float]:
    """(L·n, |L||n|) at the scene's initial state: L = I ω̃(0) and n = Rᵀẑ =
    (−sin β cos γ, sin β sin γ, cos β) in body axes (z-y-z angles; α does not enter)."""
    i = scene.initial
    sb = math.sin(i.beta)
    n = (-sb * math.cos(i.gamma), sb * math.sin(i.gamma), math.cos(i.beta))
    L = tuple(m * w for m, w in zip(scene.body.moments, i.omega))
    return math.fsum(a * b for a, b in zip(L, n)), math.hypot(*L) * math.hypot(*n)


def needs_area_level(I1: float, I2: float, I3: float) -> bool:
    """Whether the case of a body with these moments can depend on its state: only where one
    moment is four times another (the Goryachev–Chaplygin ratio, in any relabelling of the
    axes), whose case :func:`classify` decides by :func:`on_area_level`."""
    lo, mid, hi = sorted((I1, I2, I3))  # positive: a = 4 b only for a above b
    return _equal(hi, 4 * lo) or _equal(hi, 4 * mid) or _equal(mid, 4 * lo)


def on_area_level(scene) -> bool:
    """True when the scene starts on L·n = 0 (|L·n| ≤ TOLERANCE·|L||n|), the level on which
    the Goryachev–Chaplygin integral exists."""
    ln, scale = area_level(scene)
    return abs(ln) <= TOLERANCE * scale


def classify(scene) -> Classification:
    """The integrable case of a scene (``derive.sim.scene.Scene``): the case of its numbers
    (``classify_values``), except that a Goryachev–Chaplygin body whose initial state is off the
    level L·n = 0 (``on_area_level``) is "general": G is conserved only on that level, so this
    motion has no fourth integral (``body_case`` keeps "goryachev-chaplygin")."""
    terms = getattr(scene, "terms", ())
    if terms:
        # A term written by the user is outside the classical cases' hypotheses (the analysis
        # derives which integrals its symmetry leaves: derive.symbolic.symmetries.symmetries).
        torques = [t.name for t in terms if t.kind == "torque"]
        return Classification("general", "the scene has terms written by the user ("
                              + ", ".join(f"{t.kind} {t.name!r}" for t in terms)
                              + "): no classical integrable case is claimed"
                              + (f"; the torque {torques[0]!r} does work" if torques else ""),
                              dissipative=bool(torques))
    p = parameters(scene)
    damping = scene.damping.c if scene.damping is not None else 0.0
    c = classify_values(p["I1"], p["I2"], p["I3"], p["M"], p["g"], (p["cx"], p["cy"], p["cz"]),
                        damping)
    if c.case == "goryachev-chaplygin" and not on_area_level(scene):
        ln, scale = area_level(scene)
        return Classification("general", f"{c.reason}, but this state is off that level: L.n = "
                                         f"{ln:.6g} kg m^2 s^-1 (|L||n| = {scale:.6g}), so G is "
                                         "not conserved and no fourth integral is known",
                              body_case=c.case)
    return c


def integrals(c: Classification) -> list[Integral]:
    """The first integrals of a classified scene: energy, L·n and |n|² (a dissipative one: |n|²
    alone), then the case's extra one."""
    if c.dissipative:
        return [CASIMIR]
    return [ENERGY, AREA, CASIMIR] + ([c.extra] if c.extra else [])


def output_integrals() -> list[Integral]:
    """Every extra integral a simulation can write as ``integral_<name>``, in the body's axes
    (each cyclic relabelling of each case's integral, one entry per name): the registry the
    generated ``outputs.md`` lists."""
    out: dict[str, tuple[int, Integral]] = {}
    for k, integral in enumerate((EXTRA["euler"], EXTRA["lagrange"], SPHERE, EXTRA["kovalevskaya"],
                                  EXTRA["goryachev-chaplygin"])):
        for axes in RELABELLINGS:
            named = relabelled(integral, axes)
            out.setdefault(named.name, (k, named))
    return [i for _, i in sorted(out.values(), key=lambda x: (x[0], x[1].name))]


def integrals_for(scene) -> list[tuple[str, Callable]]:
    """The extra integral of the scene's case (``classify``: its state included) as
    ``[(name, f)]`` with ``f(L, n) -> array`` (L, n of shape (N, 3), body axes) at the scene's
    numbers: the simulation writes it as ``integral_<name>``. Empty for the general case
    (energy and L·n are outputs already) and for a Goryachev–Chaplygin body off L·n = 0."""
    integral = classify(scene).extra
    if integral is None:
        return []
    p = parameters(scene)

    def f(L, n, _formula=integral.formula, _p=p):
        L = np.asarray(L, dtype=float)
        n = np.asarray(n, dtype=float)
        return np.asarray(_formula(L.T, n.T, _p), dtype=float)

    return [(integral.name, f)]


def extra_relations(c: Classification) -> dict:
    """The relations under which a classified scene's extra integral is proved, in the body's
    axes (e.g. {"I3": "I2", "cy": 0, "cz": 0} for a Lagrange top about body axis 1)."""
    integral = c.canonical_extra
    if integral is None:
        return {}
    return relabel_spec(integral.relations or RELATIONS[c.case], c.axes)


def relabel_spec(spec: dict, axes) -> dict:
    """Relations written in the formulas' axes, rewritten in the body's (e.g. I2 = I1 becomes
    I3 = I2 for axes (1, 2, 0))."""
    if tuple(axes) == RELABELLINGS[0]:
        return spec
    names = {f"I{j + 1}": f"I{a + 1}" for j, a in enumerate(axes)}
    names.update({_COM[j]: _COM[a] for j, a in enumerate(axes)})

    def sub(text):
        return re.sub(r"I[123]|c[xyz]", lambda m: names[m.group(0)], str(text))

    return {sub(k): sub(v) for k, v in spec.items()}



# ---------------------------------------------------------------------------------------------
# the extra integrals in C (rendered at `derive generate` time; the measures' integral_drift)


#: The integrals the compiled measures evaluate, in the order of their C codes (1, 2, …; 0 is
#: "none"): the cases' extra integrals, then the Casimirs every undamped body conserves (|n|²,
#: and L·n = p_α), which a sweep may name. ``generated/c/derive_integrals.h`` is rendered from
#: this tuple and the formulas above, and :mod:`derive.sweeps.measures` picks a point's code from it.
C_INTEGRALS = (EXTRA["euler"], EXTRA["lagrange"], SPHERE, EXTRA["kovalevskaya"],
               EXTRA["goryachev-chaplygin"], CASIMIR, AREA)
#: The general parameters in the order the C function reads them (``parameters``' keys).
C_PARAMS = ("I1", "I2", "I3", "M", "g", "cx", "cy", "cz")


def _c_terms(expr) -> list[str]:
    """A sum as its terms printed by SymPy's C printer, the first as it is and the others with
    their sign in front ("+ a", "- b"): one term per line in the header."""
    import sympy as sp

    out = []
    for term in sp.Add.make_args(expr):
        text = sp.ccode(term)
        if out:
            text = f"- {text[1:]}" if text.startswith("-") else f"+ {text}"
        out.append(text)
    return out


def c_code(integral: Integral) -> tuple[list[str], list[str]]:
    """(value, scale) of an integral as C expressions in L1..L3, n1..n3 (the formulas' axes),
    the ``C_PARAMS`` and the norms Lnorm = |L|, nnorm = |n|, each as the terms of a sum
    (``_c_terms``). The value is ``formula`` printed by SymPy's C printer; the scale is

        S = Σ over the monomials c·L^a·n^b of the expanded formula of |c| |L|^|a| |n|^|b|,

    a bound on |I| over every L, n of those lengths (so drift / S ≤ 2), and the size of the
    numbers that cancel in I: rounding alone moves I by about eps·S. Uses SymPy (generate time)."""
    import sympy as sp

    L = sp.symbols("L1 L2 L3", real=True)
    n = sp.symbols("n1 n2 n3", real=True)
    positive = {"I1", "I2", "I3"}  # (M and g may be 0: no gravity)
    p = {k: sp.Symbol(k, real=True, positive=k in positive or None,
                      nonnegative=k in ("M", "g") or None) for k in C_PARAMS}
    F = integral.formula(L, n, p)
    Ln, nn = sp.Symbol("Lnorm", nonnegative=True), sp.Symbol("nnorm", nonnegative=True)
    groups: dict[tuple[int, int], list] = {}
    for monom, coeff in sp.Poly(sp.expand(F), *L, *n).terms():
        groups.setdefault((sum(monom[:3]), sum(monom[3:])), []).append(sp.Abs(coeff))
    scale = [sp.Add(*cs) * Ln ** a * nn ** b for (a, b), cs in sorted(groups.items())]
    return _c_terms(F), [sp.ccode(t) if k == 0 else f"+ {sp.ccode(t)}" for k, t in enumerate(scale)]
