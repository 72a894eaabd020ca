"""The bench's reference scene: the shipped example ``reference_top`` (``scenes/reference_top.toml``),
a fast, strongly nutating heavy top on which every contender races at equal error."""
from __future__ import annotations

from derive.bench.contenders import scene_data
from derive.sim import examples

#: The reference scene as a dict shaped like the TOML.
REFERENCE = scene_data(examples.path("reference_top"))


def reference_data(t_end: float = 10.0) -> dict:
    """A fresh copy of the reference scene with ``simulate.t_end`` set."""
    return scene_data(REFERENCE, t_end=t_end)
