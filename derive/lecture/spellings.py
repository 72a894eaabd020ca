"""How a text spells the derivation's symbols, so that what the reader writes back (a correction,
a why) is in the text's notation: a z-x-z text's ``\\Omega_1`` for the body angular velocity's
first component, not the lecture's ``\\tilde{\\omega}_1``.

Takes a display's LaTeX and the text's vocabulary; gives derivation symbol → the atom as the
text wrote it (a rate written d/dt, ``\\frac{d\\omega_1}{dt}``, as written). May import:
:mod:`derive.lecture.vocabulary`, :mod:`derive.lecture.written_rates`, SymPy.
"""
from __future__ import annotations

import re

import sympy as sp

from derive.lecture import vocabulary as vc
from derive.lecture.written_rates import symbol_rate, written_rate


def spellings(latex: str, vocab: vc.Vocabulary, symbols) -> dict:
    """``{symbol: the text's LaTeX for it}`` for every atom of ``latex`` that stands for one of
    ``symbols`` (a collection of derivation symbols); atoms the vocabulary cannot read are skipped.
    Where the formula spells one symbol two ways, the first spelling is kept."""
    try:
        toks = vc.scan(latex)
    except vc.NotRead:
        return {}
    out: dict = {}
    rates: dict = {}                # the rates of a variation δx the formula writes, where it writes none itself
    for tok in toks:
        if tok.kind != "atom" or not tok.value.text:
            continue
        try:
            value = vocab.resolve(tok.value)
        except vc.NotRead:
            continue
        if isinstance(value, sp.Symbol) and (value in symbols or _varied(value, vocab)):
            out.setdefault(value, tok.value.text)
            rates.update(_varied_rates(tok.value, vocab) if value not in symbols else {})
        if tok.value.dots:          # ω̇ written: ω is spelled the same way without the dots
            _undotted(tok.value, vocab, symbols, out)
    for k in range(len(toks)):      # a rate written d/dt (dω/dt, d²ω/dt²): the rate as written
        rate = written_rate(toks, k)
        if rate is not None and rate[0] is not None:
            try:
                value = symbol_rate(vocab.resolve, toks[rate[0]], rate[1], vocab)
            except vc.NotRead:
                continue
            if isinstance(value, sp.Symbol) and (value in symbols or _varied(value, vocab)):
                out.setdefault(value, latex[toks[k].pos:_end(toks[rate[2] - 1])])
    return {**rates, **out}


def _varied(value, vocab: vc.Vocabulary) -> bool:
    """Whether a symbol is the text's variation δx (`derive.lecture.variations`), which SymPy cannot
    spell: it is written back as the text writes it."""
    return isinstance(value, vc.Generic) and getattr(vocab.generic.get(value), "mark", "")[:5] == "delta"


def _end(tok) -> int:
    """Where a token ends in its formula."""
    return tok.pos + len(tok.value.text if tok.kind == "atom" else str(tok.value))


def written_back(latex: str, spelled: dict) -> str:
    """LaTeX the reader writes back, with a rate it spells as the text's fraction (``\\frac{d
    \\omega_1}{dt}``) bracketed where a power follows it: ``\\left(\\frac{d \\omega_1}{dt}\\right)^{2}``."""
    for text in {v for v in spelled.values() if v.startswith(("\\frac", "\\dfrac", "\\tfrac")) or "/" in v}:
        latex = latex.replace(text + "^", "\\left(" + text + "\\right)^")
    return latex


_DOTTED = re.compile(r"\\d?dot\s*(?:\{(?P<braced>[^{}]*)\}|(?P<bare>\\[A-Za-z]+|[A-Za-z]))")


def _undotted(atom: vc.Atom, vocab: vc.Vocabulary, symbols, out: dict) -> None:
    """Record the spelling of the atom without its dots, when taking the dot commands away gives a
    formula that reads as exactly that atom."""
    text = _DOTTED.sub(lambda m: m.group("braced") or m.group("bare"), atom.text, count=1)
    try:
        toks = vc.scan(text)
        value = vocab.resolve(toks[0].value) if len(toks) == 1 and toks[0].kind == "atom" else None
    except vc.NotRead:
        return
    if value is not None and toks[0].value.with_(text="") == atom.with_(dots=0, text="") \
            and isinstance(value, sp.Symbol) and value in symbols:
        out.setdefault(value, text)


def _varied_rates(atom: vc.Atom, vocab: vc.Vocabulary) -> dict:
    """The text's rates of a variation δx it writes undotted, spelled d(δx)/dt and d²(δx)/dt²."""
    if atom.dots:
        return {}
    out = {}
    for n, power in ((1, ""), (2, "^2")):
        key = atom.with_(dots=n, text="")
        sym = next((s for s, met in vocab.generic.items() if met == key), None)
        if sym is not None:
            out[sym] = f"\\frac{{d{power}({atom.text})}}{{dt{power}}}"
    return out
