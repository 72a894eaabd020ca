"""The vocabulary of the formula reader: the symbols of the notes, the scanner that turns LaTeX
into atoms and tokens, and `Vocabulary`, which looks each atom up among the derivation's
quantities and their usual spellings (or, open to the text's own names, makes it a `Generic`
symbol of the text's). See `derive.lecture.latex` for the parser built on them.

May import: :mod:`derive.symbolic`, SymPy and, of :mod:`derive.lecture`, ``elliptic``, ``latex_spaces``, ``latex_spellings``,
``matrix_exp``, ``variations``, ``dotted_products``, ``axis_sums``.
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass, field

import sympy as sp

from derive.lecture import elliptic
from derive.lecture.axis_sums import summed
from derive.lecture.definite_integrals import written_with_bounds
from derive.lecture.dotted_products import rate_of_product
from derive.lecture.latex_spaces import QUAD_NAMES, SPACE_NAMES
from derive.lecture.latex_spellings import BOLD_NAMES, DIGITS, LABEL_WORD, SIGN_ENDS
from derive.lecture.matrix_exp import MatrixExp, may_be_matrix
from derive.lecture.variations import variation_at
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3, Mass, g, l, p_alpha, p_gamma
from derive.symbolic.rotations import ANGLES, RATES

# --- the symbols of the notes ------------------------------------------------------------------
W = sp.symbols("omega1:4", real=True)              # ω̃ᵢ (the symbols of derive.symbolic.stability)
WD = sp.symbols("omega_d1:4", real=True)           # dω̃ᵢ/dt
BASIS = sp.symbols("e1 e2 e3", real=True)          # ê₁ ê₂ ê₃ (body)
PRIMED = sp.symbols("e1' e2' e3'", real=True)      # ê′ᵢ: the frame after the first two turns
INERTIAL = sp.symbols("e1^0 e2^0 e3^0", real=True)  # ê⁰ᵢ: the inertial frame
Omega, Omega1, Omega2 = sp.symbols("Omega Omega_1 Omega_2", real=True)
TAU = sp.symbols("tau1:4", real=True)              # τᵢ: the torque's body components
t = sp.Symbol("t", real=True)
FREE_NAMES = {"A": "A", "B": "B", "C": "C", "t": "t", "varphi": "varphi", "delta": "delta", "epsilon": "epsilon"}
"""Letters a text may use as its own constants without defining them (amplitude, time, phase…)."""


class Quantity(sp.Symbol):
    """A named quantity of the derivation (T, E, V_eff, …) as it appears in a formula: the checker
    replaces it by what the derivation says it is."""


class DT(sp.Function):
    """d/dt of its argument as written (``\\frac{d}{dt}``, ``\\frac{dX}{dt}``): the checker
    differentiates once it knows what the argument stands for."""

    def _latex(self, printer):
        # a correction written back into the text keeps the rate as the text writes one
        return r"\frac{\mathrm{d}}{\mathrm{d}t}\left(" + printer._print(self.args[0]) + r"\right)"


class Transposed(sp.Function):
    """Xᵀ of a matrix the text has named (``\\lambda^T``): the transpose once X is substituted."""


class MatProduct(sp.Function):
    """A product of the text's matrix names with a written matrix (``\\mathbf{R}_1 \\mathbf{I}_2``), kept
    in its order until the names are substituted: SymPy would take a name for a scalar and put it
    into every entry."""

    is_commutative = False


class Generic(sp.Symbol):
    """A symbol of the text's own (``u``, ``N_1``, ``T_{rot}``, ``m_1``): what it stands for is
    what the text says, in a definition the checker records, or nothing."""


def quantity(name: str) -> Quantity:
    return Quantity(name)


T_ = quantity("T")
LAGRANGIAN = quantity("L")
LVEC = quantity("Lvec")                  # angular momentum 𝐋
ENERGY = quantity("E")
EPRIME = quantity("E'")
VEFF = quantity("V_eff")
OMEGA_VEC = quantity("omega_vec")        # 𝛚 (= ω̃ in body components)
W_PRIMED = tuple(quantity(f"omega{k}'") for k in (1, 2, 3))     # ω′ᵢ = ê′ᵢ·𝛚, beside the primed axes
LMAG = quantity("|L|")                   # the magnitude of the angular momentum
DLDT = quantity("dL/dt")
DLDT_BODY = quantity("(dL/dt)_body")
MOMENTUM = {0: quantity("dL/dalpha_d"), 2: quantity("dL/dgamma_d"), 1: quantity("dL/dbeta_d")}

QUANTITY_LATEX = {
    T_: "T", LAGRANGIAN: "L", LVEC: r"\mathbf{L}", LMAG: "L", ENERGY: "E", EPRIME: "E'", VEFF: r"V_{\mathrm{eff}}",
    OMEGA_VEC: r"\boldsymbol{\omega}", DLDT: r"\frac{d\mathbf{L}}{dt}",
}


# --- errors ------------------------------------------------------------------------------------
class NotRead(Exception):
    """A formula that cannot be read: ``why`` says what and where."""

    def __init__(self, why: str, column: int | None = None):
        super().__init__(why)
        self.why = why
        self.column = column


class Unknown(NotRead):
    """An atom outside the vocabulary."""


class Words(NotRead):
    """Text, not a formula (``\\text{…}``)."""


# --- scanning ----------------------------------------------------------------------------------
GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta",
         "iota", "kappa", "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi",
         "varphi", "chi", "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma",
         "Phi", "Psi", "Omega", "top", "intercal",
         "hbar"}     # Planck's constant: a letter of the text's own, so a quantum claim about E or L stays unjudged
DECORATIONS = {"dot": "dot", "ddot": "ddot", "tilde": "tilde", "widetilde": "tilde", "hat": "hat",
               "widehat": "hat", **{name: "bold" for name in BOLD_NAMES}, "vec": "vec",
               "mathrm": "roman", "mathit": "roman", "overrightarrow": "vec",
               **{m: "mark" for m in ("bar", "breve", "check", "acute", "grave", "mathring")}}
"""An accent the derivation gives no meaning (``\\bar``, ``\\breve``, …) marks a symbol of the text's
own, apart from the letter without it (`Atom.mark`)."""
SPACES = SPACE_NAMES | QUAD_NAMES | {"left", "right", "big", "Big", "bigg", "Bigg", "displaystyle", "nonumber",
                                     "limits", "bigl", "bigr", "Bigl", "Bigr"}
"""The commands the scanner skips: the spacing, and the sizing and style that set nothing apart."""


class CrossMatrix(sp.Function):
    """[v]ₓ, the cross-product (skew) matrix of a column v: [v]ₓ w = v × w. Evaluated once v is a
    3-column (a text's symbols are substituted first); a product's factor v·s moves out."""

    becomes_matrix = True

    @classmethod
    def eval(cls, v):
        if isinstance(v, sp.MatrixBase) and v.shape == (3, 1):
            return sp.ImmutableMatrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
        if any(getattr(a, "is_commutative", True) is False for a in getattr(v, "args", ())):
            return None          # the text's matrices in it: evaluated once they are substituted
        if isinstance(v, sp.MatMul) or (isinstance(v, sp.Mul) and any(isinstance(a, sp.MatrixBase) for a in v.args)):
            done = v.doit() if hasattr(v, "doit") else v
            if isinstance(done, sp.MatrixBase) and done.shape == (3, 1):
                return cls.eval(done)
        if isinstance(v, sp.Expr) and v.free_symbols & set(BASIS):     # a vector in the body basis ê₁ ê₂ ê₃
            ex = sp.expand(v)
            coeffs = [ex.coeff(e) for e in BASIS]
            if sp.expand(ex - sum(c * e for c, e in zip(coeffs, BASIS))) == 0 and \
                    not any(c.free_symbols & set(BASIS) for c in coeffs):
                return cls.eval(sp.ImmutableMatrix(coeffs))
        return None


def _exp(arg):
    """The text's exp: of an argument that may become a matrix (a cross-product matrix or a name of
    the text's that does not commute), `MatrixExp`, which takes a skew matrix's by Rodrigues' formula."""
    return MatrixExp(arg) if may_be_matrix(arg) else sp.exp(arg)


FUNCTIONS = {"crossmatrix": CrossMatrix, "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "cot": sp.cot, "sec": sp.sec, "csc": sp.csc,
             "arcsin": sp.asin, "arccos": sp.acos, "arctan": sp.atan,
             "exp": _exp, "ln": sp.log, "log": sp.log, "sinh": sp.sinh, "cosh": sp.cosh, "tanh": sp.tanh,
             **elliptic.functions(Generic)}
INVERSES = {"sin": sp.asin, "cos": sp.acos, "tan": sp.atan}    # \tan^{-1} x is arctan x, as texts write it
RELATIONS = {"=": "=", "equiv": "≡", "approx": "≈", "simeq": "≈", "ge": "≥", "geq": "≥", "le": "≤", "ll": "≪", "gg": "≫",
             "leq": "≤", ">": ">", "<": "<", "neq": "≠", "ne": "≠", "to": "→", "Rightarrow": "⇒",
             "rightarrow": "→", "propto": "∝", "sim": "∼"}


@dataclass(frozen=True)
class Atom:
    """One symbol as written: its base letter (a Latin letter or a Greek name) and decorations."""

    base: str
    dots: int = 0
    tilde: bool = False
    hat: bool = False
    bold: bool = False
    sub: str = ""
    sup: str = ""
    primes: int = 0
    text: str = ""
    mark: str = ""
    """The accents the derivation gives no meaning, as written (``bar``, ``breve``): x̄ is the
    text's own symbol, never x."""

    def with_(self, **kw) -> "Atom":
        """The atom with the fields ``kw`` changed (the frozen dataclass's own ``__init__`` sets
        each of its ten fields through ``object.__setattr__``; its fields are plain values)."""
        if not kw.keys() <= _ATOM_FIELDS:
            raise TypeError(f"Atom has no field {sorted(kw.keys() - _ATOM_FIELDS)[0]}")
        new = object.__new__(Atom)
        new.__dict__.update(self.__dict__)
        new.__dict__.update(kw)
        return new


_ATOM_FIELDS = frozenset(Atom.__dataclass_fields__)


@dataclass(frozen=True)
class Tok:
    kind: str       # num, atom, op, rel, func, cmd, begin, end, text
    value: object
    pos: int        # 0-based offset in the formula


_CMD = re.compile(r"\\([A-Za-z]+|.)")


def group(s: str, i: int) -> tuple[str, int]:
    """The braced group starting at s[i] == '{' (content, index after it); a single token otherwise."""
    while i < len(s) and s[i] == " ":
        i += 1
    if i >= len(s):
        raise NotRead("a group is missing at the end", i + 1)
    if s[i] == "{":
        depth, j = 0, i
        while j < len(s):
            if s[j] == "\\":
                j += 2
                continue
            if s[j] == "{":
                depth += 1
            elif s[j] == "}":
                depth -= 1
                if depth == 0:
                    return s[i + 1:j], j + 1
            j += 1
        raise NotRead("unbalanced '{'", i + 1)
    m = _CMD.match(s, i)
    if m:
        return m.group(0), m.end()
    return s[i], i + 1


def _plain(s: str) -> str:
    """A subscript or superscript as plain text: 'eff', '1', 'ij', '\\alpha' → 'alpha', "'" kept."""
    s = re.sub(r"\\(mathrm|text|mathit|rm)\s*", "", s)
    s = s.replace("\\prime", "'").replace("{", "").replace("}", "").replace(" ", "")
    return re.sub(r"\\([A-Za-z]+)", r"\1", s)


def _atom_at(s: str, i: int) -> tuple[Atom, int]:
    """Read one (possibly decorated) atom at s[i]; return it and the index after its sub/superscripts."""
    m = _CMD.match(s, i)
    if m and m.group(1) in DECORATIONS:
        kind = DECORATIONS[m.group(1)]
        inner, j = group(s, m.end())
        if kind == "roman" and re.fullmatch(r"[A-Za-z]+", inner.strip()) and len(inner.strip()) > 1:
            atom = Atom(inner.strip())
        elif kind == "vec" and re.fullmatch(r"[A-Z]{2}", inner.strip()):
            atom = Atom(inner.strip(), bold=True)        # \vec{OC}: the vector from point O to point C
        else:
            atom, k = _atom_at(inner.strip(), 0)
            if k < len(inner.strip()):
                raise NotRead(f"cannot read '\\{m.group(1)}{{{inner}}}'", i + 1)
        if kind == "dot":
            atom = atom.with_(dots=atom.dots + 1)
        elif kind == "ddot":
            atom = atom.with_(dots=atom.dots + 2)
        elif kind == "tilde":
            atom = atom.with_(tilde=True)
        elif kind == "hat":
            atom = atom.with_(hat=True)
        elif kind in ("bold", "vec"):
            atom = atom.with_(bold=True)
        elif kind == "mark":
            atom = atom.with_(mark=m.group(1) + atom.mark)
    elif m and m.group(1) == "delta" and (k := variation_at(s, m.end(), GREEK | DECORATIONS.keys())) is not None:
        inner, j = _atom_at(s, k)           # δx: a variation of x, the text's own symbol (`variations`)
        atom = inner.with_(mark="delta" + inner.mark)
    elif m and m.group(1) in GREEK:
        atom, j = Atom(m.group(1)), m.end()
    elif i < len(s) and s[i].isalpha() and s[i].isascii():
        atom, j = Atom(s[i]), i + 1
    else:
        raise NotRead(f"cannot read {s[i:i + 12]!r}", i + 1)
    # sub- and superscripts that belong to the symbol: subscripts always; primes; a superscript
    # that is 0 or a prime (ê⁰₃, E′), or a letter on a bold symbol (a frame: 𝐑^α_β, 𝛚^α), or the
    # letter e on any other symbol (T^e, the external moment: a power e would be Euler's number), or a
    # sign closing the name (𝐯⁺, 𝐯_rel⁻: after and before an event); numeric superscripts otherwise are powers.
    while j < len(s):
        k = len(s) - len(s[j:].lstrip(" "))
        if k < len(s) and s[k] == "_":
            sub, j = group(s, k + 1)
            atom = atom.with_(sub=atom.sub + _plain(sub))
        elif k < len(s) and s[k] == "'":
            atom, j = atom.with_(primes=atom.primes + 1), k + 1
        elif k < len(s) and s[k] == "^":
            sup, after = group(s, k + 1)
            plain = _plain(sup)
            if plain and set(plain) == {"'"}:
                atom, j = atom.with_(primes=atom.primes + len(plain)), after
            elif plain == "0" and (atom.hat or atom.bold):
                atom, j = atom.with_(sup="0"), after
            elif atom.bold and not atom.sup and plain not in ("T", "top", "intercal", "t") and \
                    (plain in GREEK or re.fullmatch(r"[A-Za-z]", plain)):
                atom, j = atom.with_(sup=plain), after     # a frame's label on a vector or a matrix (𝐑^α_β)
            elif plain in ("+", "-") and re.match(SIGN_ENDS, s[after:]) and "^" not in atom.sub:
                atom, j = atom.with_(sub=atom.sub + "^" + plain), after     # kept with the subscript: every reader keys a name by it
            elif plain == "e" and atom.base != "e" and not atom.bold or re.fullmatch(r"\([A-Za-z]\)", plain) or re.fullmatch(LABEL_WORD, sup) and atom.base != "e":
                atom, j = atom.with_(sup=plain), after     # T^e, r^{(i)}, F^{ext}, g^{horizontal} (labels, a word): never a power
            else:
                break
        else:
            break
    return atom.with_(text=s[i:j].strip()), j


def scan(s: str) -> list[Tok]:
    """The tokens of one formula (see the module docstring), as a list of the caller's own."""
    return list(_scanned(s))


@functools.lru_cache(maxsize=4096)
def _scanned(s: str) -> tuple[Tok, ...]:
    """`scan`, memoised (its tokens and atoms are frozen): the checker's readers, and each second
    reading of a statement, scan the same formula again. A formula it cannot read raises each time."""
    toks: list[Tok] = []
    i, n = 0, len(s)
    while i < n:
        ch = s[i]
        if ch.isspace() or ch in "&~":
            i += 1
            continue
        if ch in DIGITS or (ch == "." and i + 1 < n and s[i + 1] in DIGITS):
            m = re.match(r"[0-9]*\.?[0-9]+|[0-9]+", s[i:])
            toks.append(Tok("num", m.group(0), i))
            i += m.end()
            continue
        if ch in "+-*/^_(){},|!":
            toks.append(Tok("op", ch, i))
            i += 1
            continue
        if ch in "[]":
            toks.append(Tok("op", "(" if ch == "[" else ")", i))
            i += 1
            continue
        if ch in "=<>":
            toks.append(Tok("rel", RELATIONS[ch], i))
            i += 1
            continue
        if ch == "'":
            raise NotRead("a prime on something that is not a symbol", i + 1)
        if ch == "\\":
            m = _CMD.match(s, i)
            if m is None:
                raise NotRead("a lone '\\' at the end", i + 1)
            name = m.group(1)
            if name == "\\":
                toks.append(Tok("op", "\\\\", i))
                i = m.end()
                continue
            if name in SPACES:
                i = m.end()
                continue
            if name in ("{", "}"):
                toks.append(Tok("op", "(" if name == "{" else ")", i))
                i = m.end()
                continue
            if name in ("lbrack", "rbrack", "lvert", "rvert", "vert"):
                toks.append(Tok("op", {"lbrack": "(", "rbrack": ")"}.get(name, "|"), i))
                i = m.end()
                continue
            if name in RELATIONS:
                toks.append(Tok("rel", RELATIONS[name], i))
                i = m.end()
                continue
            if name in ("text", "mbox", "textrm", "textbf", "textit", "hbox"):
                raise Words("words, not a formula", i + 1)
            if name in ("begin", "end"):
                env, j = group(s, m.end())
                toks.append(Tok(name, env.strip(), i))
                if name == "begin" and env.strip() in ("array", "alignat", "alignat*"):
                    spec = re.compile(r"\s*(?=\{)").match(s, j)
                    j = group(s, spec.end())[1] if spec else j      # its column layout {ccc}, {2}, {@{}c@{}}
                i = j
                continue
            if name in FUNCTIONS or name in ("frac", "dfrac", "tfrac", "sqrt", "sum", "partial", "cdot",
                                             "times", "otimes", "pm", "mp", "infty", "ldots", "cdots", "dots", "det"):
                toks.append(Tok("cmd", name, i))
                i = m.end()
                continue
            if name == "int" and written_with_bounds(s, i):     # a definite integral (its bounds written)
                toks.append(Tok("cmd", name, i))
                i = m.end()
                continue
            if name in ("dot", "ddot") and (rate := rate_of_product(s, i, m.end(), name, _reader)) is not None:
                toks.extend(rate[0])
                i = rate[1]
                continue
            if name in DECORATIONS or name in GREEK:
                atom, j = _atom_at(s, i)
                toks.append(Tok("atom", atom, i))
                i = j
                continue
            raise NotRead(f"cannot read '\\{name}'", i + 1)
        if ch.isalpha() and ch.isascii():
            atom, j = _atom_at(s, i)
            toks.append(Tok("atom", atom, i))
            i = j
            continue
        raise NotRead(f"cannot read {ch!r}", i + 1)
    return tuple(toks)


_reader = (group, _atom_at, _scanned, Tok, NotRead)        # the scanner's parts `rate_of_product` reads with


# --- the vocabulary ----------------------------------------------------------------------------
@dataclass
class Vocabulary:
    """Atoms → SymPy: the derivation's symbols and quantities under their usual spellings.

    ``angles`` are the notes' names of the three Euler angles, in order (the first about the
    inertial axis); ``defined`` holds the symbols the notes define themselves (Ω ≡ …).
    """

    angles: tuple = ("alpha", "beta", "gamma")
    aliases: tuple = ("phi", "theta", "psi")
    defined: dict = field(default_factory=dict)
    open: bool = False
    """Open to the text's own names: an atom outside the vocabulary is a symbol of the text's
    (`Generic`) instead of an unknown symbol."""
    generic: dict = field(default_factory=dict)
    """The text's own symbols met so far: Generic → the atom (without its text)."""
    omega_names: bool = False
    """Ω, Ω₁, Ω₂ are the lecture's frequencies (once the text defines Ω with ≡); otherwise a text's
    Ω is its own symbol."""
    names: object = None
    """The text's own names (`derive.lecture.names.Names`): they win over the usual spellings."""
    axial: int = 2
    """The body axis of the third turn (2 for z-y-z and z-x-z): the angular momentum's component
    on it is the third angle's momentum, I₃ω̃₃ = p_γ."""
    vertical: tuple = ()
    body_rate: object = None
    """() → the body components of the angular velocity's rate in the angles, their rates and
    accelerations (a callable, so that only a text that writes Ω̇ as a column pays for it)."""
    """The upward vertical's body components in the angles (Rᵀẑ), when the text names them (Poisson's γᵢ)."""
    names_off: bool = False
    """Read as if the text had named nothing (a second opinion on a learned name)."""
    delta_quantity: bool = False
    """The text writes δ alone (`derive.lecture.variations.delta_a_quantity`): δx is δ times x."""
    readings: dict = field(default_factory=dict)
    """A second reading of an ambiguous name, tried when the first makes a formula fail:
    ``{"L": LMAG}`` reads a plain L as the angular momentum's magnitude."""
    _atoms_met: dict = field(default_factory=dict, repr=False, compare=False)
    """Atom → the symbol `_generic` found for it last (see `_symbol_of`)."""

    def angle_index(self, base: str) -> int | None:
        if base in self.angles:
            return self.angles.index(base)
        head, sep, sub = base.partition("_")
        twin = {"phi": "varphi", "varphi": "phi"}.get(head)
        if twin and twin + sep + sub in self.angles:
            return self.angles.index(twin + sep + sub)      # ϕ and φ: two glyphs of one letter
        if base in self.aliases:
            return self.aliases.index(base)
        return None

    def resolve(self, a: Atom, env: dict | None = None):
        """The SymPy object an atom stands for (``env``: a summation index → 1, 2 or 3)."""
        env = env or {}
        mine = self.defined.get(a.with_(text=""))
        if mine is not None:
            return mine
        if a.mark.startswith("delta") and self.delta_quantity:    # δ the text's quantity: δx is δ times x
            x = self.resolve(a.with_(mark=a.mark[5:]), env)
            return None if x is None else self.resolve(Atom("delta"), env) * x
        if a.mark:              # x̄, Ĭ: the text's own symbol, whatever its letter means without the accent
            return self._generic(a) if self.open else None
        if self.names is not None and not self.names_off:
            value = self.names.value(a, env, self)      # the text's own names win
            if value is not None:
                return value
        sub = a.sub
        if sub and len(sub) == 1 and sub in env:
            sub = str(env[sub])
        k = self.angle_index(a.base + ("_" + a.sub if a.sub else ""))
        if k is not None and not a.hat and not a.tilde and not a.bold and not a.primes:
            if a.dots == 0:
                return ANGLES[k]
            return (RATES if a.dots == 1 else ACCELS)[k]
        b = a.base
        if b == "omega":
            if a.bold and not sub:
                return OMEGA_VEC if a.dots == 0 else None
            if sub in ("1", "2", "3") and a.primes == 1 and not a.dots and not a.bold:
                return W_PRIMED[int(sub) - 1]       # ω′ᵢ: a component on the primed axes ê′ᵢ
            if sub in ("1", "2", "3") and (not a.bold or not a.dots):
                i = int(sub) - 1          # 𝛚₃ in a scalar formula: the component, the bold a typeface
                if a.dots == 0:
                    return W[i]
                if a.dots == 1:
                    return WD[i]
            if sub == "0" and not self.open:
                raise Unknown(f"unknown symbol {a.text}")
        if b == "e" and (a.hat or a.bold):
            if sub in ("1", "2", "3"):
                i = int(sub) - 1
                if a.sup == "0":
                    return INERTIAL[i]
                if a.primes == 1:
                    return PRIMED[i]
                if a.primes == 0:
                    return BASIS[i]
        if not a.bold and not a.dots and not a.primes and (b + sub) in self.readings:
            return self.readings[b + sub]              # a second reading the checker is trying
        if b == "I" and not a.bold and not a.dots and not a.primes:
            if len(sub) == 2 and sub[0] == sub[1] and sub[0] in env:
                sub = str(env[sub[0]])            # Σ_i I_ii ω_i²: the principal moments
            if sub in ("1", "2", "3", "11", "22", "33"):
                return (I1, I2, I3)[int(sub[0]) - 1]
        if b == "M" and not sub and not a.dots:
            return Mass
        if b in ("g", "l") and not sub and not a.dots and not a.bold:
            return {"g": g, "l": l}[b]
        if b == "p" and not a.dots and not a.bold:
            k = self.angle_index(sub)
            if k in (0, 1, 2):          # the momentum conjugate to each angle: p_β = ∂L/∂β̇ is no constant
                return (p_alpha, MOMENTUM[1], p_gamma)[k]
        if b == "Omega" and not a.dots and not a.bold and self.omega_names:
            if sub == "":
                return Omega
            if sub in ("1", "2"):
                return (Omega1, Omega2)[int(sub) - 1]
        if b == "T" and not sub and not a.dots and not a.primes:
            return T_
        if b == "L" and not sub and not a.dots and not a.primes:
            return LVEC if a.bold else LAGRANGIAN
        if b == "L" and sub in ("1", "2", "3") and self.open and not self.names_off and not (a.bold or a.dots or a.primes or a.hat or a.tilde):
            return (I1, I2, I3)[int(sub) - 1] * W[int(sub) - 1]      # Lᵢ: the components of 𝐋 = Iᵢω̃ᵢ
        if b == "L" and sub in ("1", "2", "3") and self.open and not self.names_off and a.dots == 1 and not (a.bold or a.primes or a.hat or a.tilde):
            return (I1, I2, I3)[int(sub) - 1] * WD[int(sub) - 1]     # L̇ᵢ, the rate of the component Lᵢ = Iᵢω̃ᵢ: Iᵢω̃̇ᵢ
        if b == "E" and not sub and not a.dots:
            return {0: ENERGY, 1: EPRIME}.get(a.primes)
        if b == "V" and sub == "eff":
            return VEFF
        if not a.dots and not a.sub and not a.bold and not a.hat and not a.tilde and b in FREE_NAMES:
            # this module's own t: a Symbol made again is another object once SymPy's cache drops it
            return t if b == "t" else sp.Symbol(FREE_NAMES[b], real=True)
        plain = not a.dots and not a.bold and not a.hat and not a.tilde and not a.primes
        if plain and not a.sub and b == "pi":
            return sp.pi
        if plain and not a.sub and b == "e":
            return sp.E
        if b == "T" and sub in ("rot", "kin", "k", "R", "rotation") and not a.dots and not a.primes:
            return T_
        if self.open and not a.hat:
            return summed(self, a, env, self._generic)      # r_a under Σ_{a=1}^3: r₁, r₂, r₃
        return None

    def _generic(self, a: Atom):
        """The text's own symbol for an atom: one per spelling of base, decorations and scripts."""
        key = a.with_(text="")
        sym = self._symbol_of(key)
        if sym is not None:
            return sym
        name = ("d" * a.dots) + ("~" if a.tilde else "") + a.base + a.mark + (f"_{a.sub}" if a.sub else "") \
            + ("'" * a.primes) + (f"^{a.sup}" if a.sup else "")
        undotted = self._symbol_of(key.with_(dots=0)) if a.dots else None
        if undotted is not None and undotted.is_commutative is False:
            sym = Generic(name, commutative=False)      # Ẋ of a matrix: a matrix, kept in its place in a product
        else:
            sym = Generic(name, real=True)
        self.generic[sym], self._atoms_met[key] = key, sym
        return sym

    def _symbol_of(self, key: Atom):
        """The first of `generic`'s symbols whose atom is ``key``, or None: from an index of the atoms
        met where `generic` still gives that symbol this atom (it holds one symbol per atom: `_generic`
        adds an atom only when it finds none, and the checker's one edit of it, a name becoming a
        matrix, moves an atom to a new symbol), else by a walk through `generic`."""
        sym = self._atoms_met.get(key)
        if sym is not None and self.generic.get(sym) == key:
            return sym
        sym = next((s for s, atom in self.generic.items() if atom == key), None)
        if sym is not None:
            self._atoms_met[key] = sym
        return sym

    def undotted(self, sym):
        """For the text's symbol Ẋ: (X, number of dots), or None."""
        atom = self.generic.get(sym)
        if atom is None or not atom.dots:
            return None
        return self._generic(atom.with_(dots=0)), atom.dots


def p_alpha_sym():
    """p for the first angle (the derivation's ``p_alpha``)."""
    return p_alpha


def p_gamma_sym():
    """p for the third angle (the derivation's ``p_gamma``)."""
    return p_gamma

