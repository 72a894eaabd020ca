"""The model of `derive.lecture.vector_algebra`: its symbols (𝛚, 𝛚̇, one point mass, the body's
three mass points), rigid rotation (d/dt with ṙ = 𝛚 × 𝐫), the system's 𝐋, 𝐈, 𝐩 and torque, the
text rewrites the scanner needs, the products of its values and the zero test.
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass, field

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.vector_models import _is_tensor, _is_vector

POINTS = 3
W = sp.Matrix(sp.symbols("omega_x omega_y omega_z", real=True))
WD = sp.Matrix(sp.symbols("alpha_x alpha_y alpha_z", real=True))          # 𝛚̇
M0 = sp.Symbol("m", positive=True)
R0 = sp.Matrix(sp.symbols("x y z", real=True))
MU = sp.symbols(f"mu_1:{POINTS + 1}", positive=True)
RK = [sp.Matrix(sp.symbols(f"x_{k} y_{k} z_{k}", real=True)) for k in range(1, POINTS + 1)]
E = sp.eye(3)
AXIS = {"x": 0, "y": 1, "z": 2, "1": 0, "2": 1, "3": 2}
UNIT = {"i": 0, "j": 1, "k": 2, "x": 0, "y": 1, "z": 2}
TORQUES = ("tau", "Gamma")
_INT = re.compile(r"\\int(?:\s*\\limits)?(?:\s*_\s*(?:\{(?:[^{}]|\{[^{}]*\})*\}|\\[A-Za-z]+|[^\s\\]))?")
_LECTURE = re.compile(r"_\s*\{?\s*p\b|\\sum_\{?\s*p|\\ddot\s*\{?\s*\\?(?:mathbf|boldsymbol)?\s*\{?\s*I|\\tilde|"
                      r"\\widetilde|\\hat\s*\{?\s*\\?(?:mathbf|boldsymbol)?\s*\{?\s*e\b|_\{?\s*(?:body|inertial|space|rot)")
INTEGRAL = "Lambda"                  # the marker ∫ is read as (a bold Λ, which no text here writes)
# a macro's bold letter in braces, {\boldsymbol L}_i: the letter with its subscript
_BOLD_GROUP = re.compile(r"\{\s*\\(?:boldsymbol|mathbf|bm)\s*(\\[A-Za-z]+|[A-Za-z])\s*\}")
_HAT_GROUP = re.compile(r"\{\s*\\hat\s*\{\s*\\(?:boldsymbol|mathbf|bm)\s*(\\[A-Za-z]+|[A-Za-z])\s*\}\s*\}")


def prepare(text: str) -> str:
    """The rewrites the scanner needs: ∫ (with its limits) as a marker symbol, ⊗ as a juxtaposition
    (the dyadic), ı and ȷ as i and j."""
    text = _INT.sub(r" \\mathbf{\\" + INTEGRAL + "} ", text)
    text = _HAT_GROUP.sub(r"\\hat{\\boldsymbol{\1}}", text)
    text = _BOLD_GROUP.sub(r"\\boldsymbol{\1}", text)
    text = text.replace("\\otimes", " ").replace("\\imath", "i").replace("\\jmath", "j")
    return text


def lecture_notation(text: str) -> bool:
    """Whether a statement is in the lecture's own vector notation (m_p, Σ_p, Ï, ω̃, ê_i, frames),
    which `derive.lecture.vectors` reads."""
    return bool(_LECTURE.search(text))


def markers(text: str, bold: bool = False) -> bool:
    """Whether a statement is written in this module's notation: ∫ dm, ⊗, a determinant, a matrix,
    a cross product, a sum over particles, unit vectors x̂ ı̂ (and, with ``bold``, any bold vector)."""
    if bold and re.search(r"\\(?:boldsymbol|mathbf|pmb|bm|vec)\b", text):
        return True
    return bool(re.search(r"\\int|\\otimes|vmatrix|bmatrix|\\times|\\imath|\\jmath|\\sum", text))


@dataclass
class State:
    """What the reader keeps from one statement to the next of a text."""

    system: str = "body"                            # "body" or "single"
    torques: set = field(default_factory=lambda: set(TORQUES))
    defs: dict = field(default_factory=dict)        # (base, sub) → the text's value of an entry
    head: str | None = None                         # the left side this reader last set


@dataclass
class Member:
    value: object
    start: int
    end: int
    skip: str = ""                                  # why it is not compared (a force inside a product)
    generics: frozenset = frozenset()
    literal: object = None                          # the matrix as written, when the member is one
    law: bool = False                               # a torque or a force in it
    rated: bool = False                             # a time derivative in it (d/dt, a dot, 𝛂)


@dataclass
class Reading:
    members: list                                   # one list of Member per value of the free indices
    relations: list
    free: str
    source: str
    system: str


def rate(e):
    """d/dt under rigid rotation: ṙ = 𝛚 × 𝐫 for every point, 𝛚̇ = 𝛂; the masses are constant."""
    if isinstance(e, sp.MatrixBase):
        return e.applyfunc(rate)
    e = sp.sympify(e)
    if e.free_symbols & set(WD):
        raise lx.NotRead("a second time derivative of 𝛚")
    if any(s.name.endswith(("_x", "_y", "_z")) and s not in set(W) for s in e.free_symbols):
        raise lx.NotRead("the rate of a vector the text has not tied to the body")
    out = sp.S.Zero
    for r in [R0, *RK]:
        v = W.cross(r)
        out += sum(sp.diff(e, r[i]) * v[i] for i in range(3))
    out += sum(sp.diff(e, W[i]) * WD[i] for i in range(3))
    return out


@functools.lru_cache(maxsize=None)
def momentum(system: str) -> sp.ImmutableMatrix:
    """𝐋 = Σ m 𝐫 × (𝛚 × 𝐫) of the system (one point mass, or the body's points)."""
    return sp.ImmutableMatrix(_momentum(system))


@functools.lru_cache(maxsize=None)
def torque(system: str) -> sp.ImmutableMatrix:
    """d𝐋/dt under rigid rotation."""
    return sp.ImmutableMatrix(rate(momentum(system)).applyfunc(sp.expand))


def _momentum(system: str) -> sp.Matrix:
    if system == "single":
        return M0 * R0.cross(W.cross(R0))
    return sum((MU[k] * RK[k].cross(W.cross(RK[k])) for k in range(POINTS)), sp.zeros(3, 1))


@functools.lru_cache(maxsize=None)
def tensor(system: str) -> sp.ImmutableMatrix:
    """𝐈 = ∂𝐋/∂𝛚 of the system."""
    return sp.ImmutableMatrix(momentum(system).jacobian(W).applyfunc(sp.expand))


@functools.lru_cache(maxsize=None)
def linear(system: str) -> sp.ImmutableMatrix:
    """𝐩 = Σ m 𝛚 × 𝐫 of the system."""
    if system == "single":
        return sp.ImmutableMatrix(M0 * W.cross(R0))
    return sp.ImmutableMatrix(sum((MU[k] * W.cross(RK[k]) for k in range(POINTS)), sp.zeros(3, 1)))


def _as_value(v):
    if isinstance(v, sp.MatrixBase) and v.shape == (1, 1):
        return v[0, 0]
    return v


def _juxt(a, b):
    a, b = _as_value(a), _as_value(b)
    ma, mb = isinstance(a, sp.MatrixBase), isinstance(b, sp.MatrixBase)
    if ma and mb:
        if _is_vector(a) and _is_vector(b):
            return a * b.T                          # the dyadic 𝐚𝐛
        if a.shape[1] != b.shape[0]:
            raise lx.NotRead("a product of shapes that do not conform")
        return _as_value(a * b)
    return a * b


def _dot(a, b):
    a, b = _as_value(a), _as_value(b)
    if _is_vector(a) and _is_vector(b):
        return a.dot(b)
    if _is_tensor(a) and _is_vector(b):
        return a * b
    if _is_vector(a) and _is_tensor(b):
        return b.T * a
    return _juxt(a, b)


def _determinant(rows):
    """A 3×3 determinant, expanded along a row of vectors when it has one (the cross product's form)."""
    if len(rows) != 3 or any(len(r) != 3 for r in rows):
        raise lx.NotRead("a determinant that is not 3×3")
    vec = [n for n, r in enumerate(rows) if any(isinstance(x, sp.MatrixBase) for x in r)]
    if not vec:
        return sp.Matrix(rows).det()
    if len(vec) != 1:
        raise lx.NotRead("a determinant with vectors in two rows")
    n = vec[0]
    total = sp.zeros(3, 1)
    for j in range(3):
        minor = sp.Matrix([[rows[a][b] for b in range(3) if b != j] for a in range(3) if a != n])
        if any(isinstance(x, sp.MatrixBase) for x in minor):
            raise lx.NotRead("a determinant of vectors")
        total += (-1) ** (n + j) * minor.det() * rows[n][j]
    return total


def difference(a, b):
    """a − b expanded, entry by entry; None when the shapes differ."""
    a, b = _as_value(a), _as_value(b)
    if isinstance(a, sp.MatrixBase) != isinstance(b, sp.MatrixBase):
        return None
    if isinstance(a, sp.MatrixBase):
        if a.shape != b.shape:
            return None
        return (a - b).applyfunc(_zeroed)
    return _zeroed(a - b)


def _zeroed(d):
    d = sp.expand(d)
    if d != 0 and any(not p.exp.is_Integer for p in d.atoms(sp.Pow)):
        d = sp.simplify(d)          # |𝛚| and 𝛚̂: a polynomial's expansion is already canonical
    return d
