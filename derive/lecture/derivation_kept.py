"""A convention's derived quantities kept in the compile cache between commands.

`derive verify NOTES.md` derives its text's convention on first use (`derive.lecture.derivation`:
ω̃, the frames, the heavy top's Lagrangian, energy and momenta, Routh's reduction, the sleeping top,
the orientation along 𝐋, the fast top's slow precession, Lagrange's residuals of the top's L and
the free body's T). What
one command derived is kept in ``<cache>/models/derivation-<sequence>-<key>/derivation.json``
(:func:`derive.runtime.cache.models_dir`, a marked folder with a SHA-256 manifest, written
atomically by :func:`derive.runtime.cache.write_folder`) and given to the next command of the same
convention, which then derives only what is not there yet and keeps the union.

The key (:func:`source_key`) is the SHA-256 of derive's own source files, Python's version, the
SymPy and mpmath versions and SymPy's ground types and settings: any change to what a
derivation runs names another folder. A folder that is damaged (its manifest does not match),
unreadable or not of this key and convention is ignored, with a one-line note on stderr, and
written again; keeping is a saving and never a reason for a command to fail.

The format is JSON with each expression written as a tree of a whitelist of SymPy's classes
(:func:`encode`, :func:`decode`), rebuilt unevaluated in the order written, so that the rebuilt
expression is the one derived, argument for argument: unlike a pickle, reading it runs no code
but the whitelisted constructors. A quantity holding anything else is not kept.

Takes: a `Derivation`'s computed values ({"holder.name": value}). Gives: :func:`read`,
:func:`write`, :func:`encode`, :func:`decode`, :func:`source_key`.

May import: :mod:`derive.runtime.cache`, SymPy, mpmath.
"""
from __future__ import annotations

import functools
import hashlib
import json
import os
import sys
from pathlib import Path

import mpmath
import sympy as sp
from sympy.external.gmpy import GROUND_TYPES

from derive.runtime.cache import ABSENT, keep_newest, models_dir, read_folder, write_folder

#: The kept folders are named ``<PREFIX><sequence>-<key>``; the ``KEEP`` most recently used stay
#: (enough for the twelve sequences of two checkouts sharing one cache).
PREFIX, KEEP = "derivation-", 24
FILE = "derivation.json"
FORMAT = 1

_FUNCTIONS = {c.__name__: c for c in (sp.Add, sp.Mul, sp.Pow, sp.sin, sp.cos, sp.tan, sp.exp, sp.log,
                                      sp.Abs, sp.sign, sp.Equality, sp.Unequality, sp.LessThan,
                                      sp.GreaterThan, sp.StrictLessThan, sp.StrictGreaterThan)}
_CONSTANTS = ("Pi", "Exp1", "ImaginaryUnit", "Infinity", "NegativeInfinity", "ComplexInfinity", "NaN",
              "BooleanTrue", "BooleanFalse")
_MATRICES = {c.__name__: c for c in (sp.MutableDenseMatrix, sp.ImmutableDenseMatrix)}


class NotKept(ValueError):
    """A value outside the whitelist (it is derived again by each command instead)."""


def encode(obj):
    """A JSON-ready tree of ``obj``: an expression of whitelisted classes, a matrix, or a tuple,
    list or dict of those; raises `NotKept` for anything else."""
    kind = type(obj)
    if obj is None:
        return ["none"]
    if kind is sp.Symbol:
        # The assumptions the symbol was made with, so that decoding returns SymPy's own (cached)
        # symbol object, the very one derive's modules hold.
        return ["symbol", obj.name, getattr(obj, "_assumptions_orig", obj.assumptions0)]
    if isinstance(obj, sp.Integer):
        return ["integer", int(obj)]
    if isinstance(obj, sp.Rational):
        return ["rational", int(obj.p), int(obj.q)]
    if kind.__name__ in _CONSTANTS and getattr(sp.S, kind.__name__) is obj:
        return ["constant", kind.__name__]
    if _FUNCTIONS.get(kind.__name__) is kind:
        return [kind.__name__, [encode(a) for a in obj.args]]
    if _MATRICES.get(kind.__name__) is kind:
        return ["matrix", kind.__name__, obj.rows, obj.cols, [encode(e) for e in obj]]
    if kind in (tuple, list):
        return [kind.__name__, [encode(e) for e in obj]]
    if kind is dict:
        return ["dict", [[encode(k), encode(v)] for k, v in obj.items()]]
    raise NotKept(f"{kind.__name__} is not kept")


def decode(tree):
    """The value :func:`encode` wrote; ValueError (or TypeError) for a tree it cannot have written."""
    if not isinstance(tree, list) or not tree or not isinstance(tree[0], str):
        raise ValueError("not a kept value")
    tag, rest = tree[0], tree[1:]
    if tag == "none" and not rest:
        return None
    if tag == "symbol":
        name, assumptions = rest
        if not isinstance(name, str) or not isinstance(assumptions, dict) or \
                not all(isinstance(v, bool) for v in assumptions.values()):
            raise ValueError("a symbol without a name")
        return sp.Symbol(name, **assumptions)
    if tag == "integer":
        (n,) = rest
        return sp.Integer(_int(n))
    if tag == "rational":
        p, q = rest
        return sp.Rational(_int(p), _int(q))
    if tag == "constant":
        (name,) = rest
        if name not in _CONSTANTS:
            raise ValueError(f"unknown constant {name!r}")
        return getattr(sp.S, name)
    if tag in _FUNCTIONS:
        (args,) = rest
        return _FUNCTIONS[tag](*_items(args), evaluate=False)
    if tag == "matrix":
        name, rows, cols, elements = rest
        if name not in _MATRICES or _int(rows) * _int(cols) != len(_items(elements)):
            raise ValueError("a matrix of the wrong size")
        return _MATRICES[name](rows, cols, _items(elements))
    if tag in ("tuple", "list"):
        (items,) = rest
        return (tuple if tag == "tuple" else list)(_items(items))
    if tag == "dict":
        (pairs,) = rest
        if not isinstance(pairs, list) or not all(isinstance(p, list) and len(p) == 2 for p in pairs):
            raise ValueError("a dict that is not pairs")
        return {decode(k): decode(v) for k, v in pairs}
    raise ValueError(f"unknown tag {tag!r}")


def _int(n) -> int:
    if type(n) is not int:
        raise ValueError("not an integer")
    return n


def _items(items) -> list:
    if not isinstance(items, list):
        raise ValueError("not a list")
    return [decode(e) for e in items]


@functools.lru_cache(maxsize=1)
def source_key() -> str:
    """SHA-256 of what a derivation runs: derive's own ``.py`` files (path and bytes), Python's
    version, SymPy's and mpmath's versions, SymPy's ground types and ``SYMPY_*`` settings."""
    package = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for path in sorted(package.rglob("*.py")):
        h.update(path.relative_to(package).as_posix().encode() + b"\0")
        h.update(hashlib.sha256(path.read_bytes()).digest())
    settings = sorted((k, v) for k, v in os.environ.items() if k.startswith("SYMPY_"))
    h.update(repr((sys.version, sp.__version__, mpmath.__version__, GROUND_TYPES, settings)).encode())
    return h.hexdigest()


def _folder(sequence: str) -> Path:
    return models_dir() / f"{PREFIX}{sequence}-{source_key()[:24]}"


def read(sequence: str) -> tuple[dict, set]:
    """({"holder.name": value} kept for the convention ``sequence`` (``"zxz"``) under this
    :func:`source_key`, the names of those and of the values left out as outside the whitelist);
    ({}, set()) when nothing whole is kept."""
    folder = _folder(sequence)
    try:
        files, problem = read_folder(folder, FILE)
        if files is None:
            return _again(folder, problem)
        data = json.loads(files[FILE].decode("utf-8"))
        if data.get("format") != FORMAT or data.get("convention") != sequence or data.get("key") != source_key():
            return _again(folder, "is of another convention or key")
        values = {path: decode(tree) for path, tree in data["values"].items() if isinstance(path, str)}
        left_out = {path for path in data["left_out"] if isinstance(path, str)}
    except (OSError, ValueError, TypeError, KeyError, AttributeError, RecursionError):
        return _again(folder, f"has an unreadable {FILE}")
    try:
        os.utime(folder)  # just used: pruning keeps the most recently used
    except OSError:
        pass
    return values, set(values) | left_out


def _again(folder: Path, problem: str) -> tuple[dict, set]:
    """Nothing kept; a note on stderr when something damaged stands there (absent: silence)."""
    if problem != ABSENT:
        print(f"note: kept derivation {folder} {problem}; deriving it again", file=sys.stderr, flush=True)
    return {}, set()


def write(sequence: str, values: dict) -> None:
    """Keep ``values`` ({"holder.name": value}; those outside the whitelist are left out) for
    the convention ``sequence``, replacing what was kept; silent when the cache cannot be written."""
    kept = {}
    for path, value in values.items():
        try:
            kept[path] = encode(value)
        except (NotKept, RecursionError):
            pass
    text = json.dumps({"format": FORMAT, "convention": sequence, "key": source_key(), "values": kept,
                       "left_out": sorted(set(values) - set(kept))},
                      separators=(",", ":"), sort_keys=True)
    try:
        folder = _folder(sequence)
        write_folder(folder, {FILE: text}, FILE, replace=True)
        keep_newest(folder.parent, PREFIX, KEEP)
    except (OSError, RecursionError):
        pass

