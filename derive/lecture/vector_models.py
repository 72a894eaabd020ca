"""The three models of the vector reader (`derive.lecture.vectors`): what 𝐫, 𝐯, 𝐋, Ï, T and ω
stand for in a statement about particles, about body principal axes or about a rotating frame
(`Model`), which model a statement is read in (`model_of`), whether a display is one for the
vector reader (`vectorish`) and the text rewrites it needs first (`prepare`).
"""
from __future__ import annotations

import functools
import re

import sympy as sp

from derive.lecture import latex as lx
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3
from derive.symbolic.rotations import ANGLES, RATES, time_derivative

PARTICLES = 2
M_P = sp.symbols(f"m_p1:{PARTICLES + 1}", positive=True)
R_P = [sp.Matrix(sp.symbols(f"x_p{k} y_p{k} z_p{k}", real=True)) for k in range(1, PARTICLES + 1)]
R_B = sp.Matrix(sp.symbols("x_b y_b z_b", real=True))          # a body-fixed point 𝐫
L_B = sp.Matrix(sp.symbols("L_b1:4", real=True))               # 𝐋's body components (time-dependent)
LD_B = sp.Matrix(sp.symbols("Ld_b1:4", real=True))             # their rates
W = sp.Matrix(lx.W)
AXES = {"x": 0, "y": 1, "z": 2, "1": 0, "2": 1, "3": 2}
FRAMES = {"body": "body", "b": "body", "rot": "body", "rotating": "body", "inertial": "inertial",
          "space": "inertial", "fixed": "inertial", "lab": "inertial", "s": "inertial"}
_UNIT = re.compile(r"\\(?:mathbf|mathbb|boldsymbol|bm)\s*\{\s*(?:\\(?:mathbb|mathbf)\s*\{\s*)?1\s*\}(?:\s*\})?")


class _Law:
    """τ as a whole side: the law of motion d𝐋/dt = τ."""


LAW = _Law()


class _FreeIndex(Exception):
    def __init__(self, letter):
        super().__init__(letter)
        self.letter = letter


def _is_tensor(v) -> bool:
    return isinstance(v, sp.MatrixBase) and v.shape == (3, 3)


def _is_vector(v) -> bool:
    return isinstance(v, sp.MatrixBase) and v.shape == (3, 1)


# ---- the models -----------------------------------------------------------------------------------
class Model:
    """What the symbols of one statement stand for (see the module docstring)."""

    def __init__(self, name: str, derivation=None):
        self.name, self.d = name, derivation

    # particle references
    def velocity(self, k):
        return W.cross(R_P[k])

    @functools.cached_property
    def kinetic(self):
        if self.name == "principal":
            return sp.Rational(1, 2) * sum(m * w**2 for m, w in zip(self.moments, lx.W))
        return sum(sp.Rational(1, 2) * M_P[k] * self.velocity(k).dot(self.velocity(k)) for k in range(PARTICLES))

    @property
    def moments(self):
        return (I1, I2, I3)

    @functools.cached_property
    def tensor(self) -> sp.Matrix:
        if self.name == "principal":
            return sp.diag(*self.moments)
        return sp.hessian(self.kinetic, list(lx.W)).applyfunc(sp.expand)

    @functools.cached_property
    def momentum(self) -> sp.Matrix:
        if self.name == "principal":
            return sp.Matrix([m * w for m, w in zip(self.moments, lx.W)])
        if self.name == "frame":
            return L_B
        return sum((M_P[k] * R_P[k].cross(self.velocity(k)) for k in range(PARTICLES)), sp.zeros(3, 1))

    @property
    def omega(self) -> sp.Matrix:
        if self.name == "frame":
            return sp.Matrix(self.d.omega)
        return W

    # frame derivatives
    def dt(self, e):
        """d/dt of an expression in the angles, rates and 𝐋's body components (the
        derivation's chain rule, with 𝐋's components as three more coordinates)."""
        return time_derivative(e, coords=(*ANGLES, *L_B), rates=(*RATES, *LD_B), accels=ACCELS)

    def derivative(self, X: sp.Matrix, frame: str) -> sp.Matrix:
        """Body components of (dX/dt) in the inertial frame (Rᵀ d(R X)/dt) or the body frame (Ẋ)."""
        Xd = X.applyfunc(self.dt)
        if frame == "body":
            return Xd
        R = self.d.conv.matrix()
        return R.T * (R.applyfunc(self.dt) * X) + Xd


def model_of(toks, sticky: str | None) -> str:
    """frame (a time derivative of a vector), principal (I₁ I₂ I₃, I_i or ê_i), particle (m_p,
    𝐫_p, 𝐯_p, δ_ij, 𝟙, I_ij, Σ_p, or a particle statement earlier in the section), else principal."""
    atoms = [t.value for t in toks if t.kind == "atom"]
    if any(t.kind == "cmd" and t.value == "frac" for t in toks) and _has_time_derivative(toks):
        return "frame"
    if any(a.base == "I" and len(a.sub) == 1 for a in atoms) or any(a.base == "e" and (a.hat or a.bold) for a in atoms):
        return "principal"
    if any(_particle_atom(a) for a in atoms) or any(a.base == "I" and len(a.sub) == 2 for a in atoms):
        return "particle"
    return sticky or "principal"


def _particle_atom(a) -> bool:
    return (a.base in ("m", "r", "v") and a.sub[:1] == "p") or a.base == "delta" or (a.base == "Xi" and a.bold)


def _has_time_derivative(toks) -> bool:
    for k in range(len(toks) - 6):
        w = toks[k:k + 7]
        if w[0].kind == "cmd" and w[0].value == "frac" and w[2].kind == "atom" and w[2].value.base == "d" \
                and w[3].kind == "atom" and w[3].value.bold:
            return True
    return False


def vectorish(toks) -> bool:
    """Whether a statement is for this reader: a cross product, a tensor, a sum over particles,
    a particle quantity or a time derivative of a vector."""
    for t in toks:
        if t.kind == "cmd" and t.value == "times":
            return True
        if t.kind == "atom":
            a = t.value
            if _particle_atom(a) or (a.base == "I" and (a.bold or a.dots == 2 or len(a.sub) == 2)):
                return True
    return _has_time_derivative(toks)


_INDEX = r"(\\[A-Za-z]+|[A-Za-z])"
_SUMMED = re.compile(r"\\sum\s*_\s*(?:\{\s*" + _INDEX + r"\s*\}|" + _INDEX + r")")


def _particle_index(text: str) -> str | None:
    """The letter a text sums its particles over (Landau's α of ``\\sum_\\alpha m_\\alpha``): summed,
    and the index of a mass m. None when it is p already or a body axis (i, j, k)."""
    for m in _SUMMED.finditer(text):
        x = m.group(1) or m.group(2)
        if x in ("i", "j", "k", "p"):
            continue
        if re.search(r"(?<![A-Za-z\\])m\s*_\s*(\{\s*" + re.escape(x) + r"\s*\}|" + re.escape(x) + r"(?![A-Za-z]))", text):
            return x
    return None


def prepare(text: str) -> str:
    """𝟙 (``\\mathbf{1}``, ``\\mathbb{1}``) as a symbol the scanner reads; ``\\overleftrightarrow``
    (the dyadic arrow) as bold; the text's particle index (``m_{\\alpha}``, ``r_{\\alpha ,i}``,
    ``\\sum_{\\alpha}``) as p."""
    text = _UNIT.sub(r"\\mathbf{\\Xi}", text)
    x = _particle_index(text)
    if x is not None:
        x = re.escape(x) + (r"(?![A-Za-z])" if x.startswith("\\") else "")
        text = re.sub(r"_\s*\{\s*" + x + r"\s*,?\s*([ijkxyz123])?\s*\}", lambda m: "_{p" + (m.group(1) or "") + "}", text)
        text = re.sub(r"_\s*" + x, "_{p}", text)
    return text.replace("\\overleftrightarrow", "\\mathbf")
