"""A heavy body about a fixed point in Euler–Poisson form: the integrals a text states, checked.

A text on the heavy body with its centre of mass anywhere in the body (Euler's, Lagrange's and
Kovalevskaya's cases) works in the body components ω̃ᵢ of the angular velocity and γᵢ of the
upward vertical, and states its integrals as ``… = E (const)``, ``I_1\\omega_1\\gamma_1 + … = L_Z``.
Such a statement says the quantity's rate vanishes on the motion. The motion here is derived, not
quoted:

* the vertical's body components γ = Rᵀẑ come from the convention's rotation R(q), and the angles'
  rates from the derivation's ω̃(q, q̇) = W solved for q̇ (Poisson's γ̇ = γ × ω̃ follows from these
  by the chain rule, it is never written in);
* the weight −Mgẑ acts at the centre of mass 𝐫_C (its body coordinates, `derive.lecture.names`
  "centre-of-mass coordinates"), so its moment about the fixed point is τ = 𝐫_C × (−Mgγ);
* the law of angular momentum about the fixed point, d𝐋/dt = τ with 𝐋 = R I W, is carried into
  body axes with the derivation's own R: Rᵀ d(R I W)/dt = I Ẇ + (RᵀṘ) I W, RᵀṘ computed from R(q)
  and q̇(W, q) (`body_spin`; it is the cross-product matrix of W, which Euler's equations
  I Ẇ + W × I W = τ assume), with I = diag(I₁, I₂, I₃) under the text's settings.

Then dF/dt = Σᵢ ∂F/∂Wᵢ Ẇᵢ + Σⱼ ∂F/∂qⱼ q̇ⱼ(W, q), and the statement holds when it vanishes. A
quantity written with rates, accelerations or names the text has not tied is left unchecked; one
whose rate does not vanish is left unchecked too, naming it (the text's case may set what the
reader did not take), so that this check never calls a correct integral wrong.

Takes: the checker (``d``, ``ctx``, ``vocab``, ``notes.names``, ``_resolve``, ``_compare``, ``_add``).
Gives: the mixin `EulerPoisson`, and `rate_on_motion` (the rate of a quantity along the motion).

May import: :mod:`derive.lecture.latex`, :mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import functools
import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.vocabulary import Atom
from derive.lecture.stated_settings import settled, stated_angles
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3, Mass, g
from derive.symbolic.rotations import ANGLES, RATES, time_derivative


@functools.lru_cache(maxsize=None)
def _angle_rates(omega: sp.ImmutableMatrix) -> tuple:
    """q̇(W, q): the derivation's ω̃(q, q̇) = W solved for the rates (linear in them)."""
    sol = sp.solve([omega[i] - lx.W[i] for i in range(3)], RATES, dict=True)
    return tuple(sp.cancel(sol[0][r]) for r in RATES)


@functools.lru_cache(maxsize=None)
def body_spin(rotation: sp.ImmutableMatrix, omega: sp.ImmutableMatrix) -> sp.ImmutableMatrix:
    """RᵀṘ in the body angular velocity W, Ṙ = Σⱼ ∂R/∂qⱼ q̇ⱼ with q̇(W, q). Where it agrees with the
    cross-product matrix of W at sample points (RᵀṘ v = W × v: the derivation's ω̃ is the body
    angular velocity of R), that matrix; otherwise RᵀṘ as computed."""
    qdot = _angle_rates(omega)
    Rdot = sum((sp.diff(rotation, q) * v for q, v in zip(ANGLES, qdot)), sp.zeros(3, 3))
    spin = rotation.T * Rdot
    w = lx.W
    cross = sp.Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    residual = sp.lambdify((*ANGLES, *w), list(spin - cross), modules="math")
    points = ((0.43 + k, 0.56 + k / 3, 0.18 - k, 0.33 - k, 1.4, k + 0.5) for k in range(3))
    if all(abs(x) < 1e-9 for p in points for x in residual(*p)):
        return sp.ImmutableMatrix(cross)
    return sp.ImmutableMatrix(spin)


def gravity_moment(rotation, r_c, down: bool = False) -> sp.Matrix:
    """The weight's moment about the fixed point in body axes, τ = 𝐫_C × (−Mgγ), γ = Rᵀẑ the upward
    vertical (``down``: the opposite vertical, for a text whose γ points down)."""
    gamma = sp.Matrix(rotation).T[:, 2] * (-1 if down else 1)
    return sp.Matrix(r_c).cross(-Mass * g * gamma)


def euler_residuals(rotation, r_c, moments, omega, down: bool = False) -> list:
    """Euler's equations of the heavy body, Iᵢω̃̇ᵢ + (RᵀṘ I W)ᵢ − τᵢ (zero on the motion)."""
    W, inertia = sp.Matrix(lx.W), sp.diag(*moments)
    tau = gravity_moment(rotation, r_c, down)
    spin = body_spin(sp.ImmutableMatrix(rotation), sp.ImmutableMatrix(omega))
    lhs = inertia * sp.Matrix(lx.WD) + spin * inertia * W
    return [lhs[i] - tau[i] for i in range(3)]


def rate_on_motion(F, omega, rotation, r_c, moments=(I1, I2, I3)):
    """dF/dt on the motion of a heavy body about a fixed point.

    Parameters
    ----------
    F : sympy expression
        In the body components ``lx.W`` of the angular velocity, the angles and constants.
    omega : Matrix
        The derivation's body angular velocity ω̃(q, q̇).
    rotation : Matrix
        R(q), body to space; the upward vertical in body axes is γ = Rᵀẑ.
    r_c : sequence of 3
        The centre of mass's body coordinates (zero for a free body).
    moments : sequence of 3
        The principal moments, with the text's settings put in.

    Returns
    -------
    sympy expression
        Σᵢ ∂F/∂Wᵢ Ẇᵢ + Σⱼ ∂F/∂qⱼ q̇ⱼ with I Ẇ = 𝐫_C × (−Mgγ) − (RᵀṘ) I W.
    """
    W = sp.Matrix(lx.W)
    torque = gravity_moment(rotation, r_c)
    inertia = sp.diag(*moments)
    spin = body_spin(sp.ImmutableMatrix(rotation), sp.ImmutableMatrix(omega))
    wdot = inertia.inv() * (torque - spin * inertia * W)
    qdot = _angle_rates(sp.ImmutableMatrix(omega))
    return sum(sp.diff(F, W[i]) * wdot[i] for i in range(3)) + sum(sp.diff(F, q) * v for q, v in zip(ANGLES, qdot))


_DOT_CONSTANT = re.compile(r"^\s*(?P<a>.+?)\s*\\cdot\s*(?P<b>.+?)\s*=\s*(?P<name>[^=]+?)\s*=\s*\\mathrm\{const\}\s*$", re.S)
"""``\\mathbf{L}\\cdot\\mathbf{n} = L_Z = const``: a scalar product the text says is conserved (and names)."""


def _column(v):
    """A vector written on the body basis (I₁ω̃₁ê₁ + …) as its column of components; else as it is."""
    if isinstance(v, sp.MatrixBase) or not set(getattr(v, "free_symbols", ())) & set(lx.BASIS):
        return v
    e = sp.expand(v)
    col = sp.Matrix([e.coeff(b) for b in lx.BASIS])
    return col if sp.expand(e - sum(c * b for c, b in zip(col, lx.BASIS))) == 0 else v


class EulerPoisson:
    """Mixin of the checker: see the module docstring. Settings of the centre of mass's
    coordinates (``x_C = y_C = 0``: Lagrange's case) are a case of the text's: those made on one
    line hold together, and a later line's replace them (the next case it lists)."""

    def _centre_symbols(self) -> dict:
        names = self.notes.names
        found = {}
        if names is None:
            return found
        for (base, sub), meaning in names.symbols.items():
            if meaning.startswith("centre-of-mass coordinate ") and names.meaning(Atom(base, sub=sub)) == meaning:
                found[int(meaning[-1]) - 1] = self.vocab._generic(Atom(base, sub=sub))   # the symbol the text reads
        return found

    def _centre_setting(self, line, piece, parsed) -> bool:
        """``x_C = y_C = 0``: the centre of mass's coordinates set to numbers (a case). True when done."""
        centre = set(self._centre_symbols().values())
        members = [m.value for m in parsed.members]
        if len(centre) != 3 or set(parsed.relations) != {"="} or not all(
                m in centre or (getattr(m, "is_number", False) and not isinstance(m, sp.MatrixBase)) for m in members):
            return False
        values = [m for m in members if m not in centre]
        if len(values) != 1:
            return False
        if self.ctx.centre_line != line:
            for s in centre:
                self.ctx.subs.pop(s, None)
            self.ctx.centre_line = line
        for m in members:
            if m in centre:
                self.ctx.subs[m] = values[0]
                self.ctx.stated[m] = f"line {line}"
        self._add(line, piece, "setting", "unchecked",
                  "sets the centre of mass's coordinates: a case of the text's, not a claim")
        return True

    def _heavy_first(self, line, piece, parsed) -> bool:
        """The statements this module reads before the rest of the reader: True when done."""
        return self._centre_setting(line, piece, parsed) or self._heavy_statement(line, piece, parsed)

    def _centre_of_mass(self) -> list | None:
        """The centre of mass's body coordinates as the text names them (resolved with its
        definitions and settings), or None when the text names none."""
        found = self._centre_symbols()
        if len(found) != 3:
            return None
        return [self._resolve(self.ctx.subs.get(found[k], found[k])) for k in range(3)]

    def _conserved(self, line, piece, value) -> bool:
        """``F = N (const)``: F's rate on the heavy body's motion vanishes. True when a claim was added."""
        r_c = self._centre_of_mass()
        if r_c is None:
            return False
        F = self._resolve(value)
        if isinstance(F, sp.MatrixBase) or not hasattr(F, "free_symbols"):
            return False
        if F.free_symbols & (set(RATES) | set(ACCELS) | set(lx.WD)):
            return False
        allowed = set(lx.W) | set(ANGLES) | {I1, I2, I3, Mass, g}
        loose = sorted(self.tex(x) for x in F.free_symbols - allowed
                       if isinstance(x, lx.Generic) and x not in self._constants())
        F = F.xreplace(self.ctx.subs)
        r_c = [sp.sympify(x).xreplace(self.ctx.subs) for x in r_c]
        moments = [sp.sympify(m).xreplace(self.ctx.subs) for m in (I1, I2, I3)]
        if loose and set(loose) - {self.tex(x) for x in r_c}:
            self._add(line, piece, "integral", "unchecked",
                      f"states a conserved quantity in {', '.join(loose)}, which the text has not tied")
            return True
        rate = rate_on_motion(F, self.d.omega, self.d.conv.matrix(), r_c, moments)
        ok, how = self._compare(rate, sp.S.Zero, f"{piece}/integral")
        if ok:
            self._add(line, piece, "integral", "holds",
                      f"conserved on the Euler–Poisson equations of the heavy body (dF/dt: {how})")
        else:
            self._add(line, piece, "integral", "unchecked",
                      "not conserved on the heavy body's motion as read (the case the text means may set "
                      f"more than it wrote): dF/dt = {how}")
        return True

    # -- the moment: of gravity, in Euler's equations, and in a motion the text set
    def _moments(self):
        return [sp.sympify(m).xreplace(self.ctx.subs) for m in (I1, I2, I3)]

    def _centre_in(self, *values) -> list | None:
        """The centre's coordinates when the values are written with them, else None."""
        centre = self._centre_symbols()
        if len(centre) != 3 or not any(set(getattr(v, "free_symbols", ())) & set(centre.values()) for v in values):
            return None
        return [sp.sympify(self._resolve(self.ctx.subs.get(centre[k], centre[k]))) for k in range(3)]

    def _heavy_statement(self, line, piece, parsed) -> bool:
        """A moment component or an equation of motion of the heavy body (see `_gravity_claim`, `_set_motion_torque`)."""
        if len(parsed.members) != 2 or parsed.relations != ["="]:
            return False
        a, b = parsed.members[0].value, parsed.members[1].value
        if isinstance(a, sp.MatrixBase) or isinstance(b, sp.MatrixBase):
            return False
        r_c = self._centre_in(a, b)
        if r_c is not None:
            return self._gravity_claim(line, piece, a, b, r_c)
        if a in lx.TAU:
            return self._set_motion_torque(line, piece, lx.TAU.index(a), b)
        return False

    def _gravity_claim(self, line, piece, a, b, r_c) -> bool:
        """``M_1 = Mg(γ₂z_C − γ₃y_C)`` (a component of the weight's moment) or ``I_1 ω̇₁ − (I₂ − I₃)ω₂ω₃
        = Mg(…)`` (Euler's equation with it): holds when it is the derived one (a multiple of one of
        Euler's equations); one that holds only with the vertical pointing down is left unchecked."""
        rot = self.d.conv.matrix()
        if a in lx.TAU:
            k = lx.TAU.index(a)
            value = self._resolve(b)
            targets = [(gravity_moment(rot, r_c, down)[k], down) for down in (False, True)]
            what = f"component {k + 1} of the weight's moment 𝐫_C × (−Mg𝐧) about the fixed point"
        else:
            value = self._resolve(a - b)
            if not set(value.free_symbols) & set(lx.WD):
                return False
            coeffs = [sp.diff(value, wd) for wd in lx.WD]
            if any(set(c.free_symbols) - {I1, I2, I3} for c in coeffs):
                return False
            targets = [(sum(c / m * e for c, m, e in zip(coeffs, self._moments(), euler_residuals(rot, r_c, self._moments(), self.d.omega, down))
                            if c != 0), down) for down in (False, True)]
            value = value.xreplace(self.ctx.subs)
            what = "a multiple of Euler's equations with the weight's moment 𝐫_C × (−Mg𝐧) about the fixed point"
        loose = {x for x in value.free_symbols if isinstance(x, lx.Generic)} - set(r_c) - self._constants()
        loose -= {x for r in r_c for x in sp.sympify(r).free_symbols}
        if loose:
            return False
        (up, _), (down, _) = targets
        ok, how = self._compare(value, up, f"{piece}/gravity")
        if ok:
            self._add(line, piece, "moment" if a in lx.TAU else "equation of motion", "holds", f"{what}: {how}")
        elif self._compare(value, down, f"{piece}/gravity-down")[0]:
            self._add(line, piece, "moment", "unchecked", "holds with the vertical 𝐧 pointing down, "
                      "while the text's 𝐧 was read as the upward vertical: the reader cannot tell which it means")
        else:
            self._add(line, piece, "moment" if a in lx.TAU else "equation of motion", "fails", f"as written, not {what}: {how}")
        return True

    def _set_motion_torque(self, line, piece, k, b) -> bool:
        """``M_3 = 0``, ``M_1 = ω_pω_s sin θ₀ cos ψ […]``: the moment the motion the text set (its angles
        and rates, ``θ = θ₀``, ``\\dot\\phi = ω_p``) needs, from Euler's equations τ = Iω̃̇ + ω̃ × Iω̃ with
        ω̃(q, q̇). Holds when equal; never judged wrong here (the motion may be set only in part)."""
        stated = stated_angles(self)
        if not stated:
            return False
        W, inertia = sp.Matrix(self.d.omega), sp.diag(*self._moments())
        wdot = W.applyfunc(lambda x: time_derivative(x, accels=ACCELS))
        need = (inertia * wdot + W.cross(inertia * W))[k]
        full = settled({**self.ctx.subs, **{s: v for s, (v, _) in stated.items()}})
        for _ in range(3):
            need = need.xreplace(full)
        if set(need.free_symbols) & (set(RATES) | set(ACCELS)):
            return False
        value = self._resolve(b)
        if isinstance(value, sp.MatrixBase) or set(value.free_symbols) & (set(lx.W) | set(lx.WD)):
            return False
        ok, how = self._compare(value, need, f"{piece}/set-motion")
        if not ok:
            return False
        named = ", ".join(f"{self.tex(s)} = {self.tex(v)}" for s, (v, _) in stated.items())
        self._add(line, piece, "moment", "holds",
                  f"the moment Euler's equations need in the motion the text set ({named}): {how}")
        return True

    def _dot_integral(self, line, piece, text) -> bool:
        """``𝐋·𝐧 = L_Z (const)``, the two vectors ones the text has named: their scalar product in body
        components is an integral of the motion (`_conserved`). True when a claim was added."""
        m = _DOT_CONSTANT.match(text)
        if m is None:
            return False
        try:
            a, b, name = (lx.parse(m.group(k), self.vocab).members for k in ("a", "b", "name"))
        except lx.NotRead:
            return False
        if len(a) != 1 or len(b) != 1 or len(name) != 1:
            return False
        A, B = (_column(self._resolve(v[0].value)) for v in (a, b))
        if not all(isinstance(v, sp.MatrixBase) and v.shape == (3, 1) for v in (A, B)):
            return False
        value = (A.T * B)[0]
        if not self._conserved(line, piece, value):
            return False
        if self._new_name(name[0].value):
            self.ctx.defs[name[0].value] = value
        return True
