"""The symbols, slide definitions and claim types the lecture's typed formulas
(:mod:`derive.lecture.claims`) are written with: body and inertial components, the slides'
rotation matrices and definitions (I, Ω, V_eff, the assignment's passive turn), the section
titles of the notes, and the `Claim`, `Correction` and `Derived` records.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from derive.symbolic.lagrangian import I1, I2, I3, Mass, g, l, p_alpha, p_gamma
from derive.symbolic.rotations import alpha, beta, beta_d, gamma

# --- symbols of the slides -------------------------------------------------------------------
w1, w2, w3 = sp.symbols("omega1:4", real=True)             # ω̃ᵢ, body components (as in stability)
wd1, wd2, wd3 = sp.symbols("omega_d1:4", real=True)         # dω̃ᵢ/dt
W0 = sp.symbols("omega^0_1:4", real=True)                   # ω, inertial components
Lb = sp.symbols("L1:4", real=True)                          # L̃ᵢ, body components
Lbd = sp.symbols("L_d1:4", real=True)                       # (dL̃ᵢ/dt)_body
X = sp.symbols("x y z", real=True)                          # a point r, inertial components
Vx, Vy, Vz = sp.symbols("V_x V_y V_z", real=True)
A, t, phi = sp.symbols("A t varphi", real=True)
Omega, Omega1, Omega2 = sp.symbols("Omega Omega_1 Omega_2", real=True)
u, v = sp.symbols("u v", positive=True)                     # |Ω₁|, |Ω₂| in the sign cases
Veff = sp.Symbol("V_eff", real=True)
e1, e2, e3 = sp.symbols("e1 e2 e3", real=True)              # ê₁ ê₂ ê₃ (body)
e1p, e2p, e3p = sp.symbols("e1' e2' e3'", real=True)        # ê₁′ ê₂′ ê₃′ (after the α, β turns)
e30 = sp.Symbol("e3^0", real=True)                          # ê₃⁰ (inertial z)
etilde3 = sp.Symbol("etilde3", real=True)                   # the transcript's "ẽ₃": no such vector
BASIS = (e1, e2, e3)
FRAME_SYMBOLS = (e1p, e2p, e3p, e30)

# Two generic particles for the Σ_p lines.
m_p = sp.symbols("m1:3", positive=True)
r_p = tuple(sp.Matrix(sp.symbols(f"x{k} y{k} z{k}", real=True)) for k in (1, 2))
w_vec = sp.Matrix([w1, w2, w3])
half = sp.Rational(1, 2)
s, c = sp.sin, sp.cos


def psum(f):
    """Σ_p f(m_p, r_p) over the two generic particles (scalars or matrices)."""
    first, *rest = (f(m, r) for m, r in zip(m_p, r_p))
    for term in rest:
        first = first + term
    return first


def dot(a, b):
    return (a.T * b)[0, 0]


# The slides' passive elementary rotations ("Matrix representation" slides), typed as written.
def slide_Rz(x):
    return sp.Matrix([[c(x), s(x), 0], [-s(x), c(x), 0], [0, 0, 1]])


def slide_Ry(x):
    return sp.Matrix([[c(x), 0, -s(x)], [0, 1, 0], [s(x), 0, c(x)]])


# Slide definitions used by later lines (typed once, referred to by `given`).
SLIDE_I = psum(lambda m, r: m * (dot(r, r) * sp.eye(3) - r * r.T))    # I_ij ≡ Σ m (δ_ij r² − r_i r_j)
SLIDE_OMEGA = w3 * (I3 - I1) / I1                                       # Ω ≡ ω̃₃ (I₃ − I₁)/I₁
SLIDE_OMEGA1 = w3 * (I3 - I2) / I1                                      # Ω₁ ≡ ω̃₃ (I₃ − I₂)/I₁
SLIDE_OMEGA2 = w3 * (I3 - I1) / I2                                      # Ω₂ ≡ ω̃₃ (I₃ − I₁)/I₂
SLIDE_VEFF = (p_alpha - p_gamma * c(beta)) ** 2 / (2 * I1 * s(beta) ** 2) + Mass * g * l * c(beta)
SLIDE_L_BETA = (half * I1 * beta_d**2 + (p_alpha - p_gamma * c(beta)) ** 2 / (2 * I1 * s(beta) ** 2)
                + p_gamma**2 / (2 * I3) - Mass * g * l * c(beta))
ASSIGNMENT_ANGLES = {alpha: sp.pi / 2, beta: sp.pi / 2, gamma: 0}       # α = 90°, β = 90°, γ = 0°
SLIDE_PASSIVE = slide_Rz(gamma) * slide_Ry(beta) * slide_Rz(alpha)      # components in the turned axes


@dataclass(frozen=True)
class Derived:
    """A reference to a derived quantity (entry ``index`` of it, if given) of `derive.lecture.targets`."""

    name: str
    index: int | None = None


@dataclass(frozen=True)
class Correction:
    """The corrected form of a slip: a new expression, or the same one claimed to equal another
    derived quantity (a wrong label), or both."""

    latex: str
    expr: object = None
    target: str | None = None


@dataclass(frozen=True)
class Claim:
    """One formula of the slides (see the module docstring for the fields).

    ``mode`` says how ``expr`` is compared with the derived quantity:
    ``"equal"`` — the two are equal (matrices entrywise, relations as lhs − rhs ≥ 0);
    ``"solves"`` — ``expr`` lists functions of ``time`` for the ``states`` and the target is the
    right-hand side f(states) of an ODE: the claim holds if d(expr)/dt = f(expr);
    ``"beta-lagrangian"`` — ``expr`` is used as a Lagrangian in (β, β̇) and the β̈ of its
    Euler–Lagrange equation is compared with the target;
    ``"sign"`` — ``expr`` (±1) is the sign the slide asserts for the target (a qualitative claim).
    """

    id: str
    section: str
    quote: str
    latex: tuple
    expr: object
    target: str
    note: str = ""
    given: dict = field(default_factory=dict)
    cases: tuple = ({},)
    correction: Correction | None = None
    mode: str = "equal"
    states: tuple = ()
    time: object = None


S_SUMMARY = "Summary of previous results describing rigid bodies rotating about a fixed origin"
S_INERTIA = "Moment of inertia tensor Matrix notation:"
S_CONTINUED = "Continued -- summary of previous results describing rigid bodies rotating about a fixed origin"
S_DESCR = "Descriptions of rotation about a given origin -- continued"
S_TORQUE = "Descriptions of rotation about a given origin -- continued Note that the torque equation"
S_EULER = "Euler equations for rotation in body fixed frame:"
S_SYM = "Solution for symmetric top $--I_2 = I_1$ :"
S_SYM2 = "Solution of Euler equations for a symmetric top -- continued"
S_ASYM = "Solution for asymmetric top --  $I_3 \\neq I_2 \\neq I_1$ :"
S_ASYM2 = "Euler equations for asymmetric top -- continued"
S_ANGLES = "Transformation between body-fixed and inertial coordinate systems – Euler angles"
S_T = "Rotational kinetic energy"
S_TOP = "Motion of a symmetric top under the influence of the torque of gravity:"
S_STAB = "Stable/unstable solutions near β=0"
S_CONST = "#### Constants of the motion:"
S_ASSIGN = "PHY 711 -- Assignment #20"

OMEGA_SYM_CASE = {I2: I1}
SYM_SOLUTION = {w1: A * c(Omega * t + phi), w2: A * s(Omega * t + phi)}
ROOT = sp.sqrt(Omega1 * Omega2)
SAME_SIGN_CASES = ({Omega1: u, Omega2: v}, {Omega1: -u, Omega2: -v})
OPPOSITE_SIGN_CASES = ({Omega1: u, Omega2: -v}, {Omega1: -u, Omega2: v})
DUP_NOTE = "the transcript repeats this display"
