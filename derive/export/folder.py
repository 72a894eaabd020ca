"""``derive export SCENE --out DIR``: the scene's model as a self-contained C99 folder.

The folder holds the model's generated C sources and headers, its solvers, one translation unit
(``<name>_lib.c``) for the libraries, ``example.c`` (``templates/c/example.c.j2``), a
``Makefile`` and a ``README.md`` (``templates/export/``), the JSON description and the NumPy
module. ``make`` builds ``example``, ``lib<name>.a`` and ``lib<name>.so`` with ``cc -std=c99
-O2``; ``./example`` runs the scene with the same inputs, parameters, output times and driver
settings as ``derive simulate`` and prints one JSON line, ``t_end``, ``nfev`` and every output
at the last sample (``%.17g``: the doubles round-trip).

The folder is written all or nothing: into a temporary folder beside ``DIR``, renamed onto it at
the end. ``DIR`` must be new or empty (an existing file or a folder with anything in it is bad
input, exit 2), so nothing of the user's is ever overwritten.
"""
from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

from derive.codegen.render import c_double, render
from derive.errors import SceneError
from derive.export import bundle as bundles
from derive.export import contact as contact_export
from derive.export.bundle import OUTPUT_DOCS, OUTPUT_UNITS, Bundle, notice, output_groups, state_unit
from derive.methods.registry import method as compiled_method
from derive.sim.outputs import umask
from derive.sim.scene import contact_data

POLE_NOTES = {
    0: "none: the formulation has no singular set, or the scene asked for it",
    1: "refuse (DERIVE_RANGE, nothing integrated) a start from which the motion comes closer "
       "to a pole than the formulation allows",
    2: "as 1, except a pole the reduced equations pass regularly",
}


def check_out(out: Path) -> None:
    """SceneError (exit 2) unless ``out`` is a new name or an empty folder."""
    name = os.fspath(out)
    if not name or "\0" in name:
        raise SceneError(f"{name!r}: --out: not a directory name")
    if os.path.lexists(out):
        if out.is_symlink() or not out.is_dir():
            raise SceneError(f"{out}: --out: exists and is not a directory; name a new or empty one")
        if any(out.iterdir()):
            raise SceneError(f"{out}: --out: exists and is not empty; name a new or empty directory "
                             f"(nothing is overwritten)")


def _literal(ctype: str, value) -> str:
    if ctype == "double":
        return c_double(value)
    return f"{int(value)}L" if ctype == "long" else str(int(value))


def files(b: Bundle) -> dict[str, str]:
    """Every file of the exported folder: ``{name: text}``."""
    P = b.name
    sources = b.desc.c_sources()
    model, extra = b.model_files()
    out = {n: sources[n] for n in model + extra}
    includes = [f"{P}.c", f"{P}_solvers.c"] + ([f"{P}_{b.family}.c"] if b.family else [])
    out[f"{P}_lib.c"] = render("export/lib.c.j2", P=P, includes=includes, family=b.family)

    derived = set(b.desc.derived_params)
    by_index = {v.index: v for v in b.parameters()}
    params = []
    for k, name in enumerate(b.desc.params):
        if k in derived:
            params.append((name, 0.0, "derived: written by the init map"))
        else:
            v = by_index[k]
            params.append((name, v.value, f"{v.name}" + (f", {v.unit}" if v.unit else "")))
    driver = [(ctype, name, _literal(ctype, value)) for ctype, name, value in b.driver]
    scene_file = Path(b.scene.source).name if b.scene.source != "<dict>" else "the scene"
    common = dict(P=P, method=b.method, family=b.family, driver=driver,
                  pole_check=b.pole_check, pole_note=POLE_NOTES.get(b.pole_check, ""),
                  scene_file=scene_file)
    out["example.c"] = render("c/example.c.j2", initial=b.initial(), params=params,
                              t_end=b.t_end, samples=b.samples,
                              groups=output_groups(b.desc.outputs), **common)
    runtime = "derive_runtime.c"
    out["Makefile"] = render("export/Makefile.j2", sources=[n for n in model + extra if n != runtime],
                             runtime=runtime, **common)
    out["NOTICE.md"] = notice(out)

    outputs = []
    for base, cols in output_groups(b.desc.outputs):
        for k in cols:
            outputs.append((k, b.desc.outputs[k], OUTPUT_UNITS.get(base, ""),
                            OUTPUT_DOCS.get(base, "") + (f" (component {cols.index(k) + 1})"
                                                         if len(cols) > 1 else "")))
    title = " ".join((b.scene.title or "").split())
    out["README.md"] = render(
        "export/README.md.j2", title=title, formulation=b.desc.formulation,
        effects=", ".join(b.desc.effects), method_summary=compiled_method(b.method).summary,
        domain_note=b.desc.domain_note, extra_headers=extra,
        states=[(s, state_unit(s)) for s in b.desc.states], param_names=list(b.desc.params),
        parameters=b.parameters(), derived=[(k, b.desc.params[k]) for k in sorted(derived)],
        initial=b.initial(), outputs=outputs, **common)
    out[f"{P}.json"] = b.desc.source(f"models/{P}.json")
    out[f"{P}.py"] = b.desc.source(f"numpy/{P}.py")
    return out


def export_folder(scene, out, method: str | None = None) -> Bundle:
    """Write the export of ``scene`` into the folder ``out`` (new or empty), all or nothing.

    Parameters
    ----------
    scene : str, path or dict
        The scene (a TOML path, an example's name, or a dict shaped like the TOML).
    out : str or path
        The folder to create (or an empty one to fill).
    method : str, optional
        Replaces the scene's ``[simulate] method`` (a compiled method).

    Returns
    -------
    Bundle
        What was exported (model, method, numbers).

    Raises
    ------
    SceneError
        Bad input: the scene, the method, or ``out`` (exists and is not an empty folder, or
        cannot be written).
    IntegrationError
        The scene's simulation fails.
    """
    out = Path(out)
    check_out(out)  # before the work
    found = contact_data(scene) if not isinstance(scene, bundles.Scene) else None
    if found is not None:  # a top on a table: its evaluator and the phase driver
        b = contact_export.bundle(found, method)
        texts = contact_export.files(b.scene)
    else:
        b = bundles.make(scene, method)
        texts = files(b)
    parent = out.absolute().parent
    try:
        parent.mkdir(parents=True, exist_ok=True)
        tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}-", dir=parent))
    except OSError as exc:
        raise SceneError(f"{out}: --out: cannot create it ({exc.strerror or exc})") from None
    try:
        for name, text in texts.items():
            (tmp / name).write_text(text, encoding="utf-8")
        os.chmod(tmp, 0o777 & ~umask())  # mkdtemp's 0700 -> what mkdir would give
        check_out(out)  # still new or empty (rename would replace an empty folder only)
        os.rename(tmp, out)
    except OSError as exc:
        raise SceneError(f"{out}: --out: cannot write it ({exc.strerror or exc})") from None
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return b
