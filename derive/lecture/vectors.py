"""Vectors, tensors, sums over particles and frame derivatives: the displays `derive.lecture.latex` refuses.

The scalar reader (`derive.lecture.latex`) reads formulas in the derivation's scalar symbols. The
first pages of a rigid-body lecture are written in vectors instead — T = Σ_p ½ m_p (ω × r_p)·(ω × r_p),
𝐋 = Ï·ω, (d𝐫/dt)_inertial = ω × 𝐫 — and this module reads and checks those, through the same
whitelist (the tokens of `derive.lecture.latex.scan`: never ``eval``, never ``sympify``).
The grammar is `derive.lecture.vector_parser`'s (the one textbook vector algebra is read with,
under `derive.lecture.vector_algebra_model`); the three models below are
`derive.lecture.vector_models`'.

Values are SymPy objects of three shapes: a scalar, a 3-vector (a 3×1 matrix of body components)
and a tensor (a 3×3 matrix). The operations are the usual ones:

* ``a \\times b`` — the cross product (binds tighter than ``\\cdot``: a·b×c = a·(b×c));
* ``a \\cdot b`` — the dot product, or the contraction of a tensor with a vector (Ï·ω = Ï ω,
  ω·Ï = Ïᵀ ω, so ω·Ï·ω = ωᵀ Ï ω);
* ``a b`` of two vectors — the dyadic a bᵀ; ``|v|`` = √(v·v), ``v^2`` = v·v;
* ``\\mathbf{1}`` (𝟙) — the unit tensor; ``\\delta_{ij}`` — Kronecker's delta.

Three models say what the symbols stand for (chosen per statement, see `model_of`):

``particle``
    a system of particles: m_p, 𝐫_p generic (x_p, y_p, z_p), 𝐯_p = ω × 𝐫_p (the velocity of a
    point of a rigid body, the kinematic fact the notes use), ω = (ω̃₁, ω̃₂, ω̃₃) generic. A sum
    over particles Σ_p is read for **two** generic particles: a sum is linear in its summand, so
    the summand identity for a generic particle proves the sum identity, and a second particle
    keeps a formula that is not linear in the sum (a square of a sum) from passing. T ≡ Σ_p ½ m_p v_p²,
    𝐋 ≡ Σ_p m_p 𝐫_p × 𝐯_p, and the tensor Ï ≡ ∂²T/∂ω∂ω (the Hessian of T in ω: independent of
    how the notes write Ï) with components I_xx … I_zz, I_ij (i, j = 1, 2, 3).
``principal``
    body principal axes: Ï = diag(I₁, I₂, I₃), ê_i the body axes, 𝐋 = (I₁ω̃₁, I₂ω̃₂, I₃ω̃₃),
    T = ½ Σ I_i ω̃_i².
``frame``
    derivatives in a rotating frame, with R(t) of the notes' Euler angles (R = body → inertial
    components, ``derive.symbolic.rotations``): in body components the inertial derivative of a
    vector X is Rᵀ d(R X)/dt = Rᵀ Ṙ X + Ẋ and the body derivative ``(dX/dt)_{body}`` is Ẋ; 𝐫 is
    body-fixed (Ẋ = 0), 𝐋 has generic time-dependent body components, ω is the derivation's ω̃
    (angles and rates). ``(d𝐫/dt)_{inertial} = ω × 𝐫`` and the transport theorem
    d𝐋/dt = (d𝐋/dt)_body + ω × 𝐋 are checked that way.

A free body index (``\\hat{\\mathbf{e}}_i``, ``I_{ij}`` outside a sum) means "for i = 1, 2, 3": the
statement is read for each value. The torque τ as a whole side (d𝐋/dt = τ) is the law of motion,
which the derivation starts from: it is not checked.
"""
from __future__ import annotations

import itertools
import re

import sympy as sp
from sympy.core.function import AppliedUndef

from derive.lecture import latex as lx
from derive.lecture import vector_models as vm
from derive.lecture import vector_parser as vp
from derive.lecture import zero_test as zt
from derive.lecture.vector_models import Model, model_of, prepare, vectorish
from derive.lecture.vector_parser import Reading, _is_tensor, _is_vector
from derive.lecture.latex_spellings import VECTOR_MARK


_ROW_VECTOR = re.compile(VECTOR_MARK + r"\s*\{[^{}]*\}(?:\s*_\s*(?:\{[^{}]*\}|\w))?\s*\^\s*"
                         r"(?:T\b|\{\s*(?:T|\\top|\\mathrm\{T\}|\\mathsf\{T\})\s*\}|\\top\b)")
"""A bold vector transposed, ``\\boldsymbol{\\omega}^{T}``: a row, so the statement is in matrix notation."""
_BRACKET_TENSOR = re.compile(r"\[\s*" + VECTOR_MARK + r"\s*\{\s*I\s*\}(?:\s*_\s*(?:\{[^{}]*\}|\w))?\s*\]")
"""Schaub's tensor in brackets, ``[\\mathbf{I}_C]``: a matrix, so the statement is in matrix notation."""


# ---- reading and checking one statement ----------------------------------------------------------
def read(text: str, vocab, derivation, sticky: str | None = None) -> Reading:
    """Read a statement with the vector grammar in the model `model_of` picks (`lx.NotRead` when it
    cannot); ``reading.model`` is that model's name."""
    text = prepare(text)
    toks = lx.scan_cells(text)
    if not vectorish(toks):
        raise lx.NotRead("not a vector formula")
    name = model_of(toks, sticky)
    plain_l = any(t.kind == "atom" and t.value.base == "I" and (t.value.bold or t.value.dots == 2) for t in toks) \
        or any(t.kind == "cmd" and t.value == "times" for t in toks)
    model = Model(name, derivation, plain_l)
    if name == "principal" and any(t.kind == "atom" and t.value.base == "I" and not (t.value.sub or t.value.bold or
                                   t.value.dots or t.value.sup) for t in toks):
        model.matrix_products = True     # a plain I (a text's matrix, not the lecture's Ï·) acts on 𝛚 by juxtaposition
    if _ROW_VECTOR.search(text) or _BRACKET_TENSOR.search(text):
        model.matrix_products = True     # 𝛚ᵀ 𝐈 𝛚, [𝐈]𝛚: a row or a bracketed tensor is matrix notation, 𝐈 acting by juxtaposition
    if _bold_tensor_on_omega(toks):
        model.matrix_products = True     # 𝐈𝛚 written side by side: the text sets its tensor on 𝛚 as a matrix on a column
    return vp.read(toks, text, vocab, model, name)


def _bold_tensor_on_omega(toks) -> bool:
    """A bold I set right before a bold or arrowed 𝛚 (``\\mathbf{I} \\boldsymbol{\\omega}``): the inertia tensor
    acting on the angular velocity by juxtaposition, as matrix notation writes it."""
    return any(t.kind == "atom" and t.value.base == "I" and t.value.bold and not (t.value.sup or t.value.dots)
               and u.kind == "atom" and u.value.base == "omega" and (u.value.bold or u.value.text.startswith("\\vec"))
               and not u.value.dots for t, u in zip(toks, toks[1:]))


def _zero(a, b, seed) -> tuple[bool, str]:
    """a = b? Exact for polynomials (the particle and principal models), else `zero_test`'s test. A
    vector equal to 0 is equal to the zero vector."""
    if isinstance(a, sp.MatrixBase) and b == 0 and not isinstance(b, sp.MatrixBase):
        b = sp.zeros(*a.shape)
    elif isinstance(b, sp.MatrixBase) and a == 0 and not isinstance(a, sp.MatrixBase):
        a = sp.zeros(*b.shape)
    if isinstance(a, sp.MatrixBase) != isinstance(b, sp.MatrixBase) or \
            (isinstance(a, sp.MatrixBase) and a.shape != b.shape):
        return False, f"a {_shape(a)} against a {_shape(b)}"
    A = sp.Matrix(a) if isinstance(a, sp.MatrixBase) else sp.Matrix([a])
    B = sp.Matrix(b) if isinstance(b, sp.MatrixBase) else sp.Matrix([b])
    if any(zt.atoms(e, lx.DT, AppliedUndef) for e in (*A, *B)):
        # d/dt of |𝐋|² left as written cannot be evaluated at a point: undecided, never a slip
        return False, "a rate the reader leaves unevaluated (d/dt of a product) against a side it evaluates"
    diffs = [zt.bounded_expand(x - y) for x, y in zip(A, B)]
    if all(d == 0 for d in diffs):
        return True, "exact (expand)"
    if not any(d.has(sp.sin, sp.cos) for d in diffs):
        k = next(n for n, d in enumerate(diffs) if d != 0)
        where = f" (component {k + 1})" if len(diffs) == 3 else (f" (entry {k // 3 + 1},{k % 3 + 1})" if len(diffs) == 9 else "")
        return False, f"exact (expand): claim − derived ≠ 0{where}"
    found = None if any(map(zt.surely_nonzero, diffs)) else zt.counterexample(A, B, seed)
    if found is not None:             # the numeric test's outcome, without the symbolic steps' cost
        return found.ok, found.method
    try:
        steps = [None] if any(map(zt.surely_nonzero, diffs)) else [zt.symbolic_zero(d) for d in diffs]
    except (sp.PolynomialError, TypeError, ValueError):
        steps = [None]
    if all(steps):
        return True, steps[0]
    out = zt.numeric_zero(A, B, seed)
    return out.ok, out.method


def _shape(v) -> str:
    if _is_vector(v):
        return "vector"
    if _is_tensor(v):
        return "tensor"
    return "scalar"


WHY = {
    "particle": "sums over particles read for two generic particles (m_p, r_p generic, v_p = ω × r_p for "
                "a rigid body; a sum is linear in its summand, so the summand identity proves it; "
                "Ï ≡ ∂²T/∂ω∂ω)",
    "principal": "in the body's principal axes (Ï = diag(I₁, I₂, I₃), ê_i the body axes)",
    "frame": "with R(t) of the Euler angles: body components of d(R X)/dt = Rᵀ Ṙ X + Ẋ, 𝐫 body-fixed, "
             "ω̃ from the derivation",
}


def generics(value) -> set:
    """The text's own vectors a value involves (`vector_models.GENERIC`), by letter."""
    return {s.name.split(vm.GENERIC)[0] for s in getattr(value, "free_symbols", ()) if vm.GENERIC in s.name}


def reference(reading: Reading, k: int) -> int | None:
    """The member member k is checked against: the first one before it that involves the same
    vectors of the text's (``M = dH/dt|_i = dH/dt|_b + ω × H``: the last two with each other; a
    vector the derivation does not tie, M, equals nothing it can check); None if there is none."""
    first = reading.members[0]
    mine = generics(first[k].value)
    return next((j for j in range(k) if generics(first[j].value) == mine), None)


def holds(reading: Reading, k: int, seed: str, ref: int = 0) -> tuple[bool, str]:
    """Member k against member ``ref`` (the first, unless said), for each value of the free indices."""
    for n, members in enumerate(reading.members):
        ok, how = _zero(members[k].value, members[ref].value, f"{seed}/{n}")
        if not ok:
            where = ""
            if reading.free:
                vals = list(itertools.product((1, 2, 3), repeat=len(reading.free)))[n]
                where = " at " + ", ".join(f"{c} = {v}" for c, v in zip(reading.free, vals))
            return False, how + where
    return True, how


def surely_differs(reading: Reading, k: int, ref: int = 0) -> bool:
    """Whether member k is proved unequal to member ``ref`` for some value of the free indices: a
    component of their difference, built from symbols by sums, products, integer powers, sin, cos,
    tan and exp, non-zero at an exact point (`zero_test.surely_nonzero`). Such a difference is zero
    on no open set, so `holds` finds the members unequal too. A screen for the candidates of a
    correction, whose reasons are not given."""
    for members in reading.members:
        a, b = members[k].value, members[ref].value
        if isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase) and a.shape == b.shape:
            diffs = [x - y for x, y in zip(a, b)]
        elif not isinstance(a, sp.MatrixBase) and not isinstance(b, sp.MatrixBase):
            diffs = [a - b]
        else:
            continue
        if any(_analytic(d) and zt.surely_nonzero(d) for d in diffs):
            return True
    return False


def _analytic(d) -> bool:
    """Whether d is built from symbols and numbers by sums, products, integer powers, sin, cos, tan
    and exp (no roots, |·| or functions of the text's)."""
    for node in sp.preorder_traversal(d):
        if node.is_Pow and not node.exp.is_Integer:
            return False
        if isinstance(node, sp.Function) and not isinstance(node, (sp.sin, sp.cos, sp.tan, sp.exp)):
            return False
        if not isinstance(node, (sp.Expr, sp.Function)) or node.is_Atom and not (node.is_Symbol or node.is_Number):
            return False
    return True


def member_edits(src: str):
    """Single edits of one member's LaTeX, as (edited, what): a sign, a factor ½ or 2, an index,
    the order of a cross product, a power."""
    out = [(e, "the order of a cross product") for e in _cross_swaps(src)]
    lead = re.match(r"\s*-", src)
    out.append((src[lead.end():] if lead else "-" + src, "the sign of the whole side"))
    for m in re.finditer(r"(?<![_^{])[+\-]", src):
        out.append((src[:m.start()] + ("-" if m.group() == "+" else "+") + src[m.end():], "a sign"))
    for m in re.finditer(r"\\frac\s*\{\s*1\s*\}\s*\{\s*2\s*\}", src):
        out.append((src[:m.start()] + src[m.end():], "a factor 1/2"))
        out.append((src[:m.start()] + "2" + src[m.end():], "a factor 4"))
    out.append(("\\frac{1}{2} " + src.lstrip(), "a factor 1/2"))
    out.append(("2 " + src.lstrip(), "a factor 2"))
    for m in re.finditer(r"_\{?\s*([A-Za-z0-9]{1,2})\s*\}?", src):
        sub = m.group(1)
        for pos, ch in enumerate(sub):
            for other in {"i": "j", "j": "i", "1": "23", "2": "13", "3": "12"}.get(ch, ""):
                new = sub[:pos] + other + sub[pos + 1:]
                out.append((src[:m.start(1)] + new + src[m.end(1):], "an index"))
    for m in re.finditer(r"\^\s*\{?\s*2\s*\}?", src):
        out.append((src[:m.start()] + src[m.end():], "a power"))
    seen, unique = {src}, []
    for e, what in out:
        if e not in seen:
            seen.add(e)
            unique.append((e, what))
    return unique


def edited_readings(reading, k: int, reread, most: int):
    """Member k of a reading under each of its first ``most`` single edits (`member_edits`), read
    again by ``reread`` (the statement's text to a reading): (n, edited member, what, edited
    statement, its reading), for the readings of the same shape (free indices, members)."""
    src, m = reading.source, reading.members[0][k]
    for n, (edited, what) in enumerate(member_edits(src[m.start:m.end])):
        if n >= most:
            return
        again_src = src[:m.start] + edited + " " + src[m.end:]
        try:
            again = reread(again_src)
        except lx.NotRead:
            continue
        if again.free == reading.free and len(again.members[0]) == len(reading.members[0]):
            yield n, edited, what, again_src, again


def _operand(src: str, at: int, forward: bool) -> tuple[int, int] | None:
    """The span of the operand of × next to ``at``: one atom or a bracketed group."""
    try:
        toks = lx.scan(src)
    except lx.NotRead:
        return None
    k = next((n for n, t in enumerate(toks) if t.pos == at), None)
    if k is None:
        return None
    j = k + 1 if forward else k - 1
    if not 0 <= j < len(toks):
        return None
    t = toks[j]
    if t.kind == "atom":
        return t.pos, t.pos + len(t.value.text)
    if t.kind == "op" and t.value in ("(", ")"):
        step, depth = (1, 0) if forward else (-1, 0)
        for n in range(j, len(toks) if forward else -1, step):
            if toks[n].kind == "op" and toks[n].value == "(":
                depth += 1
            elif toks[n].kind == "op" and toks[n].value == ")":
                depth -= 1
            if depth == 0:
                lo, hi = sorted((t.pos, toks[n].pos))
                if src[:lo].endswith("\\left"):
                    lo -= 5
                return lo, hi + 1
    return None


def _cross_swaps(src: str):
    """Each ``a \\times b`` of the LaTeX with its operands swapped, the shortest first (the innermost
    product: r × (r × ω) is mended as r × (ω × r) before (r × ω) × r)."""
    swaps = []
    for m in re.finditer(r"\\times", src):
        left, right = _operand(src, m.start(), False), _operand(src, m.start(), True)
        if left and right:
            swaps.append((right[1] - left[0], src[:left[0]] + src[right[0]:right[1]] + src[left[1]:right[0]]
                          + src[left[0]:left[1]] + src[right[1]:]))
    return [e for _, e in sorted(swaps, key=lambda x: x[0])]


def restore(latex: str) -> str:
    """The LaTeX a reader wrote back from `prepare`'s: 𝟙 as ``\\mathbf{1}``."""
    return latex.replace("\\mathbf{\\Xi}", "\\mathbf{1}")



_FORCE, _VELOCITY, GEN = {"F", "f"}, {"V", "v"}, vm.GENERIC


def newton(reading: Reading, derivation) -> tuple[str, str] | None:
    """``\\vec{F} = m \\frac{d\\vec{V}}{dt_i}``: Newton's second law for the centre of mass, a law
    (stated, not derived) recognised in its form 𝐅 = m (d𝐕/dt)_inertial, whose body components are
    m (Rᵀ Ṙ 𝐕 + 𝐕̇). As (verdict, why), or None when the statement is not a force set equal to a
    multiple of a velocity's rate. A body-frame derivative, or a factor other than the mass, fails."""
    first = reading.members[0]
    force, other = generics(first[0].value), generics(first[1].value)
    if reading.model != "frame" or len(first) != 2 or force - _FORCE or len(force) != 1 \
            or len(other) != 1 or other - _VELOCITY:
        return None
    rhs = first[1].value
    mass = [s for s in getattr(rhs, "free_symbols", ()) if s.name.split("_")[0] in ("m", "M") and GEN not in s.name]
    if len(mass) != 1 or not _is_vector(rhs):
        return None
    model = Model("frame", derivation)
    law = mass[0] * model.derivative(model.generic_vector(next(iter(other))), "inertial")
    ok, how = _zero(rhs, law, "newton")
    if ok:
        return "holds", ("Newton's second law, 𝐅 = m (d𝐕/dt) with the derivative in an inertial frame: a law, "
                         "recognised in its form (recorded, then used)")
    V = model.generic_vector(next(iter(other)))
    body = _zero(rhs, mass[0] * model.derivative(V, "body"), "newton/body")[0]
    return "fails", ("Newton's second law is 𝐅 = m (d𝐕/dt) in an inertial frame; as written: "
                     + ("the body-frame derivative, which lacks 𝛚 × 𝐕" if body else how))
