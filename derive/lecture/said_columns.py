r"""A written column of one letter's components, after a sentence that says whose components they are.

A text writes "which give the body components of the angular velocity:" and then a display whose
left side is a column, ``\left[\begin{matrix}\omega_x \\ \omega_y \\ \omega_z\end{matrix}\right] =
…``: the sentence names the quantity, the column lists its components in order, so the letter is
that quantity's, as the letter beside the phrase inline would be. A formula standing alone in a
paragraph between ``$…$`` is such a display (encyclopaedia pages set their displays so).

Takes: the rendered text (`derive.lecture.source.rendered`) and the phrases of the meanings a
letter may carry. Gives: `columns`, each such column with its line, its rows and the one meaning
the sentence names (`derive.lecture.names` binds the letter when the rows fit it), `listed` (a
bracketed list of components as the bare list), and `is_column`
(`derive.lecture.rereading` takes a reading so given as the text's own once its column holds).

May import: the standard library (`re`).
"""
from __future__ import annotations

import re

_DISPLAY = re.compile(r"\$\$(.+?)\$\$|\\\[(.+?)\\\]|(?:^|\n[ \t]*\n)[ \t]*\$(?!\$)([^$]+?)(?<!\\)\$[ \t]*(?=\n[ \t]*\n|\s*\Z)",
                      re.S)
# a column on the left, over lines as a notebook writes it, in sized or plain brackets, perhaps boxed and
# after the vector's own name (\boxed{\vec{\Omega} = [Ω₁; Ω₂; Ω₃] = …}): the name is the letter the rows
# are components of
_COLUMN = re.compile(r"\s*(?:\\boxed\s*\{)?\s*(?:\\vec\s*\{\s*\\?[A-Za-z]+\s*\}\s*=)?"
                     r"\s*(?:(?:\\left\s*)?[\[(]\s*)?\{?\s*\\begin\{([bpBvV]?matrix)\}(.*?)\\end\{\1\}\s*\}?\s*"
                     r"(?:(?:\\right\s*)?[\])])?\s*=", re.S)
_COMPONENTS = r"\bcomponents?\s+of\s+(?:the|its)\s+(?:[\w-]+\s+)?(?:PHRASE)\b"
_SENTENCE_END = re.compile(r"[.;!?]\s|\n\s*\n|\$\$")
_LISTED = re.compile(r"^\s*(?:\\left\s*)?[\[(]\s*(.*?)\s*(?:\\right\s*)?[\])]\s*(?:\^\s*\{?\s*(?:\\top|T|\\intercal)\s*\}?)?\s*$")


_MATRIX = re.compile(r"^\s*\\begin\{([bpBvV]?matrix)\}([^&]*?)\\end\{\1\}\s*$", re.S)


def listed(latex: str) -> str:
    """Components listed in brackets, a row or the column it transposes (``[p, q, r]^\\top``, ``(p, q, r)``,
    a one-column matrix), as the bare list ``p, q, r``; any other formula as it is."""
    column = _MATRIX.match(latex)
    if column:
        return ", ".join(row.strip() for row in column.group(2).split("\\\\"))
    return _LISTED.sub(r"\1", latex)


def is_column(latex: str) -> bool:
    """Whether a statement's left side is a written column of three entries (``[ω_x; ω_y; ω_z] = …``)."""
    column = _COLUMN.match(latex)
    return column is not None and "&" not in column.group(2) and \
        len([r for r in column.group(2).split("\\\\") if r.strip()]) == 3


def columns(body: str, phrases: dict) -> list:
    """The columns of components a sentence names.

    Parameters
    ----------
    body : str
        The rendered text.
    phrases : dict
        Meaning → the regular expression of the phrase that says it (a letter's meanings).

    Returns
    -------
    list
        (line, rows, meaning) of each display whose left side is a written column of three rows with
        no ``&`` (one entry each), after a sentence that says "the components of" exactly one of
        the meanings.
    """
    out = []
    for m in _DISPLAY.finditer(body):
        inner = next(g for g in m.groups() if g is not None)
        column = _COLUMN.match(inner)
        if column is None or "&" in column.group(2):
            continue
        rows = [r.strip() for r in column.group(2).split("\\\\") if r.strip()]
        sentence = _SENTENCE_END.split(body[:m.start()].rstrip())[-1]
        said = [meaning for meaning, phrase in phrases.items()
                if re.search(_COMPONENTS.replace("PHRASE", phrase), sentence, flags=re.I)]
        if len(rows) == 3 and len(said) == 1:
            start = m.start() + len(m.group(0)) - len(m.group(0).lstrip())
            out.append((body.count("\n", 0, start) + 1, rows, said[0]))
    return out
