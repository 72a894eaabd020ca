"""Rotations and Euler angles, symbolically.

Frames. The inertial frame has unit vectors ê⁰ᵢ; the body frame ê₁, ê₂, ê₃ is fixed in the body
and diagonalises its inertia tensor. A vector v has inertial components v⁰ and body components ṽ.

Conventions. A convention is the sequence of axes of three successive rotations through the
angles (α, β, γ): the first about the inertial axis, the second about the once-rotated
(intermediate) axis, the third about the body axis. ``ZYZ`` is the notes' convention (the one of
most quantum-mechanics texts, Fetter & Walecka's lecture 26); ``ZXZ`` is that of most
classical-mechanics texts (Goldstein's φ, θ, ψ).

Matrices. ``active(axis, θ)`` turns a vector by θ about ``axis`` (right hand); ``passive(axis, θ)``
= active(axis, θ)ᵀ gives the components of a fixed vector in axes turned by θ — the matrices
written on the slides are passive. The orientation matrix

    R(α, β, γ) = active(a₁, α) · active(a₂, β) · active(a₃, γ)

maps body components to inertial ones, v⁰ = R ṽ; its columns are the body axes in inertial
components (column 3 is the symmetry axis ê₃), and ṽ = Rᵀ v⁰ = passive(a₃, γ) passive(a₂, β)
passive(a₁, α) v⁰ is the slides' product of passive matrices.

Angular velocity in the body frame, two independent routes that must agree:

1. the notes' sum  ω̃ = α̇ ê⁰₃ + β̇ ê′₂ + γ̇ ê₃, each axis written in body components
   (ê⁰_{a₁} = Rᵀ e_{a₁}, ê′_{a₂} = passive(a₃, γ) e_{a₂}, ê_{a₃} = e_{a₃});
2. the skew matrix  [ω̃]ₓ = Rᵀ Ṙ  (body-frame angular velocity tensor).

In space (inertial) components ω⁰ = R ω̃, from [ω⁰]ₓ = Ṙ Rᵀ (``omega_space``). Every one of the
twelve sequences (``convention``) gives R, ω̃, ω⁰ and the rate matrices B, B⁰ (ω̃ = B q̇,
ω⁰ = B⁰ q̇) the same way.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from math import comb

import sympy as sp
from sympy.polys.polyerrors import BasePolynomialError

_AXIS_INDEX = {"x": 0, "y": 1, "z": 2}

# Euler angles and their rates as plain symbols: Lagrangian mechanics here treats (q, q̇) as
# independent variables, and time derivatives are taken by the chain rule (see `time_derivative`).
alpha, beta, gamma = sp.symbols("alpha beta gamma", real=True)
alpha_d, beta_d, gamma_d = sp.symbols("alpha_d beta_d gamma_d", real=True)
ANGLES = (alpha, beta, gamma)
RATES = (alpha_d, beta_d, gamma_d)


def unit(axis: str) -> sp.Matrix:
    """The unit column vector along 'x', 'y' or 'z'."""
    e = sp.zeros(3, 1)
    e[_AXIS_INDEX[axis]] = 1
    return e


def active(axis: str, theta) -> sp.Matrix:
    """Active rotation by ``theta`` about ``axis`` (right-hand rule): v ↦ R v turns v."""
    c, s = sp.cos(theta), sp.sin(theta)
    i = _AXIS_INDEX[axis]
    j, k = (i + 1) % 3, (i + 2) % 3
    R = sp.eye(3)
    R[j, j], R[j, k], R[k, j], R[k, k] = c, -s, s, c
    return R


def passive(axis: str, theta) -> sp.Matrix:
    """Passive rotation: components of a fixed vector in axes turned by ``theta`` about ``axis``.

    For axis z this is the slides' [[cos, sin, 0], [−sin, cos, 0], [0, 0, 1]].
    """
    return active(axis, theta).T


def skew(w) -> sp.Matrix:
    """[w]ₓ, the matrix with [w]ₓ v = w × v."""
    return sp.Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def unskew(W: sp.Matrix) -> sp.Matrix:
    """The vector w of a skew matrix W = [w]ₓ (antisymmetric part taken, so rounding-safe)."""
    return sp.Matrix([(W[2, 1] - W[1, 2]) / 2, (W[0, 2] - W[2, 0]) / 2, (W[1, 0] - W[0, 1]) / 2])


def zyz_angles(R: sp.Matrix):
    """z-y-z angles of R = Rz(α) Ry(β) Rz(γ) (any positive multiple of R): β ∈ [0, π] from
    atan2(√(R₃₁² + R₃₂²), R₃₃) (accurate near the poles), α = atan2(R₂₃, R₁₃),
    γ = atan2(R₃₂, −R₃₁)."""
    return (sp.atan2(R[1, 2], R[0, 2]), sp.atan2(sp.sqrt(R[2, 0] ** 2 + R[2, 1] ** 2), R[2, 2]),
            sp.atan2(R[2, 1], -R[2, 0]))


def trig_reduce(expr, angles=ANGLES):
    """Canonical form of a polynomial in sin and cos of ``angles`` (rational functions: of the
    numerator and the denominator separately).

    Each sin(x), cos(x) becomes a symbol s, c and the polynomial is reduced modulo c² + s² − 1
    (remainder in c, so c appears at most linearly). Two such polynomials are equal as functions
    exactly when their reduced forms are identical: a zero test that needs no `simplify`, and
    far faster than `trigsimp` on the 3×3 products here.
    """
    expr = sp.sympify(expr)
    pairs = []
    for x in angles:
        s_, c_ = sp.Dummy("s"), sp.Dummy("c")
        # exact replacement of these atoms (`subs` does the same here, with far more work)
        expr = expr.xreplace({sp.sin(x): s_, sp.cos(x): c_, sp.tan(x): s_ / c_})
        pairs.append((x, s_, c_))
    # an expression with no denominator (positive powers only, no exp, no float) is its own
    # numerator: `together` would only take out its rational content, put back by the quotient
    polynomial = not any(p.is_Float or isinstance(p, sp.exp) or
                         (p.is_Pow and not (p.exp.is_number and p.exp.is_positive)) for p in sp.preorder_traversal(expr))
    num, den = (expr, sp.S.One) if polynomial else sp.fraction(sp.together(expr))

    def reduce(poly):
        poly = sp.expand(poly)
        present = [(s_, c_) for _, s_, c_ in pairs if poly.has(c_)]
        if not present:
            return poly
        try:
            return _rem_cos_squares(poly, present)
        except BasePolynomialError:     # c or s inside a non-polynomial term: divide as a polynomial in c alone
            for s_, c_ in present:
                poly = sp.rem(sp.Poly(poly, c_), sp.Poly(c_**2 + s_**2 - 1, c_)).as_expr()
            return sp.expand(poly)

    back = {v: f(x) for x, s_, c_ in pairs for v, f in ((s_, sp.sin), (c_, sp.cos))}
    num = reduce(num).xreplace(back)
    if den == 1:
        return num
    return num / sp.factor(reduce(den).xreplace(back))


def cos_squares_replaced(monom: list, coeff, pairs, convert=lambda n: n) -> list:
    """The terms of one monomial (exponents ``monom``, coefficient ``coeff``) with each cₖ^(2m+e)
    replaced by cₖ^e (1 − sₖ²)^m = cₖ^e Σⱼ C(m, j) (−1)^j sₖ^(2j), for each (index of sₖ, index of
    cₖ) of ``pairs``; ``convert`` takes the integer C(m, j) (−1)^j into the coefficients' domain."""
    terms = [(monom, coeff)]
    for s, c in pairs:
        m, e = divmod(monom[c], 2)
        if not m:
            continue
        grown = []
        for exps, cf in terms:
            for j in range(m + 1):
                new = list(exps)
                new[s] += 2 * j
                new[c] = e
                grown.append((new, cf * convert(comb(m, j) * (-1) ** j)))
        terms = grown
    return terms


def _rem_cos_squares(poly, pairs) -> sp.Expr:
    """The remainder of ``poly`` modulo cₖ² + sₖ² − 1 for each (sₖ, cₖ) of ``pairs`` (expanded).

    The divisors have leading terms cₖ² in distinct variables, so the remainder is each monomial's
    cₖ^(2m+e) replaced by cₖ^e (1 − sₖ²)^m = cₖ^e Σⱼ C(m, j) (−1)^j sₖ^(2j): one pass over the terms
    of a polynomial in all the sₖ, cₖ gives what dividing by each cₖ² + sₖ² − 1 in turn gives.
    """
    gens = [g for pair in pairs for g in pair]
    P = sp.Poly(poly, *gens)
    dom, out = P.domain, {}
    for monom, coeff in P.as_dict(native=True).items():
        terms = cos_squares_replaced(list(monom), coeff, [(2 * k, 2 * k + 1) for k in range(len(pairs))],
                                     dom.convert)
        for exps, cf in terms:
            key = tuple(exps)
            out[key] = out.get(key, dom.zero) + cf
    return sp.expand(sp.Poly.from_dict({k: v for k, v in out.items() if v}, *gens, domain=dom).as_expr())


def time_derivative(expr, coords=ANGLES, rates=RATES, accels=None):
    """d/dt of an expression in (q, q̇) by the chain rule: Σ ∂/∂q_i q̇_i (+ Σ ∂/∂q̇_i q̈_i)."""
    # a coordinate the expression does not hold adds 0 to the sum: it is not differentiated
    free = getattr(sp.sympify(expr), "free_symbols", ())
    d = sum((sp.diff(expr, q) * qd for q, qd in zip(coords, rates) if q in free), sp.S.Zero)
    if accels is not None:
        d += sum((sp.diff(expr, qd) * qdd for qd, qdd in zip(rates, accels) if qd in free), sp.S.Zero)
    return d


@dataclass(frozen=True)
class Convention:
    """Three rotation axes: about the inertial a₁, the intermediate a₂, the body a₃."""

    name: str
    axes: tuple[str, str, str]
    description: str

    def matrix(self, a=alpha, b=beta, c=gamma) -> sp.Matrix:
        """R = active(a₁, α) active(a₂, β) active(a₃, γ): body → inertial components."""
        a1, a2, a3 = self.axes
        return active(a1, a) * active(a2, b) * active(a3, c)

    def intermediate_axis(self, c=gamma) -> sp.Matrix:
        """ê′ (the second rotation's axis) in body components: passive(a₃, γ) e_{a₂}."""
        return passive(self.axes[2], c) * unit(self.axes[1])

    def inertial_axis(self, a=alpha, b=beta, c=gamma) -> sp.Matrix:
        """ê⁰ (the first rotation's axis) in body components: Rᵀ e_{a₁}."""
        return self.matrix(a, b, c).T * unit(self.axes[0])

    @functools.lru_cache(maxsize=None)
    def omega_body_sum(self) -> sp.Matrix:
        """Route 1, the notes' sum: ω̃ = α̇ ê⁰_{a₁} + β̇ ê′_{a₂} + γ̇ ê_{a₃} in body components."""
        w = alpha_d * self.inertial_axis() + beta_d * self.intermediate_axis() + gamma_d * unit(self.axes[2])
        return w.applyfunc(trig_reduce)

    @functools.lru_cache(maxsize=None)
    def omega_body_skew(self) -> sp.Matrix:
        """Route 2: ω̃ from the skew matrix [ω̃]ₓ = Rᵀ Ṙ."""
        R = self.matrix()
        Rdot = R.applyfunc(time_derivative)
        return sp.ImmutableMatrix(unskew(R.T * Rdot).applyfunc(trig_reduce))

    @functools.lru_cache(maxsize=None)
    def omega_space(self) -> sp.Matrix:
        """ω⁰, the angular velocity in inertial (space) components: [ω⁰]ₓ = Ṙ Rᵀ, equal to R ω̃.

        For any of the twelve sequences, ω⁰ = α̇ e_{a₁} + β̇ active(a₁, α) e_{a₂} + γ̇ active(a₁, α)
        active(a₂, β) e_{a₃}: each rate about its turn's axis, written in space components.
        """
        R = self.matrix()
        Rdot = R.applyfunc(time_derivative)
        return sp.ImmutableMatrix(unskew(Rdot * R.T).applyfunc(trig_reduce))

    @functools.lru_cache(maxsize=None)
    def space_rate_matrix(self) -> sp.Matrix:
        """B⁰(q) with ω⁰ = B⁰(q) q̇: the space components' matrix of the rates."""
        return sp.ImmutableMatrix(self.omega_space().jacobian(sp.Matrix(RATES)))

    @functools.lru_cache(maxsize=None)
    def rate_matrix(self) -> sp.Matrix:
        """B(q) with ω̃ = B(q) q̇ (linear in the rates)."""
        w = self.omega_body_sum()
        return sp.ImmutableMatrix(w.jacobian(sp.Matrix(RATES)))

    @functools.lru_cache(maxsize=None)
    def singular_set(self):
        """det B(q): the rates are recoverable from ω̃ exactly where this is non-zero."""
        return trig_reduce(self.rate_matrix().det())

    def rates_from_omega(self, w=None) -> sp.Matrix:
        """The inverse map q̇ = B(q)⁻¹ ω̃, defined off the singular set (see `singular_set`)."""
        w = sp.Matrix(sp.symbols("omega1:4", real=True)) if w is None else sp.Matrix(w)
        B = self.rate_matrix()
        return (B.adjugate() * w / self.singular_set()).applyfunc(lambda e: sp.trigsimp(sp.factor(e)))


ZYZ = Convention("zyz", ("z", "y", "z"), "z-y-z: the notes' (quantum-mechanics) convention")
ZXZ = Convention("zxz", ("z", "x", "z"), "z-x-z: Goldstein's (classical-mechanics) convention")
CONVENTIONS = {c.name: c for c in (ZYZ, ZXZ)}


def convention(sequence: str) -> Convention:
    """Any of the twelve sequences by its dashed name (``"z-x-z"``, ``"z-y-x"``): the proper Euler
    ones (first and third axis equal) and the Tait–Bryan ones (three different axes), turning
    about the new (intrinsic) axes, so R = active(a₁, α) active(a₂, β) active(a₃, γ)."""
    axes = tuple(sequence.split("-"))
    if len(axes) != 3 or any(a not in _AXIS_INDEX for a in axes) or axes[0] == axes[1] or axes[1] == axes[2]:
        raise ValueError(f"{sequence!r} is not an Euler or Tait–Bryan sequence")
    name = "".join(axes)
    if name in CONVENTIONS:
        return CONVENTIONS[name]
    kind = "proper Euler" if axes[0] == axes[2] else "Tait–Bryan"
    return Convention(name, axes, f"{sequence}: {kind} angles")
