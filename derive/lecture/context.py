"""What a text has said so far, for the notes checker: the context of a section (its settings,
small quantities, sign cases, definitions, equations) and how headings, assumptions in the prose
("for a symmetric top", "$\\omega_2, \\omega_3$ are first-order small", "$0 \\approx \\omega_y
\\ll \\omega_x$") and sign statements change it.

Gives `Context`, the mixin `Reading` of `derive.lecture.notes_check.Checker` and
`sign_under_orderings` (the sign of a difference for every value the text's orderings allow).

May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.comparing`, :mod:`derive.lecture.notes`, :mod:`derive.lecture.zero_test`,
:mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass, field

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture.comparing import free
from derive.lecture.notes import small_before_much_less
from derive.lecture.zero_test import expanded
from derive.symbolic.lagrangian import I1, I2, I3
from derive.symbolic.rotations import ANGLES


def is_ordering(values) -> bool:
    """Whether a chain the text writes (``I_1 < I_2 < I_3``, ``-1 < u_1 < u_2 < 1 < u_3``) orders
    symbols: every member a principal moment, a symbol of the text's or a number, one symbol at least."""
    values = [sp.sympify(v) for v in values]
    return len(values) > 1 and all(v.is_number and v.is_real or isinstance(v, sp.Symbol) and
                                   (v in (I1, I2, I3) or isinstance(v, lx.Generic)) for v in values) \
        and any(isinstance(v, sp.Symbol) for v in values)


@functools.lru_cache(maxsize=1024)
def sign_under_orderings(d, syms: tuple, orderings: tuple) -> str:
    """'positive', 'negative' or 'mixed': the sign of d for every value the orderings allow.
    Each chain x₁ < x₂ < … becomes positive gaps (x₁ = g₁, x₂ = g₁ + g₂, …: sizes and moments are
    positive), every other symbol a non-zero real; SymPy's sign rules then decide, or not. A chain
    with numbers in it starts from its first number c (the symbols before it c − gaps, after it
    c + gaps), and one that meets a symbol an earlier chain placed goes on from there; the bounds
    this drops only widen the values tried, so a sign found holds for the text's values too.
    Memoised: a chain of inequalities asks again for the sign of a difference it has met."""
    rep, k = {}, 0

    def gap():
        nonlocal k
        k += 1
        return sp.Symbol(f"gap{k}", positive=True)

    for chain in orderings:
        numbers = [j for j, x in enumerate(chain) if sp.sympify(x).is_number]
        start = numbers[0] if numbers else 0
        total = sp.sympify(chain[start]) if numbers else sp.S.Zero
        for x in reversed(chain[:start]):
            total = total - gap()
            rep.setdefault(x, total)
        total = sp.sympify(chain[start]) if numbers else sp.S.Zero
        for x in chain[start + 1 if numbers else 0:]:
            if sp.sympify(x).is_number:
                continue              # a bound met again: dropped (it would tie the gaps)
            if x in rep:
                total = rep[x]
                continue
            total = total + gap()
            rep[x] = total
    for x in syms:
        rep.setdefault(x, sp.Symbol(f"{x.name}_r", real=True, nonzero=True))
    e = sp.factor(sp.together(expanded(d.xreplace(rep))))
    if e.is_positive:
        return "positive"
    if e.is_negative:
        return "negative"
    return "mixed"


@dataclass
class Context:
    """What the text has said so far: assumptions of the section, definitions, equations."""

    subs: dict = field(default_factory=dict)          # I₂ → I₁, p_α → p_γ, ω̃̇₃ → 0
    small: list = field(default_factory=list)         # β ≈ 0
    cases: list = field(default_factory=lambda: [{}])  # sign cases
    solutions: dict = field(default_factory=dict)     # ω̃ᵢ → f(t)
    defs: dict = field(default_factory=dict)          # Ω → the notes' definition
    eoms: list = field(default_factory=list)          # (residual as written, line, settings of ω̃)
    head: str | None = None                           # left side continued by "= …" displays
    assumptions: list = field(default_factory=list)   # their LaTeX, for the why
    vec_model: str | None = None                      # "particle" after a sum over particles
    stated: dict = field(default_factory=dict)        # I₂ → where the text said I₁ = I₂
    orientation: int | None = None                    # the line that put the fixed first axis along 𝐋
    orientation_prose: bool = False                   # … said in the section's prose (it ends with the section)
    first_order: set = field(default_factory=set)     # ω̃ᵢ the prose calls small: equations to first order
    forms_held: dict = field(default_factory=dict)    # a quantity → the derived form the text's definition held with
    orderings: list = field(default_factory=list)     # chains the text states, smallest first (I₁ < I₂ < I₃)
    eoms2: list = field(default_factory=list)         # (second-order residual, its ω̃̈ symbols, settings of ω̃)
    running: dict = field(default_factory=dict)       # the text's names defined in running text → line
    confirmed: set = field(default_factory=set)       # those of them a claim that holds was read with
    motion: dict = field(default_factory=dict)        # a rate the text states for its motion → (value, line)
    given: dict = field(default_factory=dict)         # a left side as written → (the value the text set it to, where): kept across sections
    own_motion: dict = field(default_factory=dict)    # a variable of the text's → (power n, F, line) of its u̇ⁿ = F(u)
    changes: dict = field(default_factory=dict)       # a new variable v → (u, S(v), line) of the text's u = S(v)
    angles_stated: dict = field(default_factory=dict)  # an angle the text gives in constants (tan θ = …) → (value, line)
    held: dict = field(default_factory=dict)          # an angle running text holds at a number (θ = π/2) → (value, line); None if two
    vectors: dict = field(default_factory=dict)        # a vector of the text's → (its components, what it defined it as)
    centre_line: int | None = None                    # the line whose settings of the centre of mass hold
    constant_case: tuple | None = None                # (line, LaTeX) of a case the prose sets by constants alone
    perturbation: dict = field(default_factory=dict)  # a symbol η the text names (base, index, bold) → (i, cᵢ) of ω̃ᵢ = cᵢ + ηᵢ
    perturbation_order: int | None = None             # the order its equations keep once a remainder O(ηⁿ) was written
    steady: tuple | None = None                       # the constant column c the text set 𝛚 to, which a column δ𝛚 perturbs
    torques: dict = field(default_factory=dict)       # a name of the text's → its value in τᵢ, the torque it wrote in component i's equation
    untorqued: set = field(default_factory=set)       # components i whose equation of motion the text wrote with no torque
    columns: set = field(default_factory=set)         # the text's names it set to a written matrix in this section

    def new_section(self):
        self.subs, self.small, self.cases, self.solutions = {}, [], [{}], {}
        self.head, self.assumptions, self.vec_model, self.stated = None, [], None, {}
        self.first_order = set()
        self.motion, self.own_motion, self.changes, self.angles_stated = {}, {}, {}, {}
        self.vectors, self.held, self.constant_case = {}, {}, None
        self.perturbation, self.perturbation_order, self.torques, self.untorqued = {}, None, {}, set()
        self.steady = None
        self.columns = set()
        if self.orientation_prose:
            self.orientation, self.orientation_prose = None, False


class Reading:
    """Mixin of the checker: keeps ``self.ctx`` as the text goes on. Uses ``self.vocab``,
    ``self._add``, ``self._flush``, ``self._new_name``, ``self._spin_set``, ``self._snapshot`` and ``self.tex``."""

    def _enter_section(self, level):
        """A heading: what the text assumed in the enclosing section (a heading of a lower level)
        before its first subsection holds in each subsection; what a subsection assumed ends
        with it."""
        stack = self._sections
        if stack and stack[-1][0] < level and stack[-1][1] is None:
            stack[-1][1] = self._snapshot()            # the parent's assumptions, for its children
        while stack and stack[-1][0] >= level:
            stack.pop()
        self.ctx.new_section()
        self.vocab.readings.pop("L", None)           # L read as |𝐋| holds to the end of its section
        if stack and stack[-1][1] is not None:
            parent = stack[-1][1]
            self.ctx.subs, self.ctx.small = dict(parent.subs), list(parent.small)
            self.ctx.assumptions, self.ctx.defs = list(parent.assumptions), dict(self.ctx.defs)
            self.ctx.stated = dict(parent.stated)
        stack.append([level, None])

    def _symmetric(self, line, words):
        """The text says the body is symmetric ("a symmetric top", a section's title): I₂ = I₁."""
        if I1 not in self.ctx.subs and I2 not in self.ctx.subs:
            self.ctx.subs[I2] = I1
            self.ctx.assumptions.append(f"I_2 = I_1 ({words.strip()!r}, line {line})")
            self.ctx.stated[I2] = f"line {line}"

    def _assume(self, item):
        try:
            parsed = lx.parse(item.latex, self.vocab)
        except lx.NotRead as err:
            if re.search(r"\\tau(?![a-z])", item.latex):
                self.ctx.assumptions.append(item.latex)      # τ = 0: the torque-free case
            if item.display:
                self._add(item.line, item.latex, "assumption", "unchecked", f"an assumption ({err.why})")
            return
        m0 = parsed.members[0].value if parsed.members else None
        m1 = parsed.members[1].value if len(parsed.members) == 2 else None
        if m1 is not None and parsed.relations[0] in ("=", "≡") and not isinstance(m0, sp.Symbol) \
                and self._new_name(m1) and free(m0) and not free(m0) & {m1}:
            m0, m1 = m1, m0                      # "let (expression) = α₂": the new name written on the right
        if m1 is not None and parsed.relations[0] in ("=", "≡") and self._new_name(m0) \
                and free(m1) and not free(m1) & {m0}:
            self.ctx.defs[m0] = m1                # "with the substitution u = cos θ": a new name
            if item.display:
                self._add(item.line, item.latex, "new symbol", "unchecked",
                          f"defines the text's symbol {self.tex(m0)} (recorded, then used)")
            return
        if item.display:
            self._add(item.line, item.latex, "assumption", "unchecked",
                      "an assumption of the text: applies to the displays that follow, up to the next heading")
        self.ctx.assumptions.append(item.latex)
        values = [m.value for m in parsed.members]
        if set(parsed.relations) <= {"<", ">", "≤", "≥"} and is_ordering(values):
            self.ctx.orderings.append(values if parsed.relations[0] in ("<", "≤") else values[::-1])
            return
        if len(parsed.members) != 2:
            return
        a, b = parsed.members[0].value, parsed.members[1].value
        rel = parsed.relations[0]
        if rel == "≈" and b == 0 and isinstance(a, sp.Symbol):
            if a in ANGLES:
                self.ctx.small.append(a)
            else:
                self.ctx.subs[a] = sp.S.Zero
        elif rel in ("=", "≈") and isinstance(a, sp.Symbol) and not isinstance(a, lx.Quantity):
            if a.xreplace(self.ctx.subs) == sp.sympify(b).xreplace(self.ctx.subs):
                return                            # already so (the prose said "a symmetric top")
            self.ctx.subs[a] = b
            self.ctx.stated[a] = f"line {item.line}"
            self._spin_set(a, b)

    def _small_before_ll(self, latex):
        """``0 \\approx \\omega_y, \\omega_z \\ll \\omega_x``: what stands before ≪ is small."""
        if "\\ll" in latex:
            self._small([small_before_much_less(latex)])

    def _small(self, symbols):
        """The prose calls ω̃ᵢ (or Lᵢ = Iᵢω̃ᵢ) small: the equations that follow hold to first order in them."""
        moments = (I1, I2, I3)
        for text in symbols:
            for part in text.split(","):
                try:
                    parsed = lx.parse(part, self.vocab)
                except lx.NotRead:
                    continue
                if len(parsed.members) != 1:
                    continue
                v = parsed.members[0].value
                for i, w in enumerate(lx.W):
                    if (v == w or v == moments[i] * w) and w not in self.ctx.first_order:
                        self._flush()       # the solutions before it were written under the smallness they had
                        self.ctx.first_order.add(w)

    def _signs(self, item):
        syms = []
        for s in item.symbols:
            try:
                p = lx.parse(s, self.vocab)
            except lx.NotRead:
                return
            syms.append(p.members[0].value)
        if len(syms) != 2 or not all(isinstance(s, sp.Symbol) for s in syms):
            return
        u, v = sp.Dummy("u", positive=True), sp.Dummy("v", positive=True)
        x, y = syms
        if item.text == "same":
            self.ctx.cases = [{x: u, y: v}, {x: -u, y: -v}]
        else:
            self.ctx.cases = [{x: u, y: -v}, {x: -u, y: v}]
