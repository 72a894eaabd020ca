"""The bench's reference scene: the shipped example ``reference_top`` (``scenes/reference_top.toml``),
a fast, strongly nutating heavy top on which every contender races at equal error."""
from __future__ import annotations

import tomllib

from derive.sim import examples


def _read() -> dict:
    with open(examples.path("reference_top"), "rb") as fh:
        return tomllib.load(fh)


#: The reference scene as a dict shaped like the TOML.
REFERENCE = _read()


def reference_data(t_end: float = 10.0) -> dict:
    """A fresh copy of the reference scene with ``simulate.t_end`` set."""
    data = {k: (dict(v) if isinstance(v, dict) else v) for k, v in REFERENCE.items()}
    data["simulate"]["t_end"] = t_end
    return data
