"""The links of a chain between two integrals over the body or two sums over its particles:
``\\int_V \\mathbf f \\cdot (\\boldsymbol\\omega \\times \\mathbf r)\\, dV = \\int_V \\boldsymbol\\omega \\cdot (\\mathbf r \\times \\mathbf f)\\, dV``.

Gives the mixin `BodyLinks` of `derive.lecture.notes_check.Checker`: `_body_links`, for a statement
no other reader took whole. Texts derive 𝐋, T and the power as a chain whose head the reader cannot
tie to the body (L_n, dT/dt, a name of the text's) or whose last member names the text's own
quantity (𝛚·𝐌^(e)), while the members between are integrals over the body (``\\int_V … dV``,
``\\int … dm``) or sums over its particles (``\\sum_i m_i …``). Each link with such a member on one
side at least (𝐧·𝐋 = ∫_V ρ 𝐫 × (𝛚 × 𝐫)·𝐧 dV) is read alone, the two set equal, by the vector-algebra
reader (`derive.lecture.vector_algebra_model`: three generic mass points, 𝐯 = 𝛚 × 𝐫); it holds when
it is an identity there. A link that is not
one stays unchecked, never flagged: the text's set-up said in words (𝛚 = ω𝐧 with 𝐧 a unit vector,
a point at rest) may tie its two members. For that reading alone a volume element with no density
in the link (a density of force 𝐟 dV) is the mass element, the weights of the points (no mass, 𝐋, 𝐈
or 𝐩 in the link: an identity between two integrals of one weight holds for every weight); a bold
vector's label in a bracketed superscript (𝐟^(e), 𝐌^(e)) is dropped when each such letter carries
one label only; a position measured from a reference point, Δ𝐫ᵢ, is 𝐫ᵢ from that point as origin
(in a link without a rate, a velocity or a momentum, which a moving reference point would change,
every bold r carrying the Δ).
May import: the standard library, :mod:`derive.lecture.latex`, :mod:`derive.lecture.latex_spellings`,
:mod:`derive.lecture.statements`, :mod:`derive.lecture.vector_algebra_model`, :mod:`derive.lecture.definite_integrals`.
"""
from __future__ import annotations

import copy
import re

from derive.lecture import latex as lx
from derive.lecture import vector_algebra_model as va
from derive.lecture.definite_integrals import DEFINITE
from derive.lecture.latex_spellings import BOLD_MARK
from derive.lecture.statements import top_level

WHY = ("a link of the chain with an integral over the body (or a sum over its particles) on one side at least, "
       "read alone as an identity for three generic mass points (𝐯 = 𝛚 × 𝐫): holds")
_EQUALS = re.compile(r"(?<![<>!\\])=(?!=)")
_OVER_BODY = re.compile(r"\\int(?![A-Za-z])|\\sum(?![A-Za-z])")
_VOLUME = re.compile(r"(?:\\mathrm\s*\{\s*d\s*\}|\\mathrm\s+d|(?<![A-Za-z\\])d)\s*(?:\\,|\\;|\s)*(?:V|\^\s*\{?\s*3\s*\}?\s*r)(?![A-Za-z])")
_MASSIVE = re.compile(r"\\rho|(?<![A-Za-z\\])m(?![A-Za-z])|" + BOLD_MARK + r"\s*\{?\s*[LIpH]\b")
_LABEL = re.compile(r"(" + BOLD_MARK + r"\s*\{\s*(\\?[A-Za-z]+)\s*\})\s*\^\s*\{\s*\(\s*([A-Za-z]+)\s*\)\s*\}")
_BOLD_LETTER = r"(?:" + BOLD_MARK + r")\s*\{\s*%s\s*\}"
_DELTA_R = re.compile(r"\\Delta\s*(" + BOLD_MARK + r"\s*\{\s*r\s*\})")
_MOVING = re.compile(r"\\dot|\\frac\s*\{\s*(?:\\mathrm\s*\{\s*d\s*\}|d)|(?<![A-Za-z\\])[vp](?![A-Za-z])|" + BOLD_MARK + r"\s*\{?\s*[vp]\b")


def _members(text):
    """The chain's members, cut at each ``=`` outside brackets and braces."""
    bounds = [0, *(p for m in top_level(text, _EQUALS) for p in (m.start(), m.end())), len(text)]
    return [text[bounds[k]:bounds[k + 1]] for k in range(0, len(bounds), 2)]


def _over_body(member) -> bool:
    """A member that writes an integral without its bounds (over the body) or a sum."""
    return bool(_OVER_BODY.search(member)) and not DEFINITE.search(member)


def _labels_dropped(link):
    """The link with each bold letter's bracketed superscript label dropped (𝐟^(e) as 𝐟), or None when
    a letter carries two labels or appears without its label too."""
    found = {}
    for m in _LABEL.finditer(link):
        found.setdefault(m.group(2), set()).add(m.group(3))
    if any(len(v) > 1 for v in found.values()):
        return None
    for letter in found:
        if len(re.findall(_BOLD_LETTER % re.escape(letter), link)) != sum(m.group(2) == letter for m in _LABEL.finditer(link)):
            return None             # the letter without its label as well: two vectors
    return _LABEL.sub(r"\1", link)


def prepared(link):
    """The link as the vector-algebra reader is to read it (see the module docstring), or None."""
    link = _labels_dropped(link)
    if link is None:
        return None
    if _VOLUME.search(link) and not _MASSIVE.search(link):
        link = _VOLUME.sub(" dm", link)
    deltas = len(_DELTA_R.findall(link))
    if deltas and not _MOVING.search(link) and deltas == len(re.findall(_BOLD_LETTER % "r", link)):
        link = _DELTA_R.sub(r"\1", link)
    return link


class BodyLinks:
    """Mixin of the checker. Uses ``self._alg``, ``self._add``."""

    def _body_links(self, line, piece, text) -> bool:
        """Judge the links of adjacent members, one at least over the body (True when one holds: its claims
        are the links that hold, the other links left unread)."""
        members = _members(text)
        if len(members) < 2:
            return False
        held = []
        for a, b in zip(members, members[1:]):
            if not (_over_body(a) or _over_body(b)) or not a.strip() or not b.strip():
                continue
            link = prepared(f"{a.strip()} = {b.strip()}")
            if link is None:
                continue
            try:
                reading = va.read(link, copy.deepcopy(self._alg))
            except (lx.NotRead, ArithmeticError, TypeError, ValueError, AttributeError, IndexError, KeyError,
                    NotImplementedError, RecursionError):
                continue
            sides = reading.members[0] if len(reading.members) == 1 else None
            if reading.free or reading.unread or reading.relations != ["="] or sides is None or len(sides) != 2 \
                    or sides[0].skip or sides[1].skip or sides[0].generics != sides[1].generics \
                    or sides[0].law != sides[1].law:
                continue
            d = va.difference(sides[0].value, sides[1].value)
            if d is not None and _zero(d):
                held.append(f"{a.strip()} = {b.strip()}")
        if not held:
            return False
        for link in held:
            self._add(line, piece, "identity", "holds", f"{WHY}: {' '.join(link.split())[:80]}")
        return True


def _zero(d) -> bool:
    """d, a scalar or a matrix already expanded (`va.difference`), is zero."""
    return all(e == 0 for e in d) if hasattr(d, "shape") else d == 0
