"""The derivation the notes checker compares a text with, per convention: ω̃, the frames, the
heavy symmetric top (its Lagrangian, momenta, Routh's reduction, the sleeping top), Euler's
equations and the named quantities in the forms a text may write them.

Takes: an angle sequence (`derive.symbolic.rotations.convention`). Gives: `derivation(conv)`
(cached `Derivation`, starting from what earlier commands derived for the convention: `keep`
keeps what this one added, in the compile cache, `derive.lecture.derivation_kept`), `linear` (a
column as a linear form in ê₁ ê₂ ê₃) and `families` (the quantities one slip of a label may swap).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.derivation_kept`,
:mod:`derive.lecture.fast_top`, :mod:`derive.lecture.orientation`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import functools

import sympy as sp

from derive.lecture import derivation_kept as kept
from derive.lecture import latex as lx
from derive.lecture.fast_top import slow_precession_lead
from derive.lecture.orientation import AlongMomentum
from derive.symbolic import rotations as rot
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3, EulerLagrange, Reduction, heavy_symmetric_top, kinetic_energy
from derive.symbolic.stability import SleepingTop, SteadySpin, euler_rhs, omega0


class Derivation:
    """The derived quantities of one convention (computed on first use)."""

    def __init__(self, convention: str):
        self.rot = rot
        self.conv = rot.convention(convention)

    @functools.cached_property
    def omega(self) -> sp.Matrix:
        """ω̃ from the skew route Rᵀ Ṙ (independent of the notes' sum route)."""
        return sp.Matrix(self.conv.omega_body_skew())

    @functools.cached_property
    def frames(self) -> dict:
        """ê′ₖ and ê⁰ₖ as linear forms in the body basis (ê′ₖ = passive(a₃, γ) eₖ, ê⁰ₖ = Rᵀ eₖ)."""
        rot, out = self.rot, {}
        R = self.conv.matrix()
        for k, axis in enumerate("xyz"):
            out[lx.PRIMED[k]] = linear(rot.passive(self.conv.axes[2], rot.gamma) * rot.unit(axis))
            out[lx.INERTIAL[k]] = linear(R.T * rot.unit(axis))
        return out

    @functools.cached_property
    def along(self) -> AlongMomentum:
        """The orientation with 𝐋 along the fixed first axis (`derive.lecture.orientation`)."""
        return AlongMomentum(self.conv, self.omega)

    @functools.cached_property
    def top(self):
        return heavy_symmetric_top(self.conv)

    @functools.cached_property
    def reduction(self):
        return Reduction(self.top)

    @functools.cached_property
    def sleeping(self):
        return SleepingTop(self.reduction)

    @functools.cached_property
    def steady_force(self):
        """∂L/∂β at β̇ = 0: the β equation of motion of a steady precession (β̈ = 0 too)."""
        rot = self.rot
        return sp.expand(sp.diff(self.top.lagrangian, rot.beta).xreplace({rot.beta_d: 0}))

    @functools.cached_property
    def momenta(self) -> dict:
        """p_q = ∂L/∂q̇ of the heavy top, for each angle q."""
        return {q: self.top.momentum(q) for q in rot.ANGLES}

    @functools.cached_property
    def fast_precession(self):
        """c in α̇ = c/γ̇ + O(1/γ̇³), the fast top's slow precession (`fast_top.slow_precession_lead`
        of the steady-precession condition), or None."""
        return slow_precession_lead(self.steady_force, self.rot.alpha_d, self.rot.gamma_d)

    @functools.cached_property
    def top_residuals(self) -> tuple:
        return lagrange_residuals(self.top.lagrangian)

    @functools.cached_property
    def kinetic_residuals(self) -> tuple:
        return lagrange_residuals(self.kinetic)

    def residuals(self, lag) -> tuple:
        """d/dt ∂L/∂q̇ − ∂L/∂q of each angle q for the Lagrangian ``lag``: those of the heavy top's L
        and of the free body's T are quantities of the derivation (kept between commands)."""
        if lag == self.top.lagrangian:
            return self.top_residuals
        if lag == self.kinetic:
            return self.kinetic_residuals
        return lagrange_residuals(lag)

    def euler(self, subs: dict) -> list:
        """Euler's residuals Iᵢ ω̃̇ᵢ − ((Iω̃)×ω̃)ᵢ, with the section's substitutions."""
        return list(_euler_residuals(tuple(sp.sympify(m).xreplace(subs) for m in (I1, I2, I3))))

    def frequencies(self):
        return self.spin_frequencies

    @functools.cached_property
    def spin_frequencies(self) -> tuple:
        """(Ω₁, Ω₂) of Euler's equations linearised about a steady spin ω̃₃ about axis 3."""
        o1, o2 = SteadySpin(2).frequencies
        return o1.subs(omega0, lx.W[2]), o2.subs(omega0, lx.W[2])

    @functools.lru_cache(maxsize=None)
    def forms(self, key, args=None) -> list:
        """What a named quantity is, in the forms a text may use (each compared in turn)."""
        half = sp.Rational(1, 2)
        Iw = [I1 * lx.W[0], I2 * lx.W[1], I3 * lx.W[2]]
        if key is lx.T_:
            return [half * sum(m * w**2 for m, w in zip((I1, I2, I3), lx.W)),
                    self.top_kinetic()]
        if key is lx.LAGRANGIAN:
            if args and set(args) <= {self.rot.beta, self.rot.beta_d}:
                return [self.reduction.lagrangian_substituted]
            return [self.top.lagrangian, self.top_kinetic()]      # a free body's L is its T
        if key is lx.LVEC:
            return [linear(sp.Matrix(Iw))]
        if key is lx.ENERGY:
            return [self.reduction.energy, self.top.energy, self.top_kinetic()]
        if key is lx.EPRIME:
            return [self.reduction.reduced_energy]
        if key is lx.VEFF:
            return [self.reduction.effective_potential]
        if key is lx.LMAG:
            return [sp.sqrt(sum((m * w)**2 for m, w in zip((I1, I2, I3), lx.W)))]
        if key is lx.OMEGA_VEC:
            return [linear(sp.Matrix(lx.W)), linear(self.omega)]
        if key is lx.DLDT:
            return [linear(sp.Matrix(self.euler({})))]
        if key in (lx.MOMENTUM[0], lx.p_alpha_sym()):
            return [self.momenta[self.rot.alpha]]
        if key in (lx.MOMENTUM[2], lx.p_gamma_sym()):
            return [self.momenta[self.rot.gamma]]
        if key is lx.MOMENTUM[1]:
            return [self.momenta[self.rot.beta]]
        if key in lx.W:
            return [self.omega[lx.W.index(key)]]
        if key in lx.W_PRIMED:          # ê′ᵢ·𝛚 with ê′ᵢ in the body basis
            e = self.frames[lx.PRIMED[lx.W_PRIMED.index(key)]]
            return [sum((e.coeff(b) * w for b, w in zip(lx.BASIS, lx.W)), sp.S.Zero)]
        if key in lx.PRIMED or key in lx.INERTIAL:
            return [self.frames[key]]
        if key in lx.BASIS:
            return [key]
        if key is lx.Omega:
            o1, o2 = self.frequencies()
            return [o1.xreplace({I2: I1}), o2.xreplace({I2: I1})]
        if key is lx.Omega1:
            return [self.frequencies()[0]]
        if key is lx.Omega2:
            return [self.frequencies()[1]]
        return []

    def top_kinetic(self):
        return self.kinetic

    @functools.cached_property
    def turning(self) -> tuple:
        """R and dR/dt = Σ ∂R/∂qᵢ q̇ᵢ (only the angles enter R): the frame derivatives of the
        vector models (`derive.lecture.vector_models`)."""
        R = self.conv.matrix()
        return R, R.applyfunc(lambda e: rot.time_derivative(e, coords=rot.ANGLES, rates=rot.RATES, accels=ACCELS))

    @functools.cached_property
    def kinetic(self):
        """T = ½ Σ Iᵢ ω̃ᵢ² in the angles and rates (three distinct moments)."""
        return kinetic_energy(convention=self.conv)

    # -- kept between commands (derive.lecture.derivation_kept)
    def _holders(self) -> dict:
        """{name: object} of this derivation and the parts of it built so far."""
        return {"d": self, **{name: vars(self)[name] for name in ("top", "reduction", "sleeping") if name in vars(self)}}

    def derived(self) -> dict:
        """{"holder.name": value} of every quantity computed so far (computing none)."""
        out = {}
        for holder, obj in self._holders().items():
            for name in _cached_names(type(obj)):
                if name in vars(obj) and name not in _PARTS:
                    out[f"{holder}.{name}"] = vars(obj)[name]
        if "top" in vars(self):
            out["top.lagrangian"] = self.top.lagrangian
        if "along" in vars(self):
            out["along.trig"] = self.along.trig if self.along.ok else None
            if "rates" in vars(self.along):          # derived only on a relation with rates
                out["along.rates"] = self.along.rates
        return out

    def seed(self, values: dict) -> None:
        """Take ``values`` (as `derived` gives them) as computed; unknown names are ignored."""
        if isinstance(values.get("top.lagrangian"), sp.Expr):
            top = EulerLagrange(values["top.lagrangian"])
            reduction = Reduction(top)
            vars(self).update(top=top, reduction=reduction, sleeping=SleepingTop(reduction))
        holders = self._holders()
        for path, value in values.items():
            holder, _, name = path.partition(".")
            obj = holders.get(holder)
            if obj is not None and name in _cached_names(type(obj)) and name not in _PARTS:
                vars(obj)[name] = value
        trig, rates = values.get("along.trig", ()), values.get("along.rates")
        if trig is None or isinstance(trig, dict):
            along = vars(self)["along"] = AlongMomentum.of(trig, self.omega)
            if along.ok and isinstance(rates, dict):
                vars(along)["rates"] = rates


_PARTS = ("top", "reduction", "sleeping", "along")  # objects, kept by their own quantities


@functools.lru_cache(maxsize=64)
def lagrange_residuals(lag) -> tuple:
    """d/dt ∂L/∂q̇ − ∂L/∂q of each angle q: derived once per Lagrangian, not per statement."""
    return tuple(rot.time_derivative(sp.diff(lag, qd), accels=ACCELS) - sp.diff(lag, q)
                 for q, qd in zip(rot.ANGLES, rot.RATES))


@functools.cache
def _cached_names(cls) -> tuple:
    return tuple(name for klass in cls.__mro__ for name, attr in vars(klass).items()
                 if isinstance(attr, functools.cached_property))


@functools.cache
def derivation(convention: str) -> Derivation:
    d = Derivation(convention)
    values, known = kept.read(d.conv.name)
    d.seed(values)
    _loaded[d.conv.name] = known
    return d


_loaded: dict = {}  # {sequence: the names the cache holds, or that it cannot hold}


def keep(d: Derivation) -> None:
    """Keep what ``d`` derived in the compile cache, when it derived anything not read from there."""
    values = d.derived()
    if not set(values) <= _loaded.get(d.conv.name, set()):
        kept.write(d.conv.name, values)
        _loaded[d.conv.name] = set(values)  # what was not kept is not tried again in this process


def linear(col) -> sp.Expr:
    return sum((col[i] * lx.BASIS[i] for i in range(3)), sp.S.Zero)


def families():
    """Quantities that can stand for one another by a slip of the label."""
    return [
        [lx.T_, lx.ENERGY, lx.EPRIME, lx.VEFF, lx.LAGRANGIAN],
        list(lx.W),
        list(lx.PRIMED) + list(lx.INERTIAL),
        [lx.Omega, lx.Omega1, lx.Omega2],
        [lx.p_alpha_sym(), lx.p_gamma_sym()],
        [lx.LVEC, lx.OMEGA_VEC, lx.DLDT],
    ]


@functools.lru_cache(maxsize=64)
def _euler_residuals(moments: tuple) -> tuple:
    """Iᵢ ω̃̇ᵢ − ((Iω̃)×ω̃)ᵢ for the moments (I₁, I₂, I₃) as a section sets them; a slip's search for
    its correction asks for them once per candidate, with the same moments."""
    rhs = euler_rhs(moments, sp.Matrix(lx.W))
    return tuple(sp.expand(moments[i] * (lx.WD[i] - rhs[i])) for i in range(3))
