"""The example scenes and sweeps shipped with derive, found by name.

The repository's ``scenes/`` folder (scenes at the top, sweeps in ``scenes/sweeps/``) is the
package's ``derive/_scenes`` in an installed wheel, so ``derive simulate looping_top`` and
``derive sweep sleeping_threshold`` run from any directory. A name is used only when no file of
that name exists: a user's own ``looping_top`` file always wins.

Takes names; gives paths. Imports only :mod:`derive.codegen.render` (where the data lives).
"""
from __future__ import annotations

import difflib
import os
from pathlib import Path

from derive.codegen.render import data_dir

#: The folder of the example scenes (sweeps in its ``sweeps/`` subfolder).
SCENES = data_dir("scenes")
KINDS = {"scene": SCENES, "sweep": SCENES / "sweeps"}
#: Tops on a table (``[contact]`` scenes, run by derive.contact): scenes by name too (contact hook).
CONTACT = SCENES / "contact"


def names(kind: str = "scene") -> list[str]:
    """The example names of one kind (``"scene"`` or ``"sweep"``), sorted."""
    extra = CONTACT.glob("*.toml") if kind == "scene" else ()  # contact hook
    return sorted(p.stem for p in (*KINDS[kind].glob("*.toml"), *extra))


def path(name: str, kind: str = "scene") -> Path | None:
    """The file of the example ``name`` (with or without ``.toml``), or None if there is none."""
    stem = name[:-5] if name.endswith(".toml") else name
    if not stem or os.sep in stem or "/" in stem or stem.startswith("."):
        return None
    found = KINDS[kind] / f"{stem}.toml"
    if kind == "scene" and not found.is_file():
        found = CONTACT / f"{stem}.toml"  # contact hook
    return found if found.is_file() else None


def resolve(arg, kind: str = "scene"):
    """``arg`` itself when it names an existing file (or is not a string), else the example of
    that name if there is one, else ``arg`` unchanged (the caller reports it as not found)."""
    if not isinstance(arg, str) or os.path.lexists(arg):
        return arg
    found = path(arg, kind)
    return str(found) if found is not None else arg


def summary(file: Path) -> str:
    """The example's one-line description: its ``title``, else the first sentence of its
    leading comment (the comment's first paragraph, its lines joined, up to the first ``.``,
    ``?`` or ``!`` that ends a sentence outside parentheses), never a line cut mid-sentence."""
    lines = file.read_text(encoding="utf-8").splitlines()
    for line in lines:
        s = line.strip()
        if s.startswith("title") and "=" in s:
            return s.split("=", 1)[1].strip().strip('"')
    paragraph = []
    for line in lines:
        s = line.strip()
        text = s.lstrip("#").strip()
        if not s.startswith("#") or not text:
            if paragraph:
                break
            if not s.startswith("#") and s:
                break
            continue
        paragraph.append(text)
    return first_sentence(" ".join(paragraph))


def first_sentence(text: str) -> str:
    """``text`` up to and including the first ``.``, ``?`` or ``!`` followed by a space or the
    end, outside parentheses (``1.8e-4`` and ``(e.g. this)`` do not end it); all of it if none."""
    depth = 0
    for k, ch in enumerate(text):
        depth += (ch == "(") - (ch == ")")
        if ch in ".?!" and depth <= 0 and (k + 1 == len(text) or text[k + 1] == " "):
            return text[:k + 1]
    return text


def did_you_mean(name: str, kind: str | None = None) -> str:
    """`` (did you mean looping_top?)`` when ``name`` is close to an example's name (of
    ``kind``, or of either kind), by :func:`difflib.get_close_matches`; else ``""``."""
    stem = name[:-5] if name.endswith(".toml") else name
    if not stem or "/" in stem or os.sep in stem:
        return ""
    known = [n for k in ([kind] if kind in KINDS else KINDS) for n in names(k)]
    close = difflib.get_close_matches(stem, known, n=1, cutoff=0.75)
    return f" (did you mean {close[0]}?)" if close else ""


def copy(name: str, dest: Path, kind: str | None = None) -> Path:
    """Copy the example ``name`` to ``dest`` (a folder, or a new file name); returns the new
    file. A sweep's scene is copied beside it and its ``scene =`` path rewritten, so the copy
    runs where it lands. Never overwrites: FileExistsError."""
    kinds = [kind] if kind else ["scene", "sweep"]
    src = next((p for k in kinds if (p := path(name, k)) is not None), None)
    if src is None:
        raise KeyError(name)
    dest = Path(dest)
    target = dest / src.name if dest.is_dir() else dest
    files = {target: src.read_text(encoding="utf-8")}
    if src.parent == KINDS["sweep"]:
        text = files[target]
        lines = []
        for line in text.splitlines(keepends=True):
            if line.startswith("scene") and "=" in line and '"' in line:
                rel = line.split('"')[1]
                scene_src = (src.parent / rel).resolve()
                files[target.parent / scene_src.name] = scene_src.read_text(encoding="utf-8")
                line = f'scene = "{scene_src.name}"\n'
            lines.append(line)
        files[target] = "".join(lines)
    clash = [str(p) for p in files if os.path.lexists(p)]
    if clash:
        raise FileExistsError(clash[0])
    for p, text in files.items():
        with open(p, "x", encoding="utf-8") as fh:
            fh.write(text)
    return target


