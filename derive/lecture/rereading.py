"""Second readings of a statement, as a careful reader gives them before calling a formula wrong.

Takes: a statement the notes checker (`derive.lecture.notes_check.Checker`) has just judged, with
the context it was judged in. Gives: the mixin `Rereading` of the checker, which reads a flagged
statement again —

1. with a name's second meaning (a plain L as the angular momentum's magnitude; I₁ as the moment
   about the centre of mass where the text writes I₁ + M a²), kept when it makes the statement hold
   (L so read stays |𝐋| to the end of the section, in the definitions that follow as in claims);
2. for a symmetric body, when the formula is written for one (I₁, no I₂) and the text never said
   so: ``holds if I₁ = I₂``, never ``fails``; and a statement that holds only because the text
   made the body symmetric says where it did;
3. without the names learned from the prose: when only those make it fail, the verdict rests on
   an uncertain reading, so it is ``unchecked``, saying which reading it tried — unless another
   statement of its display, read with the same bindings, holds by the same kind of check, or the
   display that gave them, a column of the components its sentence names, holds read with them;
4. edited, one edit of its own LaTeX at a time, to find the correction in the text's notation.

Each second reading runs in a sandbox: a copy of the context, the checker's claims and context
left as they were. May import: :mod:`derive.lecture.latex`, :mod:`derive.lecture.vectors`, :mod:`derive.lecture.primed_functions`,
:mod:`derive.lecture.said_columns`,
:mod:`derive.symbolic`, SymPy.
"""
from __future__ import annotations

import re
from types import SimpleNamespace

import sympy as sp

from derive.lecture import latex as lx, primed_functions, said_columns
from derive.lecture import vectors as vc
from derive.symbolic.lagrangian import I1, I2, Mass, l


def _symbols(piece) -> set:
    """The spellings of a statement's symbols (empty where it cannot be scanned)."""
    try:
        return {(t.value.base, t.value.sub, t.value.bold, t.value.dots) for t in lx.scan(piece) if t.kind == "atom"}
    except lx.NotRead:
        return {None}


def _copied(ctx):
    """The context with containers of its own (its values are immutable SymPy objects)."""
    return type(ctx)(**{k: (v.copy() if hasattr(v, "copy") else v) for k, v in vars(ctx).items()})


_DIFFERENCE = re.compile(r"\(\s*([^()+\-=]+?)\s*-\s*([^()+\-=]+?)\s*\)")

def _latex_edits(piece: str):
    """Single edits of a statement's LaTeX, cheapest first: (edited, what)."""
    seen = {piece}
    out = []
    for m in _DIFFERENCE.finditer(piece):
        out.append((piece[:m.start()] + f"({m.group(2)} - {m.group(1)})" + piece[m.end():], "the order of a difference"))
    for m in re.finditer(r"\\(sin|cos)\b", piece):
        other = "cos" if m.group(1) == "sin" else "sin"
        out.append((piece[:m.start()] + "\\" + other + piece[m.end():], "sin ↔ cos"))
    out += list(_entry_sign_edits(piece))
    out += [(e, w) for e, w in vc.member_edits(piece) if w not in ("the sign of the whole side", "a factor 1/2", "a factor 2")
            or not e.lstrip().startswith(("-", "2 ", "\\frac{1}{2} "))]
    for edited, what in out:
        if edited not in seen:
            seen.add(edited)
            yield edited, what

def _atoms(latex: str) -> set:
    """The symbols a formula writes (decorations included, spelling aside)."""
    try:
        return {t.value.with_(text="") for t in lx.scan(latex) if t.kind == "atom"}
    except lx.NotRead:
        return set()


_MATRIX = re.compile(r"\\begin\{([pbBvV]?matrix|array)\}(\{[^{}]*\})?(.*?)\\end\{\1\}", re.S)


def _entry_sign_edits(piece: str):
    """The sign of one entry of a matrix the statement writes, flipped: (edited, what)."""
    for m in _MATRIX.finditer(piece):
        body, start = m.group(3), m.start(3)
        rows = body.split("\\\\")
        offset = start
        for r, row in enumerate(rows):
            cells = row.split("&")
            at = offset
            for c, cell in enumerate(cells):
                text = cell.strip()
                lead = at + len(cell) - len(cell.lstrip())
                if text and text != "0":
                    flipped = text[1:].lstrip() if text.startswith("-") else (
                        "-" + text[1:].lstrip() if text.startswith("+") else "- " + text)
                    edited = piece[:lead] + flipped + piece[lead + len(text):]
                    yield edited, f"the sign of the entry in row {r + 1}, column {c + 1}"
                at += len(cell) + 1
            offset += len(row) + 2


def _free_of(parsed) -> set:
    """The symbols of a parsed statement's members (none for a statement not read)."""
    out = set()
    for m in getattr(parsed, "members", ()):
        out |= set(getattr(m.value, "free_symbols", ()))
    return out


_SQUARED = re.compile(r"(\\?[A-Za-z]+(?:_\{?\s*[A-Za-z0-9]+\s*\}?)?)\s*\^\s*\{?\s*2\s*\}?")


def _powers_as_in(piece: str, others: str):
    """``piece`` with one symbol squared that the display's other statements write squared (k₅ →
    k₅² where a sibling has k₅²): the edit a display's own rows suggest."""
    squared = {re.sub(r"[{}\s]", "", m.group(1)) for m in _SQUARED.finditer(others)}
    for name in sorted(squared):
        base, _, sub = name.partition("_")
        pattern = re.escape(base) + (r"_(?:\{\s*" + re.escape(sub) + r"\s*\}|" + re.escape(sub) + ")"
                                     if sub else r"(?![A-Za-z_])")
        for m in re.finditer(pattern + r"(?!\s*\^)", piece):
            yield piece[:m.end()] + "^2" + piece[m.end():]


_PARALLEL_AXES = re.compile(r"I_\{?1\}?\s*\+\s*M\s*\\?[A-Za-z]+\s*\^\s*\{?\s*2")
"""``I_1 + Ma^2``: a text that adds M a² to I₁ gives its moments about the centre of mass."""


# Lᵢ, Mᵢ, Jᵢ, Hᵢ: an angular momentum's indexed components, no derivative or accent on them
_COMPONENTS = re.compile(r"(?<![\\A-Za-z])([LMJH])\s*_\s*\{?\s*([123])\s*\}?(?!\s*')")


def _second_readings(piece: str):
    """(name, value, description) of the names in a statement that have a second reading."""
    if re.search(r"(?<![\\A-Za-z{])L(?![A-Za-z])", piece) and not re.search(r"L\s*\(", piece):
        yield "L", lx.LMAG, "L as the magnitude of the angular momentum"
    if len({m.group(2) for m in _COMPONENTS.finditer(piece)}) > 1 and \
            len({m.group(1) for m in _COMPONENTS.finditer(piece)}) == 1:
        yield lx.BODY_COMPONENTS, True, "the components of the angular momentum as the body's, Iᵢω̃ᵢ"
    if _PARALLEL_AXES.search(piece):
        yield "I1", I1 - Mass * l ** 2, "I₁ as the moment about the centre of mass (I₁ + M l² about the fixed point)"


class Rereading:
    """Mixin of the checker: see the module docstring. Uses ``self.claims``, ``self.ctx``,
    ``self.vocab``, ``self.notes`` and ``self._statement``."""

    judging_only = False
    """Verdicts without the search for a correction (while a correction's candidates are read, and
    throughout a reader whose verdicts count only as flagged or not: a display read again in another
    sequence); a reading that sets it puts back the value it found."""

    def _read_once_or_twice(self, line, piece, dup, pieces):
        """The statement as read; if that flags it, the second readings of its names are tried:
        a plain L as the angular momentum's magnitude (kept when it makes the statement hold),
        and the statement without the names learned from the prose (when only that reading
        flags it, the verdict rests on an uncertain reading of the text: unchecked, saying so)."""
        before, saved = len(self.claims), self._snapshot()
        readings = list(_second_readings(piece))
        # with a second reading in view, the statement is judged before its correction is sought:
        # where the second reading holds, the correction would be thrown away
        judging = self.judging_only
        self.judging_only = judging or bool(readings)
        try:
            self._statement_read(line, piece, dup, pieces)
        finally:
            self.judging_only = judging
        first = self.claims[before:]
        if not any(c.verdict in ("typo", "fails") for c in first):
            self._under_symmetry(saved, line, piece, pieces, first)
            return
        if self._if_symmetric(saved, line, piece, dup, pieces, before):
            return
        if primed_functions.operator_in_other_variable(piece) and self._primed_read(piece, every=True):
            for c in first:
                if c.verdict in ("typo", "fails"):
                    c.verdict, c.correction = "unchecked", None
                    c.why = ("a derivative of the text's function beside a derivative written as an operator in "
                             f"another variable than t, which the reader does not read: {c.why}")
            return
        for name, value, what in readings:
            second, ctx = self._sandbox(saved, line, piece, dup, pieces, readings={name: value}, judging_only=True)
            if second and all(c.verdict == "holds" for c in second):
                for c in second:
                    c.why += f" (reading {what})"
                self._keep(before, second, ctx)
                if name == "L":          # the text's L is |𝐋| for the rest of its section (its definitions too)
                    self.vocab.readings[name] = value
                return
        if readings:                # read as written after all: now with its correction
            del self.claims[before:]
            self.ctx = _copied(saved)
            self._statement_read(line, piece, dup, pieces)
            first = self.claims[before:]
        if any(c.verdict == "typo" for c in first) and not dup:
            self._in_their_notation(saved, line, piece, pieces, first)
        if self._running_names_off(saved, line, piece, dup, pieces, first):
            return
        learned = self._learned(piece)
        if learned and not (primed_functions.leads(piece) and self._primed_read(piece)):
            second, ctx = self._sandbox(saved, line, piece, dup, pieces, names_off=True, judging_only=True)
            if not any(c.verdict in ("typo", "fails") for c in second):
                bindings = self._learned_bindings(piece)
                # the edit is sought now, in the reading's own state, and only where a sibling may confirm
                edit = self._one_edit(saved, line, piece, pieces) if not self.judging_only and bindings and any(
                    c.verdict == "fails" and c.correction is None for c in first) and (any(
                    p != piece and bindings <= self._learned_bindings(p) for p in pieces)
                    or self._said_and_held(bindings) is not None) else None
                for c in first:
                    # a rule tied by the prose by design (a named nutation rate, a vector said to precess) keeps its verdict
                    if c.verdict in ("typo", "fails") and c.kind not in ("nutation rate", "precession vector"):
                        self.unconfirmed = [*self.unconfirmed,
                                            (c, c.verdict, c.correction, c.why, learned, bindings, edit)]
                        c.why = (f"reading {learned} (as the prose names it) it does not hold: {c.why}; "
                                 "unchecked, since the text may mean something else by it here")
                        c.verdict, c.correction = "unchecked", None

    def _primed_read(self, piece, every=False) -> bool:
        """Is the statement's first member (any of its symbols: ``every``) a primed function the text
        defined, read as its derivative?"""
        try:
            members = lx.parse(piece, self.vocab).members
        except lx.NotRead:
            return False
        first = members[0].value if members else None
        syms = set().union(*(m.value.free_symbols for m in members if hasattr(m.value, "free_symbols"))) if every \
            else {first} if isinstance(first, sp.Symbol) else set()
        return bool(primed_functions.definitions(self.vocab, self.ctx.defs, syms, self.tex))

    def _confirmed_by_siblings(self, claims):
        """A statement left unchecked because only the prose's names flag it is judged after all
        where another statement of the same display, read with those very bindings (every learned
        name it uses, bound by the same words of the prose), holds by the same kind of check: the
        reading is then the text's own (were it not, that sibling would not hold either)."""
        pending, self.unconfirmed = self.unconfirmed, []
        # a chain one of whose links holds only on the text's own statements vouches for no reading
        circular = {s.latex for s in claims if s.self_consistent}
        for c, verdict, correction, why, learned, bindings, edit in pending:
            if not bindings or not any(x is c for x in claims):
                continue
            # a sibling that restates the text's own earlier equation holds whatever the names mean
            sibling = next((s for s in claims if s is not c and s.verdict == "holds" and s.kind == c.kind
                            and s.latex != c.latex and bindings <= self._learned_bindings(s.latex)
                            and not s.self_consistent and s.latex not in circular), None)
            said = self._said_and_held(bindings) if sibling is None else None
            before = self._held_before(bindings, c) if sibling is None and said is None else None
            if sibling is None and said is None and before is None:
                continue
            c.verdict, c.correction = verdict, correction
            c.why = (f"reading {learned} (as the prose names it) it does not hold: {why}; the reading is "
                     f"confirmed by {sibling.latex.strip()} in the same display, which holds read with those names"
                     if sibling is not None else
                     f"reading {learned} (as the prose names it) it does not hold: {why}; the reading is confirmed by "
                     f"{before.latex.strip()} at line {before.line}, which holds read with those very names"
                     if before is not None else
                     f"reading {learned} (as the text names it at line {said.line}) it does not hold: {why}; the "
                     f"reading is confirmed by {said.latex.strip()}, the display that names them, which holds read so")
            if verdict == "fails" and edit is not None:
                c.verdict, c.correction = "typo", edit

    def _held_before(self, bindings, c):
        """An earlier claim that holds by the derivation read with every one of these bindings (the same
        words of the prose bound them all), or None: were the reading not the text's, it would not hold.
        A claim that holds whatever the names stand for (a restatement, an identity) confirms nothing, and
        one written in fewer symbols does not vouch for the others (a plain L may be the Lagrangian)."""
        return next((s for s in self.claims if s.line < c.line and s.verdict == "holds" and not s.self_consistent
                     and not s.why.startswith("identical") and "whatever" not in s.why
                     and bindings <= self._learned_bindings(s.latex) and _symbols(c.latex) <= _symbols(s.latex) - {None}), None)

    def _said_and_held(self, bindings):
        """The claim that holds, read with every binding, at the one line of a display that said them all
        (a column of components after a sentence naming the quantity), or None: the text's own formula
        confirms the reading it gave."""
        lines = {where for _, _, where in bindings}
        if len(lines) != 1 or not next(iter(lines)).startswith("line "):
            return None
        at = int(next(iter(lines))[5:])
        return next((s for s in self.claims if s.line == at and s.verdict == "holds" and said_columns.is_column(s.latex)
                     and bindings <= self._learned_bindings(s.latex)), None)

    def _confirm(self, value, parsed):
        """A claim held with names the running text defined: their definitions are the text's
        meaning (were one a slip, this claim would not hold)."""
        written = set(getattr(value, "free_symbols", ())) | set(getattr(parsed.members[0].value, "free_symbols", ()))
        self.ctx.confirmed |= {s for s in self.ctx.running if s in written}

    def _running_names_off(self, saved, line, piece, dup, pieces, first) -> bool:
        """A statement flagged only through names the running text defined (a table's
        ``$\\dot\\psi_3 = \\psi$``): the slip, if any, is in that sentence, not in the display, so
        the display's flagged members are unchecked, saying which definition they rest on. Not so
        once a claim that holds has been read with every one of them (`_confirm`)."""
        used = {s: n for s, n in saved.running.items() if s in saved.defs and any(
            s in _free_of(c) for c in [self._parsed_or_none(piece)])}
        if used and set(used) <= self.ctx.confirmed:
            return False
        if not used:
            return False
        bare = _copied(saved)
        for s in used:
            del bare.defs[s]
        second, _ = self._sandbox(bare, line, piece, dup, pieces, judging_only=True)
        if any(c.verdict in ("typo", "fails") for c in second):
            return False
        names = ", ".join(f"{self.tex(s)} = {self.tex(saved.defs[s])} (line {n})" for s, n in used.items())
        for c in first:
            if c.verdict in ("typo", "fails"):
                c.why = (f"reading {names} as the running text defines it, it does not hold: {c.why}; "
                         "unchecked, since the slip may be in that sentence rather than in this display")
                c.verdict, c.correction = "unchecked", None
        return True

    def _one_edit(self, saved, line, piece, pieces) -> str | None:
        """The one edit of a statement's LaTeX after which it holds: those `_in_their_notation`
        tries, then a symbol squared that another statement of the display writes squared."""
        probe = SimpleNamespace(verdict="typo", why="", correction=None)
        try:
            self._in_their_notation(saved, line, piece, pieces, [probe])
            if probe.correction is not None:
                return probe.correction
            for edited in _powers_as_in(piece, " ".join(p for p in pieces if p != piece)):
                second, _ = self._sandbox(saved, line, edited, False, pieces, judging_only=True)
                if second and all(c.verdict == "holds" for c in second):
                    return edited.strip()
        except (NameError, NotImplementedError):   # an edited reading with no value: no edit found by it
            pass
        return None

    def _parsed_or_none(self, piece):
        try:
            return lx.parse(piece, self.vocab)
        except (lx.NotRead, lx.Words):
            return None

    def _in_their_notation(self, saved, line, piece, pieces, claims):
        """The correction of a typo as the text would write it: the one edit of its own LaTeX (a
        sign, an index, sin ↔ cos, a difference's order, a factor, a power) after which the
        statement holds, so that it can be pasted back. Kept as found when no edit of the LaTeX
        does it (the correction then is the derivation's form)."""
        found = " ".join(c.why for c in claims if c.verdict == "typo")
        entry = "(entry" in found         # a matrix's entry: its entries' signs first
        ordered = sorted(_latex_edits(piece), key=lambda e: e[1] not in found and not (
            entry and e[1].startswith("the sign of the entry")))              # the kind found first
        written = _atoms(" ".join(pieces) if pieces else piece)
        for n, (edited, what) in enumerate(ordered):
            if n >= 60:
                return
            if self._unmet(_atoms(edited) - written):
                continue
            second, _ = self._sandbox(saved, line, edited, False, pieces, judging_only=True)
            if second and all(c.verdict == "holds" for c in second):
                for c in claims:
                    if c.verdict == "typo":
                        c.correction = edited.strip()
                return

    def _unmet(self, atoms) -> bool:
        """Whether an edit writes a symbol neither the derivation nor the text has (I₁₃ for I₃₃): the
        reading would drop the member it stands in, not judge it, so the edit corrects nothing."""
        met = set(self.vocab.generic.values())
        opened, self.vocab.open = self.vocab.open, False
        try:
            for atom in atoms - met:
                try:
                    if self.vocab.resolve(atom) is None:
                        return True
                except lx.NotRead:
                    return True
        finally:
            self.vocab.open = opened
        return False

    def _symmetry_keys(self):
        return [k for k in (I1, I2) if k in self.ctx.subs and {k, self.ctx.subs[k]} == {I1, I2}]

    def _under_symmetry(self, saved, line, piece, pieces, claims):
        """A statement that holds only because the text made the body symmetric says so:
        'under I₁ = I₂' with where the text said it."""
        keys = [k for k in self._symmetry_keys() if k in saved.subs]
        # only a claim that holds is told so: with none, the reading without I₁ = I₂ has no use
        if not keys or not any(c.verdict == "holds" for c in claims) or \
                not re.search(r"I_\{?[12]|T\b|L\b|E\b|p_", piece):
            return
        bare = _copied(saved)
        for k in keys:
            del bare.subs[k]
        second, _ = self._sandbox(bare, line, piece, False, pieces, judging_only=True)
        if any(c.verdict in ("typo", "fails") for c in second):
            where = self.ctx.stated.get(keys[0], "stated in the text")
            for c in claims:
                if c.verdict == "holds":
                    c.why += f" (under I₁ = I₂, {where})"
                    c.assumes.append(f"I_1 = I_2 ({where})")

    def _if_symmetric(self, saved, line, piece, dup, pieces, before) -> bool:
        """A statement that fails as written but holds for a symmetric body, which the text has
        not said it is: 'holds if I₁ = I₂', never fails."""
        # only a formula written for a symmetric body: I₁ (or a quantity) and no I₂ in it — where
        # the text writes both, they differ, and I₁ = I₂ would hide its slip
        if self._symmetry_keys() or re.search(r"I_\{?2", piece) or \
                not re.search(r"I_\{?1|\bT\b|\bL\b|\bE\b|p_", piece):
            return False
        sym = _copied(saved)
        sym.subs[I2] = I1
        second, _ = self._sandbox(sym, line, piece, dup, pieces, judging_only=True)
        if not second or not all(c.verdict == "holds" for c in second):
            return False
        for c in second:
            c.why += " — holds if I₁ = I₂ (the text does not say so)"
            c.assumes.append("I_1 = I_2 (not stated)")
        del self.claims[before:]
        self.claims.extend(second)
        return True

    def _sandbox(self, saved, line, piece, dup, pieces, readings=None, names_off=False, judging_only=False):
        """The statement read again from the context ``saved`` with other readings: its claims and
        the context it leaves; the checker's own state is left as it was. ``judging_only`` where
        only whether it holds or is flagged counts (typo or fails alike): no correction is sought."""
        keep_claims, keep_ctx = len(self.claims), self.ctx
        kept_state = self._trial_state()
        self.ctx = _copied(saved)
        kept_readings = dict(self.vocab.readings)
        self.vocab.readings.update(readings or {})
        self.vocab.names_off = names_off
        judging = self.judging_only
        self.judging_only = judging or judging_only
        try:
            self._statement_read(line, piece, dup, pieces)
        except (lx.NotRead, ArithmeticError, TypeError, ValueError, AttributeError, IndexError,
                KeyError, NotImplementedError, RecursionError, sp.PolynomialError):
            pass
        finally:
            self.vocab.readings.clear()
            self.vocab.readings.update(kept_readings)
            self.vocab.names_off = False
            self.judging_only = judging
        out, ctx = self.claims[keep_claims:], self.ctx
        del self.claims[keep_claims:]
        self.ctx = keep_ctx
        # what the trial left (solutions waiting, statements to read again) goes with its context
        self._trial_left = (ctx, self._trial_state())
        self._trial_restored(kept_state)
        return out, ctx

    def _trial_state(self):
        return list(self.pending), list(self.deferred), list(self.flushed), getattr(self, "settings_only", None)

    def _trial_restored(self, state):
        self.pending, self.deferred, self.flushed = (list(x) for x in state[:3])
        if state[3] is not None:
            self.settings_only = state[3]

    def _keep(self, before, claims, ctx):
        """Keep a trial reading: its claims, its context and what it left to read later."""
        del self.claims[before:]
        self.claims.extend(claims)
        self.ctx = ctx
        left = getattr(self, "_trial_left", None)
        if left is not None and left[0] is ctx:
            self._trial_restored(left[1])

    unconfirmed: list | tuple = ()
    """(claim, verdict, correction, why, learned, bindings, the one edit that makes it hold) of the
    statements of the display being read that only the prose's names flag, as judged before."""

    def _learned_bindings(self, piece) -> frozenset:
        """The bindings of the learned names in a statement: (table, key, meaning, where) of each,
        the symbol's own binding where the prose named that symbol, else its letter's."""
        try:
            toks = lx.scan(piece)
        except lx.NotRead:
            return frozenset()
        names = self.notes.names
        out = set()
        for t in toks:
            a = t.value
            if t.kind != "atom" or names.meaning(a) is None:
                continue
            key = (a.base, a.sub)
            where = names.where.get(key) or next((w for k, w in names.where.items() if k[0] == key[0]), "")
            if where == "the front matter":
                continue
            table = ("symbols", key) if key in names.symbols else \
                ("letters", (a.base, "plain" if not (a.bold or a.sub) else "vector"))
            out.add((table, names.meaning(a), where))
        return frozenset(out)

    def _learned(self, piece) -> str:
        """The names in a statement whose meaning came from the prose (not the front matter)."""
        try:
            toks = lx.scan(piece)
        except lx.NotRead:
            return ""
        names = self.notes.names
        out = []
        for t in toks:
            if t.kind == "atom" and names.meaning(t.value) is not None:
                key = (t.value.base, t.value.sub)
                where = names.where.get(key) or next((w for k, w in names.where.items() if k[0] == key[0]), "")
                if where != "the front matter":
                    text = f"{t.value.text} as {names.meaning(t.value)}"
                    if text not in out:
                        out.append(text)
        return ", ".join(out)

    def _snapshot(self):
        """A copy of the context whose containers can change without touching this one."""
        return _copied(self.ctx)
