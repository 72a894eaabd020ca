"""What a text calls things: its names learned from its prose and its front matter.

Takes: the rendered text of a notes file (prose with inline ``$…$`` math, displays) and the
front matter's ``symbols:`` map. Gives: `learn`, a `Names` map from the text's spellings to
*meanings* (entries of `MEANINGS`), which `derive.lecture.latex.Vocabulary` consults before its
own spellings, so that the text's names win over the lecture's.
May import: the standard library, :mod:`derive.lecture.latex`, :mod:`derive.lecture.source`,
:mod:`derive.lecture.hat_maps`, :mod:`derive.lecture.meanings`, :mod:`derive.lecture.principal_momentum`, :mod:`derive.lecture.said_columns`
and :mod:`derive.symbolic` (the quantities a meaning stands for).

A meaning is bound the way a reader binds it: an inline symbol next to a phrase that says what
it is — "$\\mathbf{M}$ is the angular momentum", "mass $m$", "$J_z$ (angular momentum about the
vertical)", "the body-frame components $\\Omega_1, \\Omega_2, \\Omega_3$ of the angular
velocity", "a distance $h$ from the pivot to the centre of mass", "the principal moments $A$,
$B$, $C$". The phrase nearest the symbol within its clause wins. A meaning binds either the
exact symbol (``J_z``) or its letter with any index (``M``: 𝐌, M_i, M_z, |𝐌|).
A binding holds in the section whose prose makes it (the reader sets `Names.here` as it goes):
Landau's M is the mass in one section and the angular momentum's magnitude in the next. Where a
section's prose says nothing of a name, its first binding in the text holds.

The meanings are a registry of their own (`derive.lecture.meanings`): adding one adds a row there.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

import sympy as sp

from derive.errors import SceneError
from derive.lecture import gyro_names, hat_maps, principal_momentum, said_columns
from derive.lecture.meanings import ALIASES, LETTERS, MEANINGS
from derive.lecture import latex as lx
from derive.lecture import source
from derive.symbolic.lagrangian import I1, I2, I3, Mass, g, l

@dataclass
class Names:
    """The text's spellings → meanings: ``symbols`` by exact symbol (base, index), ``letters`` by
    letter (any index), and where each was learned (a line, or the front matter)."""

    symbols: dict = field(default_factory=dict)
    letters: dict = field(default_factory=dict)
    where: dict = field(default_factory=dict)
    frames: dict = field(default_factory=dict)     # (base, sub) → the frame label over a symbol bound with one
    sections: list = field(default_factory=list)
    """The lines of the text's headings: a name the prose gives in a section holds there."""
    scoped: dict = field(default_factory=dict)
    """("symbols" or "letters", key) → [(line, meaning)]: every binding the prose makes, in order."""
    declared: set = field(default_factory=set)
    """("symbols" or "letters", key) the front matter names: said outright, for the whole text."""
    here: int | None = None
    """The line the reader is at (set as it goes), or None: then the first binding of a name holds."""
    trig_letters: bool = False
    """The text defines c and s before an angle as its cosine and sine (``c\\theta \\equiv \\cos(\\theta)``)."""

    def _section(self, line: int) -> int:
        return sum(1 for h in self.sections if h <= line)

    def meaning(self, atom) -> str | None:
        """The meaning of an atom of `latex.scan`, or None. A letter learned as a vector (bold) or
        its components (indexed) names both; the plain letter only if the text used it plain. A
        name the prose gives in the section the reader is in wins (Landau's M, the top's mass in
        one section and the angular momentum's magnitude in another); else its first binding."""
        key = (atom.base, atom.sub)
        letter = (atom.base, "plain" if not (atom.bold or atom.sub) else "vector")
        if self.here is not None and self.sections:
            at = self._section(self.here)
            for table, k in (("symbols", key), ("letters", letter)):
                if (table, k) in self.declared:
                    break
                for line, meaning in self.scoped.get((table, k), ()):
                    if self._section(line) == at:
                        return meaning
        if key in self.symbols:
            return self.symbols[key]
        return self.letters.get(letter)

    def value(self, a, env: dict, vocab):
        """What an atom stands for by the meaning the text gave it (`MEANINGS`); None where it
        gave none, or the meaning says nothing of this spelling (an index it does not cover).
        ``vocab`` is the reader's `latex.Vocabulary` (the third turn's axis, the text's symbols)."""
        meaning = gyro_names.SAME.get(self.meaning(a), self.meaning(a))
        if meaning is None or meaning in gyro_names.MEANINGS:
            return None if meaning is None else gyro_names.value(meaning, a, vocab)
        sub = str(env.get(a.sub, a.sub)) if len(a.sub) == 1 else a.sub
        k = {"1": 0, "2": 1, "3": 2}.get(sub)
        if not k and k != 0 and sub in ("x", "y", "z") and meaning == "angular velocity":
            k = "xyz".index(sub)              # body axes called x, y, z
        plain = not a.dots and not a.primes and not a.hat and not a.tilde
        moments = (I1, I2, I3)
        if meaning == "angular momentum":
            if a.bold and not sub and plain:
                return lx.LVEC
            if k is not None and plain and not a.bold:
                axial = k == vocab.axial and not vocab.readings.get(lx.BODY_COMPONENTS)
                return lx.p_gamma if axial else moments[k] * lx.W[k]
            if k is not None and a.dots == 1 and not (a.bold or a.primes or a.hat or a.tilde):
                return moments[k] * lx.WD[k]     # a body component's rate: d(Iᵢω̃ᵢ)/dt = Iᵢ dω̃ᵢ/dt
            if sub in ("z", "Z") and plain:
                return lx.p_alpha
            if not sub and plain:
                return lx.LMAG
            return None
        if meaning == "angular velocity":
            if a.bold and not sub and not a.dots:
                return lx.OMEGA_VEC
            if k is not None and not a.bold and a.dots <= 1 and not a.primes:
                return (lx.W if a.dots == 0 else lx.WD)[k]
            return None
        if meaning == "torque":     # its size alone (M, T) is the text's own symbol, never the mass or the energy
            if k is not None and plain:
                return lx.TAU[k]
            return vocab._generic(a) if not sub and not a.bold and plain and vocab.open else None
        if meaning in ("force", "turn rate"):   # a tension, a turn's rate: the text's own, not T nor a component of 𝛚
            return vocab._generic(a) if plain and not a.bold and vocab.open else None
        if meaning == "body angular velocity":    # 𝛚ᵅ_{βα}: bound with its frame labels, the body components
            if a.bold and not a.dots and self.frames.get((a.base, a.sub), "") == a.sup:
                return lx.OMEGA_VEC
            if not (a.bold or sub or a.sup or a.primes or a.hat or a.tilde) and a.dots <= 1:
                # geometric mechanics' plain Ω, like its Π: the column of the body components
                if a.dots == 0:
                    return sp.ImmutableMatrix(lx.W)
                return sp.ImmutableMatrix(vocab.body_rate()) if vocab.body_rate is not None else None
            return (lx.W if a.dots == 0 else lx.WD)[k] if k is not None and not a.bold and a.dots <= 1 else None
        if meaning == "vertical":             # Poisson's γᵢ: the upward vertical in body axes, Rᵀẑ
            if not vocab.vertical or a.dots or a.hat or a.primes:
                return None
            if a.bold and not sub:
                return sp.ImmutableMatrix(vocab.vertical)
            return vocab.vertical[k] if k is not None and not a.bold else None
        if meaning in _RATE_AXES:             # p, q, r: the aircraft's roll, pitch and yaw rates, ω̃ in body axes
            w = _RATE_AXES[meaning]
            return (lx.W if a.dots == 0 else lx.WD)[w] if not a.bold and not sub and a.dots <= 1 else None
        if meaning == "identity column":      # 𝐈ᵢ, "the i-th column of the identity matrix": the unit column
            return sp.ImmutableMatrix(sp.eye(3)[:, k]) if a.bold and k is not None and plain else None
        if not plain or a.bold:
            return None
        if meaning == "potential energy" or meaning.startswith("centre-of-mass coordinate "):
            return vocab._generic(a)            # the text's own potential: its definition says what
        return {"vertical angular momentum": lx.p_alpha, "axial angular momentum": lx.p_gamma, "mass": Mass,
                "centre-of-mass distance": l, "gravitational acceleration": g, "kinetic energy": lx.T_, "energy": lx.ENERGY,
                "lagrangian": lx.LAGRANGIAN, "effective potential": lx.VEFF, "transverse moment": I1,
                "second moment": I2, "axial moment": I3}.get(meaning)


_WEIGHT = r"[mM]\s*g\s*(?:\\(?:cos|sin)\s*\\?[A-Za-z]+\s*)?(?=[-+=)\]}]|\\right|\s*$)"
_WEIGHED = re.compile(r"(?<![\\\w{}^_])(?P<T>T)\s*[-+]\s*" + _WEIGHT + r"|(?<![\w\\])" + _WEIGHT[:-2].split("(?=")[0]
                      + r"\s*[-+]\s*(?P<T2>T)(?![\w^_'{])")
r"""``T - Mg``, ``Mg - T``, ``T - mg\cos\theta``: a letter T added to a weight (a length after the g, ``Mgl``, would make an energy)."""
_INLINE = re.compile(r"(?<![\\$])\$([^$\n]+?)(?<!\\)\$")
_DISPLAY = re.compile(r"\$\$.+?\$\$|\\\[.+?\\\]|\\begin\{(equation|align|eqnarray|gather|multline|numcases|subnumcases)\*?\}.+?\\end\{\1\*?\}", re.S)
_CLAUSE = re.compile(r"[.;:!?]\s|\n\s*\n")
_HEADING = re.compile(r"^ {0,3}#{1,6}\s|^\s*\\(?:sub)*section\*?\{", re.M)


def _atoms(latex: str) -> list:
    """The atoms of an inline formula that is a symbol or a list of symbols, else []."""
    try:
        toks = lx.scan(latex)
    except lx.NotRead:
        return []
    atoms = [t.value for t in toks if t.kind == "atom"]
    rest = [t for t in toks if t.kind != "atom" and not (t.kind == "op" and t.value == ",")]
    commas = sum(t.kind == "op" and t.value == "," for t in toks)
    if commas and len(atoms) != commas + 1:
        return []           # "dp, dq, dr": a list whose items are not single symbols
    return atoms if atoms and not rest else []


def _resolve_meaning(text: str) -> str | None:
    """A front matter's meaning (``angular momentum``, ``l``, ``I_1``) as a key of `MEANINGS`."""
    t = text.strip().strip("'\"").replace("\\", "")
    if t in MEANINGS:
        return t
    if t in ALIASES:
        return ALIASES[t]
    for name, (_, phrase) in MEANINGS.items():
        if re.search(phrase, text, flags=re.I):
            return name
    return None


# "c\\theta \\equiv \\cos (\\theta)", "s\\psi = \\sin\\psi": the text's own shorthand for the cosine and sine
_TRIG_LETTERS = re.compile(r"(?<![A-Za-z\\])([cs])\s*(\\[A-Za-z]+)\s*(?:\\equiv|=)\s*\\(cos|sin)\s*\(?\s*\2(?![A-Za-z])")


def learn(body: str, declared: dict | None = None, path: str = "<notes>", macros: dict | None = None) -> Names:
    """The names a text gives its symbols (see the module docstring).

    Parameters
    ----------
    body : str
        The rendered text (`derive.lecture.source.rendered`).
    declared : dict, optional
        The front matter's ``symbols`` map (LaTeX name → meaning); it wins over the prose.
    path : str
        For the error naming a meaning the map cannot use.
    macros : dict, optional
        The file's own macros (`derive.lecture.source.macros`), expanded in its inline math.

    Returns
    -------
    Names
    """
    names = Names()
    body = _INLINE.sub(lambda m: "$" + source.normalize(m.group(1), macros).replace("$", "") + "$", body)
    names.trig_letters = bool(_TRIG_LETTERS.search(body))
    # a display ends a clause and keeps its lines, so that a position in the prose is on the text's line
    prose = _DISPLAY.sub(lambda m: " . " + "\n" * max(m.group(0).count("\n"), 0), body)
    prose = _GLOSSARY.sub(lambda m: m.group(1) + " is ", prose)      # "- $C$: the axial moment", "| $C$ | …": a list of symbols
    starts = [0] + [m.end() for m in re.finditer("\n", prose)]
    for clause in _clauses(prose):
        text, offset = clause
        found = list(_INLINE.finditer(text))
        listed = re.search(MEANINGS["principal moments"][1] + r"\W{0,12}\$", text, flags=re.I)
        named = re.search(r"\$[^$]+\$\s*,\s*\$[^$]+\$\s*,?\s*(?:and\s*)?\$[^$]+\$\s+(?:are|denote) the " +
                          MEANINGS["principal moments"][1], text, flags=re.I)
        if named:       # "$A$, $B$, $C$ are the principal moments": the three symbols right before it
            run = [m for m in found if named.start() <= m.start() < named.end()][:3]
            after = [a for m in run for a in _atoms(m.group(1))]
            if len(after) == 3:
                bind(names, after, "principal moments", f"line {_line(starts, offset + run[0].start())}")
        if listed:      # "the principal moments $A$, $B$, $C$": the three symbols right after it
            run = [m for m in found if m.start() >= listed.end() - 1][:3]
            gaps = [text[a.end():b.start()] for a, b in zip(run, run[1:])]
            after = [a for m in run for a in _atoms(m.group(1))]
            if len(after) == 3 and all(re.fullmatch(r"\s*(,|and|,\s*and)?\s*", g) for g in gaps):
                bind(names, after, "principal moments", f"line {_line(starts, offset + run[0].start())}")
        _rates_listed(names, text, found, starts, offset)
        _centre_listed(names, text, found, starts, offset)
        for k, m in enumerate(found):
            atoms = _atoms(m.group(1))
            if not atoms:
                continue
            # this symbol as §, the others as ¤: a phrase that reaches past another symbol is its
            marked = "".join(("§" if j == k else "¤") if isinstance(piece, int) else piece for j, piece in _pieces(text, found))
            # where what the text goes on to say of it does not fit its letter, the phrase before it ("moment §, the nutation …")
            meaning = next((n for n in (_nearest(marked), _nearest(marked.replace("§", "§;", 1))) if n is not None and _fits(n, atoms)), None)
            if meaning is None or MEANINGS[meaning][0] in ("list", "rates", "coords") or not _fits(meaning, atoms):
                continue
            bind(names, atoms, meaning, f"line {_line(starts, offset + m.start())}")
        _components_of(names, text, starts, offset)
    _said_of_display(names, body)
    for line, rows, meaning in said_columns.columns(body, {k: p for k, (how, p) in MEANINGS.items() if how == "letter"}):
        atoms = [a for row in rows for a in _atoms(source.normalize(row))]
        if len(atoms) == 3 and len({a.base for a in atoms}) == 1 and _fits(meaning, atoms):
            bind(names, atoms, meaning, f"line {line}")
    _rate_law(names, body)
    for line, tex in principal_momentum.velocity_letters(body, macros):      # L̇ᵢ ≡ IᵢΩ̇ᵢ: Ω is the angular velocity
        if tex.endswith("_"):       # Euler's shape on axes x, y, z: principal axes, the only ones where it has it
            _xyz_axes(names, tex[1:-1], f"line {line} (Euler's equation on principal axes x, y, z)")
        elif _fits("angular velocity", _atoms(tex)):
            bind(names, _atoms(tex), "angular velocity", f"line {line}")
    for line, tex in hat_maps.body_velocities(body):       # R^T Ṙ = Ω̂: Ω is the body angular velocity
        atoms = _atoms(tex)
        if len(atoms) == 1 and _fits("body angular velocity", atoms):
            # the symbol only: the hat map says nothing of what Ω₁, Ω₂, Ω₃ are in other sections
            key = (atoms[0].base, atoms[0].sub)
            _put(names.symbols, key, "body angular velocity", False)
            names.frames.setdefault(key, atoms[0].sup)
            names.scoped.setdefault(("symbols", key), []).append((line, "body angular velocity"))
            names.where.setdefault(key, f"line {line}")
            if not (atoms[0].bold or atoms[0].sub or atoms[0].sup):
                # in the hat map's own section its components Ω₁, Ω₂, Ω₃ are the body ones, as the map defines them
                names.scoped.setdefault(("letters", (atoms[0].base, "vector")), []).append((line, "body angular velocity"))
    for m in _DISPLAY.finditer(body):      # T − Mg = −Ma: a T added to a weight is a force, not the kinetic energy
        for w in _WEIGHED.finditer(m.group(0)):
            bind(names, _atoms(w.group("T") or w.group("T2")), "force", f"line {body.count(chr(10), 0, m.start() + w.start()) + 1}")
    names.sections = [_line(starts, h.start()) for h in _HEADING.finditer(prose)]
    _principal_axes(names, body, prose)
    for latex, what in (declared or {}).items():
        meaning = _resolve_meaning(what)
        atoms = _atoms(latex)
        if meaning is None or not atoms:
            raise SceneError(f"{path}: symbols: {latex}: {what!r} is no meaning derive knows "
                             f"(one of: {', '.join(m for m in MEANINGS if m != 'second moment')})")
        bind(names, atoms, meaning, "the front matter", override=True)
    return names


_GLOSSARY = re.compile(r"^([ \t]*(?:[-*+][ \t]+|\d+[.)][ \t]+|\|[ \t]*)?\$[^$\n]+\$)[ \t]*(?::|\|)[ \t]*(?=[^\W\d_])", re.M)
"""A line of a list or table of symbols: the symbol first, then a colon or a cell's bar and the words that say what it is."""
_RATE_AXES = {"roll rate": 0, "pitch rate": 1, "yaw rate": 2}
_LISTED = r"((?:\$[^$]+\$[\s,]*(?:and\s+)?){1,3})"
_COMPONENTS = re.compile(r"(?:components\s+" + _LISTED + r"|" + _LISTED + r"(?:be|are|denote)\s+the\s+(?:[\w-]+\s+){0,2}"
                         r"components\s+)of the (?:unit )?vector\s+\$([^$]+)\$")


_SAID = re.compile(r"(?:^|\s)(?:the|its)\s+(?:[\w-]+\s+)?(PHRASE)(?:,[^,$]{1,80},)?\s+(?:is|equals|reads|becomes)\b[^$]*$", re.I)
_ROW_SIDE = re.compile(r"^\s*(?:\\begin\{\w+\*?\}(?:\{[^{}]*\})?)?\s*([^=&]+?)\s*&?\s*=", re.M)


def _said_of_display(names: Names, body: str):
    """"The angular momentum is the inertia tensor times the angular velocity:" followed by a
    display whose rows open with one symbol (𝐇 = I𝛚, 𝐇_b = I_b𝛚_b): the sentence says what that
    symbol is, as it would next to the symbol inline."""
    for m in _DISPLAY.finditer(body):
        sentence = re.split(r"[.;!?]\s|\n\s*\n|\$\$", body[:m.start()].rstrip())[-1]
        meaning = next((name for name, (how, phrase) in MEANINGS.items() if (how == "letter" or name in gyro_names.LETTERS)
                        and re.search(_SAID.pattern.replace("PHRASE", phrase), sentence, flags=re.I)), None)
        if meaning is None:
            continue
        inner = re.sub(r"^\$\$|\$\$$", "", m.group(0))
        sides = [_atoms(source.normalize(side)) for side in _ROW_SIDE.findall(inner.replace("\\\\", "\n"))]
        atoms = [a[0] for a in sides if len(a) == 1]
        if atoms and len(atoms) == len(sides) and len({a.base for a in atoms}) == 1 and _fits(meaning, atoms):
            bind(names, atoms, meaning, f"line {body.count(chr(10), 0, m.start()) + 1}")


_RATE_SIDE = re.compile(r"^\s*(?:\^\s*\{?\w\}?\s*)?(?:\\dot\s*\{(?P<dot>.+)\}|\\frac\s*\{\s*(?:\\(?:text|mathrm)\s*\{d\}|d)"
                        r"\s*(?P<frac>[^{}]*(?:\{[^{}]*(?:\{[^{}]*\}[^{}]*)*\}[^{}]*)*)\}\s*\{\s*(?:\\(?:text|mathrm)\s*\{d\}|d)\s*t\s*\})\s*$")
"""The rate of one symbol, written ``\\dot{𝐇}`` or ``\\frac{d𝐇}{dt}`` (a frame's label before it, ``^N``, allowed)."""


def _rate_law(names: Names, body: str):
    """Euler's second law displayed alone, ``\\dot{\\vec{H}} = \\vec{L}``: the rate of the angular momentum
    (a letter that may name it) equals the torque, so the letter on the other side is the text's torque
    (Schaub's 𝐋, where others write 𝐍 or 𝛕: only the law makes it the torque) and a bold one under the
    rate its angular momentum (Schaub's 𝐇), unless the prose named them."""
    for m in _DISPLAY.finditer(body):
        inner = re.sub(r"^\$\$|\$\$$|^\\\[|\\\]$", "", m.group(0).strip()).strip()
        if inner.count("=") != 1 or "\\\\" in inner or "\\begin" in inner:
            continue
        left, right = (side.strip().rstrip(".,") for side in inner.split("="))
        rate = _RATE_SIDE.match(source.normalize(left))
        whole, torque = _atoms(source.normalize((rate.group("dot") or rate.group("frac")) if rate else "")), \
            _atoms(source.normalize(right))
        if len(whole) != 1 or len(torque) != 1 or whole[0].base == torque[0].base or whole[0].dots or \
                torque[0].dots or not _fits("angular momentum", whole) or \
                not (_fits("torque", torque) or torque[0].base == "L" and (torque[0].bold or torque[0].sub)):
            continue
        letter = (torque[0].base, "plain" if not (torque[0].bold or torque[0].sub) else "vector")
        for atoms, meaning in ((torque, "torque"), (whole * whole[0].bold, "angular momentum")) * (letter not in names.letters):
            bind(names, atoms, meaning, f"line {body.count(chr(10), 0, m.start()) + 1}")


def _components_of(names: Names, text: str, starts, offset):
    """"the components $\\gamma_1, \\gamma_2, \\gamma_3$ of the unit vector $\\mathbf{n}$ of the
    vertical": indexed symbols named as a vector's components mean what the vector means."""
    for m in _COMPONENTS.finditer(text):
        whole = _atoms(m.group(3))
        meaning = names.letters.get((whole[0].base, "vector")) if len(whole) == 1 and whole[0].bold else None
        parts = [a for s in re.findall(r"\$([^$]+)\$", m.group(1) or m.group(2)) for a in _atoms(s)]
        if meaning and MEANINGS[meaning][0] == "letter" and parts and all(a.sub and not a.bold for a in parts) \
                and _fits(meaning, parts):
            bind(names, parts, meaning, f"line {_line(starts, offset + m.start())}")


def _centre_listed(names: Names, text: str, found: list, starts, offset):
    """"the centre of mass $C$ has body coordinates $x_C, y_C, z_C$": the three symbols right after
    the phrase, in order, are the centre of mass's coordinates along the body axes."""
    phrase = re.search(MEANINGS["centre-of-mass coordinates"][1], text, flags=re.I)
    if not phrase:
        return
    after = [a for m in found if m.start() >= phrase.end() for a in _atoms(m.group(1))][:3]
    if len(after) == 3 and all(not a.bold and not a.dots for a in after):
        for k, atom in enumerate(after):
            _put(names.symbols, (atom.base, atom.sub), f"centre-of-mass coordinate {k + 1}", False)
            names.where[(atom.base, atom.sub)] = f"line {_line(starts, offset + phrase.start())}"


def _rates_listed(names: Names, text: str, found: list, starts, offset):
    """"$p, q, r$ are the roll, pitch and yaw rates" (or the phrase first), or "the body angular velocity
    $[p, q, r]^\\top$" (one formula right after it): the three symbols nearest the phrase in its clause, in
    order, are ω̃₁, ω̃₂, ω̃₃ (the aircraft's body axes). Each time the clause gives the phrase is tried; a run
    of formulas is taken only when it stands next to the phrase (a few words, no comma between), so a list
    of other things before it binds nothing."""
    said = [(m, k == "body rates") for k in ("body rates", "body angular velocity") for m in re.finditer(MEANINGS[k][1], text, re.I)]
    for phrase, either_side in said:
        before = [m for m in found if m.end() <= phrase.start()][::-1] if either_side else []
        after = [m for m in found if m.start() >= phrase.end()]
        for run, gap, between in ((before, text[before[0].end():phrase.start()] if before else "", "b"),
                                  (after, text[phrase.end():after[0].start()] if after else "", "a")):
            if not run or not re.fullmatch(r"[^,.;:$]{0,40}" if between == "b" else r"[\s:(]{0,4}", gap):
                continue
            kept = [run[0]]
            for a, b in zip(run, run[1:]):
                sep = text[b.end():a.start()] if between == "b" else text[a.end():b.start()]
                if not re.fullmatch(r"\s*(,|and|,\s*and)?\s*", sep):
                    break
                kept.append(b)
            kept = kept[::-1] if between == "b" else kept[:None if either_side else 1]
            atoms = [a for m in kept for a in _atoms(said_columns.listed(m.group(1)))]
            atoms = atoms[-3:] if between == "b" else atoms[:3]
            if len(atoms) == 3 and all(not a.bold and not a.sub for a in atoms):
                for atom, meaning in zip(atoms, _RATE_AXES):
                    bind(names, [atom], meaning, f"line {_line(starts, offset + phrase.start())}")
                return


def _principal_axes(names: Names, body: str, prose: str):
    """A text that says its axes are principal and writes I_x, ω_x (never I_1, ω_1) means its axes 1, 2, 3 by x, y, z."""
    for letter in principal_momentum.xyz_only(body) if re.search(r"principal ax[ie]s", prose, flags=re.I) else ():
        _xyz_axes(names, letter, "prose (principal axes x, y, z)", moments=False)


def _xyz_axes(names: Names, letter: str, where: str, moments: bool = True):
    """On principal axes named x, y, z: the letter's components (ω_x, Ω_x) the angular velocity's, and
    (``moments``, or the letter I) I_x, I_y, I_z the principal moments."""
    for x, m in zip("xyz", ("transverse moment", "second moment", "axial moment")) if moments or letter == "I" else ():
        _put(names.symbols, ("I", x), m, False)
        names.where[("I", x)] = where
    if letter != "I":
        _put(names.letters, (letter, "vector"), "angular velocity", False)
        names.where[(letter, "x")] = where


def _line(starts, pos) -> int:
    return sum(1 for s in starts if s <= pos)


def _fits(meaning: str, atoms) -> bool:
    """Can these symbols carry this meaning? A letter for a vector is bold, indexed or a capital
    (a lower-case plain letter near "angular momentum" is something else); a quantity that is a
    number (a mass, a length) is written without an index or with a body's label."""
    how = MEANINGS[meaning][0]
    for a in atoms:
        if meaning in LETTERS and a.base not in LETTERS[meaning]:
            return False
        if how == "letter" and not (a.bold or a.sub or a.base[0].isupper()):
            return False
        if meaning in ("mass", "centre-of-mass distance", "gravitational acceleration") and (a.bold or a.dots):
            return False
        if meaning == "mass" and a.base not in ("m", "M", "mu"):
            return False
        if meaning == "gravitational acceleration" and a.base != "g":
            return False
    return True


def _clauses(prose: str):
    """(clause text, its offset) — the stretch of prose within which a phrase names a symbol."""
    last = 0
    for m in _CLAUSE.finditer(prose):
        yield prose[last:m.end()], last
        last = m.end()
    yield prose[last:], last


def _pieces(text, found):
    """The clause as prose pieces and the indices of its inline formulas, in order."""
    last = 0
    for j, m in enumerate(found):
        yield None, text[last:m.start()]
        yield j, j
        last = m.end()
    yield None, text[last:]


def _nearest(marked: str) -> str | None:
    """The meaning whose phrase stands nearest § (the symbol): a phrase around it ("a distance §
    from the pivot to the centre of mass"), right before it ("mass §") or right after it when the
    text goes on to say what it is ("§ (angular momentum about …)", "§ is the …", "§ being the …",
    "§ of the …").
    Nothing past another symbol (¤), nothing farther than a few words."""
    at = marked.index("§")
    lead = marked[at + 1:].lstrip()
    explains = re.match(r"(\(|is the |are the |denotes |denote the |be the |represents the |stands for |of the |— |-- |, the |being the |being |the )", lead)
    best, told = None, None     # told: the nearest phrase that "§ is the …" goes on to say
    for name, (_, phrase) in MEANINGS.items():
        for m in re.finditer(phrase.replace("[^.;$]", "[^.;$¤]"), marked, flags=re.I):
            if "¤" in marked[min(m.end(), at):max(m.start(), at)]:
                continue
            if m.start() <= at < m.end():
                d = 0
            elif m.end() <= at:
                d = at - m.end()
            elif explains:
                d = m.start() - at - 1
                if told is None or d < told[0]:
                    told = (d, name)
            else:
                continue
            if best is None or d < best[0]:
                best = (d, name)
    if told is not None and told[0] <= len(explains.group(0)) + 12:
        return told[1]          # "…'s mass, § is the distance …": what the text says § is wins
    return best[1] if best is not None and best[0] <= 25 else None


def bind(names: Names, atoms, meaning, where, override=False):
    """Bind ``atoms`` to ``meaning`` (a key of :data:`MEANINGS`), said at ``where`` (``"line N"`` or
    the front matter, which ``override`` lets win over what the prose said)."""
    how = MEANINGS[meaning][0]
    if how == "list":
        for atom, m in zip(atoms, ("transverse moment", "second moment", "axial moment")):
            _put(names.symbols, (atom.base, atom.sub), m, override)
            names.where[(atom.base, atom.sub)] = where
        return
    line = int(where[5:]) if where.startswith("line ") and not override else None
    for atom in atoms:
        if how == "letter":
            kinds = ("plain", "vector") if override else ("plain" if not (atom.bold or atom.sub) else "vector",)
            if meaning == "angular momentum" and kinds == ("plain",) and atom.base == "Pi":
                kinds = ("plain", "vector")   # geometric mechanics' Π: the plain letter is the vector, Πᵢ its components
            for kind in kinds:        # the front matter names the letter in every spelling
                _put(names.letters, (atom.base, kind), meaning, override)
                if override:
                    names.declared.add(("letters", (atom.base, kind)))
                if line is not None:
                    names.scoped.setdefault(("letters", (atom.base, kind)), []).append((line, meaning))
        else:
            _put(names.symbols, (atom.base, atom.sub), meaning, override)
            names.frames.setdefault((atom.base, atom.sub), atom.sup)
            if meaning == "body angular velocity" and not (atom.bold or atom.sub or atom.sup):
                # "$\Omega$ is the body angular velocity": its components Ω₁, Ω₂, Ω₃ are the body ones
                _put(names.letters, (atom.base, "vector"), meaning, override)
                if line is not None:
                    names.scoped.setdefault(("letters", (atom.base, "vector")), []).append((line, meaning))
            if override:
                names.declared.add(("symbols", (atom.base, atom.sub)))
            if line is not None:
                names.scoped.setdefault(("symbols", (atom.base, atom.sub)), []).append((line, meaning))
        names.where[(atom.base, atom.sub)] = where


def _put(table, key, meaning, override):
    if override or key not in table:
        table[key] = meaning
