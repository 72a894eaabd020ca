"""The example scenes and sweeps shipped with derive, found by name.

The repository's ``scenes/`` folder (scenes at the top, sweeps in ``scenes/sweeps/``) is the
package's ``derive/_scenes`` in an installed wheel, so ``derive simulate looping_top`` and
``derive sweep sleeping_threshold`` run from any directory. A name is used only when no file of
that name exists: a user's own ``looping_top`` file always wins.

Takes names; gives paths. Imports only :mod:`derive.codegen.render` (where the data lives).
"""
from __future__ import annotations

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
    """The example's one-line description: its ``title``, else its first comment line."""
    title, comment = None, None
    for line in file.read_text(encoding="utf-8").splitlines():
        s = line.strip()
        if comment is None and s.startswith("#"):
            comment = s.lstrip("# ").strip() or None
        if s.startswith("title") and "=" in s:
            title = s.split("=", 1)[1].strip().strip('"')
            break
    return title or comment or ""


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


