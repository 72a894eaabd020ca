"""Lie–Poisson splitting integrators for a rigid body with a fixed point, rendered into C.

For the Euler–Poisson formulation, in the variables (L, n, e) in body axes (L = I ω̃ about the
pivot, n = Rᵀẑ the upward vertical, e = Rᵀx̂), the Hamiltonian splits into two parts whose flows are
known exactly:

    H = H_T + H_V,   H_T = Σ L_i² / (2 I_i),   H_V = M g n · r_c.

* ``kick`` (flow of H_V over τ): n and e are fixed, L ← L + τ M g n × r_c.
* ``free`` (flow of H_T over τ), L̇ = L × ω̃, ṅ = n × ω̃, ė = e × ω̃, ω̃ = I⁻¹L:
  for I₁ = I₂, H_T = |L|²/(2I₁) + (1/I₃ − 1/I₁) L₃²/2, two commuting flows, each a rotation
  about a fixed axis (n, e about L by −|L|τ/I₁; then L, n, e about body axis 3 by
  −(1/I₃ − 1/I₁) L₃ τ), so their composition is the exact flow; for three distinct moments the
  exact flow with Jacobi elliptic functions — L(t) from the elliptic solution of Euler's
  equations, n and e turned by the body's attitude change over the step, whose angle about the
  invariable direction is an elliptic integral of the third kind (Celledoni, Fassò, Säfström &
  Zanna, SIAM J. Sci. Comput. 30 (2008) 2084; the formulas are those of
  :func:`derive.reference.exact.free_asymmetric`, restarted from the current state at every step, with
  the C port of :mod:`derive.reference.elliptic` in ``templates/c/elliptic.h.j2``).

A method is a symmetric sequence of these sub-flows, a :class:`Splitting` given by its
coefficients (:data:`SCHEMES`, exact data like :mod:`derive.methods.tableaux`; the C literals are the
correctly rounded doubles): a composition of Strang steps S(γh) = kick(γh/2) ∘ free(γh) ∘
kick(γh/2) (:data:`COMPOSITIONS`; adjacent kicks merged), or a general ABA sequence
free(a₁h) kick(b₁h) free(a₂h) … free(a₁h). ``splitting4`` is ABA(10,6,4) of Blanes, Casas,
Farrés, Laskar, Makazaga & Murua, designed for near-integrable problems H = A + εB: its error is
O(εh¹⁰ + ε²h⁶ + ε³h⁴), and gravity is such a perturbation of the exactly integrated free
rotation whenever the spin energy dominates M g |r_c| (a fast top). The last sub-flow of a step
and the first of the next are merged (for ABA methods that saves one free flow per step).
Every sub-flow turns n and e by an orthogonal rotation and changes L by a multiple of
n × r_c ⟂ n, so |n| = |e| = 1, n·e = 0 and L·n stay at round-off for any h, and the method is a
Poisson (symplectic) map: the energy error stays bounded, O(hᵖ), over long runs.

The state is the model's own: (ω̃, n, e) or (L, n, e) (the C converts ω̃ ↔ L = I ω̃ at entry and at
each output; the flows act on L).

Accuracy and cost. The free flow is exact to round-off (tested against ``derive.reference.exact``);
near the separatrix of an asymmetric body (m₁ = 1 − m ≲ 1e-12) the parameter m₁ is formed from
the current state in double precision (D_y = L² − 2E I_y as a sum of two terms, which cancel
there), so the restart of each step sees the orbit's m₁ only to the state's own conditioning.
The asymmetric free flow is the costly sub-flow (R_F, R_J twice, one Landen recurrence,
trigonometry), the symmetric one is two sincos, a kick a few products. For the Lagrange top (I₁ = I₂, r_c on
axis 3) the free flow's turn about body axis 3 commutes with everything else and L₃ is
constant, so the C applies it once per output interval and a free flow is one sincos.
:func:`bench_energy` measures where that pays (the fast top: the spin is carried exactly by
the free flow). Note that Gauss–Legendre
methods conserve every quadratic invariant, and in Euler–Poisson variables the energy
Σ L_i²/(2I_i) + M g n·r_c is quadratic: compare trajectories (``measure="axis"``), not energy,
against them.

The generated C API (``<prefix>_splitting.h``) is that of the fixed-step solvers::

    int M_run_splitting4(const derive_saveat *save, long n_batch, const double *ins,
                         double *ps, double h, double *y, double *out, derive_stats *st);
"""
from __future__ import annotations

import decimal
from dataclasses import dataclass
from fractions import Fraction as F


# --------------------------------------------------------------------------------------------
# compositions (exact data)


def _dec(x: decimal.Decimal) -> F:
    """A 60-digit Decimal as a Fraction rounded to 50 significant digits."""
    return F(format(x, ".49e"))


@dataclass(frozen=True)
class Splitting:
    """One step of a symmetric splitting method given by its coefficients (exact Fractions):

        ABA (len(a) = len(b) + 1):  free(a₁h) kick(b₁h) free(a₂h) … kick(b_s h) free(a_{s+1}h)
        BAB (len(b) = len(a) + 1):  kick(b₁h) free(a₁h) kick(b₂h) … free(a_s h) kick(b_{s+1}h)

    Σa = Σb = 1 (consistency), and both sequences palindromic (a symmetric, time-reversible
    method: only even orders, the odd order conditions hold by symmetry). ``order`` is the
    classical order; methods for near-integrable problems H = A + εB also have an ε-order pair
    ``eps_orders`` (the error is O(ε h^p₁ + ε² h^p₂ + …), p₁ ≥ p₂ ≥ … ≥ order)."""

    name: str
    order: int
    a: tuple[F, ...]
    b: tuple[F, ...]
    reference: str = ""
    eps_orders: tuple[int, ...] = ()

    def __post_init__(self):
        a, b = self.a, self.b
        if abs(len(a) - len(b)) != 1 or not a or not b:
            raise ValueError(f"{self.name}: need len(a) = len(b) ± 1")
        for key, c in (("a", a), ("b", b)):
            if c != tuple(reversed(c)):
                raise ValueError(f"{self.name}: the {key} coefficients must be symmetric")
            if abs(sum(c) - 1) > F(1, 10**24):
                raise ValueError(f"{self.name}: the {key} coefficients must sum to 1")

    @property
    def stages(self) -> int:
        """Free flows per step (the costly sub-flow)."""
        return len(self.a)

    def ops(self) -> list[tuple[str, F]]:
        """The step as exact sub-flows, ("free", c) and ("kick", c), each over time c·h."""
        first, second = ((self.a, "free"), (self.b, "kick")) if len(self.a) > len(self.b) \
            else ((self.b, "kick"), (self.a, "free"))
        (x, kx), (y, ky) = first, second
        out: list[tuple[str, F]] = []
        for i, c in enumerate(x):
            out.append((kx, c))
            if i < len(y):
                out.append((ky, y[i]))
        return out


@dataclass(frozen=True)
class Composition:
    """A symmetric composition S(γ₁h) ∘ … ∘ S(γ_s h) of the Strang step
    S(τ) = kick(τ/2) ∘ free(τ) ∘ kick(τ/2).

    ``gammas`` are exact (Fractions: rational, or 50-digit values of the algebraic numbers;
    published decimals where the method is known only numerically). ``order`` is the classical
    order of the composition. :meth:`splitting` is the same step as a BAB :class:`Splitting`
    (adjacent kicks merged)."""

    name: str
    order: int
    gammas: tuple[F, ...]
    reference: str = ""

    def __post_init__(self):
        g = self.gammas
        if g != tuple(reversed(g)):
            raise ValueError(f"{self.name}: composition weights must be symmetric")
        if abs(sum(g) - 1) > F(1, 10**24):
            raise ValueError(f"{self.name}: weights must sum to 1")

    @property
    def stages(self) -> int:
        return len(self.gammas)

    def splitting(self) -> Splitting:
        """The BAB splitting: a = γ, b = (γ₁/2, (γ₁ + γ₂)/2, …, γ_s/2)."""
        g = self.gammas
        b = tuple((x + y) / 2 for x, y in zip((F(0),) + g, g + (F(0),)))
        return Splitting(self.name, self.order, g, b, self.reference)

    def ops(self) -> list[tuple[str, F]]:
        return self.splitting().ops()


def _triple_jump() -> tuple[F, ...]:
    """Yoshida's / Suzuki's triple jump: γ₁ = γ₃ = 1/(2 − 2^(1/3)), γ₂ = 1 − 2γ₁."""
    with decimal.localcontext() as ctx:
        ctx.prec = 60
        g1 = 1 / (2 - decimal.Decimal(2) ** (decimal.Decimal(1) / 3))
        return (_dec(g1), _dec(1 - 2 * g1), _dec(g1))


def _mclachlan5() -> tuple[F, ...]:
    """McLachlan's 5-stage order-4 weights: γ₁ = γ₅ = 0.28, γ₂ = γ₄ the root near 0.6255 of
    f(x) = 2(γ₁³ + x³) + (1 − 2γ₁ − 2x)³ (the order-4 condition Σγ³ = 0; Newton's method to
    60 digits), γ₃ = 1 − 2(γ₁ + γ₂)."""
    with decimal.localcontext() as ctx:
        ctx.prec = 60
        g1, x = decimal.Decimal("0.28"), decimal.Decimal("0.6254664")
        for _ in range(100):
            r = 1 - 2 * g1 - 2 * x
            step = (2 * (g1**3 + x**3) + r**3) / (6 * x * x - 6 * r * r)
            x -= step
            if abs(step) < decimal.Decimal("1e-58"):
                break
        return tuple(_dec(v) for v in (g1, x, 1 - 2 * g1 - 2 * x, x, g1))


# Kahan & Li's s9odr6a, as published (26 digits) in Hairer, Lubich & Wanner, Geometric
# Numerical Integration, 2nd ed., eq. (V.3.11).
_KL9 = tuple(F(x) for x in ("0.39216144400731413927925056", "0.33259913678935943859974864",
                           "-0.70624617255763935980996482", "0.08221359629355080023149045"))

COMPOSITIONS: dict[str, Composition] = {c.name: c for c in (
    Composition("strang", 2, (F(1),), "G. Strang, SIAM J. Numer. Anal. 5 (1968) 506"),
    Composition("triple-jump", 4, _triple_jump(),
                "H. Yoshida, Phys. Lett. A 150 (1990) 262; M. Suzuki, Phys. Lett. A 146 (1990) 319"),
    Composition("mclachlan-s5", 4, _mclachlan5(),
                "R. I. McLachlan, SIAM J. Sci. Comput. 16 (1995) 151"),
    Composition("kahan-li-s9", 6,
                _KL9 + (F("0.79854399093482996339895035"),) + tuple(reversed(_KL9)),
                "W. Kahan & R.-C. Li, Math. Comp. 66 (1997) 1089, s9odr6a"),
)}


def _aba(c: tuple[str, ...], d: tuple[str, ...], kicks: int) -> tuple[tuple[F, ...], tuple[F, ...]]:
    """(a, b) of a symmetric ABA method with ``kicks`` kicks from the first halves of its
    coefficient lists, a₁…a_⌈(s+1)/2⌉ and b₁…b_⌈s/2⌉, published decimals."""
    na, nb = (kicks + 2) // 2, (kicks + 1) // 2
    if len(c) != na or len(d) != nb:
        raise ValueError("need the first halves of a and b")
    ha, hb = tuple(F(x) for x in c), tuple(F(x) for x in d)
    a = ha + tuple(reversed(ha[: (kicks + 1) - na]))
    b = hb + tuple(reversed(hb[: kicks - nb]))
    return a, b


SCHEMES: dict[str, Splitting] = {s.name: s for s in (
    *(c.splitting() for c in COMPOSITIONS.values()),
    # 40-digit published values (as tabulated for the Solar System integrations of Farrés et al.
    # and in REBOUND's SABA(10,6,4)); the ε-order 10 is the quadrature condition
    # Σ bᵢ cᵢᵏ = 1/(k + 1), k ≤ 9, at the kick times cᵢ, which they meet to 1e-40.
    Splitting("aba(10,6,4)", 4, *_aba(
        ("0.03809449742241219545697532230863756534060", "0.1452987161169137492940200726606637497442",
         "0.2076276957255412507162056113249882065158", "0.4359097036515261592231548624010651844006",
         "-0.6538612258327867093807117373907094120024"),
        ("0.09585888083707521061077150377145884776921", "0.2044461531429987806805077839164344779763",
         "0.2170703479789911017143385924306336714532", "-0.01737538195906509300561788011852699719871"),
        kicks=8),
        "S. Blanes, F. Casas, A. Farrés, J. Laskar, J. Makazaga & A. Murua, Appl. Numer. Math. 68 "
        "(2013) 58; A. Farrés et al., Celest. Mech. Dyn. Astr. 116 (2013) 141", eps_orders=(10, 6, 4)),
)}


@dataclass(frozen=True)
class SplittingMethod:
    """A registered splitting method: a :class:`Splitting` of the exact sub-flows. Driver
    ``fixed``: its one C parameter is the maximum step ``h``."""

    name: str
    scheme: Splitting
    summary: str
    driver: str = "fixed"

    @property
    def order(self) -> int:
        return self.scheme.order

    @property
    def params(self) -> tuple[tuple[str, str], ...]:
        return (("double", "h"),)


METHODS: dict[str, SplittingMethod] = {m.name: m for m in (
    SplittingMethod("splitting2", SCHEMES["strang"],
                    "Lie-Poisson splitting, Strang (exact free flow and gravity kick), order 2, fixed step"),
    SplittingMethod("splitting4", SCHEMES["aba(10,6,4)"],
                    "Lie-Poisson splitting, ABA(10,6,4) of Blanes et al. for near-integrable problems, "
                    "order 4, fixed step"),
    SplittingMethod("splitting6", SCHEMES["kahan-li-s9"],
                    "Lie-Poisson splitting, Kahan-Li 9-stage composition, order 6, fixed step"),
)}


# --------------------------------------------------------------------------------------------
# which models


_GRAVITY = {"gravity": "axial", "gravity_general": "general"}


def applicable(model) -> str | None:
    """None if the splitting methods can integrate ``model``, else the reason: they need the
    Euler–Poisson formulation and conservative effects whose flow is an exact kick (gravity,
    axial or general); a non-conservative effect (damping) has no Hamiltonian to split."""
    if model.formulation != "euler-poisson":
        return (f"the splitting methods need the 'euler-poisson' formulation, "
                f"not {model.formulation!r}")
    bad = [e for e in model.effects if e not in _GRAVITY]
    if bad:
        return f"the splitting methods need a conservative body: the effect {bad[0]!r} is not a gravity kick"
    if len(model.effects) > 1:
        return "the splitting methods take at most one gravity effect"
    return None
