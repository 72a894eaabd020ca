"""Where a model's generated code comes from, without SymPy on the warm path.

A model is identified by its key (formulation, symmetric body, effects). Its generated files are

* in ``generated/`` (committed, written by ``derive generate``) for the models the package ships
  (``models.CATALOGUE_KEYS`` and every model an example scene runs: ``codegen.sources.SHIPPED``), or
* in the compile cache (``cache.cache_dir() / "models"``), derived once with SymPy the first time
  a scene needs it (once, whatever the number of processes asking: under the folder's
  lock), in a folder keyed by a content hash of the package's derivation sources and
  templates, so a change to the derivation invalidates it. The folder carries the cache's marker
  (``cache.MARKER``) and a ``SHA256SUMS`` of every file in it; one that does not verify (a
  file missing, truncated or changed) is derived again, once, with a one-line note.

Either way a :class:`Description` (``models/<name>.json``: states, parameters, outputs, sizes,
cost, the derived parameters, the domain note) says everything the simulation needs, and the C
and NumPy files are read as text. Only :func:`derive_model` imports SymPy.
"""
from __future__ import annotations

import functools
import hashlib
import json
import sys
from dataclasses import dataclass
from pathlib import Path

from derive.codegen.render import GENERATED, RUNTIME_FILES, TAYLOR_INCS, TEMPLATES
from derive.errors import note
from derive.runtime.cache import (ABSENT, entry_lock, models_dir, read_folder, writable_cache_dir,
                                  write_folder)
from derive.symbolic import effects as fx
from derive.symbolic.formulations import model_name

@dataclass(frozen=True)
class Description:
    """A generated model as the simulation sees it (the JSON written beside its code)."""

    name: str
    formulation: str
    symmetric: bool
    effects: tuple
    states: tuple
    params: tuple
    outputs: tuple  # flat output names, in the order of <name>_observables_at
    nin: int
    cost: int
    derived_params: tuple  # parameter indices the init map writes
    checks: tuple
    has_angles: bool
    domain_note: str
    folder: str  # where the files are: c/<name>.h, c/<name>.c, c/<name>_solvers.{h,c}, numpy/<name>.py
    # the cost model's numbers (derive.methods.costs): the Taylor jet's weight (0: no Taylor
    # kernel) and the output map's operation count
    jet_weight: float = 0.0
    output_cost: int = 0

    @property
    def key(self) -> tuple:
        return (self.formulation, self.symmetric, self.effects)

    def source(self, rel: str) -> str:
        return (Path(self.folder) / rel).read_text(encoding="utf-8")

    def c_sources(self) -> dict[str, str]:
        """{file name: text} of the model and its solvers (the compile unit's inputs)."""
        names = [f"{self.name}{suffix}" for suffix in (".h", ".c", "_solvers.h", "_solvers.c",
                                                        "_splitting.h", "_splitting.c",
                                                        "_taylor.h", "_taylor.c")]
        names += ["derive_elliptic.h", *RUNTIME_FILES, *TAYLOR_INCS]
        return {n: self.source(f"c/{n}") for n in names if (Path(self.folder) / "c" / n).is_file()}

    @classmethod
    def from_json(cls, text: str, folder: Path) -> "Description":
        d = json.loads(text)
        return cls(name=d["name"], formulation=d["formulation"], symmetric=d["symmetric"],
                   effects=tuple(d["effects"]), states=tuple(d["states"]),
                   params=tuple(d["params"]), outputs=tuple(d["outputs"]), nin=d["nin"],
                   cost=d["cost"], derived_params=tuple(d["derived_params"]),
                   checks=tuple(d["checks"]), has_angles=d["has_angles"],
                   domain_note=d["domain_note"], folder=str(folder),
                   jet_weight=d.get("jet_weight", 0.0), output_cost=d.get("output_cost", 0))


def _norm(key) -> tuple:
    formulation, symmetric, effects = key
    return (formulation, bool(symmetric), tuple(e.name for e in fx.lookup(effects)))


def describe(key) -> Description:
    """The description of the model with this key: from generated/, from the cache, or derived
    now (SymPy) and cached."""
    return _describe(_norm(key))


def cache_info():
    """Hits and misses of :func:`describe` in this process (functools' cache_info)."""
    return _describe.cache_info()


@functools.lru_cache(maxsize=None)
def _describe(key) -> Description:
    _absent.discard(key)
    _known.add(key)
    return _load(key)


def _load(key) -> Description:
    """The description of the model with this key: from generated/, from the cache, or derived
    now (SymPy) and cached; a cached one that does not verify is derived again."""
    name = model_name(*key)
    shipped = GENERATED / "models" / f"{name}.json"
    if shipped.is_file():
        return Description.from_json(shipped.read_text(encoding="utf-8"), GENERATED)
    folder = _cache_folder(name, key)
    desc, problem = _cached(folder, name)
    if desc is not None:
        return desc
    # an unwritable cache: a private one, warned
    writable = _cache_folder(name, key, writable_cache_dir(), writing=True)
    if writable != folder:
        folder = writable
        desc, problem = _cached(folder, name)
        if desc is not None:
            return desc
    if problem != ABSENT:
        print(f"note: derived model {folder} {problem}; deriving it again", file=sys.stderr,
              flush=True)
    folder.parent.mkdir(parents=True, exist_ok=True)
    with entry_lock(folder.parent, folder.name):  # processes that need it at once derive it once
        desc, _ = _cached(folder, name)
        if desc is not None:  # derived by the process this one waited for
            return desc
        if problem == ABSENT:
            note(f"deriving model {name} with SymPy (first run of this model: a few seconds; "
                 f"kept in the compile cache afterwards)")
        derive_model(key, folder)
    desc, problem = _cached(folder, name)
    if desc is None:
        raise RuntimeError(f"the model just derived into {folder} {problem}")
    return desc


def _cached(folder: Path, name: str) -> tuple[Description | None, str]:
    """(the description of the model derived into ``folder``, "") if the folder is whole: every
    file its manifest lists, the description among them, has the SHA-256 written with it and
    the description parses; else (None, why not), ``ABSENT`` if there is nothing there."""
    required = f"models/{name}.json"
    files, problem = read_folder(folder, required)
    if files is None:
        return None, problem
    try:
        return Description.from_json(files[required].decode("utf-8"), folder), ""
    except (ValueError, KeyError, TypeError) as exc:
        return None, f"has an unreadable description ({type(exc).__name__})"


def shipped(key) -> Description | None:
    """The description of a model the package ships in generated/ (the same on every machine
    and in every process, whatever the cache holds), else None."""
    key = _norm(key)
    if (GENERATED / "models" / f"{model_name(*key)}.json").is_file():
        return describe(key)
    return None


def available(key) -> Description | None:
    """The description if it exists already (generated/ or the cache), without deriving."""
    key = _norm(key)
    if key in _known:
        return describe(key)
    if key in _absent:
        return None
    name = model_name(*key)
    for folder in (GENERATED, _cache_folder(name, key)):
        # A damaged cached model is healed by describe (derived again, once).
        if (folder / "models" / f"{name}.json").is_file():
            _known.add(key)
            return describe(key)
    _absent.add(key)  # until this process derives it (describe)
    return None


_known: set = set()
_absent: set = set()


def _cache_folder(name: str, key, root: Path | None = None, writing: bool = False) -> Path:
    variant = f"{name}-{_derivation_hash()[:16]}-{_effects_fingerprint(key[2])}"
    return models_dir(root, writing) / variant  # never through a `models` that is not a real folder


@functools.lru_cache(maxsize=1)
def _derivation_hash() -> str:
    """SHA-256 of what a derivation depends on: the package's modules, the templates and the
    effects registry's declarations (a test may register a toy effect)."""
    h = hashlib.sha256()
    package = Path(__file__).resolve().parents[1]
    for base, pattern in ((package, "*.py"), (TEMPLATES, "*.j2")):
        for path in sorted(base.rglob(pattern)):
            h.update(path.relative_to(base).as_posix().encode() + b"\0" + path.read_bytes())
    return h.hexdigest()


def _effects_fingerprint(effect_names) -> str:
    """Part of a variant's folder name for effects registered at run time (not in the sources)."""
    effects = fx.lookup(effect_names)
    return _fingerprint(tuple(effects), tuple(id(e) for e in effects))


@functools.lru_cache(maxsize=None)
def _fingerprint(effects, ids) -> str:
    import inspect

    h = hashlib.sha256()
    for e in effects:
        h.update(repr((e.name, e.table, e.param_names, e.axisymmetric)).encode())
        for fn in (e.potential, e.torque):
            if fn is not None:
                try:
                    h.update(inspect.getsource(fn).encode())
                except (OSError, TypeError):
                    h.update(repr(fn).encode())
    return h.hexdigest()[:12]


def derive_model(key, folder: Path) -> None:
    """Derive the model (SymPy), render its files and write them with its description, the
    cache's marker and a ``SHA256SUMS`` of them into ``folder`` (atomically: a reader sees no
    folder or the whole one). A damaged folder already there is replaced: removed if the cache
    made it (marked), else moved aside (``cache.make_room``)."""
    # SymPy and the code generators load only when a model is derived: a cached one never needs them.
    from derive.symbolic import models
    from derive.codegen.sources import model_sources

    model = models.build(*key)
    write_folder(folder, model_sources(model), f"models/{model.name}.json")


def clear_memory() -> None:
    """Forget the descriptions loaded in this process (tests that register effects)."""
    _describe.cache_clear()
    _derivation_hash.cache_clear()
    _fingerprint.cache_clear()
    _known.clear()
    _absent.clear()
