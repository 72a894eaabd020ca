"""Read lecture notes as written: Markdown with LaTeX math, its front matter and its prose context.

What is read:

* **Front matter** (optional, first lines between ``---`` fences), ``key: value`` lines parsed by
  hand through a whitelist — ``convention`` (``z-y-z`` or ``z-x-z``) and ``angles`` (a bracketed
  list of three LaTeX names, e.g. ``[\\phi, \\theta, \\psi]``); anything else is an error. No YAML
  library, nothing evaluated. Without a ``convention`` there, the text's own statement of it
  holds (`derive.lecture.stated_convention`: ``R = R_3(\\theta_1) R_1(\\theta_2) R_3(\\theta_3)``,
  "3-1-2 Euler angles"), section by section (a ``"convention"`` item where a section changes it).
* **Displays**: ``$$…$$`` and ``\\[…\\]`` (over any number of lines), with the 1-based line on
  which each starts; ``aligned``/``split``/``array`` environments inside them are left for the
  checker to cut into rows. Inline ``$…$`` math is read too: a relation there is a claim (kind
  decided later) or, after a word such as *if*, *for*, *suppose*, *assume*, *with*, *when* or in
  a heading, or as the first math of a sentence that opens with such a word ("For a symmetric
  top, $I_1 = I_2$, …"), an **assumption**. A display with ``\\equiv`` defines, never assumes.
  A value set equal to a new symbol in running prose ("$\\dot\\phi = \\omega_\\phi$") is also the
  text's name for it after its section (`derive.lecture.prose_definitions`).
* **Context**: headings (Markdown ``#`` lines) cut the notes into sections; an assumption ("If
  $I_1 = I_2$", "For $\\tau = 0$", "Suppose $p_\\alpha = p_\\gamma$ and $\\beta \\approx 0$", a
  display right after "If"/"Suppose") applies to the displays that follow it until the next
  heading. "…$\\Omega_1$ and $\\Omega_2$ are both positive or both negative" (or "have opposite
  signs") is a sign assumption on those symbols.

`read_notes` returns the `Notes` (front matter and an ordered list of `Item`); an unreadable file
raises `derive.errors.SceneError` (exit 2, one line).
"""
from __future__ import annotations

import difflib
import re
from dataclasses import dataclass, field, replace
from pathlib import Path

from derive.errors import SceneError
from derive.lecture import bracket_cross
from derive.lecture import formula_names
from derive.lecture import moment_letters
from derive.lecture import named_frames
from derive.lecture import names as nm
from derive.lecture import notebook
from derive.lecture import package_macros
from derive.lecture import prose_definitions
from derive.lecture import source
from derive.lecture import statements
from derive.lecture import undefined_macros
from derive.lecture import stated_convention


def ValidationError(path, key, what) -> SceneError:
    """Bad notes input: ``<file>: <key>: <what>`` (exit status 2 on the command line)."""
    return SceneError(f"{path}: {key}: {what}")

PROPER = ("z-y-z", "z-x-z", "x-y-x", "x-z-x", "y-x-y", "y-z-y")
TAIT_BRYAN = ("z-y-x", "z-x-y", "x-y-z", "x-z-y", "y-x-z", "y-z-x")
CONVENTIONS = PROPER + TAIT_BRYAN
"""The twelve sequences, turning about the new (intrinsic) axes: six proper Euler, six Tait–Bryan."""
DEFAULT_ANGLES = {**{c: ("phi", "theta", "psi") for c in CONVENTIONS}, "z-y-z": ("alpha", "beta", "gamma"),
                  "z-y-x": ("psi", "theta", "phi")}
"""The angles' usual names, in the order of the turns: the 3-2-1 (yaw, pitch, roll) sequence turns
through ψ about z, θ about y, φ about x, as aircraft and spacecraft texts name them."""
TRIGGERS = {"if", "for", "suppose", "assume", "assuming", "when", "with", "let", "given", "provided", "set",
            "setting", "put", "putting", "taking", "substitution", "substituting", "since", "because"}
_ANGLE_NAME = re.compile(r"\\?([A-Za-z]+)\s*(?:_\s*(\{.+\}|\\?[A-Za-z0-9]+))?")
_BOLD_L = r"\$\s*\\(?:mathbf|vec|boldsymbol|bm)\s*\{?\s*[LJH]\s*\}?\s*\$"
_Z_AXIS = r"(?:\$\s*[zZ]\s*\$|\b[zZ])\s*[- ]?\s*axis"
_FIXED = r"(?:(?:fixed|space|spatial|inertial|laboratory)\s+)"
_VERB = r"(?:(?:points?|pointing|lies|lying|is|taken|chosen|directed)\s+)"
ALONG_MOMENTUM = re.compile(
    r"(?<!body )(?<!body-)(?<!body-fixed )(?:\b" + _FIXED + r"(?:[zZ]\s*)?[- ]?axis|" + _FIXED + r"?" + _Z_AXIS + r")\s+(?:is\s+)?"
    r"(?:taken|chosen|put|placed|laid|set)?\s*along\s+(?:the\s+)?(?:conserved\s+|constant\s+)?"
    r"(?:angular momentum|" + _BOLD_L + r")"
    r"|(?:angular momentum\s+(?:vector\s+)?(?:" + _BOLD_L + r"\s+)?" + _VERB + r"|" + _BOLD_L + r"\s+" + _VERB + r"?)"
    r"along\s+(?:the\s+)?" + _FIXED + r"?" + _Z_AXIS, re.I)
"""The prose choosing the fixed first axis along the angular momentum (a free body's usual frame): "the fixed axis
is taken along the angular momentum", "take the $z$-axis along $\\mathbf{L}$", "$\\mathbf{L}$ points along the
$z$ axis" (read on the text with its inline math; a body axis chooses nothing)."""
SYMMETRIC = re.compile(r"\b(?:axi)?symmetric(?:al)?\s+(?:heavy\s+)?(?:top|body|rigid body|rotor|gyroscope|spinning top)s?\b"
                        r"|\bLagrange(?:'s)?\s+(?:top|case)\b|\baxisymmetric\b|(?<!\bno\s)(?<!\bnot\s)\b(?:two\s+|the\s+)equal\s+moments\b", re.I)
"""Prose that makes the body symmetric about axis 3 (I₁ = I₂) for the rest of its section."""
_SMALL = re.compile(r"\b(?:are|is)\s+(?:also\s+)?(?:an?\s+)?(?:very\s+)?(?:(?:first|1st)[- ]order\s+)?small\b"
                    r"|\bsmall of (?:the )?first order\b|\b(?:as|to\s+be)\s+(?:very\s+)?small\b(?!\s+as\b)", re.I)
"""Prose that calls the quantities before it in its sentence small (to first order): "are small", "are
very small", "is first-order small", "are small perturbations", "takes … as small", "assumed to be small"."""
_RELATION = statements.RELATION
_MUCH_LESS = re.compile(r"\\ll(?![a-z])")


def small_before_much_less(latex: str) -> str:
    """What a ≪ says is small: the part before it, after an ≈ that sets it near zero
    (``0 \\approx \\omega_y, \\omega_z \\ll \\omega_x`` gives ``\\omega_y, \\omega_z``)."""
    return re.split(r"\\approx|\\simeq", _MUCH_LESS.split(latex)[0])[-1]


@dataclass(frozen=True)
class Item:
    """One thing of the notes, in order.

    ``kind``: ``"heading"`` (``text`` is the title), ``"convention"`` (``text``: the sequence a
    section states, ``symbols``: its angles' names, from here on), ``"context"`` (``text``: ``"symmetric"``, the
    prose says the body is symmetric; ``"along momentum"``, it takes the fixed axis along 𝐋), ``"display"`` (``latex``), ``"inline"`` (a
    relation in running text: a claim), ``"assumption"`` (``latex``: a relation assumed from
    here to the next heading), ``"signs"`` (``symbols``: the LaTeX of the symbols, ``text``:
    ``"same"`` or ``"opposite"``) or ``"small"`` (``symbols``: the LaTeX of quantities the prose
    calls small, "$\\omega_2, \\omega_3$ are first-order small": equations to first order in them). ``line`` is 1-based; ``lead`` the prose just before the math.
    """

    kind: str
    line: int
    latex: str = ""
    text: str = ""
    lead: str = ""
    symbols: tuple = ()
    display: bool = False
    level: int = 0                 # a heading's level (the number of #)
    alone: bool = False            # inline math that is its paragraph's whole line: a display in all but its $…$


@dataclass
class Notes:
    """The notes read: where from, the front matter and the items in order."""

    path: str
    convention: str = "z-y-z"
    angles: tuple = DEFAULT_ANGLES["z-y-z"]
    declared: dict = field(default_factory=dict)
    items: list = field(default_factory=list)
    names: nm.Names = field(default_factory=nm.Names)
    angles_stated: bool = False
    """The angles' names are the text's own, read from its displays or prose (no front matter)."""
    convention_stated: bool = False
    """The convention is given (``--convention``, the front matter) or stated by the text itself."""
    body: str = ""
    """The rendered text (prose and math), for readings that need what the prose says."""
    aliases: tuple | None = None
    """Other names of the angles, when the text is read again in a sequence it states nothing of:
    the names the z-y-z reading took (`angle_aliases` otherwise)."""


def _symbols(value: str, path: str) -> dict:
    """``{M: angular momentum, a: l}``: the text's names (LaTeX) → what they stand for."""
    value = value.strip()
    if not (value.startswith("{") and value.endswith("}")):
        raise ValidationError(path, "symbols", "expected a map like {M: angular momentum, a: l}")
    out = {}
    for entry in _top_level_commas(value[1:-1]):
        if not entry.strip():
            continue
        name, sep, meaning = entry.rpartition(":")
        if not sep or not name.strip() or not meaning.strip():
            raise ValidationError(path, "symbols", f"expected 'name: meaning', got {entry.strip()!r}")
        out[name.strip().strip("'\"")] = meaning.strip().strip("'\"")
    return out


def _top_level_commas(text: str) -> list[str]:
    """Split at the commas outside braces (``I_{1,2}: …`` keeps its comma)."""
    parts, depth, start = [], 0, 0
    for k, ch in enumerate(text):
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(text[start:k])
            start = k + 1
    parts.append(text[start:])
    return parts


def _front_matter(lines: list[str], path: str) -> tuple[dict, int]:
    """derive's keys (``convention``, ``angles``, ``symbols``) between the opening and closing ``---``.

    ``symbols`` is a flow map on its line, or a block of indented ``name: meaning`` lines. The
    front matter is shared with the tools that publish the text (Jekyll's ``layout``, jupytext's
    nested ``jupytext:`` map, MyST's ``kernelspec``, a list of ``tags``): any other key, with the
    indented or ``- `` lines under it, is theirs and is skipped unread; a key one slip away from
    one of derive's (``convetion``, ``angle``) is refused, naming it."""
    if not lines or lines[0].strip() != "---":
        return {}, 0
    out = {}
    block = None          # the key whose indented lines follow ("symbols")
    theirs = False        # the lines follow a key of another tool's
    for k, raw in enumerate(lines[1:], start=2):
        line = raw.strip()
        if line == "---":
            if block is not None:
                out[block] = _symbols("{" + ", ".join(out.pop("_" + block, [])) + "}", path)
            return out, k
        if not line or line.startswith("#") or theirs and (raw[:1] in (" ", "\t") or line.startswith("- ")):
            continue
        theirs = False
        if block is not None and raw[:1] in (" ", "\t"):
            out.setdefault("_" + block, []).append(line.lstrip("- "))
            continue
        if block is not None:
            out[block] = _symbols("{" + ", ".join(out.pop("_" + block, [])) + "}", path)
            block = None
        key, sep, value = line.partition(":")
        key, value = key.strip(), value.strip()
        if not sep:
            raise ValidationError(path, f"front matter line {k}", f"expected 'key: value', got {line!r}")
        if key == "convention":
            value = value.strip("'\"").lower().replace("–", "-").replace(" ", "")
            if re.fullmatch(r"[xyz]{3}", value):
                value = "-".join(value)
            if value not in CONVENTIONS:
                raise ValidationError(path, "convention", f"{value!r} is not one of {', '.join(CONVENTIONS)}")
            out[key] = value
        elif key == "angles":
            if not (value.startswith("[") and value.endswith("]")):
                raise ValidationError(path, "angles", "expected a list like [\\phi, \\theta, \\psi]")
            names = [v.strip().strip("'\"") for v in value[1:-1].split(",")]
            parsed = []
            for name in names:
                m = _ANGLE_NAME.fullmatch(name)
                if not m:
                    raise ValidationError(path, "angles", f"{name!r} is not a symbol name")
                # a subscripted angle (\\psi_{\\beta\\alpha}) is named by its letters: psi_betaalpha
                sub = re.sub(r"[\\{}\s]", "", m.group(2) or "")
                parsed.append(m.group(1) + ("_" + sub if sub else ""))
            if len(parsed) != 3 or len(set(parsed)) != 3:
                raise ValidationError(path, "angles", "expected three different names")
            out[key] = tuple(parsed)
        elif key == "symbols":
            if value:
                out[key] = _symbols(value, path)
            else:
                block = key
        elif near := difflib.get_close_matches(key.lower(), ("convention", "angles", "symbols"), n=1, cutoff=0.8):
            raise ValidationError(path, key, f"not a front matter key of derive's: {near[0]}?")
        else:
            out[key], theirs = value, True
    raise ValidationError(path, "front matter", "no closing '---'")


_INDEXED = re.compile(r"\s*(\\?[A-Za-z]+)\s*_\s*(?:\{\s*([ijk])\s*\}|([ijk]))\s*\\equiv\s*(.+?)\s*[,.;]?\s*", re.S)


def components(latex: str) -> list[str]:
    """A definition with a free index, ``c_i \\equiv \\cos\\theta_i``, as its three components
    (``c_{1} \\equiv \\cos\\theta_{1}``, …); any other formula as itself. The index must appear
    on the right side too, and no sum or product may bind it."""
    m = _INDEXED.fullmatch(latex)
    if not m or re.search(r"\\(?:sum|prod)(?![A-Za-z])", m.group(4)):
        return [latex]
    index = m.group(2) or m.group(3)
    used = re.compile(r"_\s*(?:\{\s*" + index + r"\s*\}|" + index + r"(?![A-Za-z]))")
    if not used.search(m.group(4)):
        return [latex]
    return [f"{m.group(1)}_{{{n}}} \\equiv " + used.sub("_{" + n + "}", m.group(4)) for n in "123"]


def _last_word(text: str) -> str:
    words = re.findall(r"[A-Za-z]+", text)
    return words[-1].lower() if words else ""


_SENTENCE_END = re.compile(r"[.!?:;]\s|\n\s*\n|^#[^\n]*\n", re.M)


def _opens_with_trigger(body: str, pos: int) -> bool:
    """Is the math at ``pos`` the first math of a sentence that opens with a trigger word?

    "For a symmetric top, $I_1 = I_2$, …" and "With no torque, $\\tau = 0$, …" state assumptions
    although the word just before the math is no trigger."""
    start = max(0, pos - 400)
    for m in _SENTENCE_END.finditer(body, max(0, pos - 400), pos):
        start = m.end()
    prefix = body[start:pos]
    if "$" in prefix or "\\]" in prefix:
        return False
    words = re.findall(r"[A-Za-z]+", prefix)
    return bool(words) and words[0].lower() in TRIGGERS


_ABSENT = re.compile(r"\b(?:no|without|absent|vanish(?:es|ing)?)\b", re.I)
_BARE_ZERO = re.compile(r"^\s*\\?[A-Za-z]+(?:_\{?\w+\}?)?\s*=\s*0\s*$")


def _absence_stated(body: str, pos: int, latex: str) -> bool:
    """Is the math at ``pos`` a bare symbol set to zero right after prose saying something is
    absent? "no external moment acts, $T=0$" (or "…are present. That is $T=0$") states the
    setting in symbols: an assumption, not a claim about the text's T."""
    if not _BARE_ZERO.match(latex):
        return False
    prefix = body[max(0, pos - 160):pos]
    prefix = prefix[prefix.rfind("\n\n") + 1:]
    return bool(_ABSENT.search(source.MATH.sub(" ", prefix)))


def _signs(prose: str) -> str | None:
    p = prose.lower()
    if "opposite sign" in p:
        return "opposite"
    if "both positive or both negative" in p or "same sign" in p:
        return "same"
    return None


def parse_notes(text: str, path: str = "<notes>", convention: str | None = None) -> Notes:
    """The `Notes` of a Markdown text (see the module docstring); ``convention`` overrides the
    front matter's."""
    lines = text.split("\n")
    declared, skip = _front_matter(lines, path)
    body = bracket_cross.marked(source.rendered("\n".join([""] * skip + lines[skip:]), source.latex_source(text, path)))
    # the front matter (or the command line) wins; else the convention the text states itself
    stated = [] if convention or "convention" in declared else stated_convention.stated(body)
    conv = convention or declared.get("convention") or (stated[0].convention if stated else "z-y-z")
    if conv not in CONVENTIONS:
        raise ValidationError(path, "--convention", f"{conv!r} is not one of {', '.join(CONVENTIONS)}")
    own = None if "angles" in declared or not stated else stated[0].angles
    angles = declared.get("angles") or own or DEFAULT_ANGLES[conv]
    notes = Notes(path, conv, tuple(angles), declared, angles_stated=own is not None,
                  convention_stated=bool(convention or declared.get("convention") or stated))
    user_macros = {**package_macros.loaded(body), **source.macros(body)}   # the file's own win
    user_macros.update(undefined_macros.as_symbols(body, user_macros))
    notes.names = nm.learn(body, declared.get("symbols"), path, user_macros)
    formula_names.learn(notes.names, body)
    moment_letters.learn(notes.names, body, tuple(angles), user_macros)
    notes.body = body
    starts = [0]
    for m in re.finditer("\n", body):
        starts.append(m.end())

    def line_of(pos: int) -> int:
        lo, hi = 0, len(starts) - 1
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if starts[mid] <= pos:
                lo = mid
            else:
                hi = mid - 1
        return lo + 1

    # headings first (their inline math is context, never a claim)
    heading_lines = {}
    for k, raw in enumerate(body.split("\n"), start=1):
        if raw.lstrip().startswith("#") and k > skip:
            heading_lines[k] = raw.strip().lstrip("#").strip()
    events = []
    for k, title in heading_lines.items():
        level = len(body.split("\n")[k - 1].lstrip()) - len(body.split("\n")[k - 1].lstrip().lstrip("#"))
        events.append((starts[k - 1], Item("heading", k, text=title, level=level)))
        for m in source.MATH.finditer(title):
            inner = source.normalize(m.group("i") or m.group("d") or "").lstrip("-").strip()
            if _RELATION.search(inner) and "\\neq" not in inner and "\\equiv" not in inner:
                events.append((starts[k - 1] + 1, Item("assumption", k, latex=inner, lead=title)))
    prev_end = 0
    in_prose = prose_definitions.ProseDefinitions(body, tuple(angles), dict(declared.get("symbols") or {}))
    frames = named_frames.learned(body)
    named: list = []
    for m in source.MATH.finditer(body):
        line = line_of(m.start())
        if line in heading_lines:
            continue
        lead = body[prev_end:m.start()]
        prev_end = m.end()
        lead_line = lead.split("\n")
        # the prose that introduces the math: same line, or the previous non-empty line for a display
        near = lead_line[-1].strip() if lead_line[-1].strip() or m.group("i") else \
            next((x.strip() for x in reversed(lead_line) if x.strip()), "")
        if m.group("i") is None:
            raw = next(m.group(g) for g in ("d", "b", "e") if m.group(g) is not None)
            latex = named_frames.relabelled(source.normalize(raw, user_macros), frames)
            if not latex:
                continue            # the file's macro definitions, nothing to read
            word = _last_word(near) if near and not near.endswith((".", ";")) else ""
            inequality = re.search(r"\\ge|\\le|(?<!\\)[<>]", latex)
            # X ≡ … introduces a symbol (a definition, checked), never an assumption
            defines = "\\equiv" in latex
            kind = "assumption" if word in TRIGGERS and _RELATION.search(latex) and not inequality \
                and not defines else "display"
            for one in components(latex):
                events.append((m.start(), Item(kind, line, latex=one, lead=near, display=True)))
            continue
        latex = named_frames.relabelled(source.normalize(m.group("i"), user_macros), frames)
        line_text = body[starts[line - 1]:body.find("\n", m.start()) if body.find("\n", m.start()) >= 0 else len(body)]
        signs = _signs(line_text)
        if signs and not _RELATION.search(latex):
            events.append((m.start(), Item("signs", line, text=signs, symbols=(latex,), lead=near)))
            continue
        if _MUCH_LESS.search(latex):    # "$\omega_2, \omega_3 \ll \Omega$": what stands before ≪ is small
            events.append((m.start(), Item("small", line, symbols=(small_before_much_less(latex),), lead=near)))
            continue
        if not _RELATION.search(latex):
            continue
        word = _last_word(near)
        if word == "that":              # "we assume that $\omega_1 = \Omega$": the word before "that" says it
            word = _last_word(near[:near.lower().rfind("that")])
        # "(… $\omega_2 = \Omega$ to first order)": an aside in brackets states a condition
        wrapped = latex.startswith("(") and latex.endswith(")") or body[:m.start()].rstrip(" ").endswith("(")
        after_assumption = word == "and" and events and events[-1][1].kind == "assumption" \
            and line - events[-1][1].line <= 1
        assumed = word in TRIGGERS or wrapped or after_assumption or _opens_with_trigger(body, m.start()) \
            or _absence_stated(body, m.start(), latex)
        # "… named $\dot\phi = \omega_\phi$ …": a setting in its section, the text's name after it
        defined = None if assumed else in_prose.definition(m.start(), latex, line_text)
        if defined:
            named.append((m.start(), Item("inline", line, latex=defined, lead=near)))
        rest = body[m.end():body.find("\n", m.end()) if body.find("\n", m.end()) >= 0 else len(body)]
        # the line's whole content, or a list item's (``3. $T = …$``): set apart as a display is
        alone = re.fullmatch(r"\s*(?:(?:[-*+]|\d+[.)])\s+)?", body[starts[line - 1]:m.start()]) is not None \
            and re.fullmatch(r"\s*[.,;:]?\s*", rest) is not None
        for one in components(latex.strip("()") if assumed and wrapped else latex):
            events.append((m.start(), Item("assumption" if assumed else "inline", line, latex=one, lead=near,
                                           alone=alone)))
    # a section that states another convention (or other names) than the one before it
    current = (conv, tuple(angles))
    for st in stated[1:]:
        here = (st.convention, tuple(declared.get("angles") or st.angles or DEFAULT_ANGLES[st.convention]))
        if here != current:
            events.append((starts[st.line - 1], Item("convention", st.line, text=st.convention, symbols=here[1])))
            current = here
    # what the prose says of the body: "a symmetric top" holds to the next heading
    prose = source.MATH.sub(lambda m: " " * (m.end() - m.start()), body)
    for m in SYMMETRIC.finditer(prose):
        events.append((m.start(), Item("context", line_of(m.start()), text="symmetric", lead=m.group(0))))
    for m in ALONG_MOMENTUM.finditer(source.MATH.sub(lambda m: m.group(0) if m.group("i") else " " * (m.end() - m.start()), body)):
        events.append((m.start(), Item("context", line_of(m.start()), text="along momentum", lead=m.group(0))))
    for m in _SMALL.finditer(prose):
        start = max([0] + [e.end() for e in _SENTENCE_END.finditer(prose, 0, m.start())])
        maths = [x.group("i") for x in source.MATH.finditer(body, start, m.start()) if x.group("i")]
        if maths:
            events.append((m.start(), Item("small", line_of(m.start()), symbols=tuple(
                source.normalize(x, user_macros) for x in maths), lead=m.group(0))))
    events += prose_definitions.carried(named, [(at, it.level) for at, it in events if it.kind == "heading"])
    events.sort(key=lambda e: e[0])
    # merge consecutive sign items of one line ("$\Omega_1$ and $\Omega_2$ are both …")
    items: list[Item] = []
    for _, item in events:
        if item.kind == "signs" and items and items[-1].kind == "signs" and items[-1].line == item.line:
            last = items.pop()
            item = Item("signs", item.line, text=item.text, symbols=last.symbols + item.symbols, lead=last.lead)
        items.append(item)
    notes.items = _chains_across(items)
    return notes


# a display's last sign '=' with nothing after it (not part of <=, >=, != or \ne)
_OPEN_EQUALS = re.compile(r"(?<![<>!=\\])=\s*$")


def _chains_across(items: list) -> list:
    """A display that ends with ``=`` before a display that begins with ``=`` (a chain of
    equalities set over several displays, one equation to a line, as Sphinx sets a ``math``
    directive's paragraphs): the chain goes on in the next display, so its trailing ``=`` is no
    empty side; the next display's members are read against the chain's head, as a row of an
    aligned chain is."""
    out = list(items)
    for k in range(len(out) - 1):
        before, after = out[k], out[k + 1]
        if before.kind == after.kind == "display" and _OPEN_EQUALS.search(before.latex) \
                and re.match(r"\s*=(?!=)", after.latex):
            out[k] = replace(before, latex=_OPEN_EQUALS.sub("", before.latex).rstrip())
    return out


def read_notes(path, convention: str | None = None) -> Notes:
    """Read a notes file (UTF-8 Markdown, a LaTeX source, or a Jupyter notebook's Markdown cells:
    `derive.lecture.notebook`). Unreadable → `SceneError` naming the file."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise ValidationError(str(path), "file", "not found") from None
    except IsADirectoryError:
        raise ValidationError(str(path), "file", "is a directory, not a notes file") from None
    except UnicodeDecodeError as err:
        raise ValidationError(str(path), "file", f"not UTF-8 text (byte {err.start})") from None
    except OSError as err:
        raise ValidationError(str(path), "file", err.strerror or "cannot be read") from None
    if "\x00" in text:
        raise ValidationError(str(path), "file", "binary, not Markdown text")
    if p.suffix.lower() == ".ipynb":
        text = notebook.markdown(text, str(path))
    return parse_notes(text, str(path), convention)


def angle_aliases(notes) -> tuple:
    """Other names of the angles: the usual φ, θ, ψ when the text declares none; when it declares
    them with a subscript (``\\psi_{\\beta\\alpha}``), their bare letters, which texts write once
    the frames are clear (none if two angles share a letter); those set in ``notes.aliases``."""
    if notes.aliases is not None:
        return notes.aliases
    if "angles" not in notes.declared and not notes.angles_stated:
        return _variant_glyphs(DEFAULT_ANGLES["z-x-z"], notes.body)
    bases = tuple(a.split("_")[0] for a in notes.angles)
    if all("_" in a for a in notes.angles) and len(set(bases)) == 3:
        return bases
    return ()


_RATE_OF_VARPHI = re.compile(r"\\dot\s*\{?\s*\\varphi(?![A-Za-z])")


def _written(letter: str, body: str) -> bool:
    return re.search(r"\\" + letter + r"(?![A-Za-z])", body) is not None


def _variant_glyphs(names: tuple, body: str) -> tuple:
    """The usual φ, θ, ψ in the glyphs the text writes them in: a text whose tilt is ϑ
    (``\\vartheta``, never ``\\theta``) writes its angles in the variant letters, ϑ and φ
    (``\\varphi`` unless it also writes ``\\phi``); a text that writes θ keeps the usual names,
    but for a φ whose rate it writes (``\\dot{\\varphi}``, never ``\\phi``): a phase has no rate."""
    if _RATE_OF_VARPHI.search(body) and not _written("phi", body):
        names = tuple("varphi" if n == "phi" else n for n in names)
    if not _written("vartheta", body) or _written("theta", body):
        return names
    swap = {"theta": "vartheta", "phi": "phi" if _written("phi", body) else "varphi"}
    return tuple(swap.get(n, n) for n in names)

