"""Where a model's generated code comes from, without SymPy on the warm path.

A model is identified by its key (formulation, symmetric body, effects). Its generated files are

* in ``generated/`` (committed, written by ``derive generate``) for the models the package ships
  (``models.CATALOGUE_KEYS`` and every model an example scene runs: ``SHIPPED``), or
* in the compile cache (``cbuild.cache_dir() / "models"``), derived once with SymPy the first time
  a scene needs it, in a folder keyed by a content hash of the package's derivation sources and
  templates, so a change to the derivation invalidates it.

Either way a :class:`Description` (``models/<name>.json``: states, parameters, outputs, sizes,
cost, the derived parameters, the domain note) says everything the simulation needs, and the C
and NumPy files are read as text. Only :func:`derive_model` imports SymPy.
"""
from __future__ import annotations

import functools
import hashlib
import json
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path

from . import effects as fx
from .formulations import INPUT_NAMES, model_name

#: (formulation, symmetric, effects) of the models written to generated/ besides the contract's
#: catalogue: the ones the example scenes and the common scene shapes run, so that a warm
#: `derive simulate` of any of them needs no derivation.
SHIPPED = (
    ("euler-angles", True, ()),
    ("reduced", True, ()),
    ("euler-poisson", False, ()),
    ("euler-poisson", True, ()),
    ("euler-poisson", True, ("gravity",)),
    ("euler-poisson", True, ("gravity", "damping")),
    ("euler-poisson", True, ("gravity_general",)),
    ("euler-poisson", False, ("gravity_general",)),
)


@dataclass(frozen=True)
class Description:
    """A generated model as the simulation sees it (the JSON written beside its code)."""

    name: str
    formulation: str
    symmetric: bool
    effects: tuple
    states: tuple
    params: tuple
    outputs: tuple  # flat output names, in the order of <name>_observables
    nin: int
    cost: int
    derived_params: tuple  # parameter indices the init map writes
    checks: tuple
    has_angles: bool
    domain_note: str
    folder: str  # where the files are: c/<name>.h, c/<name>.c, c/<name>_solvers.{h,c}, numpy/<name>.py

    @property
    def key(self) -> tuple:
        return (self.formulation, self.symmetric, self.effects)

    def source(self, rel: str) -> str:
        return (Path(self.folder) / rel).read_text(encoding="utf-8")

    def c_sources(self) -> dict[str, str]:
        """{file name: text} of the model and its solvers (the compile unit's inputs)."""
        names = [f"{self.name}{suffix}" for suffix in (".h", ".c", "_solvers.h", "_solvers.c",
                                                        "_splitting.h", "_splitting.c")]
        names.append("derive_elliptic.h")
        return {n: self.source(f"c/{n}") for n in names if (Path(self.folder) / "c" / n).is_file()}

    @classmethod
    def from_json(cls, text: str, folder: Path) -> "Description":
        d = json.loads(text)
        return cls(name=d["name"], formulation=d["formulation"], symmetric=d["symmetric"],
                   effects=tuple(d["effects"]), states=tuple(d["states"]),
                   params=tuple(d["params"]), outputs=tuple(d["outputs"]), nin=d["nin"],
                   cost=d["cost"], derived_params=tuple(d["derived_params"]),
                   checks=tuple(d["checks"]), has_angles=d["has_angles"],
                   domain_note=d["domain_note"], folder=str(folder))


def description_json(spec) -> str:
    """The JSON description of a model from its kernel spec (written by codegen)."""
    from .kernelspec import STEP_COST_PER_STATE

    m = spec.model
    return json.dumps({
        "name": m.name, "formulation": m.formulation, "symmetric": m.symmetric,
        "effects": list(m.effects), "states": list(m.state_names), "params": list(m.param_names),
        "outputs": list(spec.observable_names), "nin": len(INPUT_NAMES),
        "cost": spec.cost + STEP_COST_PER_STATE * len(m.states),
        "derived_params": list(spec.init_param_index), "checks": list(spec.check_names),
        "has_angles": spec.observable_names[:3] == ("alpha", "beta", "gamma"),
        "domain_note": m.domain_note,
    }, indent=1, sort_keys=True) + "\n"


def _generated() -> Path:
    from .render import GENERATED

    return GENERATED


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
    now (SymPy) and cached."""
    name = model_name(*key)
    shipped = _generated() / "models" / f"{name}.json"
    if shipped.is_file():
        return Description.from_json(shipped.read_text(encoding="utf-8"), _generated())
    folder = _cache_folder(name, key)
    path = folder / "models" / f"{name}.json"
    if not path.is_file():
        from .cbuild import writable_cache_dir  # an unwritable cache: a private one, warned

        folder = _cache_folder(name, key, writable_cache_dir())
        path = folder / "models" / f"{name}.json"
        if not path.is_file():
            from .errors import note

            note(f"deriving model {name} with SymPy (first run of this model: a few seconds; "
                 f"kept in the compile cache afterwards)")
            derive_model(key, folder)
    return Description.from_json(path.read_text(encoding="utf-8"), folder)


def available(key) -> Description | None:
    """The description if it exists already (generated/ or the cache), without deriving."""
    key = _norm(key)
    if key in _known:
        return describe(key)
    if key in _absent:
        return None
    name = model_name(*key)
    for folder in (_generated(), _cache_folder(name, key)):
        if (folder / "models" / f"{name}.json").is_file():
            _known.add(key)
            return describe(key)
    _absent.add(key)  # until this process derives it (describe)
    return None


_known: set = set()
_absent: set = set()


def _cache_folder(name: str, key, root: Path | None = None) -> Path:
    from .cbuild import MODELS, cache_root

    return (root or cache_root()) / MODELS / f"{name}-{_derivation_hash()[:16]}-{_effects_fingerprint(key[2])}"


@functools.lru_cache(maxsize=1)
def _derivation_hash() -> str:
    """SHA-256 of what a derivation depends on: the package's modules, the templates and the
    effects registry's declarations (a test may register a toy effect)."""
    from .render import TEMPLATES

    h = hashlib.sha256()
    here = Path(__file__).resolve().parent
    for path in sorted(here.glob("*.py")) + sorted(TEMPLATES.rglob("*.j2")):
        h.update(path.name.encode() + b"\0" + path.read_bytes())
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
    """Derive the model (SymPy), render its files and write them with its description into
    ``folder`` (atomically: a reader sees no folder or the whole one)."""
    from . import models
    from .codegen import model_sources

    model = models.build(*key)
    files = model_sources(model)
    folder.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{folder.name}-", dir=folder.parent))
    for rel, text in files.items():
        path = tmp / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    try:
        os.replace(tmp, folder)
    except OSError:  # another process got there first: theirs is identical
        import shutil

        shutil.rmtree(tmp, ignore_errors=True)


def clear_memory() -> None:
    """Forget the descriptions loaded in this process (tests that register effects)."""
    _describe.cache_clear()
    _derivation_hash.cache_clear()
    _fingerprint.cache_clear()
    _known.clear()
    _absent.clear()
