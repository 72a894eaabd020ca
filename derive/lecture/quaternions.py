"""Displays in quaternions (attitude texts: aerospace, robotics, IMU filters), judged in their
four components.

Takes: the items of a text that writes of quaternions — its headings, the names its prose
and displays set (``\\mathbf{v}=\\mathbf{u}\\theta``, ``\\theta=\\|\\boldsymbol\\omega\\|\\Delta t``, "a
unit axis $\\mathbf{u}$", ``\\ddot{\\boldsymbol\\omega}=0``) and each display with a quaternion in it.
Gives: the mixin `Quaternions` of `derive.lecture.notes_check.Checker`, whose `_quaternions`
judges such a display when it can read a link of it, by `derive.lecture.quaternion_reader`:

* a chain's links, each member against the one before it that was read (a member outside the
  grammar is left out, the links around it checked across it, never flagged for it), at three
  exact points of the text's names; a member that ends in ``\\cdots`` is a truncated series,
  compared with the other member's series to the order of its shortest sum;
* rows that give a quaternion's successive rates (``\\dot{\\mathbf{q}} = …``, ``\\ddot{\\mathbf{q}} =
  …``, ``\\dddot{\\mathbf{q}} = …``): each row after the first against the rate of the row before,
  the quaternion's rate the first row's, the other names' rates their own (zero where the text
  assumes so);
* a chain headed by q's rate or by a step of q (``\\mathbf{q}_{t+1}``): its first member read
  judged by `derive.lecture.quaternion_kinematics` (one of the four forms of a unit quaternion's
  rate; the Taylor series or the exact step of the text's rate);
* a name written with its argument set equal to a matrix (``\\boldsymbol\\Omega(\\boldsymbol\\omega) =
  \\begin{bmatrix} … \\end{bmatrix}``): the text's definition, read in its place from then on.

A product of two quaternions is Hamilton's (i j = k) where the text names Hamilton's product, the
JPL one (its reverse) where it names that, and otherwise both: a link is judged only when both
rules give one verdict. A link that fails with a bold vector the text has not called a unit vector
is held to fail only if it fails with that vector a unit one too.

May import: :mod:`derive.lecture.latex_spellings`, :mod:`derive.lecture.quaternion_algebra`, :mod:`derive.lecture.quaternion_kinematics`,
:mod:`derive.lecture.quaternion_reader`, :mod:`derive.lecture.statements`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture.quaternion_algebra import Names, Quat, Unread, components
from derive.lecture.quaternion_kinematics import Point, QuaternionSteps, difference, flat, only_omega, step_of
from derive.lecture.quaternion_reader import applied_name, read
from derive.lecture.statements import top_level
from derive.lecture.latex_spellings import BOLD_MARK, VECTOR_MARK

_EQUALS = re.compile(r"(?<![<>!\\])=")
_MARK = re.compile(r"\\otimes|(?:^|[=&(]|\\\\)\s*\\frac\s*\{\s*d\s*q\s*\}|" + BOLD_MARK + r"\s*\{?\s*q\b|e\^\{?\s*" + BOLD_MARK)
"""A display in quaternions: a ⊗, a bold q, e to a bold vector, or dq/dt standing as a member of its own (after a
moment, ``I_{yy}\\frac{dq}{dt}``, q is a body rate, as ``\\dot{q}`` there is)."""
_BOLD_NAME = VECTOR_MARK + r"\s*\{?\s*\\?([A-Za-z]+)\s*\}?"
_NAME_ONLY = re.compile(r"\s*(?:\\Delta\s*)?(?:\\(?:dot|ddot|dddot)\s*\{?\s*)?" + _BOLD_NAME + r"\s*\}?\s*(?:\(t\))?\s*$")
_RATE_ROW = re.compile(r"\s*\\(dot|ddot|dddot)\s*\{\s*" + _BOLD_NAME + r"\s*\}\s*$")
_UNIT = re.compile(r"\bunit\s+(?:\w+\s+){0,2}\$\s*" + _BOLD_NAME)
_ZERO_RATE = re.compile(r"^\s*\\(dot|ddot)\s*\{?\s*" + _BOLD_NAME + r"\s*\}?\s*=\s*0\s*$")
_SET = re.compile(r"^\s*(" + _BOLD_NAME + r"|\\[A-Za-z]+)\s*=\s*(?!.*=)(.+)$", re.S)
_ORDER = {"dot": 1, "ddot": 2, "dddot": 3}
_PLAIN_RATE = re.compile(r"^\s*(?:\\dot\s*\{?\s*q\s*\}?|\\frac\s*\{\s*d\s*q\s*\}\s*\{\s*d\s*t\s*\})\s*$")
_Q_RATE = re.compile(r"^\s*(?:\\dot\s*\{\s*" + BOLD_MARK + r"\s*\{?\s*q\s*\}?\s*\}|\\dot\s*" + BOLD_MARK +
                     r"\s*\{\s*q\s*\}|\\frac\s*\{\s*d\s*" + BOLD_MARK + r"\s*\{\s*q\s*\}\s*\}\s*\{\s*dt\s*\})\s*$")
_RATE_WRITTEN = {n: re.compile(r"\\" + acc + r"\s*\{?\s*" + BOLD_MARK + r"\s*\{?\s*\\omega")
                 for acc, n in _ORDER.items()}

class Quaternions(QuaternionSteps):
    """Mixin of the checker. Uses ``self.notes`` and ``self._add``."""

    @property
    def _q_text(self) -> bool:
        """Whether the text writes of quaternions (decided once)."""
        if not hasattr(self, "_q_scopes"):
            body = self.notes.body
            self._q_on = re.search(r"quaternion|cuaterni|quaternio|四元数", body, re.I) is not None
            self._q_scopes = [(0, {}, set(), {})]       # (heading level, names set, unit vectors, zero rates)
            self._q_next = 0                             # the first item not yet read for what it sets
            low = body.lower()
            hamilton, jpl = "hamilton" in low, re.search(r"\bjpl\b", low) is not None
            self._q_rules = (False,) if hamilton and not jpl else (True,) if jpl and not hamilton else (False, True)
            self._q_unit_names = {m.group(1) for m in _UNIT.finditer(body)} | \
                ({"q"} if re.search(r"\bunit\s+quaternions?\s+\$\s*q\b", body) else set())
            # the components' order only where the text names them: q_w is the scalar, or q_0 is; not with a q_4
            self._q_style = "" if re.search(r"\bq_\{?4\b", body) else "0123" if re.search(r"\bq_\{?0\b", body) \
                else "wxyz" if re.search(r"\bq_\{?w\b", body) else ""
            # a text that names the components and never writes q bold calls the quaternion plain q
            self._q_plain = bool(self._q_style) and not re.search(VECTOR_MARK + r"\s*\{?\s*q\b", body)
        return self._q_on

    def _quaternion_item(self, item) -> None:
        """Keep what the text sets, section by section: names, unit vectors, rates assumed zero."""
        if item.kind == "heading":
            while len(self._q_scopes) > 1 and self._q_scopes[-1][0] >= item.level:
                self._q_scopes.pop()
            self._q_scopes.append((item.level, {}, set(), {}))
            return
        if item.kind in ("assumption", "inline"):
            _, sets, units, zero = self._q_scopes[-1]
            rate = _ZERO_RATE.match(item.latex)
            if rate:
                zero[(rate.group(2), _ORDER[rate.group(1)])] = True
                return
            m = _SET.match(item.latex)
            key = m and ("bold " + m.group(2) if m.group(2) else m.group(1).lstrip("\\"))
            if m and "\\begin" not in m.group(3) and len(key) > 1 and key.split()[-1] not in re.findall(_BOLD_NAME, m.group(3)):
                sets[key] = m.group(3).strip()
                if key.startswith("bold ") and re.match(r"\s*\\frac\s*\{\s*" + _BOLD_NAME + r"\s*\}\s*\{\s*\\\|", m.group(3)):
                    units.add(m.group(2))        # 𝐮 = 𝛚/‖𝛚‖: a unit vector by its definition

    def _q_names(self, jpl: bool) -> Names:
        defined, zero = {}, {}
        for _, sets, _, zeros in self._q_scopes:
            defined.update(sets)
            zero.update(zeros)
        rates = {}
        for name in ("omega",):
            for order in (1, 2, 3):
                rates[(name, order)] = (0, 0, 0) if any(zero.get((name, k)) for k in range(1, order + 1)) else \
                    components(name + "d" * order, "xyz")
        return self._q_with_rates(Names(defined=defined, rates=rates, style=self._q_style, jpl=jpl,
                                        step=getattr(self, "_q_step_now", None), plain_q=self._q_plain))

    def _q_units(self) -> set:
        return self._q_unit_names.union(*(u for _, _, u, _ in self._q_scopes))

    # -- a display
    def _quaternions(self, item, latex) -> bool:
        """Judge a display in quaternions; False (nothing added) when no link of it could be read."""
        if item.kind != "display" or not self._q_text:
            return False
        while self._q_next < len(self.notes.items) and self.notes.items[self._q_next] is not item:
            self._quaternion_item(self.notes.items[self._q_next])     # what the text set before the display
            self._q_next += 1
        rows = _rows(latex)
        self._q_applied(rows)
        if not _MARK.search(latex):
            return False
        rated = _rate_rows(rows)
        verdicts = self._q_rates(rows) if rated else self._q_chains(rows)
        self._q_step_now = None
        if not any(v[0] in ("holds", "fails") for v in verdicts):
            return False
        for row, (verdict, why) in zip(rows, verdicts):
            self._add(item.line, row, "quaternion algebra", verdict, why)
        return True

    def _q_applied(self, rows):
        """A name written with its argument set equal to a matrix or a quaternion the reader reads
        (``\\boldsymbol\\Omega(\\boldsymbol\\omega) = … = \\begin{bmatrix} … \\end{bmatrix}``): the text's
        definition of it, its last member read, from here on."""
        members = _members(rows[0]) if len(rows) == 1 else None
        key = applied_name(members[0]) if members and len(members) > 1 else None
        if key is None:
            return
        for tex in reversed(members[1:]):
            try:
                value = read(tex, self._q_names(False))
            except (Unread, ArithmeticError, TypeError, ValueError, NotImplementedError, sp.PolynomialError):
                continue
            if isinstance(value, (Quat, sp.MatrixBase)):
                self._q_scopes[0][1][key] = tex      # an operator the text defines holds in all it goes on to
                return

    def _q_chains(self, rows) -> list:
        """A verdict for each row: the link that ends at the row's last member."""
        out, before = [], None       # before: the last member read, (its LaTeX)
        for row in rows:
            members = _members(row)
            if members is None:
                out.append(("unchecked", "not a chain of equalities"))
                before = None
                continue
            if not row.lstrip().startswith("="):
                before, head = None, members[0]
                if _NAME_ONLY.match(members[0]) or re.match(r"\s*\\frac\s*\{\s*d", members[0]) or step_of(members[0]):
                    members = members[1:]     # the name the chain sets or goes on to
                else:
                    head = None
                self._q_step_now = step_of(head) if head else None
            verdict = ("unchecked", "names the quantity the chain goes on to")
            for tex in members:
                if not tex.strip():
                    continue
                if before is None:
                    try:
                        self._q_values(tex)
                        before = tex
                        verdict = self._q_headed(head, tex)
                    except Unread as err:
                        verdict = ("unchecked", f"cannot read it in quaternions: {err.why}")
                    except (ArithmeticError, TypeError, ValueError, NotImplementedError, sp.PolynomialError):
                        verdict = ("unchecked", "a step of the quaternion reader failed on it")
                    continue
                link = self._q_link(before, tex)
                if link is None:
                    verdict = verdict if verdict[0] == "fails" else ("unchecked", self._q_why)
                    continue
                verdict = link if verdict[0] != "fails" else verdict
                before = tex
            out.append(verdict)
        return out

    def _q_headed(self, head, tex):
        """The verdict of a chain's first member read, against its head when the head is q's rate or
        a step of q."""
        try:
            if head is not None and (_Q_RATE.match(head) or self._q_plain and _PLAIN_RATE.match(head)):
                return self._q_rate_claim(tex)
            if head is not None and step_of(head):
                return self._q_step_claim(tex, step_of(head))
        except Unread as err:
            return "unchecked", f"cannot judge it in quaternions: {err.why}"
        except (ArithmeticError, TypeError, ValueError, NotImplementedError, sp.PolynomialError):
            return "unchecked", "a step of the quaternion reader failed on it"
        return "unchecked", "the first member read: the links after it are checked against it"

    def _q_values(self, tex, jpl=False, point=None):
        return read(tex, self._q_names(jpl), point)

    def _q_link(self, a, b):
        """(verdict, why) of ``a = b``, or None (``self._q_why`` says why) when it is not judged."""
        results = []
        for jpl in self._q_rules:
            try:
                results.append(self._q_equal(a, b, jpl))
            except Unread as err:
                self._q_why = f"cannot read it in quaternions: {err.why}"
                return None
            except (ArithmeticError, TypeError, ValueError, NotImplementedError, sp.PolynomialError):
                self._q_why = "a step of the quaternion reader failed on it"
                return None
        if any(r is None for r in results):
            self._q_why = "a member's kind (a quaternion or a scalar) differs from the other's"
            return None
        rule = "Hamilton's product" if self._q_rules == (False,) else "the JPL product" if self._q_rules == (True,) \
            else "Hamilton's product or the JPL one"
        if all(r == "holds" for r in results):
            return "holds", f"the two members agree as quaternions ({rule})"
        if all(r == "fails" for r in results):
            return "fails", ("the member differs from the one before it as a quaternion, component by component "
                             f"({rule}, at exact values of the text's names)")
        self._q_why = "holds with one rule of the product (Hamilton's or the JPL one) and not the other; the text does not say which"
        return None

    def _q_equal(self, a, b, jpl):
        """'holds', 'fails' or None (not comparable) for ``a = b``."""
        names = self._q_names(jpl)
        names.truncated = []
        read(a, names)
        cut_a = list(names.truncated)
        names.truncated = []
        read(b, names)
        cut_b = list(names.truncated)
        if cut_a or cut_b:
            return self._q_series(a, b, jpl, cut_a or cut_b, bool(cut_a))
        units = self._q_units()
        verdict = self._q_at_points(a, b, jpl, units)
        if verdict == "fails":
            loose = {n for n in re.findall(_BOLD_NAME, a + b) if n not in units and n != "omega" and n != "p"
                     and "bold " + n not in names.defined} | ({"q"} if "q" not in units and names.style else set())
            if loose and self._q_at_points(a, b, jpl, units | loose) != "fails":
                raise Unread(f"it holds only where {', '.join(sorted(loose))} is of unit length, which the text has not said")
        return verdict

    def _q_point(self, k, units, keep=()):
        """The k-th exact point: every symbol the reader makes, by its name."""
        return Point(k, units, keep)

    def _q_at_points(self, a, b, jpl, units):
        names = self._q_names(jpl)
        for k in range(3):
            point = self._q_point(k, units)
            d = difference(read(a, names, point), read(b, names, point))
            if d is None:
                return None
            if any(abs(sp.N(c, 30)) > sp.Float("1e-20") for c in d):
                return "fails"
        return "holds"

    def _q_series(self, a, b, jpl, cut, a_cut):
        """A truncated series (``… + \\cdots``) against the other member, to the order of its shortest sum."""
        names = self._q_names(jpl)
        free_scalars = {s for c in cut for s in _atoms(c) if not re.search(r"_[xyzw0-3]$", s.name)}
        var = None
        for s in free_scalars:
            if all(sp.Poly(sp.expand(x), s).degree() >= 1 for x in (c for c in flat(cut)) if x != 0 and x.has(s)):
                var = s if var is None else False
        if not var:
            raise Unread("a series in no single variable")
        order = min(sp.Poly(sp.expand(x), var).degree() for x in flat(cut) if x != 0 and x.has(var))
        units = self._q_units()
        for k in range(3):
            point = self._q_point(k, units, keep=(var,))
            pa, pb = read(a, names, point), read(b, names, point)
            d = difference(pa, pb)
            if d is None:
                return None
            for c in d:
                low = sp.series(c, var, 0, order + 1).removeO()
                if any(abs(sp.N(coeff, 30)) > sp.Float("1e-20") for coeff in sp.Poly(sp.expand(low), var).all_coeffs()):
                    return "fails"
        return "holds"

    # -- rows of successive rates
    def _q_rates(self, rows) -> list:
        rated = _rate_rows(rows)
        out = [self._q_headed(rows[0].split("=")[0] if rated[0][2] == "q" else None, rated[0][1])]
        for k in range(1, len(rows)):
            prev, cur = rated[k - 1], rated[k]
            if cur is None or prev is None or cur[0] != prev[0] + 1 or cur[2] != prev[2]:
                out.append(("unchecked", "not the rate of the row before"))
                continue
            results = []
            try:
                for jpl in self._q_rules:
                    results.append(self._q_rate_step(prev[1], cur[1], rated[0][1], rated[0][2], jpl))
                    written = max([n for n in (1, 2, 3) if _RATE_WRITTEN[n].search(prev[1] + cur[1])], default=0)
                    if results[-1] == "fails" and self._q_rate_step(prev[1], cur[1], rated[0][1], rated[0][2], jpl,
                                                                    above=written) == "holds":
                        raise Unread("it holds only where the rates of omega the rows do not write vanish, "
                                     "which the text has not said")
            except Unread as err:
                out.append(("unchecked", f"cannot read it in quaternions: {err.why}"))
                continue
            except (ArithmeticError, TypeError, ValueError, NotImplementedError, sp.PolynomialError):
                out.append(("unchecked", "a step of the quaternion reader failed on it"))
                continue
            if all(r == "holds" for r in results):
                out.append(("holds", "the rate of the row before, with the first row's rate of the quaternion"))
            elif all(r == "fails" for r in results):
                out.append(("fails", "not the rate of the row before: with the first row's rate of the quaternion "
                                     "and the product rule (the factors kept in order) the row before differentiates to "
                                     "another quaternion, component by component"))
            else:
                out.append(("unchecked", "holds with one rule of the product and not the other; the text does not say which"))
        return out

    def _q_rate_step(self, before, row, rate, name, jpl, above=None):
        """'holds' or 'fails': ``row`` against the rate of ``before``, the quaternion ``name``'s rate
        ``rate`` (with the rates of omega above the order ``above`` taken zero, when given)."""
        names = self._q_names(jpl)
        if above is not None:
            names.rates.update({("omega", n): (0, 0, 0) for n in (1, 2, 3) if n > above})
        comps = components(name, self._q_style)
        rates = {}
        for order in (1, 2, 3):
            lower = components("omega", "xyz") if order == 1 else names.rates[("omega", order - 1)]
            rates.update((lo, hi) for lo, hi in zip(lower, names.rates[("omega", order)]) if isinstance(lo, sp.Symbol))
        dq, value = read(rate, names), read(before, names)
        if not isinstance(value, Quat) or not isinstance(dq, Quat):
            raise Unread("a rate that is not a quaternion")
        if not (only_omega(value, self._q_style) and only_omega(dq, self._q_style)):
            raise Unread("rows in vectors whose rates the text does not give")
        rates.update(zip(comps, dq.c))
        derived = [sum(sp.diff(c, s) * r for s, r in rates.items()) for c in value.c]
        units = self._q_units()
        for k in range(3):
            point = self._q_point(k, units)
            d = difference(point.put(Quat(tuple(derived))), read(row, names, point))
            if d is None:
                raise Unread("a row that is not a quaternion")
            if any(abs(sp.N(c, 30)) > sp.Float("1e-20") for c in d):
                return "fails"
        return "holds"


def _atoms(value):
    return set().union(*(sp.sympify(c).free_symbols for c in flat([value])))


def _rows(latex: str) -> list[str]:
    """The display's rows: an ``array``, ``aligned`` or ``align`` cut at its row ends (a matrix's
    rows stay whole), its alignment marks dropped."""
    body = re.sub(r"\\(?:begin|end)\{(?:array|aligned|align\*?|split|eqnarray\*?|gathered)\}(?:\{[^{}]*\})?", " ", latex)
    rows, depth, start, k = [], 0, 0, 0
    while k < len(body):
        if body.startswith("\\begin{", k):
            depth += 1
        elif body.startswith("\\end{", k):
            depth -= 1
        elif body.startswith("\\\\", k):
            if depth == 0:
                rows.append(body[start:k])
                start = k + 2
            k += 2
            continue
        k += 1
    rows.append(body[start:])
    cleaned = []
    for r in rows:
        depth, out = 0, []
        for piece in re.split(r"(\\begin\{[a-z]*matrix\}|\\end\{[a-z]*matrix\})", r):
            if piece.startswith("\\begin"):
                depth += 1
            elif piece.startswith("\\end"):
                depth -= 1
            elif depth == 0:
                piece = piece.replace("&", " ")
            out.append(piece)
        row = " ".join("".join(out).split())
        row = re.sub(r"^(?:\\q?quad\s*|\{\}\s*)+", "", row)
        if cleaned and re.match(r"[+-]", row):
            cleaned[-1] += " " + row          # a long right side carried over to the next row
        elif row:
            cleaned.append(row)
    return cleaned


def _members(row: str) -> list[str] | None:
    """A row's members, cut at its top-level ``=`` (None when it has another relation)."""
    if re.search(r"\\(?:gets|leq?|geq?|approx|neq|to|rightarrow)(?![A-Za-z])|[<>]", re.sub(r"\\lim_\{[^{}]*\}", "", row)):
        return None
    bounds = [0, *(p for m in top_level(row, _EQUALS) for p in (m.start(), m.end())), len(row)]
    return [row[bounds[k]:bounds[k + 1]].strip() for k in range(0, len(bounds), 2)]


def _rate_rows(rows):
    """For rows ``\\dot{X} = …``, ``\\ddot{X} = …`` of one bold X, each row's (order, right side, X)
    (None for a row of another shape); None unless the first two rows are such, in order."""
    out = []
    for row in rows:
        members = _members(row)
        m = _RATE_ROW.match(members[0]) if members and len(members) == 2 else None
        out.append((_ORDER[m.group(1)], members[1], m.group(2)) if m else None)
    if len(out) < 2 or out[0] is None or out[1] is None or out[0][0] != 1 or out[1][0] != 2 or out[0][2] != out[1][2]:
        return None
    return out


__all__ = ["Quaternions"]
