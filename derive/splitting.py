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
  :func:`derive.exact.free_asymmetric`, restarted from the current state at every step, with
  the C port of :mod:`derive.elliptic` in ``templates/c/elliptic.h.j2``).

A method is a symmetric sequence of these sub-flows, a :class:`Splitting` given by its
coefficients (:data:`SCHEMES`, exact data like :mod:`derive.tableaux`; the C literals are the
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

Accuracy and cost. The free flow is exact to round-off (tested against ``derive.exact``);
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

    int M_solve_splitting4(const double *y0, const double *p, const double *t_out, long n_out,
                           double h, double *y_out, derive_stats *st);
    int M_solve_batch_splitting4(long n_batch, const double *y0s, const double *ps,
                                 const double *t_out, long n_out, double h,
                                 double *y_out, derive_stats *st);
"""
from __future__ import annotations

import ctypes
import decimal
import time
from dataclasses import dataclass
from fractions import Fraction as F

import numpy as np

from .render import render

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


def _context(model, names) -> dict:
    why = applicable(model)
    if why:
        raise ValueError(why)
    pn = model.param_names
    idx = {name: pn.index(name) for name in pn}
    idx["I2"] = idx.get("I2", idx["I1"])  # symmetric body: I2 = I1
    gravity = _GRAVITY[model.effects[0]] if model.effects else "none"
    methods = []
    for name in names:
        m = METHODS[name]
        ops = [{"kind": k, "c": float(c)} for k, c in m.scheme.ops()]
        eps = " + ".join(f"eps{'^' + str(i + 1) if i else ''} h^{p}"
                         for i, p in enumerate(m.scheme.eps_orders))
        methods.append({"name": m.name, "summary": m.summary, "order": m.order,
                        "scheme": m.scheme.name, "form": "ABA" if ops[0]["kind"] == "free" else "BAB",
                        "stages": m.scheme.stages, "kicks": sum(op["kind"] == "kick" for op in ops),
                        "eps_note": f", error O({eps})" if eps else "",
                        "edge": ops[0], "inner": [op for op in ops[1:-1] if op["c"] != 0]})
    return {"prefix": model.name, "symmetric": model.symmetric, "gravity": gravity,
            "axial": model.symmetric and gravity == "axial",
            "idx": idx, "methods": methods, "omega_state": _omega_state(model)}


def _omega_state(model) -> bool:
    """True when the model's state starts with ω̃ (else with L = I ω̃)."""
    head = model.state_names[:3]
    if head not in (("omega1", "omega2", "omega3"), ("L1", "L2", "L3")):
        raise ValueError(f"{model.name}: expected the state to start with omega1:3 or L1:3")
    return head[0] == "omega1"


def render_splitting(model, methods: list[str] | None = None) -> dict[str, str]:
    """``<name>_splitting.h``, ``<name>_splitting.c`` and (three distinct moments) the shared
    ``derive_elliptic.h`` for an Euler–Poisson ``model``. The C includes ``<name>_solvers.h``
    (``derive_stats``, the ``DERIVE_*`` codes, the model header) and needs nothing else from
    the model: it reads the parameters by their names in ``model.param_names``."""
    names = list(METHODS) if methods is None else list(methods)
    for n in names:
        if n not in METHODS:
            raise ValueError(f"unknown splitting method {n!r}; known: {', '.join(METHODS)}")
    ctx = _context(model, names)
    files = {f"{model.name}_splitting.h": render("c/splitting.h.j2", **ctx),
             f"{model.name}_splitting.c": render("c/splitting.c.j2", **ctx)}
    if not model.symmetric:
        files["derive_elliptic.h"] = render("c/elliptic.h.j2")
    return files


# --------------------------------------------------------------------------------------------
# compiled: the splitting solvers beside the model's own


def sources(model, methods: list[str] | None = None) -> tuple[dict[str, str], str]:
    """Every C file of the model, its registered solvers and its splitting solvers, and the
    name of the one translation unit that includes the .c files."""
    from .codegen import model_sources

    files = {k[2:]: v for k, v in model_sources(model).items() if k.startswith("c/")}
    files.update(render_splitting(model, methods))
    unity = f"{model.name}_split_unity.c"
    files[unity] = "".join(f'#include "{n}"\n' for n in
                           (f"{model.name}.c", f"{model.name}_solvers.c", f"{model.name}_splitting.c"))
    return files, unity


class Splitter:
    """A compiled Euler–Poisson model with its splitting solvers (``solve``) and, as
    ``kernel`` (:class:`derive.integrate.Kernel`), the registered ones (dop853, gauss4, …)."""

    def __init__(self, model, flags=None):
        from .cbuild import DEFAULT_FLAGS, compile_library
        from .integrate import STATS_DTYPE, Kernel

        files, unity = sources(model)
        self.model = model
        self.lib = compile_library(f"{model.name}_split", files, unity,
                                   DEFAULT_FLAGS if flags is None else flags)
        self.kernel = Kernel(self.lib, model.name)
        self._stats = STATS_DTYPE
        f64 = np.ctypeslib.ndpointer(dtype=np.float64, flags="C_CONTIGUOUS")
        st = np.ctypeslib.ndpointer(dtype=STATS_DTYPE, flags="C_CONTIGUOUS")
        self._fns = {}
        for name in METHODS:
            fn = getattr(self.lib, f"{model.name}_solve_{name}")
            fn.argtypes = [f64, f64, f64, ctypes.c_long, ctypes.c_double, f64, st]
            fn.restype = ctypes.c_int
            bf = getattr(self.lib, f"{model.name}_solve_batch_{name}")
            bf.argtypes = [ctypes.c_long, f64, f64, f64, ctypes.c_long, ctypes.c_double, f64, st]
            bf.restype = ctypes.c_int
            self._fns[name] = (fn, bf)

    def solve(self, method: str, y0, p, t_out, h: float):
        """(y at every t_out, the derive_stats record) for one trajectory."""
        t = np.ascontiguousarray(t_out, dtype=np.float64)
        y = np.full((t.size, 9), np.nan)
        st = np.zeros(1, dtype=self._stats)
        self._fns[method][0](np.ascontiguousarray(y0, dtype=np.float64),
                             np.ascontiguousarray(p, dtype=np.float64), t, t.size, float(h), y, st)
        return y, st[0]

    def solve_batch(self, method: str, y0s, ps, t_out, h: float):
        """(y[b, k], stats[b]) for n_batch trajectories."""
        t = np.ascontiguousarray(t_out, dtype=np.float64)
        y0s = np.ascontiguousarray(y0s, dtype=np.float64)
        n = y0s.shape[0]
        ps = np.ascontiguousarray(np.broadcast_to(np.asarray(ps, dtype=np.float64),
                                                  (n, len(self.model.params))))
        y = np.full((n, t.size, 9), np.nan)
        st = np.zeros(max(n, 1), dtype=self._stats)
        self._fns[method][1](n, y0s, ps, t, t.size, float(h), y, st)
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


# --------------------------------------------------------------------------------------------
# measurement (reported by the bench, never asserted on time)


#: (α, β, γ) at which the fast and slow Lagrange tops of :func:`bench_case` start (from rest
#: but for their spin); :func:`_reference` starts the exact solution there too.
_TOP_START = (0.0, 0.5, 0.0)


def bench_case(case: str):
    """(model, p, y0, period) of a named benchmark body:

    ``fast-top``    Lagrange top I₁ = 1, I₃ = 0.5, M g l = 1, released at β = 0.5 from rest
                    with p_γ = 1000, so p_γ²/(I₁ M g l) = 10⁶; period: the nutation period
                    2π I₁/p_γ.
    ``lagrange``    the same top with p_γ = 10 (p_γ²/(I₁ M g l) = 100, a slow top); period
                    2π I₁/p_γ.
    ``asymmetric``  I = (1, 1.5, 2) kg m², M g = 9.81 N, r_c = (0.05, 0.02, 0.1) m, started at
                    (α, β, γ) = (0.1, 0.6, 0.2) with ω̃ = (0.3, −0.2, 12) rad/s (three distinct
                    moments: the elliptic free flow); period 2π/|ω̃₀|.
    """
    from . import models
    from .exact import euler_matrix

    if case in ("fast-top", "lagrange"):
        model = models.build("euler-poisson", True, ("gravity",))
        p_gamma = 1000.0 if case == "fast-top" else 10.0
        p = np.array([1.0, 0.5, 1.0, 9.81, 1.0 / 9.81])
        y0 = initial_state(model, p, (0.0, 0.0, p_gamma / p[1]), euler_matrix(*_TOP_START))
        return model, p, y0, 2 * np.pi * 1.0 / p_gamma
    if case == "asymmetric":
        model = models.build("euler-poisson", False, ("gravity_general",))
        p = np.array([1.0, 1.5, 2.0, 1.0, 9.81, 0.05, 0.02, 0.1])
        w0 = np.array([0.3, -0.2, 12.0])
        return (model, p, initial_state(model, p, w0, euler_matrix(0.1, 0.6, 0.2)),
                2 * np.pi / np.linalg.norm(w0))
    raise ValueError(f"unknown benchmark case {case!r}; known: fast-top, lagrange, asymmetric")


def _reference(case, model, p, y0, t, sp) -> np.ndarray:
    """(n, e) of the benchmark body at the times t, shape (len(t), 6): the exact Lagrange top
    (derive.exact.heavy_top) for the symmetric cases, else DOP853 at rtol 1e-13."""
    from .exact import heavy_top

    if case in ("fast-top", "lagrange"):
        I1, I3, M, g, l = p
        w3 = float(angular_momentum(model, p, y0)[2]) / I3
        tr = heavy_top(I1, I3, M, g, l, *_TOP_START, 0.0, 0.0, w3, t)
        return np.concatenate([tr.R[:, 2, :], tr.R[:, 0, :]], axis=1)
    return sp.kernel.solve("dop853", y0, p, t, rtol=1e-13, atol=1e-15).y[:, 3:9]


def _axis(ne: np.ndarray) -> np.ndarray:
    """The body's axis 3 in space, R ê₃ = (e₃, (n × e)₃, n₃), from (n, e) rows."""
    n, e = ne[:, 0:3], ne[:, 3:6]
    return np.stack([e[:, 2], n[:, 0] * e[:, 1] - n[:, 1] * e[:, 0], n[:, 2]], axis=1)


def bench_energy(case: str = "asymmetric", periods: float = 1e4, target: float = 1e-8,
                 methods=("splitting4", "dop853", "gauss4"), repeat: int = 3,
                 samples: int = 997, budget: float = 60.0, measure: str = "energy") -> dict:
    """Cost of each method to keep the energy error below ``target`` over ``periods`` periods
    of a :func:`bench_case` body.

    Energy error: max over the run of |E(t) − E(0)| / (M g |r_c|) — relative to the scale of the
    potential energy, the part the integrators can get wrong (a fast top's E is dominated by the
    spin energy p_γ²/(2I₃), which would hide every error). Sampled at ``samples`` + 1 equally
    spaced times (a prime, so the output grid does not resonate with the nutation; fixed-step
    methods are not forced below the step they choose). Each method's setting — the step h
    (splitting, Gauss) or rtol (DOP853, atol = rtol/100) — is scanned from cheap to expensive
    on a grid of ratio 2^(1/2), and the first setting that meets the target and whose next
    grid value meets it too (no lucky resonance) is taken; its wall time is the best of
    ``repeat`` runs. A method whose scan exceeds ``budget`` seconds is reported as None.
    ``measure`` ``"axis"`` takes instead the error of the body's axis 3 in space, max |R ê₃ −
    (R ê₃)_ref| over the samples (precession and nutation: what a top's user watches), against
    the exact solution (Lagrange tops) or DOP853 at rtol 1e-13: the trajectory, which the energy
    alone does not judge (Gauss methods keep the quadratic energy of these variables exactly
    whatever their step).
    Returns {"case", "periods", "target", method: {"setting", "error", "seconds", "nfev"},
    "ratio_dop853"} with ratio_dop853 = seconds(dop853) / seconds(splitting4).
    """
    model, p, y0, period = bench_case(case)
    sp = Splitter(model)
    _, mg_rc = body(model, p)
    scale = float(np.linalg.norm(mg_rc)) or float(abs(energy(model, p, y0)))
    t = np.linspace(0.0, periods * period, int(samples) + 1)
    e0 = float(energy(model, p, y0))
    if measure not in ("energy", "axis"):
        raise ValueError(f"measure must be 'energy' or 'axis', not {measure!r}")
    ref = _reference(case, model, p, y0, t, sp) if measure != "energy" else None

    def run(method, setting):
        t0 = time.perf_counter()
        if method in METHODS:
            y, st = sp.solve(method, y0, p, t, setting)
            ok, nfev = st["status"] == 0, int(st["nfev"])
        else:
            kw = {"rtol": setting, "atol": setting * 1e-2} if method == "dop853" else {"h": setting}
            sol = sp.kernel.solve(method, y0, p, t, check=False, **kw)
            y, ok, nfev = sol.y, sol.success, sol.nfev
        dt = time.perf_counter() - t0
        if not ok:
            err = np.inf
        elif measure == "axis":
            err = float(np.max(np.linalg.norm(_axis(y[:, 3:9]) - _axis(ref), axis=1)))
        else:
            err = float(np.max(np.abs(energy(model, p, y) - e0)) / scale)
        return err, dt, nfev

    out: dict = {"case": case, "periods": periods, "target": target, "measure": measure}
    for method in methods:
        # Fixed steps start at the output spacing (a larger h would be cut to it anyway).
        start = 1e-3 if method == "dop853" else min(64 * period, float(t[1] - t[0]))
        grid = [start * 2.0 ** (-k / 2) for k in range(80)]
        spent, found, prev = 0.0, None, None
        for setting in grid:
            err, dt, _ = run(method, setting)
            spent += dt
            if err <= target:
                if prev is not None:
                    found = prev
                    break
                prev = setting
            else:
                prev = None
            if spent > budget:
                break
        if found is None:
            out[method] = None
            continue
        runs = [run(method, found) for _ in range(repeat)]
        out[method] = {"setting": found, "error": runs[0][0],
                       "seconds": min(r[1] for r in runs), "nfev": runs[0][2]}
    base = (out.get("splitting4") or {}).get("seconds")
    sec = (out.get("dop853") or {}).get("seconds")
    out["ratio_dop853"] = sec / base if base and sec else None
    return out
