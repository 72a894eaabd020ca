"""The three models of the vector reader (`derive.lecture.vectors`): what 𝐫, 𝐯, 𝐋, Ï, T and ω
stand for in a statement about particles, about body principal axes or about a rotating frame
(`Model`, the values the grammar of `derive.lecture.vector_parser` asks for), which model a
statement is read in (`model_of`), whether a display is one for the vector reader (`vectorish`)
and the text rewrites it needs first (`prepare`).
"""
from __future__ import annotations

import functools
import itertools
import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.latex_spaces import SPACE
from derive.lecture.vector_parser import LAW, _FreeIndex
from derive.lecture.zero_test import expanded, expanded_derivative
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3
from derive.symbolic.rotations import ANGLES, RATES, time_derivative
from derive.lecture.latex_spellings import VECTOR_MARK

PARTICLES = 2
M_P = sp.symbols(f"m_p1:{PARTICLES + 1}", positive=True)
R_P = [sp.Matrix(sp.symbols(f"x_p{k} y_p{k} z_p{k}", real=True)) for k in range(1, PARTICLES + 1)]
R_B = sp.Matrix(sp.symbols("x_b y_b z_b", real=True))          # a body-fixed point 𝐫
L_B = sp.Matrix(sp.symbols("L_b1:4", real=True))               # 𝐋's body components (time-dependent)
LD_B = sp.Matrix(sp.symbols("Ld_b1:4", real=True))             # their rates
W = sp.Matrix(lx.W)
_J = sp.symbols("J_11 J_12 J_13 J_22 J_23 J_33", real=True)
RIGID = sp.ImmutableMatrix([[_J[0], _J[1], _J[2]], [_J[1], _J[3], _J[4]], [_J[2], _J[4], _J[5]]])
"""The text's inertia tensor I (I_b) in a rotating frame: any symmetric matrix, constant in body axes."""
FRAMES = {"body": "body", "b": "body", "B": "body", "rot": "body", "rotating": "body", "inertial": "inertial",
          "space": "inertial", "fixed": "inertial", "lab": "inertial", "s": "inertial", "i": "inertial",
          "I": "inertial", "N": "inertial", "rel": "body", "relative": "body", "R": "body"}
GENERIC = "_vec"
"""The mark of a generic vector's body components (``V_vec1``): a vector of the text's in a frame
derivative, with time-dependent components of its own."""
_KNOWN_VECTORS = {"r", "L", "omega", "Omega", "e", "I", "Xi", "tau"}
ROTATIONAL = ("rot", "rotation", "rotational")
"""Subscripts that name a kinetic energy's rotational part (T_rot, T_{\\text{rot}}), the whole of it in
the models here, where the body only turns."""
POINT_LABELS = ("cm", "CM", "com", "G", "O", "C")
"""Subscripts naming the point a momentum is taken about (𝐇_cm, 𝐋_G): the centre of mass, or the
point the body turns about."""
_UNIT = re.compile(r"\\(?:mathbf|mathbb|boldsymbol|bm)\s*\{\s*(?:\\(?:mathbb|mathbf)\s*\{\s*)?1\s*\}(?:\s*\})?")


def principal_tensor() -> dict:
    """`RIGID`'s entries in principal axes: the diagonal I₁, I₂, I₃, no products of inertia."""
    return {_J[0]: I1, _J[3]: I2, _J[5]: I3, _J[1]: 0, _J[2]: 0, _J[4]: 0}


def is_quantity(a) -> bool:
    """Whether a symbol is one known quantity (T, 𝐋, Ï, I_ij): a member that is its definition."""
    return a.base in ("T", "L") or (a.base == "I" and (a.bold or a.dots == 2 or len(a.sub) == 2))


# ---- the models -----------------------------------------------------------------------------------
class Model:
    """What the symbols of one statement stand for (see the module docstring)."""

    vocabulary = True                   # a scalar the model does not know is the scalar reader's
    free = "ij"                         # the letters a free body index may be
    matrix_products = False             # a tensor acts on a vector with ·, never by juxtaposition
    frames = FRAMES

    def __init__(self, name: str, derivation=None, plain_l_vector: bool = False):
        self.name, self.d = name, derivation
        self.plain_l_vector = plain_l_vector
        self.rates = name == "frame"    # the grammar reads d𝐗/dt only in a rotating frame
        self.matrix_products = name == "frame"    # I_b 𝛚_b: the text's tensor on a column
        self.generic = {}               # a letter → (its body components, their rates)

    def generic_vector(self, base: str) -> sp.Matrix:
        """𝐕 of the text's in a rotating frame: body components V₁ V₂ V₃ of their own, time-dependent."""
        if base not in self.generic:
            self.generic[base] = (sp.Matrix(sp.symbols(f"{base}{GENERIC}1:4", real=True)),
                                  sp.Matrix(sp.symbols(f"{base}{GENERIC}d1:4", real=True)))
        return self.generic[base][0]

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
        return sp.Matrix(_tensor(self.name))

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

    def principal_rigid(self) -> dict:
        """𝐋 of a rigid body where the statement writes the principal moments I₁, I₂, I₃ beside its
        frame derivative: (I₁ω₁, I₂ω₂, I₃ω₃) in body axes, its rate (I₁ω̇₁, I₂ω̇₂, I₃ω̇₃)."""
        L = sp.diag(I1, I2, I3) * self.omega
        return {**dict(zip(L_B, L)), **dict(zip(LD_B, sp.diag(I1, I2, I3) * self.omega.applyfunc(self.dt)))}

    def rigid(self) -> dict:
        """𝐋 of a rigid body where the statement writes its tensor: 𝐋 = I𝛚 with I constant in body
        axes (`RIGID`), so (d𝐋/dt)_body = I𝛚̇; as the substitution of 𝐋's body components and rates."""
        L = RIGID * self.omega
        return {**dict(zip(L_B, L)), **dict(zip(LD_B, RIGID * self.omega.applyfunc(self.dt)))}

    # frame derivatives
    def dt(self, e):
        """d/dt of an expression in the angles, rates and 𝐋's body components (the
        derivation's chain rule, with 𝐋's components as three more coordinates)."""
        comps = [c for X, _ in self.generic.values() for c in X]
        rates = [c for _, Xd in self.generic.values() for c in Xd]
        return time_derivative(e, coords=(*ANGLES, *L_B, *comps), rates=(*RATES, *LD_B, *rates), accels=ACCELS)

    def derivative(self, X: sp.Matrix, frame: str) -> sp.Matrix:
        """Body components of (dX/dt) in the inertial frame (Rᵀ d(R X)/dt) or the body frame (Ẋ)."""
        generic = tuple((tuple(X), tuple(Xd)) for X, Xd in self.generic.values())
        out = _derivative(self.d, generic, sp.ImmutableMatrix(X), frame, type(X))
        return out.copy() if isinstance(out, sp.MutableDenseMatrix) else out

    # the grammar's hooks (`derive.lecture.vector_parser`)
    def rate(self, X, frame):
        """d𝐫/dt, d𝐋/dt in a frame; None for a scalar (the scalar reader's d/dt)."""
        if isinstance(X, sp.MatrixBase) and X.shape == (3, 3) and X.free_symbols <= set(RIGID) and frame == "body":
            return sp.zeros(3, 3)                 # the body's tensor seen from the body, where it is constant
        if X is R_B or X is L_B or any(X is G for G, _ in self.generic.values()) or \
                isinstance(X, sp.MatrixBase) and X.shape[1] == 1 and X.free_symbols <= {*ANGLES, *RATES, *RIGID}:
            return self.derivative(X, frame)      # …or a vector given in the angles (the vertical Rᵀẑ) and rates
            #    (𝛚, I𝛚 with the body's constant tensor), or constant body components (a body axis ê_i, whose inertial rate is 𝛚 × ê_i)
        if isinstance(X, sp.MatrixBase):
            raise lx.NotRead("the time derivative of a vector other than 𝐫 and 𝐋")
        return None

    def points(self):
        return []

    def summed(self, p, names, upper, env, tok):
        """Σ_p over particles (two generic ones) or Σ_i, Σ_ij over body axes (1, 2, 3)."""
        index = "".join(names)
        if index == "p":
            ranges = [("p", range(PARTICLES))]
        elif index and all(ch in "ijk" for ch in index):
            ranges = [(ch, (1, 2, 3)) for ch in index]
        else:
            p.fail(f"a sum over {index!r}", tok)
        return [{**env, **{n: v for (n, _), v in zip(ranges, values)}}
                for values in itertools.product(*(r for _, r in ranges))]

    def atom(self, p, a, env, tok):
        """The value of a symbol in this model, or None (then the scalar reader's vocabulary)."""
        v = self._vector(p, a, env, tok)
        if v is None and a.sub in ("i", "j") and a.sub not in env:
            raise _FreeIndex(a.sub)
        return v

    def _vector(self, p, a, env, tok):
        plain = not a.hat and not a.tilde and not a.primes and not a.dots
        if self.name == "frame" and a.base == "omega" and not a.bold and a.sub in ("1", "2", "3") and a.dots <= 1 \
                and not (a.hat or a.tilde or a.primes or a.sup):
            w = self.omega[int(a.sub) - 1]          # ω_i, ω̇_i beside frame derivatives: 𝛚's body components
            return self.dt(w) if a.dots else w
        if self.name == "frame" and a.base == "omega" and a.bold and not a.sub and a.dots == 1 and not a.tilde:
            return self.omega.applyfunc(self.dt)      # 𝛚̇ beside frame derivatives: the rates of its body components
        if (a.base == "omega" or _text_letter(p, a, "angular velocity")) and not a.sub and not a.dots and not a.tilde:
            return self.omega         # the text's letter for the angular velocity (Landau's 𝛀) too
        if a.base == "e" and (a.hat or a.bold) and not a.primes and not a.sup and len(a.sub) == 1:
            return sp.eye(3)[:, p.axis(a.sub, env, tok)]
        if a.base == "I" and not a.sub and (a.bold or a.dots == 2):
            return self.tensor
        if self.name == "frame" and a.base == "I" and a.sub in ("", "b", "B") and plain and not a.bold and not a.sup:
            return RIGID                # I, I_b beside frame derivatives: the body's tensor, constant in body axes
        if a.base == "I" and a.sub in POINT_LABELS and a.bold and plain and not a.sup:
            # Schaub's [𝐈_C]: the body's tensor about its centre of mass (beside frame derivatives, constant in body axes)
            return RIGID if self.name == "frame" else self.tensor
        if a.base == "I" and len(a.sub) == 2 and not a.bold:
            return self.tensor[p.axis(a.sub[0], env, tok), p.axis(a.sub[1], env, tok)]
        if a.base == "I" and a.sub in ("i", "j") and not a.bold:
            return self.moments[p.axis(a.sub, env, tok)]
        if a.base == "Xi" and a.bold:
            return sp.eye(3)
        if a.base == "delta" and len(a.sub) == 2:
            return sp.Integer(int(p.axis(a.sub[0], env, tok) == p.axis(a.sub[1], env, tok)))
        if a.base == "m" and a.sub == "p" and plain:
            return M_P[_particle(p, env, tok)]
        if a.base == "r" and plain and a.sub[:1] == "p":
            r = R_P[_particle(p, env, tok)]
            if len(a.sub) == 2 and not a.bold:
                return r[p.axis(a.sub[1], env, tok)]
            if a.sub == "p":
                return r if a.bold else sp.sqrt(r.dot(r))
        if a.base == "x" and plain and not a.bold and len(a.sub) == 2 and a.sub[0] == "p":
            return R_P[_particle(p, env, tok)][p.axis(a.sub[1], env, tok)]   # x_{α,k}: r_α's k-th coordinate
        if a.base == "v" and plain and a.sub == "p":
            v = self.velocity(_particle(p, env, tok))
            return v if a.bold else sp.sqrt(v.dot(v))
        if a.base == "r" and plain and a.bold and not a.sub:
            return R_B
        if a.base == "L" and plain and not a.sub and (a.bold or self.plain_l_vector) and not _text_letter(p, a, "torque"):
            return self.momentum
        if self.name == "frame" and a.base == "L" and plain and not a.bold and not a.sup and a.sub in ("1", "2", "3"):
            return self.momentum[int(a.sub) - 1]    # L₃ beside frame derivatives: 𝐋's body component
        if a.base in ("L", "H") and plain and a.bold and a.sub in POINT_LABELS and not _text_letter(p, a, "torque"):
            return self.momentum        # 𝐋_cm, 𝐇_G: about the centre of mass, the point the body turns about here
        if self.name == "principal" and a.base == "I" and plain and not a.sub and not a.sup and not a.bold:
            return self.tensor          # a plain I beside the body axes ê_i: the diagonal tensor of principal axes
        if _text_letter(p, a, "angular momentum") and plain and (a.bold and not a.sub or len(a.sub) == 1 and
                                                                 self.name == "particle" and not a.bold):
            return self.momentum if not a.sub else self.momentum[p.axis(a.sub, env, tok)]   # Landau's 𝐌, M_i
        if a.base == "T" and plain and (not a.sub or a.sub in ROTATIONAL) and not a.sup \
                and not (a.bold and _text_letter(p, a, "torque")):
            # T, T_rot (the body only turns here, so T is all rotation), and a bold 𝐓 as the scalar reader reads it
            return self.kinetic
        if a.bold and plain and not a.sub and _text_letter(p, a, "vertical") and p.vocab.vertical:
            return sp.Matrix(p.vocab.vertical)    # the text's unit vector of the vertical, Rᵀẑ
        if (a.base == "tau" or a.bold and _text_letter(p, a, "torque")) and (not a.sub or a.sub in POINT_LABELS):
            return LAW                  # τ, or the letter the text calls the torque (Goldstein's 𝐍)
        if self.name == "frame" and a.bold and plain and not a.sub and not a.sup and a.base not in _KNOWN_VECTORS:
            return self.generic_vector(a.base)
        return None


@functools.lru_cache(maxsize=None)
def _tensor(name: str) -> sp.ImmutableMatrix:
    """`Model.tensor`, which the model's name alone decides: derived once, not for each statement."""
    model = Model(name)
    if name == "principal":
        return sp.ImmutableMatrix(sp.diag(*model.moments))
    kinetic = expanded(model.kinetic)
    return sp.ImmutableMatrix(3, 3, lambda i, j: expanded_derivative(kinetic, lx.W[i], lx.W[j]))


@functools.lru_cache(maxsize=256)
def _derivative(d, generic: tuple, X: sp.ImmutableMatrix, frame: str, kind: type) -> sp.MatrixBase:
    """`Model.derivative` of X (of the matrix class ``kind``) in the convention of the derivation
    ``d``, with the text's generic vectors ``generic`` as (components, rates): derived once, a
    statement being read again under its second readings."""
    model = Model("frame", d)
    model.generic = {k: (sp.Matrix(c), sp.Matrix(r)) for k, (c, r) in enumerate(generic)}
    X = kind(X)
    Xd = X.applyfunc(model.dt)
    if frame == "body":
        return Xd
    R, Rd = d.turning            # R and dR/dt of the convention, kept between commands
    return R.T * (Rd * X) + Xd


def _text_letter(p, a, meaning) -> bool:
    """Whether the text names a's letter, as a vector, by this meaning (`derive.lecture.names`)."""
    names = getattr(p.vocab, "names", None)
    return names is not None and not p.vocab.names_off and names.letters.get((a.base, "vector")) == meaning


def _particle(p, env, tok):
    if "p" not in env:
        p.fail("a particle quantity outside a sum over particles", tok)
    return env["p"]


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
    return (a.base in ("m", "r", "v") and a.sub[:1] == "p") or (a.base == "x" and len(a.sub) == 2 and a.sub[0] == "p") \
        or a.base == "delta" or (a.base == "Xi" and a.bold)


def _has_time_derivative(toks) -> bool:
    for k in range(len(toks) - 6):
        w = toks[k:k + 7]
        # the vector may stand in a group of its own, d{\bf G} as plain TeX writes it, or a tensor in brackets, d[𝐈_C]
        x = w[4] if w[3].kind == "op" and w[3].value in ("{", "(") else w[3]
        if w[0].kind == "cmd" and w[0].value == "frac" and w[2].kind == "atom" and w[2].value.base == "d" \
                and x.kind == "atom" and (x.value.bold or x.value.text.startswith("\\vec")):
            return True
    return False


def vectorish(toks) -> bool:
    """Whether a statement is for this reader: a cross product, a tensor, a sum over particles,
    a particle quantity, a time derivative of a vector, or a vector written along the body axes ê_i."""
    atoms = [t.value for t in toks if t.kind == "atom"]
    if any(a.base == "e" and a.hat and a.sub in ("1", "2", "3") for a in atoms) and \
            any((a.bold or a.text.startswith("\\vec")) and a.base not in ("e", "omega") for a in atoms[:1]):
        return True
    for k, t in enumerate(toks):
        if t.kind == "cmd" and t.value == "times":
            return True
        if t.kind == "atom":
            a = t.value
            if _particle_atom(a) or (a.base == "I" and (a.bold or a.dots == 2 or len(a.sub) == 2)):
                return True
            if _tensor_on_omega(a, toks[k + 1] if k + 1 < len(toks) else None):
                return True
    return _has_time_derivative(toks)


def _tensor_on_omega(a, after) -> bool:
    """A plain I acting on a bold 𝛚 (``I\\boldsymbol{\\omega}``, ``\\boldsymbol{\\omega}\\cdot I\\boldsymbol{\\omega}``):
    the inertia tensor, as a text that writes the tensor without bold has it."""
    return a.base == "I" and not (a.sub or a.sup or a.bold or a.dots or a.hat or a.tilde or a.primes) \
        and after is not None and after.kind == "atom" and after.value.base == "omega" and after.value.bold \
        and not after.value.sub and not after.value.dots


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


_VEC = VECTOR_MARK + r"\s*\{(?:[^{}]|\{[^{}]*\})*\}"
_LABEL = r"(\{[^{}]*\}|[A-Za-z])"
DIFFERENTIAL = r"(?:\\mathrm\s*\{\s*d\s*\}|d)" + SPACE
"""The differential d, upright or italic, with the spacing a text may set after it (``\\mathrm{d}\\,``)."""
_RELATIVE_RATE = re.compile(r"\\frac\s*\{\s*\\tilde\s*\{\s*" + DIFFERENTIAL + r"\s*\}" + SPACE + r"(" + _VEC + r")\s*\}\s*\{\s*" + DIFFERENTIAL + r"\s*t\s*\}")
_ZERO_VECTOR = re.compile(VECTOR_MARK + r"\s*\{\s*0\s*\}")
# the fraction in a group of its own and the vector in one, as plain TeX's {d{\bf G}\over dt} writes them
_FRAC_RATE = (r"(?P<o>\{\s*)?\\frac\s*\{\s*" + DIFFERENTIAL + r"\s*(?P<b>\{\s*)?(" + _VEC + r")\s*(?(b)\}\s*)\}\s*\{\s*"
              + DIFFERENTIAL + r"\s*t")
_RATE_BAR = re.compile(_FRAC_RATE + r"\s*\}\s*(?(o)\}\s*)\\right\s*\|\s*_\s*" + _LABEL)
_RATE_DT = re.compile(_FRAC_RATE + r"\s*_\s*" + _LABEL + r"\s*\}(?(o)\s*\})")
# the frame as a superscript on the bracket, Schaub's (d𝐫/dt)^N: the subscript other texts write
_RATE_SUP = re.compile(r"(\\left\s*\(\s*\\frac\s*\{\s*" + DIFFERENTIAL + r"\s*" + _VEC + r"\s*\}\s*\{\s*" + DIFFERENTIAL
                       + r"\s*t\s*\}\s*\\right\s*\))\s*\^\s*" + _LABEL)
# the rate seen from a frame as an operator on a bracket, ^B d/dt (…)
_OPERATOR_PRESCRIPT = re.compile(r"(?:\{\s*\})?\^\s*" + _LABEL + SPACE + r"\\frac\s*\{\s*" + DIFFERENTIAL + r"\s*\}\s*\{\s*"
                                  + DIFFERENTIAL + r"\s*t\s*\}\s*(?P<sized>\\left\s*)?\(")
# the brackets that open and close inside the operator's: sized ones pair with sized, plain with plain
_LEFT_RIGHT = re.compile(r"(\\left\s*[(\[.|]|\\right\s*[)\].|])|[()]")
_SUBSCRIPTED = _VEC + r"(?:\s*_\s*(?:\{[^{}]*\}|[A-Za-z0-9]))?"
# Kane's and Schaub's frame written before the rate of a vector or of a tensor in brackets, ^B d[𝐈_C]/dt
_RATE_PRESCRIPT = re.compile(r"(?:\{\s*\})?\^\s*" + _LABEL + SPACE + r"\\frac\s*\{\s*" + DIFFERENTIAL + r"\s*(" + _SUBSCRIPTED
                             + r"|(?:\^\s*(?:\{[^{}]*\}|[A-Za-z])" + SPACE + r")?\[\s*" + _SUBSCRIPTED + r"\s*\])\s*\}\s*\{\s*" + DIFFERENTIAL + r"\s*t\s*\}")
# a frame's label before a vector, or before a tensor in brackets (Schaub's ^B[𝐈_C], its components in B)
_VECTOR_PRESCRIPT = re.compile(r"(?:\{\s*\})?\^\s*" + _LABEL + SPACE + r"(?=" + _VEC + r"(?!\s*\^)|\[\s*" + _VEC + r")")
_BODY_LABEL = re.compile(r"(" + VECTOR_MARK + r"\s*\{\s*\\?[A-Za-z]+)\s*_\s*(?:\{\s*b\s*\}|b)\s*\}")
_RELATIVE = re.compile(r"(" + _VEC + r")\s*_\s*\{\s*b\s*/\s*i\s*\}")
_FRAME_PAIR = re.compile(r"(" + _VEC + r")\s*_\s*\{\s*([A-Za-z])\s*/\s*([A-Za-z])\s*\}")
_UPRIGHT_PAIR = re.compile(r"_\s*\{\s*\\mathrm\s*\{\s*([A-Za-z])\s*\}\s*/\s*\\mathrm\s*\{\s*([A-Za-z])\s*\}\s*\}")
"""``_{\\mathrm{B}/\\mathrm{N}}``: the frames' letters as a ``\\mathcal{B}/\\mathcal{N}`` subscript is normalised."""


def frame_rates(text: str) -> str:
    """A derivative in a frame as the texts write it — ``\\left.\\frac{d\\vec v}{dt}\\right|_i``,
    ``\\frac{d\\vec V}{dt_b}`` — as ``\\left(\\frac{d\\vec v}{dt}\\right)_{i}``; in such a statement a
    vector's body-frame label (``\\vec{V_b}``, ``\\vec{\\omega}_{b/i}``) names the same vector, read in
    body components as every vector is."""
    def framed(m):
        return r"\left(\frac{d " + m.group(3) + r"}{dt}\right)_{" + m.group(4).strip("{}").strip() + "}"
    new = _RATE_DT.sub(framed, _RATE_BAR.sub(framed, text))
    new = _RATE_SUP.sub(lambda m: m.group(1) + "_{" + m.group(2).strip("{}").strip() + "}"
                        if m.group(2).strip("{}").strip() in FRAMES else m.group(0), new)
    if "^" in new:
        new = _prescribed(new)
    # d̃𝐧/dt, the relative (body-frame) derivative of the Russian and Chinese texts; 𝟎 the zero vector
    new = _ZERO_VECTOR.sub("0", _RELATIVE_RATE.sub(lambda m: r"\left(\frac{d " + m.group(1) + r"}{dt}\right)_{b}", new))
    if new == text:
        return text
    return _body_in_inertial(_RELATIVE.sub(r"\1", _BODY_LABEL.sub(r"\1}", new)))


def _body_in_inertial(text: str) -> str:
    """ω's subscript naming the body in the inertial frame (``\\boldsymbol{\\omega}_{B/N}``) gone: the
    vector read in body components, as every vector of a statement about rates in frames is."""
    return _FRAME_PAIR.sub(lambda m: m.group(1) if "\\omega" in m.group(1) and
                           (FRAMES.get(m.group(2)), FRAMES.get(m.group(3))) == ("body", "inertial") else m.group(0),
                           _UPRIGHT_PAIR.sub(r"_{\1/\2}", text))


def _prescribed(text: str) -> str:
    """``^N\\frac{d\\vec H}{dt}`` as ``\\left(\\frac{d\\vec H}{dt}\\right)_{N}`` when N names a frame the
    reader knows, the operator ``^B\\frac{d}{dt}\\left(…\\right)`` too; then a known frame's label before a
    vector or a bracketed tensor (``^B\\vec H``, ``^B[\\mathbf{I}_C]``) goes, every vector being read in body
    components, and ω's subscript naming the body in the inertial frame (``_{B/N}``) with it; all only
    when every frame label of the statement is one the reader knows."""
    labels = {m.group(1).strip("{}").strip() for m in (*_RATE_PRESCRIPT.finditer(text), *_VECTOR_PRESCRIPT.finditer(text))}
    if not labels or not labels <= set(FRAMES):
        return text
    new = _RATE_PRESCRIPT.sub(lambda m: r"\left(\frac{d " + m.group(2) + r"}{dt}\right)_{" + m.group(1).strip("{}").strip()
                              + "}", _operator_prescribed(text))
    return _VECTOR_PRESCRIPT.sub(lambda m: "" if m.group(1).strip("{}").strip() in FRAMES else m.group(0), new)



def _operator_prescribed(text: str) -> str:
    """``^B\\frac{d}{dt}\\left(X\\right)``, the rate seen from a frame as an operator on a bracket, sized or
    plain (``^B\\frac{d}{dt}(X)``), as ``\\left(\\frac{d}{dt}\\left(X\\right)\\right)_{B}``, the bracket closed
    where its own closing bracket is."""
    m = _OPERATOR_PRESCRIPT.search(text)
    if m is None:
        return text
    sized = m.group("sized") is not None
    depth = 1
    for tok in _LEFT_RIGHT.finditer(text, m.end()):
        if (tok.group(1) is not None) != sized:
            continue
        depth += 1 if tok.group(0).startswith(("\\left", "(")) else -1
        if depth == 0:
            break
    else:
        return text
    label = m.group(1).strip("{}").strip()
    closing = tok.group(0) if sized else r"\right)"
    return (text[:m.start()] + r"\left(\frac{d}{dt}\left(" + text[m.end():tok.start()] + closing + r"\right)_{" + label + "}"
            + _operator_prescribed(text[tok.end():]))


def prepare(text: str) -> str:
    """𝟙 (``\\mathbf{1}``, ``\\mathbb{1}``) as a symbol the scanner reads; ``\\overleftrightarrow``
    (the dyadic arrow) as bold; the text's particle index (``m_{\\alpha}``, ``r_{\\alpha ,i}``,
    ``\\sum_{\\alpha}``) as p; derivatives in a frame (`frame_rates`)."""
    text = frame_rates(_UNIT.sub(r"\\mathbf{\\Xi}", text))
    x = _particle_index(text)
    if x is not None:
        x = re.escape(x) + (r"(?![A-Za-z])" if x.startswith("\\") else "")
        text = re.sub(r"_\s*\{\s*" + x + r"\s*,?\s*([ijkxyz123])?\s*\}", lambda m: "_{p" + (m.group(1) or "") + "}", text)
        text = re.sub(r"_\s*" + x, "_{p}", text)
    return text.replace("\\overleftrightarrow", "\\mathbf")
