"""The Taylor solvers' output map over a block of samples: ``<prefix>outputs_block``
(templates/c/taylor.c.j2, printed by ``derive.codegen.taylor._BlockPrinter``), a loop gcc
vectorises: the parameters' part computed before it, each piecewise term a select on the bits
of values computed unconditionally.

The reference is the map as the model's C prints it, one sample at a time: the same CSE, the
piecewise terms C conditionals (``(c) ? (a) : (b)``), the same acos (``derive_acos_poly``,
tested against libm in tests/test_taylor_acos.py). For every shipped model with a Taylor output
map, on random states and columns with exact 0, ±1 among them and parameters with
p_alpha = ±p_gamma (the guarded poles of the reduced tops, where the branch not taken is 0/0),
the block's outputs have the reference's bits — or are NaN where it is — whether a sample is
alone or in a block of 16, in the default build and the vector build (``-march=native``, what single
runs use at every block size; the lanes build's map, one sample at a time, is checked against
the scalar driver by tests/test_taylor_lanes.py); and
``<prefix>outputs_block_trig``, which computes the cyclic angles' sin and cos in its own loop, has
the bits of ``<prefix>trig_block`` followed by the map."""
from __future__ import annotations

import math
import os
import subprocess

import numpy as np
import pytest
import sympy as sp

from derive.codegen.jet import decompose
from derive.codegen.kernelspec import Block, CPrinter, KernelSpec
from derive.codegen.sources import shipped_keys
from derive.codegen.taylor import _pointwise
from derive.runtime.cbuild import DEFAULT_FLAGS, VECTOR_FLAGS
from derive.symbolic.models import build
from tests.bits_harness import GEN, compile_harness, run_bits

# the vector and lanes builds are only what they are at derive's own optimisation level
pytestmark = pytest.mark.optimised


class _RefPrinter(CPrinter):
    """The model's own printing (Piecewise as C conditionals), acos as the block's."""

    def __init__(self, prefix):
        super().__init__()
        self.prefix = prefix

    def _print_acos(self, expr):
        return f"derive_acos_poly({self._print(expr.args[0])})"


def _reference(model, d, prefix) -> str:
    """The output map one sample at a time, as ``<prefix>outputs_pointwise`` printed it."""
    pw = _pointwise(model, d)
    block = Block.of([e for _, e in d.pointwise], "x")
    pr = _RefPrinter(prefix)
    lines = ["static void ref_map(double t, const double *y, const double *p, double *o)", "{"]
    lines += [f"    const double {s} = y[{i}];" for i, s in pw["states"] + pw["columns"]]
    lines += [f"    const double {s} = p[{i}];" for i, s in pw["params"]]
    lines += ["    (void)t;", "    (void)y;", "    (void)p;"]
    lines += [f"    const double {n} = {pr.doprint(e)};" for n, e in block.temps]
    lines += [f"    o[{j}] = {pr.doprint(e)};" for (j, _), e in zip(d.pointwise, block.outputs)]
    return "\n".join(lines + ["}"])


HARNESS = r"""
#include <stdio.h>

static double rd(void)
{
    unsigned long long b;
    double x;
    if (scanf("%llx", &b) != 1)
        return 0.0;
    memcpy(&x, &b, sizeof x);
    return x;
}

static void wr(double x)
{
    unsigned long long b;
    memcpy(&b, &x, sizeof b);
    printf("%016llx ", b);
}

/* stdin: NP parameters, the number of samples n, then n samples of NV values and a time.
 * stdout, per sample: the reference's outputs, the block's (blocks of 16), the block's alone;
 * with TRIG, then the block's after trig_block and the block map computing those itself. */
int main(void)
{
    static double vb[NV][KO], v1[NV][KO], ob[NOBS][KB], o1[NOBS][KB], vt[NV][KO], ot[NOBS][KB],
        of[NOBS][KB];
    double p[NP], y[NV], tb[KB], ref[NOBS];
    long n, s, k0;
    int i, j, k, nb;
    for (i = 0; i < NP; ++i)
        p[i] = rd();
    n = (long)rd();
    for (k0 = 0; k0 < n; k0 += KB) {
        nb = n - k0 < KB ? (int)(n - k0) : KB;
        for (k = 0; k < nb; ++k) {
            for (i = 0; i < NV; ++i)
                vb[i][k] = rd();
            tb[k] = rd();
        }
        BLOCK(nb, tb, vb, p, ob);
#ifdef TRIG
        memcpy(vt, vb, sizeof vt);
        TRIG(nb, vt);
        BLOCK(nb, tb, vt, p, ot);
        BLOCK_TRIG(nb, tb, vb, p, of);
#endif
        for (k = 0; k < nb; ++k) {
            for (i = 0; i < NV; ++i)
                y[i] = v1[i][0] = vb[i][k];
            BLOCK(1, tb + k, v1, p, o1);
            ref_map(tb[k], y, p, ref);
            for (j = 0; j < NOBS; ++j)
                wr(ref[j]);
            for (j = 0; j < NOBS; ++j)
                wr(ob[j][k]);
            for (j = 0; j < NOBS; ++j)
                wr(o1[j][0]);
#ifdef TRIG
            for (j = 0; j < NOBS; ++j)
                wr(ot[j][k]);
            for (j = 0; j < NOBS; ++j)
                wr(of[j][k]);
#endif
            printf("\n");
        }
    }
    (void)s;
    return 0;
}
"""


def _harness(tmp_path, name, flags, model, d):
    m = model.name
    prefix = f"derive_{m}_taylor_"
    nv = len(model.states) + len(d.columns) + 2 * len(d.trig)
    nobs = len(d.pointwise)
    rows = ", ".join(f"(o)[{j}]" for j in range(nobs))
    return compile_harness(tmp_path, flags, name,
        # the Taylor solver alone: its output map reads none of the model's other files
        f'#include "{m}_taylor.c"\n'
        f"#define NV {nv}\n#define KB DERIVE_T_KB\n#define KO DERIVE_T_KO\n#define NP {m}_NP\n#define NOBS {nobs}\n"
        f"#define BLOCK(nb, tb, v, p, o) {prefix}outputs_block(nb, tb, v, p, {rows})\n"
        + (f"#define TRIG {prefix}trig_block\n"
           f"#define BLOCK_TRIG(nb, tb, v, p, o) {prefix}outputs_block_trig(nb, tb, v, p, {rows})\n"
           if d.trig else "")
        + _reference(model, d, prefix) + HARNESS)


def _inputs(model, d, rng, n=400):
    """Parameter sets (random, then p_alpha = p_gamma, = -p_gamma, both 0 where the model has
    them) and n samples each: NV values in [-1.5, 1.5], a third of them exactly 0, 1 or -1."""
    nv = len(model.states) + len(d.columns) + 2 * len(d.trig)
    names = [str(s) for s in model.params]
    base = rng.uniform(0.5, 2.0, len(names))
    sets = [base]
    if "p_alpha" in names and "p_gamma" in names:
        a, g = names.index("p_alpha"), names.index("p_gamma")
        for pa in (base[g], -base[g], 0.0):
            q = base.copy()
            q[a] = pa
            q[g] = base[g] if pa else 0.0
            sets.append(q)
    samples = rng.uniform(-1.5, 1.5, (n, nv + 1))
    exact = rng.random((n, nv)) < 1 / 3
    samples[:, :nv][exact] = rng.choice([0.0, 1.0, -1.0], exact.sum())
    return sets, samples


def _run(exe, p, samples) -> np.ndarray:
    """The harness's rows as bits (the parameters, the count, then the samples in)."""
    vals = list(p) + [float(len(samples))] + list(samples.ravel())
    return run_bits(exe, np.array(vals)).view(np.uint64)


def _same(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Equal bits, or both NaN."""
    fa, fb = a.view(np.float64), b.view(np.float64)
    return (a == b) | (np.isnan(fa) & np.isnan(fb))


MODELS = [m for m in shipped_keys() if (GEN / f"{m}_taylor.c").exists()]
#: The model checked in ``make test`` (the heavy top: every rule of the tops); every other model
#: in ``make test-slow``.
FAST_MODELS = ("heavy_top",)


@pytest.mark.parametrize("name", [m if m in FAST_MODELS else pytest.param(m, marks=pytest.mark.slow) for m in MODELS])
def test_the_block_map_is_the_conditional_map_bit_for_bit(tmp_path, name):
    model = build(*shipped_keys()[name])
    d = decompose(KernelSpec.of(model), outputs=True)
    if not d.pointwise:
        pytest.skip("no output map from the series")
    nobs = len(d.pointwise)
    rng = np.random.default_rng(20)
    sets, samples = _inputs(model, d, rng)
    builds = [_harness(tmp_path, "plain", [*DEFAULT_FLAGS], model, d),
              _harness(tmp_path, "vector", [*DEFAULT_FLAGS, *VECTOR_FLAGS], model, d)]
    for p in sets:
        runs = [_run(exe, p, samples) for exe in builds]
        for r in runs:
            ref, blk, one = r[:, :nobs], r[:, nobs:2 * nobs], r[:, 2 * nobs:3 * nobs]
            assert _same(blk, ref).all(), (name, p, np.argwhere(~_same(blk, ref))[:5])
            assert _same(one, ref).all(), (name, p)
        for r in runs[1:]:
            np.testing.assert_array_equal(runs[0], r)
        if d.trig:  # the map with its own sin and cos: trig_block's, then the map, to the bit
            r = runs[0]
            assert _same(r[:, 4 * nobs:], r[:, 3 * nobs:4 * nobs]).all(), name


SELECTS = r"""
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static inline double derive_select(uint64_t m, double a, double b)
{
    uint64_t ia, ib;
    memcpy(&ia, &a, sizeof ia);
    memcpy(&ib, &b, sizeof ib);
    ia = (ia & m) | (ib & ~m);
    memcpy(&a, &ia, sizeof a);
    return a;
}

int main(void)
{
    const double a = A;
    const double xs[6] = {0.0, -0.0, 1.0, -2.0, INFINITY, NAN};
    double r[6];
ONCE
    int k;
    for (k = 0; k < 6; ++k) {
        const double x = xs[k];
EACH
        r[k] = OUT;
    }
    for (k = 0; k < 6; ++k)
        printf("%.17g\n", r[k]);
    return 0;
}
"""


@pytest.mark.parametrize("a, expected", [
    (0.0, [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),      # the guard holds: 0, also where a/x is 0/0
    (3.0, [math.inf, -math.inf, 4.0, -0.5, math.inf, "nan"]),  # a/x + (x if x > 0 else 1)
])
def test_a_guarded_term_is_the_guards_value_where_the_other_branch_is_singular(tmp_path, a,
                                                                              expected):
    """The selects themselves: a guard on a parameter (hoisted out of the loop) and a condition
    on the sample (in it). At a = 0 the guarded a/x is 0/0 at x = 0 (and NaN at x = nan): the
    output is the guard's 0, not NaN."""
    from derive.codegen.taylor import _BlockPrinter
    ap, x = sp.Symbol("a"), sp.Symbol("x")
    e = sp.Piecewise((0, sp.Eq(ap, 0)), (ap / x + sp.Piecewise((x, x > 0), (1, True)), True))
    pr = _BlockPrinter([ap])
    out = pr.doprint(e)
    once = "\n".join(f"    const {ty} {n} = {t};" for ty, n, t in pr.once)
    each = "\n".join(f"        const {ty} {n} = {t};" for ty, n, t in pr.each)
    assert any("a == 0" in t for _, _, t in pr.once)  # the guard: before the loop
    assert any("x > 0" in t for _, _, t in pr.each)   # the sample's condition: in it
    src = tmp_path / "sel.c"
    src.write_text(SELECTS.replace("ONCE", once).replace("EACH", each).replace("OUT", out)
                   .replace("const double a = A;", f"const double a = {a!r};"))
    exe = tmp_path / "sel"
    cc = os.environ.get("CC", "cc")
    subprocess.run([cc, *DEFAULT_FLAGS, "-Wall", "-Wextra", "-Werror", "-pedantic", str(src),
                    "-o", str(exe), "-lm"], check=True, capture_output=True, text=True)
    got = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout.split()
    for g, want in zip(got, expected):
        if want == "nan":
            assert g in ("nan", "-nan")
        else:
            assert str(float(g)) == str(float(want)), (got, expected)  # (the sign of 0 too)
