"""Markdown's fenced blocks as a reader of the rendered page meets them.

Takes: the text of a Markdown notes file. Gives `rendered_fences`, the text with each fenced block
as it renders, every line kept in its place:

* a block in the language ``math`` (GitHub, GitLab, Documenter) or MyST's ``{math}`` directive is a
  display, ``$$ … $$`` on its fences (its ``:label:`` options blanked);
* a MyST directive that holds Markdown, ``````{prf:example}``, ``{note}``, ``{admonition}`` … (any
  ``{name}`` but the code directives), is its body: the fence lines and the directive's options are
  blanked and the body is read as the text around it, displays and all;
* any other block (code) is blanked.

A fence is three or more backticks or tildes, closed by a line of at least as many of the same
character (CommonMark): a directive fenced with four backticks holds ``{math}`` blocks of three.

May import: the standard library.
"""
from __future__ import annotations

import re

_OPEN = re.compile(r"^[ \t]*(?P<fence>`{3,}|~{3,})[ \t]*(?P<info>[^\n`]*)$")
_CODE_DIRECTIVES = {"code", "code-block", "code-cell", "sourcecode", "literalinclude", "eval-rst", "raw"}
_OPTION = re.compile(r"^[ \t]*:[\w-]+:")


def _kind(info: str) -> str:
    """"math", "directive" (a body of Markdown) or "code", by a fence's info string."""
    name = info.strip()
    if name in ("math", "{math}"):
        return "math"
    m = re.match(r"\{([\w:-]+)\}", name)
    return "directive" if m and m.group(1) not in _CODE_DIRECTIVES else "code"


def _closes(line: str, fence: str) -> bool:
    stripped = line.strip()
    return stripped.startswith(fence) and set(stripped) == {fence[0]}


def rendered_fences(text: str) -> str:
    """The text with its fenced blocks as they render (see the module docstring)."""
    lines = text.split("\n")
    out, open_ = [], []          # open_: the fences of the directives the line is inside
    k = 0
    while k < len(lines):
        line = lines[k]
        if open_ and _closes(line, open_[-1]):
            open_.pop()
            out.append(" " * len(line))
            k += 1
            continue
        m = _OPEN.match(line)
        if m is None:
            out.append(line)
            k += 1
            continue
        fence, kind = m.group("fence"), _kind(m.group("info"))
        if kind == "directive":
            open_.append(fence)
            out.append(" " * len(line))
            k += 1
            while k < len(lines) and _OPTION.match(lines[k]):       # the directive's :class: … options
                out.append(" " * len(lines[k]))
                k += 1
            continue
        end = next((j for j in range(k + 1, len(lines)) if _closes(lines[j], fence)), None)
        if end is None:          # a fence never closed is read as the text it is
            out.append(line)
            k += 1
            continue
        body = lines[k + 1:end]
        if kind == "math":
            body = [" " * len(b) if _OPTION.match(b) and all(_OPTION.match(x) for x in body[:i]) else b
                    for i, b in enumerate(body)]
            out.extend(["$$", *body, "$$"])
        else:
            out.extend(" " * len(x) for x in lines[k:end + 1])
        k = end + 1
    return "\n".join(out)
