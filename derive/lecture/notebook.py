"""A Jupyter notebook's Markdown cells as the notes the reader takes.

Takes: the text of an ``.ipynb`` file (nbformat 4 JSON). Gives: :func:`markdown`, the Markdown
of its Markdown cells, each line placed on the line of the file where the notebook stores it, so
that a claim's ``line`` is the notebook file's line (as for any notes file). Code cells, raw
cells and outputs are not rendered text and are left out. A first cell that opens with a ``---``
front matter gives the notes' front matter.

May import: the standard library and :mod:`derive.errors`.
"""
from __future__ import annotations

import json

from derive.errors import SceneError


def _bad(path: str, key: str, what: str) -> SceneError:
    return SceneError(f"{path}: {key}: {what}")   # exit status 2, as for any bad notes file


def markdown(text: str, path: str) -> str:
    """The Markdown cells of the notebook ``text``, line for line where the file holds them.

    nbformat writes a cell's ``source`` as a list of strings, one per line of the JSON file;
    each is found in the file in order, and a line that cannot be found (another writer's
    escaping, a source written as one string) comes right after the one before. Cells are kept
    apart by at least one empty line, so a display never runs into the next cell."""
    try:
        nb = json.loads(text)
    except ValueError as err:
        raise _bad(path, "file", f"not a notebook: {err}") from None
    cells = nb.get("cells") if isinstance(nb, dict) else None
    if not isinstance(cells, list):
        raise _bad(path, "cells", "missing: a Jupyter notebook (nbformat 4) has a list of cells")
    placed: dict[int, str] = {}
    offset, last = 0, -1
    for cell in cells:
        if not isinstance(cell, dict) or cell.get("cell_type") != "markdown":
            continue
        source = cell.get("source", "")
        pieces = source if isinstance(source, list) else [source]
        if not all(isinstance(p, str) for p in pieces):
            raise _bad(path, "source", "a Markdown cell's source is not text")
        first = True
        for piece in pieces:
            found = _find(text, piece, offset)
            if found is not None:
                offset = found + 1
            line = text.count("\n", 0, found) if found is not None else last + 1
            for k, row in enumerate(piece.rstrip("\n").split("\n")):
                lowest = last + (2 if first and last >= 0 else 1)
                opens = first and not placed and row.strip() == "---"   # a front matter opens the notes
                line = 0 if opens else max(line + (k > 0), lowest)
                placed[line] = row
                last, first = line, False
    return "\n".join(placed.get(n, "") for n in range(last + 1)) + "\n"


def _find(text: str, piece: str, start: int) -> int | None:
    """Where the JSON string of ``piece`` starts in ``text`` from ``start`` (either escaping)."""
    hits = [text.find(json.dumps(piece, ensure_ascii=a), start) for a in (False, True)]
    hits = [h for h in hits if h >= 0]
    return min(hits) if hits else None
