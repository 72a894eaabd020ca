"""The Taylor solvers' sin and cos of the cyclic angles: ``derive_sincos_poly``
(templates/c/libm.h.j2), arithmetic alone so that a block of samples vectorises, with libm
beyond its range. Compiled here in a small C harness that includes the generated solver of
``reduced_u_sym_gravity`` (its α and γ are such angles) and calls its block routine.

Checked: within 1 ulp of libm's sin and cos (and equal on almost every argument) from 1e-300 to
the range's end; libm's own numbers beyond it and for inf and nan; the same bits for a sample
alone, inside a block, and in the build of the lanes driver (``-march=native``)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from derive.runtime.cbuild import DEFAULT_FLAGS, NATIVE_FLAGS
from tests.bits_harness import PREFIX, compile_harness, run_bits, taylor_sizes, ulps

# (the Taylor solver alone: its block routine reads none of the model's other files)
HARNESS = r"""
#include "reduced_u_sym_gravity_taylor.c"
#include <stdio.h>

/* reads n doubles (as hex of their bits) from stdin; writes, per argument, the bits of sin and
 * cos from a block of 16 (the vectorised loop), from a block of 1 (the scalar epilogue). */
int main(void)
{
    static double vb[P_NV][P_KO], v1[P_NV][P_KO];
    double x[P_KB];
    unsigned long long bits;
    int n = 0, k;
    for (;;) {
        int got = scanf("%llx", &bits);
        if (got == 1)
            memcpy(&x[n++], &bits, sizeof bits);
        if (n == P_KB || (got != 1 && n > 0)) {
            for (k = 0; k < n; ++k)
                vb[2][k] = x[k];  /* gamma, the second angle: its pair at NW + 2, NW + 3 */
            TRIG_BLOCK(n, vb);
            for (k = 0; k < n; ++k) {
                unsigned long long a, b, c, d;
                v1[2][0] = x[k];
                TRIG_BLOCK(1, v1);
                memcpy(&a, &vb[P_NW + 2][k], 8);
                memcpy(&b, &vb[P_NW + 3][k], 8);
                memcpy(&c, &v1[P_NW + 2][0], 8);
                memcpy(&d, &v1[P_NW + 3][0], 8);
                printf("%016llx %016llx %016llx %016llx\n", a, b, c, d);
            }
            n = 0;
        }
        if (got != 1)
            return 0;
    }
}
"""


def _harness(tmp_path, flags, name):
    n = taylor_sizes("reduced_u_sym_gravity")
    return compile_harness(tmp_path, flags, name,
                           f"#define P_NV {n['NV']}\n#define P_KB DERIVE_T_KB\n#define P_KO DERIVE_T_KO\n"
                           f"#define P_NW {n['NW']}\n"
                           f"#define TRIG_BLOCK {PREFIX}trig_block\n" + HARNESS)


@pytest.fixture(scope="module")
def plain(tmp_path_factory):
    """The harness built with the libraries' flags, once for the tests that run it."""
    return _harness(tmp_path_factory.mktemp("trig"), [*DEFAULT_FLAGS], "trig")




def _libm(x: np.ndarray):
    """glibc's sin and cos (through :mod:`math`: NumPy may use its own SIMD routines)."""
    def one(f, z):
        return f(z) if math.isfinite(z) else math.nan
    return (np.array([one(math.sin, z) for z in x.tolist()]),
            np.array([one(math.cos, z) for z in x.tolist()]))




@pytest.fixture(scope="module")
def arguments():
    rng = np.random.default_rng(20)
    limit = 2.0 ** 19 * np.pi / 2
    parts = [rng.uniform(-s, s, 25_000) for s in (1e-6, 1.0, 10.0, 1e3, limit)]
    near = (np.arange(-2000, 2000) * np.pi / 2)  # next to the quadrants' edges
    parts += [near, np.nextafter(near, np.inf), np.nextafter(near, -np.inf),
              np.array([0.0, -0.0, 1e-300, -1e-300, 5e-324, limit * 0.999999, -limit * 0.999999])]
    return np.concatenate(parts)


def test_sincos_is_within_one_ulp_of_libm_and_the_same_alone_or_in_a_block(plain, arguments):
    r = run_bits(plain, arguments)
    s, c = _libm(arguments)
    assert ulps(r[:, 0], s).max() <= 1 and ulps(r[:, 1], c).max() <= 1
    # equal to libm on all but a few per cent, so a 1-ulp bound is not a loose one
    assert (r[:, 0] == s).mean() > 0.95 and (r[:, 1] == c).mean() > 0.95
    np.testing.assert_array_equal(r[:, 0].view(np.uint64), r[:, 2].view(np.uint64))
    np.testing.assert_array_equal(r[:, 1].view(np.uint64), r[:, 3].view(np.uint64))


def test_sincos_beyond_its_range_is_libm(plain):
    x = np.array([1e6, -1e6, 3e7, 1e300, -1e300, np.inf, -np.inf, np.nan])
    r = run_bits(plain, x)
    s, c = _libm(x)
    np.testing.assert_array_equal(r[:, 0], s)
    np.testing.assert_array_equal(r[:, 1], c)


@pytest.mark.slow  # (the lanes' runs are the scalar runs bit for bit: test_taylor_lanes*.py)
def test_sincos_has_the_same_bits_in_the_lanes_build(tmp_path, plain, arguments):
    """The lanes driver's library is built with -march=native: its last samples must be the
    scalar driver's to the bit, so the same arithmetic vectorised wider gives the same bits."""
    scalar = run_bits(plain, arguments)
    native = run_bits(_harness(tmp_path, [*DEFAULT_FLAGS, *NATIVE_FLAGS], "trig_native"), arguments)
    np.testing.assert_array_equal(scalar.view(np.uint64), native.view(np.uint64))


@pytest.mark.parametrize("gamma0", [0.0, 1.0e9])
def test_angles_beyond_the_polynomial_range_take_libm_in_a_run(gamma0):
    """The reference top (reduced-u) with γ starting at 1e9 rad, beyond sincos_poly's range
    (2^19 π/2): the run's blocks take trig_block's libm fallback, and the outputs made of
    cos γ, sin γ (ω1, ω2, L1, L2) agree with the output map of the written states to
    round-off, as they do from γ = 0 (the polynomial path)."""
    import derive
    from derive.bench.reference import reference_data
    data = reference_data(10.0)
    data["initial"] = dict(data["initial"], gamma=gamma0)
    data["simulate"] = dict(data["simulate"], method="taylor", rtol=1e-8, atol=1e-10,
                            samples=201)
    plan = derive.prepare(data).plan
    c = plan.candidates[0]
    out, y, p, st = c.kernel.simulate(plan.inputs, c.params, plan.t, c.args, c.pole_check)
    assert st["status"] == 0
    ref = c.kernel.outputs_at(plan.t, y, p)
    for j in (3, 4, 15, 16):
        scale = max(np.max(np.abs(ref[j])), 1.0)
        assert np.max(np.abs(out[j] - ref[j])) <= 1e-12 * scale, (j, gamma0)
