"""Statements in textbook vector algebra for the notes checker (read by the vector grammar under
`derive.lecture.vector_algebra_model`): each member against the first readable one, in the model
of rigid rotation that module derives.

Gives the mixin `AlgebraStatements` of `derive.lecture.notes_check.Checker`: `_algebra_first`
(a statement in that notation, before the scalar reader) and `_algebra` (the reading and the
verdicts).

May import: :mod:`derive.lecture.latex_spellings`, :mod:`derive.lecture.latex`, :mod:`derive.lecture.kane_notation`, :mod:`derive.lecture.frame_labels`, :mod:`derive.lecture.free_rotation`, :mod:`derive.lecture.point_moments`, :mod:`derive.lecture.vector_algebra_model`, :mod:`derive.lecture.vector_parser` (its
`UNREAD` entry), the single edits
of :mod:`derive.lecture.vectors`, :mod:`derive.lecture.fixed_axis`, :mod:`derive.lecture.body_plane`, :mod:`derive.lecture.headless_chains`,
:mod:`derive.lecture.own_torque`, :mod:`derive.lecture.point_labels`, :mod:`derive.lecture.lone_point`, :mod:`derive.lecture.body_values`, :mod:`derive.lecture.chain_end_names`,
:mod:`derive.lecture.written_matrices` (`numbers_set`, `columns_only`),
SymPy.

A text's set-up of a rotation about a fixed axis (𝛚 = ω k̂) is recorded, not judged; after it, a
statement that fails with a plain distance r measured from the origin is read again with r measured
from the axis, and holds if that reading holds (`derive.lecture.fixed_axis`).
"""
from __future__ import annotations

import copy
import itertools
import re

import sympy as sp

from derive.lecture import body_plane
from derive.lecture import body_values
from derive.lecture import chain_end_names
from derive.lecture import fixed_axis
from derive.lecture import free_rotation
from derive.lecture import frame_labels
from derive.lecture import headless_chains
from derive.lecture import kane_notation
from derive.lecture import latex as lx
from derive.lecture import lone_point
from derive.lecture import own_torque
from derive.lecture import point_labels
from derive.lecture import point_moments
from derive.lecture import vector_algebra_model as va
from derive.lecture import vector_parser as vp
from derive.lecture import vectors as vc
from derive.lecture.written_matrices import columns_only, numbers_set
from derive.lecture.latex_spellings import VECTOR_MARK

# The prose calling a bold p a position ("its position $\mathbf{p}^E$"): then 𝐩 is no momentum m𝐯.
_PLACE = re.compile(r"\bposition\s+(?:of\s+[\w ]{0,30})?\$\\(?:mathbf|boldsymbol|bm|vec)\s*\{?\s*p\b")

WHY = ("rigid rotation from first principles: 𝐯 = 𝛚 × 𝐫, 𝐋 = Σ m 𝐫 × (𝛚 × 𝐫), 𝐈 = ∂𝐋/∂𝛚, "
       "torque d𝐋/dt; sums and ∫ dm read for three generic mass points")


class AlgebraStatements:
    """Mixin of the checker. Uses ``self.ctx``, ``self._add``, ``self.claims`` and ``self.judging_only``."""

    @property
    def _alg(self) -> va.State:
        if "_alg_state" not in self.__dict__:
            names = getattr(self.notes, "names", None)
            momenta = frozenset(b for (b, kind), m in (names.letters.items() if names else ()) if
                                kind == "vector" and m == "angular momentum")
            torques = {b for (b, kind), m in (names.letters.items() if names else ()) if
                       kind == "vector" and m == "torque"} - momenta     # 𝐌 "being the external torque"
            places = frozenset({"p"} if _PLACE.search(self.notes.body or "") else ())   # 𝐩ᴺ "the position of the body"
            self._alg_state = va.State(products=va.products_of_inertia(self.notes.body or ""), momenta=momenta,
                                       torques=set(va.TORQUES) | torques, places=places)
            self._alg_read = False
        return self._alg_state

    def _algebra_first(self, text) -> bool:
        """Whether a statement goes to this reader before the scalar one: written in its notation
        (or continuing a side it read), once it has read a display of the text or when the
        statement has its markers; never the lecture's own vector notation."""
        if va.lecture_notation(text) or numbers_set(text) or columns_only(text, self.vocab, self.ctx.defs):
            return False            # {\bf n} = (0, 0, 1) and what the text writes of such columns: the scalar reader's
        text = (frame_labels.dropped(text) or (text,))[0]          # 𝛚_B, 𝐈_B: one frame's components
        text = chain_end_names.put_in(text, getattr(self, "chain_end_latex", {}), None)   # J_z = Σ mᵢ rᵢ²: a sum
        state = self._alg
        if va.markers(text, bold=self._alg_read) or _torque_law(text, state):
            return True
        return self._alg_read and (state.head is not None and text.startswith(state.head) or _mentions(text, state))

    def _algebra(self, line, piece, text) -> bool:
        """Read and judge a statement (False when this reader cannot read it); one written in a
        frame's components (`derive.lecture.frame_labels`) is read without the frame's label."""
        if va.lecture_notation(text):
            return False
        framed, said = frame_labels.dropped(text), frame_labels.WHY
        if framed is None:          # 𝛕_c = 𝐈_c 𝛚̇ + …: Euler's equation about one labelled point
            framed, said = point_moments.dropped(text), point_moments.WHY
        if framed is None:
            return self._algebra_unlabelled(line, piece, text)
        start = len(self.claims)
        read = self._algebra_unlabelled(line, piece, framed[0])
        for claim in self.claims[start:]:
            claim.why += said.format(label=framed[1]) if claim.verdict != "unchecked" else ""
        return read

    def _algebra_unlabelled(self, line, piece, text) -> bool:
        written, text = text, chain_end_names.put_in(text, getattr(self, "chain_end_latex", {}), line)   # J_z as defined
        state = self._alg
        axis = fixed_axis.setting(text)
        if axis is not None:
            state.axis = axis
            self._alg_read = True
            self._add(line, piece, "assumption", "unchecked", fixed_axis.WHY)
            return True
        kept_axis = state.axis
        if state.axis is None:
            state.axis = fixed_axis.implied(written)    # L_z beside a plain ω: a rotation about z
        try:
            return self._algebra_read(line, piece, text, state)
        finally:
            state.axis = kept_axis

    def _algebra_read(self, line, piece, text, state, partial=None) -> bool:
        try:
            reading = partial or va.read(text, state)
        except lx.NotRead:
            reading = self._named_reading(text)
            if reading is None:
                return self._headless(line, piece, text, state) or self._entry_by_entry(line, piece, text, state)
        if set(reading.relations) - {"=", "≡"} or len(reading.members[0]) < 2:
            return False
        self._alg_read = True
        state.system = reading.model
        first = reading.members[0]
        state.head = reading.source[:first[0].end].strip()
        self.ctx.head = state.head
        if _products_set_to_zero(reading):
            self._add(line, piece, "assumption", "unchecked",
                      "products of inertia set to zero: an assumption about the body (principal axes, "
                      "e.g. by symmetry), not a consequence the derivation can check")
            return True
        where = f" for {', '.join(reading.free)} = 1, 2, 3" if reading.free else ""
        ref = next((k for k, m in enumerate(first) if not m.skip), None)
        for k in range(1, len(first)):
            if first[k].skip or ref is None or k == ref:
                if first[k].skip:
                    self._add(line, piece, "identity", "unchecked", first[k].skip)
                continue
            verdict, why = self._algebra_pair(reading, ref, k)
            if verdict == "fails" and lone_point.mixed(reading, ref, k):
                verdict, why = "unchecked", lone_point.WHY
            if verdict == "fails" and point_labels.involved(first[ref].value, first[k].value):
                rest = point_labels.at_rest(first[k].value, first[ref].value)
                verdict, why = ("holds", point_labels.AT_REST.format(point=rest[0], what=rest[1])) if rest \
                    else ("unchecked", point_labels.WHY)
            if verdict == "fails" and ref == 0 and k == 1 and reading.relations[0] == "≡":
                verdict, why = "unchecked", ("a definition (≡, :=) of the text's own: its name means here what "
                                             "the text sets it to, not what the reader took it for")
            if verdict == "fails" and state.axis is not None and fixed_axis.plain_r(text):
                verdict, why = self._from_the_axis(text, ref, k, verdict, why)
            if verdict == "fails" and (body_values.one_body(first[ref].value, first[k].value) or body_values.one_body(first[k].value, first[ref].value)):
                verdict, why = "unchecked", body_values.ONE_BODY
            if verdict == "fails" and self._plane_at(line) is not None:
                verdict, why = self._in_the_plane(reading, ref, k, self._plane_at(line), verdict, why)
            if verdict == "holds" and ref == 0 and reading.free and _INDEX_ENTRY.match(reading.source[:first[0].end]):
                state.entries = True       # I_ij = … in index form: the text's I_xy is the tensor's entry
            fix = self._algebra_fix(reading, ref, k) if verdict == "fails" and not self.judging_only \
                and not reading.unread else None
            if fix:
                verdict, why = "typo", f"{why}; one edit ({fix[1]}) makes it hold"
            self._add(line, piece, "definition" if ref == 0 and _named(text) else "identity", verdict,
                      why + (where if verdict != "unchecked" else ""), fix[0] if fix else None)
        return True

    def _entry_by_entry(self, line, piece, text, state) -> bool:
        """A tensor with a few entries in symbols the model does not know (a slip's stray letter, y_z
        for y_a): its other entries read and judged one by one (`_masked`), and the statement taken
        only when one of them fails (else False: the other readers read it as before, and nothing
        of this reading is kept)."""
        try:
            reading = va.read(text, copy.deepcopy(state), partial=True)
        except lx.NotRead:
            return False
        first = reading.members[0]
        if not reading.unread or set(reading.relations) - {"=", "≡"} or len(first) < 2 or first[0].skip:
            return False
        if not any(self._algebra_pair(reading, 0, k, record=False)[0] == "fails" for k in range(1, len(first))):
            return False
        return self._algebra_read(line, piece, text, state, reading)

    def _named_reading(self, text):
        """``K = X …`` with K a plain letter this reader does not know: the text's own name. Set to
        one expression it reads (``K = \\sum_i \\frac12 m_i v_i^2``), K stands for that expression
        in the statements that follow (kept, None returned); a chain after it, or K named before,
        is read with K's expression in its place. None when that does not read either."""
        self._alg_kane = getattr(self, "_alg_kane", False) or kane_notation.kane(text)
        text = kane_notation.rewrite(text, self._alg_kane)      # 𝐈̄_a after the text wrote 𝐫̄^{P_i/O}
        m = _NAME_FIRST.match(text)
        if m is None:
            return None
        state, name, rest = self._alg, m.group(1).replace(" ", ""), _expanded(text[m.end():], self._alg.named)
        try:
            instance = _instance(name, state.named)
            if instance is not None:        # I_{ba} after I_{ab} ≔ …: the definition at these indices
                return va.read(instance + " = " + rest, state) if va.markers(rest, bold=True) else None
            if name in state.named:         # K named before: its expression in its place
                if state.named_by[name] == text:
                    return None             # the statement that named it, met again: not a claim about it
                return va.read(state.named[name] + " = " + rest, state) if va.markers(rest, bold=True) else None
            reading, aliases = _aliased(rest, state)
        except lx.NotRead:
            return None
        first = reading.members[0]
        for each in (name, *aliases):
            state.named[each] = reading.source[first[0].start:first[0].end].strip()
            state.named_by[each] = text
        self._alg_read = True
        return va.read(rest, state) if len(first) > 1 else None

    def _headless(self, line, piece, text, state) -> bool:
        """A chain headed by the text's own vector (`derive.lecture.headless_chains`): the head
        unchecked, the members after it read and judged as a chain of their own."""
        parts = headless_chains.split(text)
        if parts is None:
            return self._own_vector_set(line, piece, text, state)
        head, rest = parts
        first = None
        while first is None and rest is not None:
            try:
                first = va.read(rest, copy.deepcopy(state))
            except lx.NotRead:
                rest = headless_chains.next_members(rest)     # a member in the text's own vectors: left with the head
        if first is None:
            return False
        section = self._section_of(line)
        named = self.__dict__.setdefault("_named_heads", {})
        value = first.members[0][0].value if not first.free else None
        if (head, section) in named and value is not None:
            self._named_again(line, piece, head, named[(head, section)], value)
        else:
            self._add(line, piece, "identity", "unchecked", headless_chains.WHY.format(name=head))
        before = len(self.claims)
        read = self._algebra_read(line, piece, rest, state)
        mine = [c.verdict for c in self.claims[before:]]
        if read and value is not None and mine and all(v == "holds" for v in mine) and (head, section) not in named:
            named[(head, section)] = (line, value)     # the chain holds: the name is its value from here on
        return read

    def _own_vector_set(self, line, piece, text, state) -> bool:
        """``\\vec M_{O} = …``, the text's own vector set equal to one expression: recorded the
        first time (`headless_chains.definition`); set again, ``holds`` when the two expressions agree
        with the text's names put in, else unjudged (either may be the one the text meant)."""
        parts = headless_chains.definition(text)
        if parts is None:
            return False
        head, rest = parts
        key, rest = re.sub(r"\s+", "", head), _expanded(rest, state.named)
        if key not in state.named:
            try:
                va.read(rest, copy.deepcopy(state))
            except lx.NotRead:
                return False
            state.named[key], state.named_by[key] = rest, text
            self._add(line, piece, "definition", "unchecked", f"defines the text's vector {head} (recorded, then used)")
            return True
        again = r"\left(" + state.named[key] + r"\right) = " + rest
        try:
            reading = va.read(again, state)
        except lx.NotRead:
            return False
        verdict, why = self._algebra_pair(reading, 0, 1)
        if verdict == "fails" and state.axis is not None and fixed_axis.plain_r(again):
            verdict, why = self._from_the_axis(again, 0, 1, verdict, why)
        if verdict != "holds":
            verdict, why = "unchecked", (f"sets the text's vector {head} equal to another expression than where it "
                                         "was set; either may be the one the text meant")
        else:
            why = f"the text's vector {head} as it was set, with its names put in: {why}"
        self._add(line, piece, "identity", verdict, why)
        return True

    def _note_plane(self, line, piece):
        """A bare ``z = 0`` (`body_plane.setting`): the body's plane for the rest of its section."""
        axis = body_plane.setting(piece)
        if axis is not None:
            self._plane = (axis, line, self._section_of(line))

    def _plane_at(self, line) -> int | None:
        """The axis of the plane the text set before ``line`` in its section, or None."""
        plane = getattr(self, "_plane", None)
        return plane[0] if plane and line > plane[1] and self._section_of(line) == plane[2] else None

    def _in_the_plane(self, reading, ref, k, axis, verdict, why):
        """Member k against member ``ref`` again with the mass points in the plane: holds if it holds there."""
        sub = body_plane.in_plane(axis)
        for members in reading.members:
            d = va.difference(members[k].value, members[ref].value)
            if d is None or not _zero(d.subs(sub)):
                return verdict, why
        return "holds", f"{WHY}, {body_plane.WHY.format(axis='xyz'[axis])}"

    def _section_of(self, line) -> int:
        names = getattr(self.notes, "names", None)
        return names._section(line) if names is not None and names.sections else 0

    def _named_again(self, line, piece, head, earlier, value):
        """The text's vector named again in its section: the value the chain gives it against the
        value of the chain that named it."""
        at, old = earlier
        d = va.difference(value, old)
        if d is not None and self._alg.axis is not None:
            d = va.difference(d.subs(fixed_axis.off_axis(self._alg.axis)), 0 * d)
        if d is None or point_labels.involved(value, old):
            self._add(line, piece, "identity", "unchecked", headless_chains.WHY.format(name=head))
        elif _zero(d):
            self._add(line, piece, "identity", "holds", headless_chains.AGAIN.format(name=head, line=at))
        else:
            self._add(line, piece, "identity", "fails", headless_chains.OTHER.format(name=head, line=at))

    def _from_the_axis(self, text, ref, k, verdict, why):
        """The other reading of a plain distance r about a fixed axis: measured from the axis."""
        state = copy.deepcopy(self._alg)
        state.radial = "axis"
        try:
            again = va.read(text, state)
        except lx.NotRead:
            return verdict, why
        v2, why2 = self._algebra_pair(again, ref, k, record=False)
        if v2 == "holds":
            return "holds", why2 + "; with r the distance from the fixed axis (a plain r is that distance as well)"
        return verdict, why

    def _algebra_fix(self, reading, ref, k):
        """One edit of member k's LaTeX (a sign, a factor, an index, a cross product's order, a
        power) after which it equals the reference member: (the statement corrected, what), or None."""
        reread = lambda text: va.read(text, copy.deepcopy(self._alg))  # noqa: E731
        for _, _, what, again_src, again in vc.edited_readings(reading, k, reread, 60):
            if self._algebra_pair(again, ref, k, record=False)[0] == "holds":
                return re.sub(r"\s+", " ", again_src.replace("\\mathbf{\\" + va.INTEGRAL + "}", "\\int")).strip(), what
        return None

    def _algebra_pair(self, reading, ref, k, record=True) -> tuple[str, str]:
        first = reading.members[0]
        if first[ref].generics != first[k].generics:
            torque = own_torque.sides(reading, ref, k)
            if torque is not None:
                axis = self._alg.axis
                return own_torque.judged(reading, *torque, WHY, _where, fixed_axis.off_axis(axis) if axis is not None else None)
            name = own_torque.added(reading, ref, k) if self._alg.axis is None else None
            if name is not None:
                return "holds", f"{WHY}: the text's {name} read as the torque, a term of the equation of motion: exact (expand)"
            loose = sorted(first[ref].generics ^ first[k].generics)
            return "unchecked", f"involves {', '.join(loose)}, which the text has not tied to the body"
        a, b = first[ref], first[k]
        if (a.law and not b.law and not b.rated) or (b.law and not a.law and not a.rated):
            return "unchecked", ("a torque or a force set equal to an expression without a rate: a law or an "
                                 "assumption of the text (the reader knows only τ = d𝐋/dt and 𝐅 = d𝐩/dt)")
        convention = False
        principal = False
        free_body = False
        for members in reading.members:
            d = va.difference(members[k].value, members[ref].value)
            if d is None:
                return "unchecked", "cannot compare its sides: their shapes differ"
            if self._alg.axis is not None:
                d = va.difference(d.subs(fixed_axis.off_axis(self._alg.axis)), 0 * d)
            if reading.unread:
                verdict = _masked(d, members[k].value, members[ref].value)
                if verdict is None:
                    continue
                return verdict[0], verdict[1].format(why=WHY, unread="; ".join(reading.unread))
            if _zero(d):
                continue
            if ref == 0 and _entry_name(reading.source, members[0]) and not isinstance(d, sp.MatrixBase) \
                    and (self._alg.products or not self._alg.entries) \
                    and _zero(va.difference(members[k].value, -members[ref].value)):
                convention = True          # a product of inertia defined with the other sign
                continue
            if _principal_only(reading.source) and _zero(_in_principal_axes(d)):
                principal = True           # written in the principal moments I_11, I_22, I_33 only
                continue
            lit = members[k].literal if members[k].literal is not None else members[ref].literal
            if isinstance(d, sp.MatrixBase) and d.shape == (3, 3) and lit is not None and \
                    all(_zero(d[i, j]) or (i != j and lit[i, j] == 0) for i, j in itertools.product(range(3), repeat=2)):
                principal = True           # the written tensor is diagonal where the derived one is not
                continue
            if _principal_only(reading.source) and reading.model == "single" and not _PLAIN_MASS.search(reading.source):
                # the point mass is an earlier statement's: the text may speak of a body here
                return "unchecked", ("written in the principal moments only, while the system read last is "
                                     "one point mass, which has no three principal moments of its own")
            if _set_perpendicular(reading, k):
                return "unchecked", ("a scalar product set to zero: the two vectors taken perpendicular, a "
                                     "condition of the text's set-up, not a consequence the derivation decides")
            if body_values.particular(members[k].value, members[ref].value) or body_values.particular(members[ref].value, members[k].value):
                return "unchecked", body_values.PARTICULAR
            if not (a.law or b.law) and self._alg.axis is None and reading.model != "single" \
                    and free_rotation.vanishes_for_free_body(d, va.torque(reading.model)):
                free_body = True           # no torque written: the law of motion of a free body
                continue
            return "fails", f"as written: {_where(d)} ({WHY})"
        if convention:
            name = _entry_name(reading.source, reading.members[0][0])
            if record:
                self._alg.defs[name] = reading.members[0][k].value
            return "holds", (f"{WHY}: the entry of 𝐈 with the opposite sign — the text's product of inertia "
                             "(some texts define I_xy = ∫xy dm and write −I_xy in the tensor)")
        if principal:
            return "holds", f"{WHY}: holds if the axes are principal axes (the products of inertia vanish)"
        if free_body:
            return "holds", (f"{WHY}: holds for a free body (no torque): zero once 𝛚̇ is taken from "
                             "𝐈𝛚̇ = −𝛚 × 𝐈𝛚")
        if reading.unread:
            return "unchecked", (f"the entries it reads agree ({WHY}); an entry is not read "
                                 f"({'; '.join(reading.unread)})")
        return "holds", f"{WHY}: exact (expand)"


_NAME_FIRST = re.compile(r"\s*((?:\\(?:mathbf|boldsymbol|bm|pmb|vec)\s*\{\s*[A-Za-z]\s*\}|[A-Za-z])(?:\s*_\s*\{\s*[A-Za-z]{1,2}\s*\}|\s*_\s*[A-Za-z]"
                         r"|\s*_\s*\{\s*[A-Za-z]{3,}\s*\})?)"
                         r"\s*(?:=(?!=)|\\equiv)")
"""A statement opening with a lone symbol set equal to what follows (``K = …``, ``\\mathbf{I}_{a} \\equiv …``
in any bold or under an arrow, ``\\boldsymbol{r}_{G} = …``, ``\\vec{r}_{G} = …``,
``I_{ab} \\equiv …``, a word for its label, ``T_{rot} = …``)."""


def _expanded(text: str, named: dict) -> str:
    """The text with the names a text set before put back as their expressions, longest first; a
    name with letter indices (``I_{ab}``) also at other letters (``I_{ba}``, ``I_{aa}``: `_instance`)."""
    for name in sorted(named, key=len, reverse=True):
        pattern = re.escape(name).replace(r"\{", r"\s*\{\s*").replace(r"\}", r"\s*\}").replace("_", r"\s*_\s*")
        text = re.sub(pattern + r"(?![A-Za-z_{])", lambda _: r"\left(" + named[name] + r"\right)", text)
    for m in reversed(list(_INDEXED.finditer(text))):
        value = _instance(m.group(0), named)
        if value is not None:
            text = text[:m.start()] + r"\left(" + value + r"\right)" + text[m.end():]
    return text


_INDEXED = re.compile(r"(?<![\\A-Za-z])([A-Za-z])\s*_\s*\{\s*([a-h])\s*([a-h])\s*\}")
"""A scalar with two letter indices, ``I_{ab}``: an inertia scalar over generic unit vectors."""


def _instance(symbol: str, named: dict) -> str | None:
    """The expression of ``I_{ba}`` or ``I_{aa}`` when the text defined ``I_{ab}`` over its indices'
    letters (its unit vectors 𝐧_a, 𝐧_b): the definition with the letters renamed, or None."""
    m = _INDEXED.fullmatch(symbol.strip())
    if m is None or symbol.replace(" ", "") in named:
        return None
    for name, value in named.items():
        d = _INDEXED.fullmatch(name)
        if d is None or d.group(1) != m.group(1) or d.group(2) == d.group(3):
            continue
        rename = {d.group(2): m.group(2), d.group(3): m.group(3)}
        return re.sub(r"_\{\s*([a-h])\s*\}", lambda x: "_{" + rename.get(x.group(1), x.group(1)) + "}", value)
    return None
_MOMENT = re.compile(r"I_\s*\{?\s*(11|22|33|xx|yy|zz|12|21|13|31|23|32|xy|yx|xz|zx|yz|zy)\b")
_PLAIN_MASS = re.compile(r"(?<![A-Za-z\\])m(?![A-Za-z])")
"""A plain m in a statement: it speaks of one point mass itself."""
_PRINCIPAL_POINTS = {c: 0 for k, point in enumerate(va.RK) for i, c in enumerate(point) if i != k}
"""The body's three mass points each on its own axis: every product of inertia vanishes, the
three principal moments stay generic."""


def _principal_only(source: str) -> bool:
    """A statement that writes the tensor's diagonal entries (I_11, I_yy) and none off it."""
    subs = _MOMENT.findall(source)
    return bool(subs) and all(s[0] == s[1] for s in subs)


def _in_principal_axes(d):
    """A difference on the body whose axes are principal (`_PRINCIPAL_POINTS`)."""
    return va.difference(d.subs(_PRINCIPAL_POINTS) if isinstance(d, sp.Basic) or isinstance(d, sp.MatrixBase)
                         else d, sp.zeros(*d.shape) if isinstance(d, sp.MatrixBase) else 0)


_INDEX_ENTRY = re.compile(r"^\s*I_\s*\{?\s*[a-z]\s*,?\s*[a-z]\s*\}?\s*$")
"""``I_{ij}``: the left side of the tensor's entries written in index form."""


def _set_perpendicular(reading, k) -> bool:
    """``… = 2 𝐋 · 𝛕 = 0``: member k is zero and the member before it a scalar product."""
    first = reading.members[0]
    return k > 0 and first[k].value == 0 and "\\cdot" in reading.source[first[k - 1].start:first[k - 1].end]


def _masked(d, a, b):
    """A difference of two tensors with entries set aside (`vp.UNREAD`): None when the entries read
    agree, else (verdict, why with ``{why}`` and ``{unread}`` to fill). Only a 3×3 tensor of the body
    (its entries free of the rates) is judged so; an entry 0 in one side ``a``, ``b`` where the
    other's is not leaves it unchecked (principal axes the text may assume)."""
    if not isinstance(d, sp.MatrixBase) or d.shape != (3, 3):
        return "unchecked", "an entry of a matrix is not read ({unread})"
    aside = [vp.UNREAD in sp.sympify(x).free_symbols for x in d]
    if 3 * sum(aside) > len(aside):
        return "unchecked", "too many of its matrix's entries are not read ({unread})"
    read = sp.Matrix(d.shape[0], d.shape[1], [0 if a else x for a, x in zip(aside, d)])
    if _zero(read):
        return None
    if any(x != 0 and (a[n] == 0 or b[n] == 0) for n, x in enumerate(read)):
        return "unchecked", "an entry written 0 where the derived one is not, beside an entry not read ({unread})"
    if any(sp.sympify(x).free_symbols & (set(va.W) | set(va.WD)) for x in read):
        return "unchecked", "a tensor in the rates, beside an entry not read ({unread})"
    return "fails", "as written: " + _where(read) + " ({why}); an entry left out, not read ({unread})"


def _zero(d) -> bool:
    if isinstance(d, sp.MatrixBase):
        return all(x == 0 for x in d)
    return d == 0


def _where(d) -> str:
    if not isinstance(d, sp.MatrixBase):
        return "claim − derived ≠ 0"
    k = next(n for n, x in enumerate(d) if x != 0)
    if d.shape == (3, 1):
        return f"claim − derived ≠ 0 (component {k + 1})"
    return f"claim − derived ≠ 0 (entry {k // d.shape[1] + 1},{k % d.shape[1] + 1})"


def _tokens(text) -> list:
    """The scanner's tokens of a text, none when it cannot scan it."""
    try:
        return lx.scan(text)
    except lx.NotRead:
        return []


def _named(text) -> bool:
    toks = _tokens(va.prepare(text))
    return len(toks) > 1 and toks[0].kind == "atom" and toks[1].kind == "rel"



def _products_set_to_zero(reading) -> bool:
    """I_xy = I_yz = 0: every member an off-diagonal entry of the inertia tensor but one literal 0."""
    for members in reading.members:
        names = [_entry_name(reading.source, m) for m in members]
        zeros = [m for m, n in zip(members, names) if n is None]
        if len(zeros) != 1 or len(members) < 2 or reading.source[zeros[0].start:zeros[0].end].strip() != "0":
            return False
    return True


def _entry_name(source, member):
    """('I', 'xy') when the member is one off-diagonal entry of the inertia tensor, else None."""
    toks = _tokens(source[member.start:member.end])
    if len(toks) == 1 and toks[0].kind == "atom" and toks[0].value.base == "I" and len(toks[0].value.sub) == 2 \
            and toks[0].value.sub[0] != toks[0].value.sub[1] and not toks[0].value.bold:
        return ("I", toks[0].value.sub)
    return None


def _torque_law(text, state) -> bool:
    """d𝐋/dt set equal to a bold letter the prose names the torque (``\\boldsymbol M`` "being the
    external torque") or to a torque labelled by its source (``\\vec{\\tau}_g``): the law of motion,
    this reader's."""
    if not re.search(r"\\frac\s*\{\s*(?:\\mathrm\s*\{?\s*d\s*\}?|d)\s*" + VECTOR_MARK, text):
        return False
    return any(t.kind == "atom" and t.value.bold and t.value.base in state.torques
               and ((not t.value.sub and t.value.base not in va.TORQUES) or va.labelled_torque(t.value.sub))
               for t in _tokens(va.prepare(text)))


def _aliased(rest, state):
    """The reading of a name's expression, and the other names set to it first (``J_{xy} = J_{yx} =
    \\sum_i m_i x_i y_i``: J_{yx} is one); `lx.NotRead` when neither reads."""
    try:
        return va.read(rest, copy.deepcopy(state)), ()
    except lx.NotRead:
        alias = _NAME_FIRST.match(rest)
        if alias is None:
            raise
        reading = va.read(rest[alias.end():], copy.deepcopy(state))
        if len(reading.members[0]) > 1:
            raise
        return reading, (alias.group(1).replace(" ", ""),)


def _mentions(text, state) -> bool:
    """A torque letter of the text, an entry of the inertia tensor (I_xy), or a name the text set
    here (or one at other indices, `_instance`), in the statement."""
    m = _NAME_FIRST.match(text)
    if m is not None and (m.group(1).replace(" ", "") in state.named or _instance(m.group(1), state.named)):
        return True
    for t in _tokens(va.prepare(text)):
        if t.kind != "atom":
            continue
        a = t.value
        if a.base in state.torques and a.base not in va.TORQUES:
            return True
        if a.base == "I" and len(a.sub) == 2 and all(c in "xyz" for c in a.sub):
            return True
    return False
