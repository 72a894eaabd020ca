"""A chain headed by the text's own vector: ``\\vec a_i^t = \\alpha \\hat k \\times \\vec r_i = \\alpha(x_i \\hat j - y_i \\hat i)``.

Takes: one statement's LaTeX. Gives: `split`, the head (a single bold symbol the vector model
cannot tie to the body — a label such as a_i^t, F_{i,inertial}) and the rest of the chain after its
first ``=``, when the rest is itself a chain. May import: the standard library,
:mod:`derive.lecture.latex`, :mod:`derive.lecture.vector_algebra_model`.

Texts name an intermediate vector and then work it out: the name says what the chain is about,
and the members after it are claims about each other (each equal to the next) that can be checked
without knowing the name. The head itself stays unchecked, said so; the rest is read as a chain
of its own; when its first member is itself written in the text's own vectors (𝐫ᵢ × 𝐅ᵢ with 𝐅ᵢ a
label of the text), that member is left with the head and the members after it are the chain
(`next_members`), and a row after it that goes on with ``=`` is checked against the row before it
(`own_head`, `derive.lecture.chain_links`). Such a vector set equal to one expression it reads
(`definition`) stands for that expression afterwards: a later statement setting it equal to another
holds when the two agree with the text's definitions put in, and is left unjudged when they do not
(either may be the one the text meant). Once such a chain holds, the name is its value in that section of the text: the same
name heading a later chain there is compared with it (a label slipped onto the wrong quantity,
a_i^t for the normal acceleration, is flagged).
"""
from __future__ import annotations

from derive.lecture import latex as lx
from derive.lecture import vector_algebra_model as va

WHY = ("the text's own vector {name}, not tied to the body (a name the text gives the chain): "
       "the members after it are checked against each other")
AGAIN = "{name} as the chain that named it at line {line} (its value there): the same"
OTHER = ("{name} was named at line {line} for another value (a chain that held there); this chain "
         "gives it a different one: the name on its left is not the quantity its members work out")


def split(text: str) -> tuple[str, str] | None:
    """(the head's LaTeX, the rest of the chain), or None when the statement is not such a chain."""
    prepared = va.prepare(text)
    try:
        toks = lx.scan(prepared)
    except lx.NotRead:
        return None
    eq = next((k for k, t in enumerate(toks) if t.kind == "rel"), None)
    if eq is None or toks[eq].value != "=" or not _own_vector(toks[:eq]):
        return None
    after = toks[eq + 1:]
    if sum(t.kind == "rel" for t in after) < 1 or any(t.kind == "rel" and t.value != "=" for t in after):
        return None
    return prepared[:toks[eq].pos].strip(), prepared[toks[eq].pos + 1:].strip()


def own_head(text: str) -> bool:
    """Whether a chain's left side is a single bold symbol, a superscript label at most (𝐌_{O,i}, 𝐚ᵢᵗ):
    a name the text gives, which a row going on with ``=`` does not tie to the body."""
    try:
        toks = lx.scan(va.prepare(text))
    except lx.NotRead:
        return False
    return _own_vector(toks)


def _own_vector(toks) -> bool:
    if not toks or toks[0].kind != "atom" or not _label_only(toks[1:]):
        return False
    return toks[0].value.bold or toks[0].value.text.startswith("\\vec")


def _label_only(toks) -> bool:
    """Nothing after the head's letter, or a superscript label (``^t``, ``^{n}``) on it."""
    if not toks:
        return True
    if toks[0].kind != "op" or toks[0].value != "^":
        return False
    rest = [t for t in toks[1:] if not (t.kind == "op" and t.value in "{}")]
    return len(rest) == 1 and rest[0].kind == "atom" and not rest[0].value.bold


def next_members(rest: str) -> str | None:
    """The chain after its first member (``a = b = c`` gives ``b = c``), or None when fewer than two
    members would be left or the first relation is not ``=``."""
    try:
        toks = lx.scan(rest)
    except lx.NotRead:
        return None
    rels = [t for t in toks if t.kind == "rel"]
    if len(rels) < 2 or rels[0].value != "=":
        return None
    return rest[rels[0].pos + 1:].strip()


def definition(text: str) -> tuple[str, str] | None:
    """(the head's LaTeX, the one member after it) for ``\\vec M_{O} = …`` — the text's own vector
    set equal to one expression, no chain — else None. The head's key is its LaTeX without spaces."""
    prepared = va.prepare(text)
    try:
        toks = lx.scan(prepared)
    except lx.NotRead:
        return None
    rels = [k for k, t in enumerate(toks) if t.kind == "rel"]
    if len(rels) != 1 or toks[rels[0]].value != "=" or not _own_vector(toks[:rels[0]]):
        return None
    at = toks[rels[0]].pos
    return prepared[:at].strip(), prepared[at + 1:].strip()
