"""Vector algebra as textbooks write it: components, matrices, sums over particles and integrals over the mass.

`derive.lecture.vectors` reads the lecture's own vector notation (m_p, 𝐫_p, Σ_p, Ï, ê_i). Texts
that derive the inertia tensor write the same physics another way: a point mass m at 𝐫 = x x̂ + y ŷ
+ z ẑ, 𝐋 = 𝐫 × 𝐩 with 𝐯 = 𝛚 × 𝐫, ω_x ω_y ω_z, a ``bmatrix`` acting on a column, a determinant with
unit vectors in its first row, Σᵢ mᵢ over particles, ∫ … dm over the body, I_xx = ∫(y² + z²) dm,
𝐓 = d𝐋/dt. This module is the model such a statement is read in, derived from first principles
(`Algebra`: its symbols, rigid rotation, 𝐋, 𝐈, 𝐩, the torque; the text rewrites; `read`); the
grammar of `derive.lecture.vector_parser` reads the statement into SymPy under it (scalars,
3-vectors as 3×1 matrices, tensors as 3×3 matrices) through the scanner's whitelist:

* **the system.** A statement with a sum over particles or an integral over the mass speaks of a
  body: three generic mass points μ_k at 𝐫_k = (x_k, y_k, z_k) (Σᵢ and ∫ dm are both linear in
  the summand, so an identity for generic points is the identity, and three points keep a formula
  that is not linear in the sum from passing). Inside the sum or integral x, y, z, 𝐫 and r are
  the current point's (xᵢ, 𝐫ᵢ, mᵢ with the sum's index too). A statement with a plain m and no
  sum speaks of one point mass m at 𝐫 = (x, y, z) (𝐫ᵢ, mᵢ outside a sum: "the particle in
  question"). Otherwise the system of the previous statement.
* **rigid rotation.** Every point moves with 𝐯 = 𝛚 × 𝐫; 𝐩 = m𝐯; 𝐋 = Σ m 𝐫 × (𝛚 × 𝐫); the
  inertia tensor is 𝐈 = ∂𝐋/∂𝛚 (so 𝐋 = 𝐈𝛚 however a text writes 𝐈); I_xx, I_xy, I_ij are its
  entries, I_𝛚 = 𝛚̂ᵀ𝐈𝛚̂ the moment about the axis of 𝛚, L_x a component of 𝐋, L_𝛚 = 𝐋·𝛚̂.
* **time derivatives.** d/dt moves each point by ṙ = 𝛚 × 𝐫 and 𝛚 by 𝛚̇ = 𝛂 (generic): the
  torque (τ, Γ, or a letter the text sets equal to 𝐫 × 𝐅) is d𝐋/dt and the force 𝐅 is d𝐩/dt —
  the laws of motion, the starting point — so 𝐓 = 𝐈𝛂 is compared with d(𝐈𝛚)/dt = 𝐈𝛂 + 𝛚 × 𝐈𝛚.
* **generic vectors.** Any other bold letter 𝐚 is a generic vector (a_x, a_y, a_z); a relation
  is an identity for all of them only if both sides involve the same ones.

Products, matrices, determinants and transposes are the grammar's (`derive.lecture.vector_parser`).
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass, field

import sympy as sp

from derive.lecture import kane_notation
from derive.lecture import mass_elements
from derive.lecture import latex as lx
from derive.lecture.latex_spaces import SPACE
from derive.lecture.latex_spellings import BOLD, BOLD_MARK, VECTOR_MARK
from derive.lecture import point_labels
from derive.lecture import vector_parser as vp
from derive.lecture import zero_test as zt
from derive.lecture.vector_parser import AXES, INTEGRAL, _as_value

POINTS = 3
W = sp.Matrix(sp.symbols("omega_x omega_y omega_z", real=True))
WD = sp.Matrix(sp.symbols("alpha_x alpha_y alpha_z", real=True))          # 𝛚̇
M0 = sp.Symbol("m", positive=True)
R0 = sp.Matrix(sp.symbols("x y z", real=True))
MU = sp.symbols(f"mu_1:{POINTS + 1}", positive=True)
RK = [sp.Matrix(sp.symbols(f"x_{k} y_{k} z_{k}", real=True)) for k in range(1, POINTS + 1)]
E = sp.eye(3)
DENSITY = sp.Symbol("rho", positive=True)
UNIT = {"i": 0, "j": 1, "k": 2, "x": 0, "y": 1, "z": 2}
TORQUES = ("tau", "Gamma")
FRAME_LETTERS = frozenset("abcdghkmnost")
"""Letters whose hatted 1, 2, 3 (b̂₁, n̂₂) are a frame's unit vectors, in a statement with no rate;
r̂ᵢ, v̂ᵢ, ûᵢ name directions of their own, and the body's ê_i turn with it (`derive.lecture.vectors`)."""


def _has_rate(toks) -> bool:
    """A dot or a d/dt among a statement's tokens."""
    return any(t.kind == "atom" and (t.value.dots or t.value.base == "d") or t.kind == "cmd" and t.value == "partial"
               for t in toks)
TORQUE_LABELS = re.compile(r"g|grav(?:ity)?|weight|W|ext|e|net|tot(?:al)?")
"""Subscripts that name where a torque comes from, not a component: 𝛕_g (the weight's), 𝛕_ext."""


def labelled_torque(sub: str) -> bool:
    """Whether a torque letter's subscript labels it (``g``, ``\\text{ext}``) rather than indexing it."""
    return TORQUE_LABELS.fullmatch(re.sub(r"^(?:text|mathrm|rm)", "", sub)) is not None
_LECTURE = re.compile(r"_\s*\{?\s*p\b|\\sum_\{?\s*p|\\ddot\s*\{?\s*(?:" + BOLD + r")?\s*\{?\s*I|\\tilde|"
                      r"\\widetilde|\\hat\s*\{?\s*(?:" + BOLD + r")?\s*\{?\s*e\b|_\{?\s*(?:body|inertial|space|rot)")
_ROT_NAME = re.compile(r"\s*[A-Za-z]\s*_\s*\{?\s*rot[a-z]*\s*\}?\s*=")
"""A name labelled as the rotational part opening the statement, ``T_{rot} =``."""
# a macro's bold letter in braces, {\boldsymbol L}_i: the letter with its subscript
_BOLD_GROUP = re.compile(r"\{\s*" + BOLD_MARK + r"\s*(\\[A-Za-z]+|[A-Za-z])\s*\}")
# a period between a vector and the next operand, (\vec{a}.\vec{c}): the dot product, not a sentence's end
_DOT_AS_PERIOD = re.compile(r"(?<=[}\)])\s*\.\s*(?=\\(?:vec|hat|boldsymbol|mathbf|bm|left)\b|\()")
POINT_LABELS = ("cm", "CM", "com", "G", "O", "C")
"""Subscripts that name the point moments are taken about (𝐇_cm, 𝐇_G, 𝐫_{/cm}): the point the
positions are measured from, the origin of this model."""
_POINT_SUPERSCRIPT = re.compile(r"\^\s*\{\s*(?:" + "|".join(POINT_LABELS) + r")\s*\}")
_DOTLESS = re.compile(r"([A-Za-z])?\\([ij])math(?![A-Za-z])")
"""ı, ȷ: i and j, set apart from a command written before them unbraced (``\\hat\\imath`` is î)."""
# an accent over a bold letter written without braces, \dot{\boldsymbol\omega}: the accent over the bold letter
_ACCENTED_BOLD = re.compile(r"\\(dot|ddot)\s*\{\s*\\(boldsymbol|mathbf|bm)\s*(\\[A-Za-z]+|[A-Za-z])\s*\}")
_HAT_GROUP = re.compile(r"\{\s*\\hat\s*\{\s*" + BOLD_MARK + r"\s*(\\[A-Za-z]+|[A-Za-z])\s*\}\s*\}")




_MOMENTUM_ELEMENT = re.compile(r"(?:\\mathrm\s*\{?\s*d\s*\}?|\bd)\s*" + BOLD_MARK + r"\s*\{?\s*p\s*\}?(?![A-Za-z_])")


_UNIT_TENSOR = re.compile(BOLD_MARK + r"\s*\{?\s*e\s*\}?(?![A-Za-z_{])(?!\s*_)")
# the unit tensor written as a one (\one, \mathbb{1}, \mathbf{1}) or as the identity of size 3 (I_3, I_{3×3}, 𝟙₃),
# and the dyadic 𝐫𝐫 (a bold letter twice in a row)
_UNIT_ONE = re.compile(r"\\one(?![A-Za-z])|(?:\\(?:mathbb|mathds|mathrm)|" + BOLD_MARK + r")\s*\{\s*1\s*\}(?!\s*[_^])|"
                       r"(?:(?:\\(?:mathbb|mathds|mathrm)|" + BOLD_MARK + r")\s*\{\s*[I1]\s*\}|(?<![A-Za-z\\])[I1])"
                       r"\s*_\s*(?:3|\{\s*3\s*(?:(?:\\times|\\cdot|x)\s*3\s*)?\})")
_DYADIC = re.compile(r"\{?\s*" + VECTOR_MARK + r"\s*\{?\s*(\\?[A-Za-z]+)\s*\}?\s*\}?\s*\{?\s*" + VECTOR_MARK + r"\s*\{?\s*\1(?![A-Za-z])\s*\}?(?!\s*_)")


_PART_LABEL = re.compile(r"(\\vec\s*\{?\s*a\s*\}?\s*_\s*(?:\{[^{}]*\}|[A-Za-z0-9]))\s*\^\s*\{?\s*([tn])\s*\}?(?![A-Za-z{])")
"""An acceleration's t or n written as a superscript after its subscript (𝐚ᵢᵗ, ``\\vec a_i^t``): the label
of its tangential or normal part, never a power or a transpose (t is written τ for the scanner, which
takes a bold symbol's ^t for a transpose)."""


_MOMENT_OF = re.compile(r"M\s*_\s*\{?\s*([xyz])\s*\}?" + SPACE + r"(?:\\(?:left|bigl|Bigl|big|Big)\s*)?\(\s*"
                        r"(\\vec\s*\{?\s*F\s*\}?\s*(?:_\s*(\{[^{}]*\}|[A-Za-z0-9]))?)\s*"
                        r"(?:\\(?:right|bigr|Bigr|big|Big)\s*)?\)")
"""M_z(𝐅ᵢ), the moment of a force about an axis, its argument in plain or sized brackets, spaced
or not (``M_z \\left(\\vec F_i\\right)``, ``M_z \\; (\\vec F_i)``; never across a quad, which ends a statement):
(𝐫ᵢ × 𝐅ᵢ)_z, 𝐫ᵢ the point the force acts at."""


def prepare(text: str) -> str:
    text = kane_notation.rewrite(text)
    return _prepare(text)


def _prepare(text: str) -> str:
    """The rewrites the scanner needs: ∫ (with its limits) as a marker symbol, ⊗ as a juxtaposition
    (the dyadic), ı and ȷ as i and j, a period between two vectors as their dot product
    ((𝐚.𝐜)𝐛), a point's label written as a superscript (I_xx^{cm}) dropped, an acceleration's
label t, n braced (𝐚ᵢᵗ as 𝐚ᵢ^τ), the moment of a force about an axis M_z(𝐅ᵢ) as (𝐫ᵢ × 𝐅ᵢ)_z, ρ … dV as dm (and
    under a sum a piece's Δmᵢ and ρᵢ … ΔVᵢ as mᵢ), the
    momentum element d𝐩 as 𝐯 dm, beside a dyadic 𝐞 or a one as the unit tensor, and an accent over a bold
    letter written without braces (``\\dot{\\boldsymbol\\omega}``) as over the braced letter."""
    text = _DOT_AS_PERIOD.sub(r" \\cdot ", text)
    text = _POINT_SUPERSCRIPT.sub("", text)
    text = _MOMENT_OF.sub(lambda m: f"(\\vec r{'_' + m.group(3) if m.group(3) else ''} \\times {m.group(2)})_{m.group(1)}", text)
    text = _PART_LABEL.sub(lambda m: m.group(1) + ("^{\\tau}" if m.group(2) == "t" else "^{n}"), text)
    text = _MOMENTUM_ELEMENT.sub(r" \\boldsymbol{v} \\, dm", text) if "\\int" in text else text
    if "\\otimes" in text or _DYADIC.search(text):    # beside a dyadic, a one (and beside ⊗ a bold e) is the unit tensor
        text = _UNIT_ONE.sub(r" \\mathrm{I} ", _UNIT_TENSOR.sub(r"\\mathrm{I}", text) if "\\otimes" in text else text)
    text = mass_elements.mass_element(mass_elements.pieces(text) if "\\sum" in text else text)
    text = mass_elements.INTEGRAL_SIGN.sub(r" \\mathbf{\\" + INTEGRAL + "} ", text)
    text = _ACCENTED_BOLD.sub(r"\\\1{\\\2{\3}}", text)
    text = _HAT_GROUP.sub(r"\\hat{\\boldsymbol{\1}}", text)
    text = _BOLD_GROUP.sub(r"\\boldsymbol{\1}", text)
    text = _DOTLESS.sub(lambda m: (m[1] + " " if m[1] else "") + m[2], text.replace("\\otimes", " "))
    return text


def lecture_notation(text: str) -> bool:
    """Whether a statement is in the lecture's own vector notation (m_p, Σ_p, Ï, ω̃, ê_i, frames),
    which `derive.lecture.vectors` reads; an integral over the mass, which that reader does not read,
    under a name labelled as the rotational part (T_rot = ½ ∫ ṙ·ṙ dm) is this module's."""
    marks = _LECTURE.findall(text)
    return bool(marks) and not ("\\int" in text and _ROT_NAME.match(text) and len(marks) == 1)


def markers(text: str, bold: bool = False) -> bool:
    """Whether a statement is written in this module's notation: ∫ dm, ⊗, a determinant, a matrix,
    a cross product, a sum over particles, unit vectors x̂ ı̂ (and, with ``bold``, any bold vector)."""
    if bold and re.search(r"\\(?:boldsymbol|mathbf|pmb|bm|vec)\b", text) or kane_notation.kane(text):
        return True
    return bool(re.search(r"\\int|\\otimes|vmatrix|bmatrix|\\times|\\imath|\\jmath|\\sum", text))


@dataclass
class State:
    """What the reader keeps from one statement to the next of a text."""

    system: str = "body"                            # "body" or "single"
    torques: set = field(default_factory=lambda: set(TORQUES))
    defs: dict = field(default_factory=dict)        # (base, sub) → the text's value of an entry
    head: str | None = None                         # the left side this reader last set
    products: bool = False                          # I_xy names the product of inertia +∫xy dm
    entries: bool = False                           # the text wrote I_ij = … in index form: I_xy is the entry
    momenta: frozenset = frozenset()                # the letters the text names the angular momentum (𝐇)
    places: frozenset = frozenset()                 # the letters the text names a position (𝐩ᴺ), not a momentum
    named: dict = field(default_factory=dict)       # a letter the text set to an expression here (K = Σ ½ m v²)
    named_by: dict = field(default_factory=dict)    # the statement that set it
    axis: int | None = None                         # the fixed axis of rotation a text set (𝛚 = ω k̂)
    radial: str = "origin"                          # a plain r: the distance from the origin, or from the axis


_MINUS_PRODUCT = re.compile(r"(?:&|\\\\|matrix\}|\{ccc\})\s*-\s*I_\s*\{?\s*(?:\\(?:text|mathrm|textrm|rm)\s*\{\s*)?"
                            r"([xyz])\s*,?\s*([xyz])")
"""−I_xy off an inertia matrix's diagonal, its index also set upright (``-I_\\text{xy}``, ``-I_{\\mathrm{xy}}``)."""


def products_of_inertia(body: str) -> bool:
    """Whether a text writes its inertia matrix with −I_xy off the diagonal: then its I_xy, I_xz,
    I_yz are the products of inertia +∫ x y dm (the engineering convention), the tensor's entry
    being −I_xy; otherwise I_xy is the tensor's entry −∫ x y dm (the physicists' convention)."""
    return any(a != b for a, b in _MINUS_PRODUCT.findall(body))


def rate(e):
    """d/dt under rigid rotation: ṙ = 𝛚 × 𝐫 for every point, 𝛚̇ = 𝛂; the masses are constant.
    The system's 𝐋 gives its `torque` (derived once)."""
    if isinstance(e, sp.MatrixBase):
        system = next((s for s in ("single", "body") if e == momentum(s)), None)
        return torque(system) if system else e.applyfunc(rate)
    return _rate(sp.sympify(e))


@functools.lru_cache(maxsize=1024)
def _rate(e):
    """`rate` of a scalar, memoised: a statement is read again under its second readings."""
    if e.free_symbols & set(WD):
        raise lx.NotRead("a second time derivative of 𝛚")
    if any(s.name.endswith(("_x", "_y", "_z")) and s not in set(W) for s in e.free_symbols):
        raise lx.NotRead("the rate of a vector the text has not tied to the body")
    out, free = sp.S.Zero, e.free_symbols
    for r in [R0, *RK]:
        if free.isdisjoint(r):
            continue            # a point the expression does not hold: its rate adds 0
        v = W.cross(r)
        out += sum(sp.diff(e, r[i]) * v[i] for i in range(3))
    out += sum(sp.diff(e, W[i]) * WD[i] for i in range(3) if W[i] in free)
    return out


@functools.lru_cache(maxsize=None)
def momentum(system: str) -> sp.ImmutableMatrix:
    """𝐋 = Σ m 𝐫 × (𝛚 × 𝐫) of the system (one point mass, or the body's points)."""
    return sp.ImmutableMatrix(_momentum(system))


@functools.lru_cache(maxsize=None)
def torque(system: str) -> sp.ImmutableMatrix:
    """d𝐋/dt under rigid rotation."""
    L = momentum(system)
    motion = dict(zip(W, WD))             # the field d/dt moves along (`rate`): 𝛚̇ = 𝛂, ṙ = 𝛚 × 𝐫
    for r in [R0, *RK]:
        motion.update(zip(r, W.cross(r)))
    return sp.ImmutableMatrix([zt.expanded_derivative(zt.expanded(L[i]), field=motion) for i in range(3)])


@functools.lru_cache(maxsize=None)
def _point_motion(point) -> dict:
    """The velocity 𝛚 × 𝐫 of the model's point (None: the single point, else the body's point k)
    and its acceleration 𝛂 × 𝐫 + 𝛚 × (𝛚 × 𝐫), with the tangential and normal parts, derived
    once: every occurrence of 𝐯ᵢ or 𝐚ᵢ in a statement, and every reading of it, asks again."""
    r = R0 if point is None else RK[point]
    tangential, normal = WD.cross(r), W.cross(W.cross(r))
    return {"v": W.cross(r), "at": tangential, "an": normal, "a": tangential + normal}


def _moved(env, kind) -> sp.Matrix:
    """A copy of `_point_motion`'s ``kind`` for the point ``env`` is at (a reading may change it)."""
    return _point_motion(env.get("point"))[kind].copy()


def _momentum(system: str) -> sp.Matrix:
    if system == "single":
        return M0 * R0.cross(W.cross(R0))
    return sum((MU[k] * RK[k].cross(W.cross(RK[k])) for k in range(POINTS)), sp.zeros(3, 1))


@functools.lru_cache(maxsize=None)
def tensor(system: str) -> sp.ImmutableMatrix:
    """𝐈 = ∂𝐋/∂𝛚 of the system."""
    L = momentum(system).applyfunc(zt.expanded)
    return sp.ImmutableMatrix(3, 3, lambda i, j: zt.expanded_derivative(L[i], W[j]))


@functools.lru_cache(maxsize=None)
def linear(system: str) -> sp.ImmutableMatrix:
    """𝐩 = Σ m 𝛚 × 𝐫 of the system."""
    if system == "single":
        return sp.ImmutableMatrix(M0 * W.cross(R0))
    return sp.ImmutableMatrix(sum((MU[k] * W.cross(RK[k]) for k in range(POINTS)), sp.zeros(3, 1)))


def generic_components(name: str) -> sp.Matrix:
    """The components of a vector of the text's that the model does not know (𝐌, 𝐍_cm, 𝐧_a)."""
    return sp.Matrix(sp.symbols(f"{name}_x {name}_y {name}_z", real=True))


def difference(a, b):
    """a − b expanded, entry by entry; None when the shapes differ."""
    a, b = _as_value(a), _as_value(b)
    if isinstance(a, sp.MatrixBase) != isinstance(b, sp.MatrixBase):
        if a == 0 or b == 0:        # 0 written for the zero vector (𝐈𝛚̇ + 𝛚 × 𝐈𝛚 = 0)
            a, b = (sp.zeros(*b.shape), b) if a == 0 else (a, sp.zeros(*a.shape))
        else:
            return None
    if isinstance(a, sp.MatrixBase):
        if a.shape != b.shape:
            return None
        return (a - b).applyfunc(_zeroed)
    return _zeroed(a - b)


@functools.lru_cache(maxsize=4096)
def _zeroed(d):
    """d expanded, and simplified where it holds a root or another power that is no integer,
    unless it is shown non-zero at a point (no identity makes it 0 then). Kept per expression: a
    statement read again (under another reading of its names, or edited to find the correction)
    compares the same differences."""
    d = zt.expanded(d)
    if d != 0 and any(not p.exp.is_Integer for p in d.atoms(sp.Pow)) and not zt.nonzero_somewhere(d):
        d = sp.simplify(d)          # |𝛚| and 𝛚̂: a polynomial's expansion is already canonical
    return d


class Algebra:
    """The values of one statement's symbols under rigid rotation (the grammar's model, see
    `derive.lecture.vector_parser`), in a system of one point mass or the body's points."""

    vocabulary = False                  # every symbol is this model's (else the statement is not read)
    free = "ijkl"
    matrix_products = True              # the texts' matrices act on columns by juxtaposition
    rates = True
    frames = {"r": "body", "rel": "body", "rot": "body", "b": "body", "body": "body"}
    """A derivative's subscript naming the turning frame, (d𝐗/dt)_r: the rate seen from the body;
    none: the inertial one."""

    def __init__(self, state: State, system: str):
        self.state, self.system = state, system

    def rate(self, X, frame):
        """d𝐗/dt, or seen from the body (d𝐗/dt)_r = d𝐗/dt − 𝛚 × 𝐗 (the transport theorem)."""
        if frame == "body" and isinstance(X, sp.MatrixBase) and X.shape == (3, 1):
            return rate(X) - W.cross(X)
        return rate(X) if frame != "body" or not isinstance(X, sp.MatrixBase) else None

    def points(self):
        return [({"point": k, "index": None}, MU[k]) for k in range(POINTS)]

    def summed(self, p, names, upper, env, tok):
        """Σᵢ over the body's points (the index's upper limit a letter, or mᵢ in the statement)."""
        if len(names) != 1 or len(names[0]) != 1:
            p.fail("a sum over more than one index", tok)
        if env.get("index") is not None and not upper and not _particle_letter(p.source, names[0]):
            return [{**env, names[0]: n} for n in (1, 2, 3)]   # Σ_j x_{aj} ω_j inside Σ_a: over the axes
        if any(t is not None and t.kind == "num" for t in upper):
            p.fail("a sum over the body's axes", tok)    # Σ_{i=1}^{3}: not over particles
        return [{**env, "point": k, "index": names[0]} for k in range(POINTS)]

    def _point(self, env):
        k = env.get("point")
        return (M0, R0) if k is None else (MU[k], RK[k])

    @staticmethod
    def _own(sub, env) -> bool:
        """Whether a subscript names the current point (none, or the sum's index; 𝐫ᵢ outside a sum
        is the particle in question)."""
        return sub == "" or sub == env.get("index") or (env.get("point") is None and sub == "i")

    def atom(self, p, a, env, tok):
        """The value of a symbol (None: not this model's); records on the parser the generic
        vectors, torques, forces and rates the member involves."""
        base, sub, bold = a.base, a.sub, a.bold or a.text.startswith("\\vec")
        if a.dots > 1 or a.primes or a.tilde:
            return None
        if a.dots == 1:
            p.rated = True
            inner = self.atom(p, a.with_(dots=0), env, tok)
            if inner is None:
                return None
            if base == "omega":
                return WD if bold else (WD[AXES[sub]] if sub in AXES else None)
            return rate(inner)
        mass, r = self._point(env)
        if a.hat and base in UNIT and (not sub or base == "x"):
            kinds = p.__dict__.setdefault("unit_kinds", set())
            kinds.add((bool(sub), a.primes))  # x̂₃ beside ẑ, î′ beside î: two frames' unit vectors, not one basis
            return E[:, p.axis(sub, env, tok) if sub else UNIT[base]] if len(kinds) == 1 else None
        if a.hat and not a.bold and base in FRAME_LETTERS and sub in ("1", "2", "3") and not a.sup:
            seen = p.__dict__.setdefault("frame_letters", {base})
            if seen != {base} or _has_rate(p.toks):
                return None                  # b̂ᵢ beside n̂ᵢ (two frames), or under a rate (which frame turns?)
            return E[:, int(sub) - 1]        # b̂₁, b̂₂, b̂₃: a frame's unit vectors, the axes of this model
        axis = self.state.axis
        if base == "omega":
            n = sp.sqrt(W.dot(W))
            if a.hat:
                return W / n
            if bold:
                return W
            if not sub and axis is not None:
                return W[axis]               # about a fixed axis: ω is the signed rate about it
            if _index_letter(sub, env, self.free) and _particles_apart(p.source, sub):
                return W[p.axis(sub, env, tok)]     # ω_i beside Σ_a: a component at an index
            return n if not sub else (W[AXES[sub]] if sub in AXES else None)
        if base == "alpha":
            p.rated = True
            if not bold and not sub and axis is not None:
                return WD[axis]
            if bold and (sub.isdigit() or sub in ("i", "j", "k", "n")):
                return None                  # 𝛂ᵢ, 𝛂₁: a particle's or another body's, not this body's rate
            return WD if bold else (WD[AXES[sub]] if sub in AXES else None)
        if a.hat:
            return None
        if base == "rho" and not bold and f"\\rho_{{{sub}}}" == mass_elements.KEPT_DENSITY:
            return DENSITY                   # a density that multiplies only part of an integrand
        if base == "r" and sub.startswith("/") and sub[1:] in POINT_LABELS:
            sub = ""                         # 𝐫_{/cm}: the position relative to the point, this model's 𝐫
        element = env.get("point") is not None and env.get("index") is None and sub == "i" and "i" not in env
        if base == "r" and (self._own(sub, env) or element):     # 𝐫ᵢ in an integral (no index): its element
            if not bold and self.state.radial == "axis" and axis is not None:
                return sp.sqrt(sum(r[i]**2 for i in range(3) if i != axis))   # the distance from the axis
            return r if bold else sp.sqrt(r.dot(r))
        if base == "r" and not bold and sub in ("x", "y", "z"):
            return r[AXES[sub]]              # r_x, r_y, r_z: the current point's coordinates
        if base in "xyz" and len(base) == 1 and not bold:
            if self._own(sub, env):
                return r[AXES[base]]
            if base == "x" and len(sub) == 1:
                return r[p.axis(sub, env, tok)]
            pair = sub.replace(",", "")
            if base == "x" and len(pair) == 2 and env.get("index") in pair and pair[0] != pair[1]:
                return r[p.axis(pair.replace(env["index"], ""), env, tok)]   # x_{ai}, x_{a,i}: point a's i-th coordinate
            return None
        if base == "m" and not bold and self._own(sub, env):
            return mass
        if base == "v" and self._own(sub, env):
            v = _moved(env, "v")
            return v if bold else sp.sqrt(v.dot(v))
        if base == "v" and not bold and sub in ("x", "y", "z"):
            return _moved(env, "v")[AXES[sub]]
        if bold and point_labels.labels(sub) is not None:
            value = point_labels.value(base, sub, a.sup, W, WD)
            if value is not None:
                return value                 # 𝐯_B, 𝐫_{AB}, 𝐚_{BA}^t: points of the body named by letters
        if base == "a" and bold and sub and self._own(sub, env) and a.sup in ("", "t", "n", "tau"):
            p.rated = True                   # 𝐚ᵢ: the point's acceleration; ᵗ, ⁿ its tangential and normal parts
            return _moved(env, {"t": "at", "tau": "at", "n": "an"}.get(a.sup, "a"))
        if base == "p" and bold and self._own(sub, env):
            return None if "p" in self.state.places else mass * _moved(env, "v")
        if base == "F" and bold and sub and sub == env.get("index"):
            p.rated = True                   # 𝐅ᵢ summed over the points: the rate of the point's momentum
            return mass * rate(_moved(env, "v"))
        if base == "delta" and len(sub) == 2:
            return sp.Integer(int(p.axis(sub[0], env, tok) == p.axis(sub[1], env, tok)))
        return self._system_atom(p, a, env, tok, mass, r, bold)

    def _system_atom(self, p, a, env, tok, mass, r, bold):
        """𝐋, 𝐈 and their entries, the torque, the force, a generic vector."""
        base, sub = a.base, a.sub
        system = "body" if sub in ("system", "textsystem", "G", "mathcalG", "mathrmG") else self.system
        point = env.get("point") is not None and sub == env.get("index")
        if base == "L" and base not in self.state.torques or base in self.state.momenta or (base == "H" and bold):
            if bold:                        # 𝐇, engineering dynamics' angular momentum (Beer & Johnston, Kane)
                if point:
                    return mass * r.cross(W.cross(r))
                return momentum(system) if sub in ("", "system", "textsystem", *POINT_LABELS) else None
            if len(sub) == 1 and sub in AXES:
                return momentum(self.system)[AXES[sub]]
            if _index_letter(sub, env, self.free) and _particles_apart(p.source, sub):
                return momentum(self.system)[p.axis(sub, env, tok)]   # J_i = Σ_a …: a component at an index
            if "omega" in sub:
                return momentum(self.system).dot(W / sp.sqrt(W.dot(W)))
            return None
        if base == "I":
            if a.text.startswith(("\\mathrm", "\\mathbb")) and not sub:
                return sp.eye(3)
            if point:
                return (mass * r.cross(W.cross(r))).jacobian(W)
            if sub in ("", "system", "textsystem", "G", "mathcalG", "mathrmG"):
                return tensor(system)
            if "omega" in sub:
                n = W / sp.sqrt(W.dot(W))
                return (n.T * tensor(self.system) * n)[0, 0]
            if len(sub) == 1 and sub in "xyz" and not bold and re.search(r"\\sum|\\mathbf\{\\" + INTEGRAL, p.source):
                # I_x beside the body's own integral or sum is the moment about the x axis, I_xx; a
                # relation of moments alone (I_x + I_y = I_z) is a case of the text's body, left unread
                return tensor(self.system)[AXES[sub], AXES[sub]]
            if len(sub) == 2 and not bold:
                if (base, sub) in self.state.defs:
                    return self.state.defs[(base, sub)]
                i, j = p.axis(sub[0], env, tok), p.axis(sub[1], env, tok)
                entry = tensor(self.system)[i, j]
                return -entry if self.state.products and i != j else entry
            return None
        if base in self.state.torques or (base == "F" and bold and not sub):
            p.law = True
        if base in self.state.torques:
            if bold and not sub:
                return torque(self.system)
            if not bold and sub in AXES and len(sub) == 1:
                return torque(self.system)[AXES[sub]]
            if bold and labelled_torque(sub):
                return torque(self.system)
            return None
        if base == "F" and bold and not sub:
            p.force_at.append(p.i)
            return rate(linear(self.system))
        if len(base) == 1 and base.isalpha() and base not in "dmt":
            comps = generic_components(base)
            if bold and not sub:
                p.generics.add(base)
                return comps
            if bold and sub in POINT_LABELS and base not in "rvpIL":   # 𝐌_cm, 𝐍_O: about a point, a vector of the text's
                p.generics.add(base + sub)
                return generic_components(base + sub)
            if bold and len(sub) == 1 and sub in "abcdefgh" and not a.sup and sub != env.get("index") \
                    and base not in "rvp":      # 𝐧_a, a vector of the text's named by a letter (Kane's n̂_a)
                p.generics.add(base + sub)
                return generic_components(base + sub)
            if not bold and sub in ("x", "y", "z"):
                p.generics.add(base)
                return comps[AXES[sub]]
        return None


_SUM_INDEX = re.compile(r"\\sum(?:\\limits)?\s*_\s*\{?\s*([A-Za-z])(?![A-Za-z])")
_PARTICLE_SUB = r"(?:(?<![A-Za-z\\])m|" + VECTOR_MARK + r"\s*\{?\s*[rvp]\s*\}?)\s*_\s*(?:\{\s*%s\s*\}|%s(?![A-Za-z]))"


def _particle_letter(source: str, letter: str) -> bool:
    """Whether a statement writes a particle's mass or bold position, velocity or momentum with
    ``letter`` as its subscript (m_j, 𝐫_j): then a sum over it runs over particles."""
    return re.search(_PARTICLE_SUB % (re.escape(letter), re.escape(letter)), source) is not None


def _index_letter(sub: str, env: dict, free: str) -> bool:
    """A one-letter subscript that is an index (free, or a sum's over the axes), not an axis."""
    return len(sub) == 1 and sub not in AXES and (sub in free or isinstance(env.get(sub), int))


def _particles_apart(source: str, letter: str) -> bool:
    """Whether the statement sums over particles with a letter other than ``letter`` and never writes a
    particle with it: ``letter`` then indexes the axes, as in J_i = Σ_a m_a (…x_{ai}…)."""
    return not _particle_letter(source, letter) and any(
        s != letter and _particle_letter(source, s) for s in set(_SUM_INDEX.findall(source)))


def system_of(toks, state: State) -> str:
    """body (a sum or an integral), single (a plain m, or a particle's momentum 𝐩 with no index),
    else the previous statement's system."""
    if any(t.kind == "cmd" and t.value == "sum" for t in toks) or \
            any(t.kind == "atom" and t.value.base == INTEGRAL for t in toks):
        return "body"
    if any(t.kind == "atom" and t.value.base == "m" and t.value.sub in ("", "i") and not t.value.bold for t in toks):
        return "single"
    if any(t.kind == "atom" and t.value.base == "p" and (t.value.bold or t.value.text.startswith("\\vec"))
           and not t.value.sub for t in toks):
        return "single"         # 𝐋 = 𝐫 × 𝐩 with no sum: one particle's momentum, so one particle's 𝐋
    if any(t.kind == "atom" and t.value.sub in ("system", "textsystem") for t in toks):
        return "body"
    return state.system


def learn_torque(toks, state: State) -> None:
    """A bold letter set equal to 𝐫 × 𝐅 is the text's torque."""
    if len(toks) >= 5 and toks[0].kind == "atom" and toks[0].value.bold and toks[1].kind == "rel" \
            and toks[2].kind == "atom" and toks[2].value.base == "r" and toks[3].kind == "cmd" \
            and toks[3].value == "times" and toks[4].kind == "atom" and toks[4].value.base == "F":
        state.torques.add(toks[0].value.base)


_BODY_VECTOR = re.compile(r"(\\vec\s*\{\s*\\?[A-Za-z]+)\s*_\s*(?:\{\s*b\s*\}|b)\s*\}")
_BODY_TENSOR = re.compile(r"(?<![\\A-Za-z])I\s*_\s*(?:\{\s*b\s*\}|b)(?![A-Za-z])")
_OTHER_LABEL = re.compile(r"_\s*\{?\s*(?:i|I|w|s|b\s*/)|\\frac\s*\{\s*d|\\dot")


def one_frame(text: str) -> str:
    """``\\vec{H_b} = I_b \\vec{\\omega_b}``: every vector and the tensor in body components (the
    label b on each, no other frame and no rate): an algebraic relation, the same in any one
    frame's components, read without the label."""
    if _OTHER_LABEL.search(text) or not (_BODY_VECTOR.search(text) or _BODY_TENSOR.search(text)):
        return text
    return _BODY_TENSOR.sub("I", _BODY_VECTOR.sub(r"\1}", text))


def read(text: str, state: State, partial: bool = False) -> vp.Reading:
    """Read a statement with the vector grammar under this model (`lx.NotRead` when it cannot);
    ``reading.model`` is the system it speaks of ("body" or "single"); ``partial``: a matrix entry
    with a symbol the model does not know is set aside (`derive.lecture.vector_parser.read`)."""
    text = prepare(one_frame(text))
    toks = lx.scan_cells(text)
    learn_torque(toks, state)
    system = system_of(toks, state)
    return vp.read(toks, text, lx.Vocabulary(), Algebra(state, system), system, partial)
