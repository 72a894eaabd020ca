"""Check every formula of a notes file against the derivation: ``derive verify NOTES.md``.

The notes are read by `derive.lecture.notes` (displays, assumptions, front matter) and each
formula by `derive.lecture.latex` (SymPy objects in the derivation's own symbols). A display is
cut into statements — rows of ``aligned``/``split`` blocks (``\\\\``), pieces separated by
``\\qquad`` or ``\\Rightarrow`` — and a display that starts with ``=`` or ``\\approx`` continues
the previous statement's left side, one that starts with ``+``/``-`` its right side.

Kinds, decided from the vocabulary (`derive.lecture.latex.Vocabulary`):

* ``definition`` — a known quantity (T, L, **L**, E, E′, V_eff, p_α, p_γ, ω̃ᵢ, **ω**, ê′ᵢ, ê⁰ᵢ,
  d**L**/dt, Ω, Ω₁, Ω₂) equated to expressions: each is compared with the derived quantity
  (after the notes' own definitions, earlier quantities, and, when the rates α̇, γ̇ appear,
  ω̃ᵢ and p_α, p_γ in terms of the angles, are substituted). A quantity the notes *define* with
  ``≡`` (Ω ≡ …) is recorded and its definition used afterwards, right or wrong.
* ``identity`` — both sides written out, no known quantity on the left: they must be equal.
* ``equation of motion`` — a formula with ω̃̇ᵢ: its residual lhs − rhs must be a constant
  non-zero multiple of one of Euler's equations Iᵢω̃̇ᵢ − ((Iω̃)×ω̃)ᵢ (the derivation's, under the
  section's assumptions, e.g. I₁ = I₂).
* ``solution`` — ω̃ᵢ(t) = f(t): the group of consecutive solutions is substituted into the
  latest earlier equations of motion for those components, for each sign case the text states.
* ``approximation`` — ``≈`` with a small quantity stated in the text (β ≈ 0): claim − derived
  has no terms in its series up to the claim's own order.
* ``inequality`` — compared with the derived stability condition (as lhs − rhs ≥ 0), or with
  its k₂ ≥ 0 up to a positive factor (p_γ² ≥ 4 M g l I₁).
* ``steady precession`` — with β̇ = 0 stated in the text, a relation of α̇, β and p_γ (or γ̇,
  ω̃₃): lhs − rhs must be a multiple, by a factor free of the rates, of the β equation at
  β̇ = β̈ = 0, i.e. of ∂L/∂β = 0 (M g l = α̇ (p_γ − I₁ α̇ cos β) in z-y-z).
* ``lagrangian`` — L(β, β̇) = …: besides the identity, used as a Lagrangian in β its
  Euler–Lagrange equation must give the derived β̈.

The zero test is that of `derive.lecture.verify` (bounded symbolic steps, then seeded exact or
50-digit numeric points). Verdicts: ``holds``; ``typo`` when one single edit of the formula —
a sign, an index, sin ↔ cos, a factor 2 or ½, a power ±1, a swapped label, a duplicated row —
makes it hold (the corrected formula is given in LaTeX); ``fails`` with why; ``unchecked`` with
why (not a claim, unknown symbol, cannot parse).
"""
from __future__ import annotations

import contextlib
import functools
import gc
import re

import sympy as sp

from derive.lecture import latex as lx
from derive.lecture import notes as nt
from derive.lecture import delta_quotients, dimensional_arguments, rearranged, summation_index, worked_values
from derive.lecture.arithmetic import arithmetic
from derive.lecture.comparing import free, series_order
from derive.lecture.context import Context
from derive.lecture.derivation import derivation, keep
from derive.lecture.notes_claims import VERDICTS, Claim, exit_status, render, summary  # noqa: F401  (the report's API)
from derive.lecture.own_rates import OwnRates
from derive.lecture.reading_rules import ReadingRules
from derive.lecture.spellings import spellings, written_back
from derive.lecture.stated_convention import general_form
from derive.lecture.statements import continues, repeated_labels, restates_side, statements, top_level
from derive.lecture.text_motion import top_relations
from derive.lecture.text_matrices import matrices_put
from derive.lecture.inferred_convention import inferred
from derive.lecture.index_definitions import instance
from derive.symbolic.lagrangian import ACCELS, I1, I2, I3
from derive.symbolic.rotations import ANGLES, RATES

_NOT_FOLLOWED = (lx.NotRead, ArithmeticError, TypeError, ValueError, AttributeError, IndexError, KeyError,
                 NotImplementedError, RecursionError, sp.polys.polyerrors.BasePolynomialError)
"""What a step of the reader raises on a formula it cannot follow (SymPy's own errors among them)."""


def _failed_step(err) -> str:
    return (str(err) if isinstance(err, lx.NotRead) else
            f"a step of the reader failed on it ({type(err).__name__}): it is left unjudged")


def _name_tex(name: str) -> str:
    """An angle's name (``theta``, ``psi_betaalpha``) as LaTeX."""
    base, _, sub = name.partition("_")
    return "\\" + base + (f"_{{{sub}}}" if sub else "")


# ---- the checker ------------------------------------------------------------------------------
class Checker(ReadingRules):
    """Walks the items of `Notes` in order, keeping the context, and checks each statement."""

    def __init__(self, notes: nt.Notes):
        self.notes = notes
        self.vocab = lx.Vocabulary(angles=tuple(notes.angles), aliases=nt.angle_aliases(notes),
                                   open=True, names=notes.names, delta_quantity=lx.delta_quantity(notes.body))
        self.d = derivation(notes.convention)
        self.derivations = [self.d]      # every convention the text used or was tried in, kept for the next command
        self.vocab.axial = "xyz".index(self.d.conv.axes[2])
        self.vocab.body_rate = self._body_rate
        if notes.names is not None and "vertical" in notes.names.letters.values():
            self.vocab.vertical = tuple(self.d.conv.matrix().T[:, 2])   # the upward vertical in body axes
        self.ctx = Context()
        self._sections = []          # [heading level, the context its subsections start from]
        self._open_display()
        self.claims: list[Claim] = []
        self._inline_claims = set()     # id() of the claims read from math in a sentence
        self.pending: list = []     # solution statements waiting for their group
        self.pending_subs = None    # the settings of the display that wrote them
        self.flushed: list = []     # the verdicts of the group, until placed
        self._last_fix = None       # the corrected value the last single-edit search found
        self.spelled = {}           # derivation symbol → how the text last wrote it (spellings)
        self.deferred: list = []    # (claim, line, statement, context) read again with later definitions

    # -- names for LaTeX output
    @functools.cached_property
    def names(self) -> dict:
        names = {}
        angle_tex = [_name_tex(a) for a in self.notes.angles]
        for k in range(3):
            a = angle_tex[k]
            names[ANGLES[k]] = a
            names[RATES[k]] = rf"\dot{{{a}}}"
            names[ACCELS[k]] = rf"\ddot{{{a}}}"
            names[lx.W[k]] = rf"\tilde{{\omega}}_{{{k + 1}}}"
            names[lx.WD[k]] = rf"\dot{{\tilde{{\omega}}}}_{{{k + 1}}}"
            names[lx.BASIS[k]] = rf"\hat{{\mathbf{{e}}}}_{{{k + 1}}}"
            names[lx.PRIMED[k]] = rf"\hat{{\mathbf{{e}}}}_{{{k + 1}}}'"
            names[lx.INERTIAL[k]] = rf"\hat{{\mathbf{{e}}}}_{{{k + 1}}}^{{0}}"
        names[lx.p_alpha_sym()] = rf"p_{{{angle_tex[0]}}}"
        names[lx.p_gamma_sym()] = rf"p_{{{angle_tex[2]}}}"
        names.update(lx.QUANTITY_LATEX)
        return names

    def tex(self, obj) -> str:
        return written_back(sp.latex(obj, symbol_names={**self.names, **self.spelled}), self.spelled)

    # -- the walk
    def run(self) -> list[Claim]:
        items = self.notes.items
        k = 0
        while k < len(items):
            item, met = items[k], set(self.vocab.generic)
            if self.notes.names is not None:
                self.notes.names.here = item.line
            if item.kind == "heading":
                self._flush()
                self._place_flushed(len(self.claims))
                self._enter_section(item.level)
                self._problem_begun(item.text)
                if nt.SYMMETRIC.search(item.text):
                    self._symmetric(item.line, item.text)
            elif item.kind == "convention":
                self._stated_convention(item)
            elif item.kind == "context" and item.text == "along momentum":
                self.ctx.orientation, self.ctx.orientation_prose = item.line, True
            elif item.kind == "context":
                self._symmetric(item.line, item.lead)
            elif item.kind == "assumption":
                self._small_before_ll(item.latex)
                self._frame_setting(item.latex)
                self._basis_setting(item.latex)
                self._assume(item)
            elif item.kind == "signs":
                self._signs(item)
            elif item.kind == "small":
                self._small(item.symbols)
            elif item.kind in ("display", "inline"):
                self._small_before_ll(item.latex)
                latex = "= " + item.latex if item.kind == "display" and restates_side(item.lead, item.latex) else item.latex
                # displays that start with + or − continue the previous one's right side
                while item.kind == "display" and k + 1 < len(items) and items[k + 1].kind == "display" \
                        and continues(latex, items[k + 1].latex) and not restates_side(items[k + 1].lead, items[k + 1].latex):
                    k += 1
                    latex = latex + " " + items[k].latex
                start = len(self.claims)
                if not self._quaternions(item, latex):
                    self._display_probed(item, latex)
                if item.kind == "inline" and not item.alone:
                    self._inline_claims.update(map(id, self.claims[start:]))
            self._perturbation_named(item, met)
            k += 1
        self._flush()
        self._place_flushed(len(self.claims))
        self._read_later_definitions()
        self._rotation_products()
        self._axis_angle_turns()
        self._check_changes()
        self._inline_unflagged()
        return self.claims

    def _inline_unflagged(self):
        """Math in a sentence is read for the names, cases and conditions it gives (and confirmed
        where it holds), never flagged: prose writes a condition ("the angles where $U(\\theta)=E$")
        or a name of its own ("the unit vector $\\hat e_1 = …$") as an equation."""
        for c in self.claims:
            if id(c) in self._inline_claims and c.verdict in ("typo", "fails"):
                c.why = f"math in the prose, read as a condition or a name the text sets, not as a claim (as an identity: {c.why})"
                c.kind, c.verdict, c.correction = "setting", "unchecked", None

    def _add(self, line, latex, kind, verdict, why="", correction=None):
        self.claims.append(Claim(line, latex, kind, verdict, correction, why))

    # -- a display
    def _display(self, item, latex):
        start = len(self.claims)
        try:
            self._display_statements(item, latex)
        except _NOT_FOLLOWED as err:     # a step around the statements' own guards: the display is unjudged
            self._add(item.line, latex, "unknown", "unchecked", f"cannot check it: {_failed_step(err)}")
            self._close_display()
        self._cases_not_applied(item, start)
        self._free_indices_unlike(item, latex, start)
        self._untied_partials_unjudged(start)

    def _display_statements(self, item, latex):
        pieces = statements(latex)
        if not pieces:
            self._add(item.line, latex, "text", "unchecked", "not a formula")
            return
        seen = []
        start, self.unconfirmed = len(self.claims), []
        self._open_display(inline=item.kind == "inline", line=item.line)
        if self._frame_display(item.line, pieces) or self._coordinate_turn(item.line, pieces) or self._axis_product(item.line, pieces) or \
                self._at_setting(item.line, pieces) or self._elliptic_solution(item.line, pieces) or \
                self._unspun_frame(item.line, pieces):
            self._close_display()
            return
        self._named_at_chain_end(latex, item.line)
        relabelled = repeated_labels(pieces)
        previous, mark, unlike = None, None, []
        for k, piece in enumerate(pieces):
            if k == len(pieces) - 1 > 0 and statements(latex.rsplit("\\Rightarrow", 1)[-1]) == [piece]:
                mark = len(self.display_settings)     # what is set from here is the display's conclusion
            # a row going on with "=" that repeats one before restates the chain's value, no copied row
            dup = piece in seen and len(pieces) > 2 and not re.match(r"\s*(=|\\approx|\\equiv)", piece)
            seen.append(piece)
            if piece in relabelled:
                self._add(item.line, piece, "setting", "typo", "repeats the label of an earlier row of this block with "
                          "another value; the row that should stand here is the label the block leaves out (an index)",
                          relabelled[piece])
                self._given(item.line, relabelled[piece])
                continue
            first_eq = top_level(piece, _EQUALS)
            if not re.match(r"\s*(=|\\approx|\\equiv)", piece) and first_eq:
                # a row that goes on with "=" continues this statement, read or not — never an older one
                self.ctx.head = piece[:first_eq[0].start()].strip()
            before = len(self.claims)
            # what is written back uses the text's latest spelling of each symbol it has written
            self.spelled.update(spellings(piece, self.vocab, {*self.names, I1, I2, I3}))
            implied = self._implied(pieces, k, latex)       # judged before the conclusion sets its name
            try:
                if not (self._nested_spins(item.line, piece) or self._turn_rates(item.line, piece)):
                    self._read_axes_or_plain(item.line, piece, dup, pieces)
                self._hat_unread(item.line, piece, before)
                self._lost_backslash(item.line, piece, latex, before)
                for after in (self._letter_digits, self._exponent_relation, self._scalar_vector_sum, self._stated_theorem, self._index_euler):
                    after(item.line, piece, before)
                self._judge_implied(implied, before)
                self._row_step(item.line, piece, before)
                self._shape_moment(item.line, piece, before)
            except _NOT_FOLLOWED as err:
                # a formula the checker cannot follow is reported as such, never given a verdict
                self._add(item.line, piece, "unknown", "unchecked", f"cannot check it: {_failed_step(err)}")
                if not isinstance(err, lx.NotRead):
                    self.deferred.append((self.claims[-1], item.line, piece, self._snapshot()))
            self._linked(item.line, piece, before, previous, dup, pieces)
            unlike.append(self._unlike_terms(item.line, piece))
            previous = piece
            self._place_flushed(before)
            self._note_motion(item.line, piece)
        self._confirmed_by_siblings(self.claims[start:])
        self._close_display(self.display_settings[mark:] if mark is not None else ())
        self._unlike_flagged(item.line, [u for u in unlike if u], start)

    def _place_flushed(self, at):
        """A group of solutions a later statement closed, placed before it (not its claims to reread)."""
        if self.flushed:
            self.claims[at:at] = self.flushed
            self.flushed = []

    def _statement(self, line, piece, duplicate=False, pieces=()):
        if self.notes.names is not None:
            self.notes.names.here = line        # the names the prose gives in this section hold
        self._note_plane(line, piece)
        text = piece
        if re.match(r"\s*(=|\\approx|\\equiv)", piece) and self.ctx.head:
            text = self.ctx.head + " " + piece
        if re.match(r"\s*\\Omega\s*(_\s*\{?\s*[12]\s*\}?)?\s*\\equiv", text):
            self.vocab.omega_names = True          # the lecture's frequencies, defined by the text
        if general_form(text):
            self._add(line, piece, "rotation", "unchecked", "not a claim: the general form of a sequence of three turns")
            return
        other = self._turn_read_apart(text)
        if other is not None:
            self._add(line, piece, "rotation", *other)
            return
        text = self._single_axis_turns(text)
        self._hat_note(line, text)
        self.generics_before = set(self.vocab.generic)     # the text's symbols met before this statement
        if self._vector_size(line, piece, pieces):
            return
        if self._two_cases(line, piece, duplicate, pieces) or self._definite_integral(line, piece, text) or self._perturbed(line, piece, text) \
                or self._operator(line, piece, text) or self._coordinate(line, piece, text) or self._constants_collapsed(line, piece, text):
            return
        step = rearranged.check(text)
        if step is not None:
            self._add(line, piece, "rearrangement", *step)
            return
        summed = next(((k, s) for k, s in (("sum", summation_index.slip(text)), ("rate", delta_quotients.slip(text))) if s), None)
        if summed is not None:        # a summand that does not run with its index, a quotient that lost its Δ
            self._add(line, piece, summed[0], "typo", summed[1][1], None if self.judging_only else summed[1][0])
            return
        if self._basis_statement(line, piece, text) or self._algebra_first(text) and self._algebra_or_named(line, piece, text):
            return
        if self._body_axes_first(line, piece, text):
            return
        self._rates = getattr(self, "_rates", None) or OwnRates()   # a worked example's numbers, ḟ(t) of its f(t)
        given = {k: v for table in (self.ctx.subs, self.ctx.defs) for k, v in table.items()
                 if isinstance(k, sp.Symbol) and isinstance(v, sp.Expr) and v.is_number}   # r = 0.1 given
        for kind, (verdict, why) in [*(("arithmetic", a) for a in arithmetic(text, self.vocab, given)),
                                     *(("rate", r) for r in self._rates.check(line, text, self.vocab))]:
            self._add(line, piece, kind, verdict, why)
        try:
            parsed = lx.parse(text, self.vocab)
        except lx.Words:
            self._add(line, piece, "text", "unchecked", "not a claim: words, not a formula")
            return
        except lx.NotRead as err:
            why = err.why
            if self._dot_integral(line, piece, text) or self._vectors(line, piece, text) or self._algebra_or_named(line, piece, text) \
                    or self._roots_restated(line, piece, text) or self._named_vectors(line, piece, text) \
                    or self._body_links(line, piece, text):
                return
            if why.startswith("unknown symbol") and self._new_symbol(line, piece, text):
                return
            self._add(line, piece, "unknown", "unchecked", why)
            return
        if len(parsed.members) < 2:
            if not self._written_out(line, piece, parsed):      # or it writes out the name defined before it
                self._add(line, piece, "expression", "unchecked", "not a claim: no relation")
            return
        head_end = _first_relation(text)
        if head_end is not None:
            self.ctx.head = text[:head_end].strip()
        if (own := dimensional_arguments.dimensional_argument(parsed.members)) is not None:
            self._add(line, piece, "unknown", "unchecked", own)
            return
        self._text = text                   # the statement with the left side it continues
        if not duplicate and self._heavy_first(line, piece, parsed):
            return
        parsed = self._constant_dropped(line, piece, parsed)
        parsed = parsed if parsed is None else self._loose_ends_dropped(parsed)
        if parsed is not None and not duplicate and self._second_order(line, piece, parsed):
            return
        if parsed is not None and not duplicate and self._small_moment(line, piece, parsed):
            return
        row = None if parsed is None or duplicate else self._solution_row(parsed)
        if row is not None:
            if any(p[2] == row[0] for p in self.pending):
                self._flush()                  # a component met again starts a new group (Lᵢ after ω̃ᵢ)
            self.pending.append((line, piece, *row))
            self.settings_only = False
            return
        if parsed is not None and not duplicate and self._text_motion(line, piece, parsed):
            return
        if parsed is None or (not duplicate and self._text_statement(line, piece, parsed)):
            return
        self.settings_only = False
        rels = set(parsed.relations)
        if rels & {"≠", "→", "∝", "∼", "⇒", "≪", "≫"}:
            self._add(line, piece, "relation", "unchecked", f"not a claim the derivation decides ({', '.join(sorted(rels))})")
            return
        if duplicate:
            self._duplicate(line, piece, parsed, pieces)
            return
        m0 = parsed.members[0]
        self._flush()
        if rels & {"≥", "≤", ">", "<"}:
            self._inequality(line, piece, parsed)
        elif self._steady_section() and not isinstance(m0.value, lx.Quantity) and len(parsed.members) == 2 \
                and m0.value not in lx.W and not isinstance(m0.value, lx.Generic) \
                and (free(m0.value) | free(parsed.members[1].value)) & {self.d.rot.alpha_d}:
            self._steady(line, piece, parsed)
        elif isinstance(m0.value, lx.Quantity):
            self._definition(line, piece, parsed)
        elif any(free(self._resolve(m.value)) & set(lx.WD) for m in parsed.members):
            self._eom(line, piece, parsed)
        elif len(parsed.members) == 2 and any(free(m.value) & set(ACCELS) for m in parsed.members) \
                and not isinstance(m0.value, sp.MatrixBase):       # a column of rates' rates is an identity
            if not self._euler_in_angles(line, piece, [m.value for m in parsed.members]):
                self._angle_eom(line, piece, parsed)
        elif "≈" in rels and not self.ctx.small:
            self._add(line, piece, "approximation", "unchecked", "an approximation with no small quantity stated in the text")
        else:
            self._definition(line, piece, parsed)

    def _new_symbol(self, line, piece, text) -> bool:
        """X ≡ … with X unknown: record X (a new symbol of the notes) and its definition."""
        m = re.match(r"\s*(.+?)\s*\\equiv\s*(.+)$", text)
        if not m:
            return False
        try:
            atoms = lx.scan(m.group(1))
            rhs = lx.parse(m.group(2), self.vocab)
        except lx.NotRead:
            return False
        if len(atoms) != 1 or atoms[0].kind != "atom" or len(rhs.members) != 1:
            return False
        atom = atoms[0].value
        sym = sp.Symbol(atom.text, real=True)
        self.vocab.defined[atom.with_(text="")] = sym
        self.ctx.defs[sym] = rhs.members[0].value
        self._add(line, piece, "new symbol", "unchecked", f"defines a new symbol {atom.text} (recorded, then used)")
        return True

    # -- preparing sides
    def _resolve(self, v, keep=()):
        """Quantities → derived values, the notes' definitions → their right sides (not ``keep``)."""
        for _ in range(4):
            rep, syms = {}, free(v)
            for s in syms:
                if s in keep:
                    continue
                if isinstance(s, lx.Quantity):
                    forms = self.d.forms(s)
                    if forms:
                        rep[s] = self.ctx.forms_held.get(s, forms[0])
                elif isinstance(s, lx.Generic) and s in self.ctx.subs:
                    rep[s] = self.ctx.subs[s]      # a case the text sets for its own symbol wins
                elif s in self.ctx.defs:
                    rep[s] = self.ctx.defs[s]
                elif (value := instance(s, self.ctx.defs)) is not None:
                    rep[s] = value      # I_31 by the text's I_jh
            rep.update(self._dotted_definitions(v, syms))
            if not rep:
                break
            v = matrices_put(v, rep, self._basis_columns(v)) if any(isinstance(x, sp.MatrixBase) for x in rep.values()) \
                else v.xreplace(rep)
        return self._calculus(v)

    # -- kinds
    def _definition(self, line, piece, parsed):
        start, m0 = len(self.claims), parsed.members[0]
        key = m0.value
        forms = self._forms_of(key, m0.args) if isinstance(key, sp.Symbol) else []
        if any(r == "≡" for r in parsed.relations) and key in (lx.Omega, lx.Omega1, lx.Omega2):
            if self._own_sign(line, piece, parsed, forms):
                return
            self.ctx.defs[key] = parsed.members[1].value
        approx = "≈" in parsed.relations
        if not forms:
            # an identity: both sides written out
            if isinstance(key, sp.Symbol) and not isinstance(key, lx.Quantity) and key not in lx.BASIS \
                    and len(parsed.members) == 2 and not free(parsed.members[1].value) & {key}:
                kind = "definition"
            else:
                kind = "identity"
            left = self._resolve(key)
            for k, m in enumerate(parsed.members[1:], start=1):
                self._one(line, piece, "identity" if kind == "identity" else kind, left, m.value, parsed, k,
                          approx=approx, label=key)
            return self._links_past_head(line, piece, parsed, start)
        for k, m in enumerate(parsed.members[1:], start=1):
            if m.value == 0 and key is lx.DLDT:
                self._torque_free(line, piece, parsed)
                continue
            before = len(self.claims)
            self._one(line, piece, "approximation" if approx else "definition", None, m.value, parsed, k,
                      approx=approx, label=key, forms=forms, args=m0.args)
            if key in self.ctx.defs and parsed.relations[k - 1] == "≡" and \
                    any(c.verdict in ("typo", "fails") for c in self.claims[before:]):
                # a flagged definition is not carried forward (one slip is reported once): the
                # displays after it use its correction, or the derived quantity
                self.ctx.defs[key] = self._last_fix if self._last_fix is not None else forms[0]
        self._links_past_head(line, piece, parsed, start)
        self._untied_links(line, piece, parsed, start)
        if key is lx.LAGRANGIAN and m0.args and set(m0.args) <= {self.d.rot.beta, self.d.rot.beta_d}:
            self._lagrangian(line, piece, parsed.members[-1].value)

    def _one(self, line, piece, kind, left, value, parsed, k, approx=False, label=None, forms=None, args=None):
        """Check member k against the label's derived forms (or the written left side)."""
        keep = (label,) if label in (lx.Omega, lx.Omega1, lx.Omega2) and parsed.relations[k - 1] == "≡" else ()
        val = self._resolve(value, keep=keep)
        targets = forms if forms else [left]
        small = order = None
        if approx and not self.ctx.small:
            self._add(line, piece, "approximation", "unchecked", "an approximation with no small quantity stated in the text")
            return
        if approx:
            small = self.ctx.small[-1]
            order = series_order(val, small)
        seed, why = f"{piece}/{k}", ""
        for f in targets:
            ok, why = self._compare(val, self._resolve(f), seed, small, order)
            if ok:
                self._confirm(value, parsed)
                self._add(line, piece, kind, "holds", why)
                if forms and isinstance(label, lx.Quantity) and f is not forms[0] and not args and not approx:
                    self.ctx.forms_held[label] = f      # the text's L is the free body's T: so from here on
                return
        oriented = None if small is not None else self._oriented(line, val, targets, seed)
        on_motion = None if small is not None or oriented else self._on_the_motion(val, targets, seed)
        if oriented := oriented or on_motion or (small is None and self._fast_top(label, val)):
            self._confirm(value, parsed)
            self._add(line, piece, kind, "holds", oriented)
            self.claims[-1].self_consistent = bool(on_motion)   # on the text's own motion: vouches for no reading
            return
        if " against a " in why:
            self._add(line, piece, kind, "unchecked", f"cannot compare its sides: {why}")
            return
        loose = sorted(self.tex(x) for x in free(val) if isinstance(x, lx.Generic) and x not in self.ctx.defs
                       and x not in self._constants())
        untied = ("A", "B", "C")      # letters the reader knows only as free symbols (vocabulary.FREE_NAMES)
        if not loose and (forms or sum(type(m.value) is sp.Symbol and m.value.name in untied and m.value not in self.ctx.defs for m in parsed.members) > 1):
            # capitals the text never tied to the body are its own (diag(A, B, C) for the inertia tensor defines
            # them; A = B = C = M L^2/6 gives one body's moments): a relation in them is no slip
            loose = sorted(str(x) for x in free(val).union(*map(free, targets)) if x.name in untied and x not in self.ctx.defs)
        undecided = f"involves {', '.join(loose)}, which the text has not defined" if loose else \
            None if forms else self._undecidable([m.value for m in parsed.members], val, targets)
        undecided = undecided or worked_values.unchecked(piece, val, [self._resolve(f) for f in targets], self.tex, label)
        if undecided and undecided.startswith("an equation for the angles") and len(targets) == 1 and \
                self._at_stated_angles(line, piece, kind, value, val, self._resolve(targets[0]), parsed, k, keep):
            return
        if undecided:
            self._add(line, piece, kind, "unchecked", undecided)
            return
        if len(targets) == 1 and self._root_branch(val, self._resolve(targets[0]), seed):
            self._add(line, piece, kind, "unchecked", f"as written: {why}; its square holds: the two sides differ "
                      "by the sign of a square root, which the values the text allows decide")
            return
        self._last_fix = None
        fix = None if self.judging_only else self._search(value, targets, label, parsed, k, small, order, keep)
        if fix:
            self._add(line, piece, kind, "typo", f"as written: {why}; one edit ({fix[1]}) makes it hold", fix[0])
        else:
            self._add(line, piece, kind, "fails", f"as written: {why}")

    def _root_branch(self, val, target, seed) -> bool:
        """Do scalar sides with a square root in them differ only by its sign (equal squares)?"""
        if isinstance(val, sp.MatrixBase) or isinstance(target, sp.MatrixBase):
            return False
        if not any(p.exp.is_Rational and p.exp.q == 2 for e in (val, target) for p in sp.sympify(e).atoms(sp.Pow)):
            return False
        return self._compare(val ** 2, target ** 2, seed + "/squared")[0]

    def _lagrangian(self, line, piece, value):
        """L(β, β̇) used as a Lagrangian: β̈ from its Euler–Lagrange equation against the derived one."""
        rot = self.d.rot
        b, bd = rot.beta, rot.beta_d
        val = self._resolve(value)
        try:
            accel = (sp.diff(val, b) - bd * sp.diff(val, bd, b)) / sp.diff(val, bd, 2)
        except (TypeError, ValueError, ZeroDivisionError):
            return
        derived = self.d.reduction.beta_acceleration
        ok, why = self._compare(accel, derived, piece + "/lagrangian")
        if ok:
            self._add(line, piece, "lagrangian", "holds", "as a Lagrangian in β: " + why)
        else:
            self._add(line, piece, "lagrangian", "fails",
                      f"as a Lagrangian in β its Euler–Lagrange equation gives the wrong β̈ ({why}): the β motion "
                      f"follows from Routh's L_β = ½I₁β̇² − V_eff − p_γ²/(2I₃), the centrifugal term with the opposite sign")


_EQUALS = re.compile(r"(?<![<>!\\])=")


def _first_relation(text: str) -> int | None:
    spans = top_relations(text)
    return spans[0][0] if spans else None


# ---- running and reporting ----------------------------------------------------------------------
def check_notes(path, convention: str | None = None) -> list[Claim]:
    """Read the notes file and check every formula (see the module docstring)."""
    with _collector_paused():
        return inferred(nt.read_notes(path, convention), lambda seq: nt.read_notes(path, seq), _checked)


def check_text(text: str, convention: str | None = None, path: str = "<notes>") -> list[Claim]:
    """Like `check_notes`, for Markdown text already in memory."""
    with _collector_paused():
        return inferred(nt.parse_notes(text, path, convention), lambda seq: nt.parse_notes(text, path, seq), _checked)


@contextlib.contextmanager
def _collector_paused():
    """A reading with Python's cycle collector paused: SymPy's expressions are freed by their
    reference counts, while each collection walks every object alive; what a reading leaves in
    cycles goes at the first collection after it."""
    was = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was:
            gc.enable()


def _checked(notes: nt.Notes) -> list[Claim]:
    checker = Checker(notes)
    claims, probes = checker.run(), checker.probes_read()
    for d in {id(d): d for d in checker.derivations}.values():
        keep(d)  # what the text's conventions needed, for the next command
    return claims, probes
