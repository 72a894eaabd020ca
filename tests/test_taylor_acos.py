"""The Taylor solvers' own acos: ``derive_acos_poly`` (templates/c/libm.h.j2),
fdlibm's e_acos.c by arithmetic alone with its branches chosen on the bits, so that the output
map's loop over a block of samples vectorises (``<prefix>outputs_block``). Compiled here in a
small C harness that includes ``derive_libm.h``, the header the generated solver of
``reduced_u_sym_gravity`` (β = acos u is one of its outputs) takes it from, and calls the
function over a block (the model's own code is not what is measured, and not compiled).

Checked: within 1 ulp of glibc's acos (through :mod:`math`), equal to it on almost every
argument, exact at the edges (±1, ±0.5, ±0, tiny and subnormal arguments), NaN beyond [-1, 1]
and for NaN and inf; the same bits in a vectorised loop, alone, and in the build of the lanes
driver (``-march=native``)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from derive.runtime.cbuild import DEFAULT_FLAGS, NATIVE_FLAGS
from tests.bits_harness import GEN, compile_harness, run_bits, ulps

HARNESS = r"""
#include "derive_libm.h"
#include <stdio.h>

/* reads doubles (hex of their bits) from stdin; writes, per argument, the bits of acos from a
 * loop over a block of 16 (vectorised) and from a call alone (through a volatile argument). */
int main(void)
{
    double x[16], r[16];
    volatile double one;
    unsigned long long bits;
    int n = 0, k;
    for (;;) {
        int got = scanf("%llx", &bits);
        if (got == 1)
            memcpy(&x[n++], &bits, sizeof bits);
        if (n == 16 || (got != 1 && n > 0)) {
            for (k = 0; k < n; ++k)
                r[k] = ACOS(x[k]);
            for (k = 0; k < n; ++k) {
                unsigned long long a, b;
                double s;
                one = x[k];
                s = ACOS(one);
                memcpy(&a, &r[k], 8);
                memcpy(&b, &s, 8);
                printf("%016llx %016llx\n", a, b);
            }
            n = 0;
        }
        if (got != 1)
            return 0;
    }
}
"""


def _harness(tmp_path, flags, name):
    return compile_harness(tmp_path, flags, name, "#define ACOS derive_acos_poly\n" + HARNESS)


def test_the_solver_takes_its_acos_from_the_header_the_harness_includes():
    """What the harness measures is the solver's own acos: the reduced-u solver includes
    ``derive_libm.h`` and calls ``derive_acos_poly`` for β."""
    text = (GEN / "reduced_u_sym_gravity_taylor.c").read_text()
    assert '#include "derive_libm.h"' in text and "derive_acos_poly(" in text
    assert "double derive_acos_poly" not in text  # (not a definition of its own)


@pytest.fixture(scope="module")
def plain(tmp_path_factory):
    """The harness built with the libraries' flags, once for the tests that run it."""
    return _harness(tmp_path_factory.mktemp("acos"), [*DEFAULT_FLAGS], "acos")




def _libm(x: np.ndarray) -> np.ndarray:
    """glibc's acos (through :mod:`math`: NumPy may use its own SIMD routines); NaN outside
    [-1, 1]."""
    return np.array([math.acos(z) if -1.0 <= z <= 1.0 else math.nan for z in x.tolist()])




EDGES = np.array([1.0, -1.0, 0.5, -0.5, 0.0, -0.0, np.nextafter(1.0, 0.0), np.nextafter(-1.0, 0.0),
                  np.nextafter(0.5, 0.0), np.nextafter(0.5, 1.0), np.nextafter(-0.5, 0.0),
                  np.nextafter(-0.5, -1.0), 2.0 ** -57, -(2.0 ** -57), 2.0 ** -56, 1e-300,
                  -1e-300, 5e-324, -5e-324, 2.2250738585072014e-308, 1e-160, 1e-8, -1e-8])


@pytest.fixture(scope="module")
def arguments():
    rng = np.random.default_rng(20)
    parts = [rng.uniform(-1.0, 1.0, 100_000), rng.uniform(-1e-6, 1e-6, 10_000),
             1.0 - rng.uniform(0.0, 1e-6, 10_000), -1.0 + rng.uniform(0.0, 1e-6, 10_000),
             0.5 + rng.uniform(-1e-6, 1e-6, 10_000), -0.5 + rng.uniform(-1e-6, 1e-6, 10_000),
             np.cos(rng.uniform(0.0, np.pi, 20_000)), EDGES]
    return np.concatenate(parts)


def test_acos_is_within_one_ulp_of_libm_and_the_same_alone_or_in_a_block(plain, arguments):
    r = run_bits(plain, arguments)
    ref = _libm(arguments)
    assert ulps(r[:, 0], ref).max() <= 1
    assert (r[:, 0] == ref).mean() > 0.9  # (94 %): a 1-ulp bound that is not a loose one
    np.testing.assert_array_equal(r[:, 0].view(np.uint64), r[:, 1].view(np.uint64))


def test_acos_at_the_edges_is_libm(plain):
    """±1, ±0.5 and their neighbours, ±0, tiny and subnormal arguments: libm's numbers (acos 1
    = 0 exactly, acos -1 = pi, acos of a tiny x = pi/2)."""
    r = run_bits(plain, EDGES)
    np.testing.assert_array_equal(r[:, 0], _libm(EDGES))
    np.testing.assert_array_equal(r[:, 1], _libm(EDGES))


def test_acos_outside_its_domain_is_nan(plain):
    x = np.array([np.nextafter(1.0, 2.0), np.nextafter(-1.0, -2.0), 1.5, -3.0, 1e300, -1e300,
                  np.inf, -np.inf, np.nan, -np.nan])
    r = run_bits(plain, x)
    assert np.isnan(r).all()


@pytest.mark.slow  # (the lanes' runs are the scalar runs bit for bit: test_taylor_lanes*.py)
def test_acos_has_the_same_bits_in_the_lanes_build(tmp_path, plain, arguments):
    """The lanes driver's library is built with -march=native; its last samples must be the
    scalar driver's to the bit."""
    scalar = run_bits(plain, arguments)
    native = run_bits(_harness(tmp_path, [*DEFAULT_FLAGS, *NATIVE_FLAGS], "acos_native"), arguments)
    np.testing.assert_array_equal(scalar.view(np.uint64), native.view(np.uint64))
