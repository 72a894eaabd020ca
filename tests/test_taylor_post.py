"""The passes after a solve over its output arrays, fast on the usual samples and
the rule's own numbers on all: ``<prefix>canonical_angles`` (templates/c/solvers.c.j2) skips
the chunks of 16 samples that ``<prefix>angles_usual`` finds it would leave as they are (a
vectorised test on the bits), and runs the rule on the others.

The reference is the rule with every library call made (tests/test_pipeline.py), on smooth
trajectories — the case the fast path takes — with the rare events among them: a pole passage
(β through 0 and π), α's whole-turn jumps, a jump of α beyond π/2, differences of exactly π/2
and π, signed zeros, β = -0, NaN and inf, each also on the edge of a chunk."""
from __future__ import annotations

import numpy as np
import pytest

from derive.methods import registry as solvers
from derive.runtime import catalogue
from derive.runtime.integrate import ModelKernel
from test_pipeline import _canonical_reference


def _kernel():
    desc = catalogue.describe(("euler-angles", True, ("gravity",)))
    return ModelKernel.load(desc, solvers.DEFAULT_METHOD)


def _canonical(kernel, ang):
    n = len(ang)
    y = np.column_stack([ang, np.zeros((n, 3))])
    return kernel.outputs_at(np.arange(n, dtype=float), y, np.array([1.0, 0.5, 1.0, 1.0, 1.0]))[:3]


def _smooth(rng, n):
    t = np.linspace(0.0, 10.0, n)
    return np.column_stack([0.3 + 0.7 * t + 0.1 * np.sin(3 * t),
                            1.0 + 0.4 * np.sin(2 * t + rng.uniform()),
                            6.0 * t + 0.2 * np.cos(5 * t)])


def _put(ang, k, col, values):
    """ang[k, col], ang[k + 1, col], ... = values, as far as the trajectory goes."""
    m = min(len(values), len(ang) - k)
    ang[k:k + m, col] = values[:m]


EVENTS = {
    "none": lambda ang, k: None,
    "pole": lambda ang, k: _put(ang, k, 1, [0.05, -0.02, -0.1]),
    "bottom": lambda ang, k: _put(ang, k, 1, [3.1, 3.2, np.pi]),
    "turn": lambda ang, k: ang.__setitem__((slice(k, None), 0), ang[k:, 0] + 4 * np.pi),
    "jump": lambda ang, k: ang.__setitem__((slice(k, None), 0), ang[k:, 0] + 2.0),
    "half_pi": lambda ang, k: ang.__setitem__((k, 0), ang[k - 1, 0] + 0.5 * np.pi),
    "pi": lambda ang, k: ang.__setitem__((k, 2), ang[k - 1, 2] + np.pi),
    "below_pi": lambda ang, k: ang.__setitem__((k, 2), ang[k - 1, 2] + np.nextafter(np.pi, 0)),
    "zero": lambda ang, k: ang.__setitem__((k, 0), 0.0),
    "minus_zero": lambda ang, k: ang.__setitem__((k, 2), -0.0),
    "beta_minus_zero": lambda ang, k: ang.__setitem__((k, 1), -0.0),
    "beta_pi": lambda ang, k: ang.__setitem__((k, 1), np.pi),
    "nan": lambda ang, k: ang.__setitem__((k, 2), np.nan),
    "inf": lambda ang, k: ang.__setitem__((k, 0), np.inf),
    "huge": lambda ang, k: ang.__setitem__((k, 0), 1e300),
}


@pytest.mark.parametrize("event", sorted(EVENTS))
def test_canonical_angles_are_the_rule_bit_for_bit_on_smooth_trajectories(event):
    kernel = _kernel()
    rng = np.random.default_rng(7)
    for n in (2, 17, 1001):
        for k in sorted({1, 15, 16, 17, 31, 32, n // 2, n - 3, n - 1}):
            if not 1 <= k < n:
                continue
            ang = _smooth(rng, n)
            EVENTS[event](ang, k)
            got = _canonical(kernel, ang.copy())
            with np.errstate(invalid="ignore"):  # (inf - inf in the rule, as in C)
                want = _canonical_reference(ang[:, 0], ang[:, 1], ang[:, 2])
            for g, w in zip(got, want):
                assert np.array_equal(g.view(np.int64), w.view(np.int64)), (event, n, k)
