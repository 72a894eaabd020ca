"""Generated C and NumPy against the notes' formulas typed by hand (tests/handwritten.py).

≥ 1000 random states per model, including states within 1e-8 of β = 0 and β = π; near the
poles the slides' own expressions cancel catastrophically in double precision, so there the
reference is the same hand-typed formula evaluated at 40 digits (mpmath).
"""
import ctypes
import importlib.util
import json
import os
import shutil
import subprocess
import sys
from importlib import metadata

import mpmath as mp
import numpy as np
import pytest

import compile_once
import handwritten as hw
from derive import generate
from derive.runtime.cbuild import compile_library
from derive.codegen.render import GENERATED, ROOT

N = 1000
RNG = np.random.default_rng(7)
MODELS = ("euler_free", "heavy_top", "heavy_top_reduced", "rigid_body")


def _numpy_module(name):
    spec = importlib.util.spec_from_file_location(f"gen_{name}", GENERATED / "numpy" / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


class CModel:
    """The committed generated/c/<name>.c compiled and loaded, called state by state."""

    def __init__(self, name):
        src = {f"{name}.h": (GENERATED / "c" / f"{name}.h").read_text(),
               f"{name}.c": (GENERATED / "c" / f"{name}.c").read_text()}
        self.lib = compile_library(f"test_{name}", src, f"{name}.c")
        self.mod = _numpy_module(name)
        D = ctypes.POINTER(ctypes.c_double)
        for fn in ("rhs", "jac"):
            f = getattr(self.lib, f"{name}_{fn}")
            f.argtypes = [ctypes.c_double, D, D, D]
            f.restype = ctypes.c_int
            setattr(self, f"_{fn}", f)
        at = self.lib[f"{name}_observables_at"]
        at.argtypes = [ctypes.c_long, D, D, D, D]
        at.restype = ctypes.c_int
        zero = np.zeros(1)
        # the outputs of one state: the output map over one sample
        self._observables = lambda t, y, p, out: at(1, zero.ctypes.data_as(D), y, p, out)

    def call(self, fn, y, p, n_out):
        y = np.ascontiguousarray(y, dtype=float)
        p = np.ascontiguousarray(p, dtype=float)
        out = np.empty(n_out)
        D = ctypes.POINTER(ctypes.c_double)
        status = getattr(self, f"_{fn}")(0.0, y.ctypes.data_as(D), p.ctypes.data_as(D), out.ctypes.data_as(D))
        return status, out


@pytest.fixture(scope="module", params=MODELS)
def cmodel(request):
    return CModel(request.param)


def close(a, b, rtol=1e-12):
    """|a − b| ≤ rtol·max(|b|, scale), the scale being the largest magnitude in the set."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = np.max(np.abs(b)) if b.size else 1.0
    return np.all(np.abs(a - b) <= rtol * np.maximum(np.abs(b), 1e-3 * scale))


def _betas(n):
    """Mostly generic tilts, a fifth within 1e-8 of each pole."""
    b = RNG.uniform(0.01, np.pi - 0.01, n)
    k = n // 5
    b[:k] = RNG.uniform(1e-12, 1e-8, k)
    b[k:2 * k] = np.pi - RNG.uniform(1e-12, 1e-8, k)
    return b


def test_euler_free_c_and_numpy_match_notes():
    c = CModel("euler_free")
    W = RNG.normal(size=(N, 3)) * 10
    P = RNG.uniform(0.5, 2.0, size=(N, 3))
    Fnp = c.mod.rhs(0.0, W.T, P.T).T
    for w, p, fnp in zip(W, P, Fnp):
        status, fc = c.call("rhs", w, p, 3)
        ref = hw.euler_free(np, *w, *p)
        assert status == 0
        assert close(fc, ref) and close(fnp, ref)


def test_heavy_top_c_and_numpy_match_notes_and_refuse_the_pole():
    c = CModel("heavy_top")
    betas = _betas(N)
    Y = np.column_stack([RNG.uniform(-3, 3, N), betas, RNG.uniform(-3, 3, N), RNG.normal(size=(N, 3)) * [2, 2, 30]])
    P = np.column_stack([RNG.uniform(0.5, 2, N), RNG.uniform(0.2, 1, N), RNG.uniform(0.1, 2, N),
                         np.full(N, 9.81), RNG.uniform(0.01, 0.5, N)])
    Fnp = c.mod.rhs(0.0, Y.T, P.T).T
    Onp = c.mod.observables(0.0, Y.T, P.T).T
    names = c.mod.OBSERVABLE_NAMES
    refused = 0
    for y, p, fnp, onp in zip(Y, P, Fnp, Onp):
        a, b, g, ad, bd, gd = y
        I1, I3, M, gg, l = p
        status, fc = c.call("rhs", y, p, 6)
        if np.sin(b) ** 2 <= np.finfo(float).eps:
            assert status != 0, "the Euler-angle kernel must refuse a state at its singularity"
            refused += 1
        else:
            assert status == 0
            ref = np.concatenate([[ad, bd, gd], hw.heavy_top_accel(np, b, ad, bd, gd, I1, I3, M, gg, l)])
            assert close(fc, ref) and close(fnp, ref)
        _, oc = c.call("observables", y, p, len(names))
        obs = dict(zip(names, oc))
        obs_np = dict(zip(names, onp))
        ref_obs = {
            "energy": hw.energy_lagrangian(np, b, ad, bd, gd, I1, I3, M, gg, l),
            "p_alpha": hw.p_alpha(np, b, ad, gd, I1, I3),
            "p_gamma": hw.p_gamma(np, b, ad, gd, I3),
        }
        w = hw.omega(np, a, b, g, ad, bd, gd)
        for k in range(3):
            ref_obs[f"omega{k + 1}"] = w[k]
        for key, ref in ref_obs.items():
            scale = abs(ref) + (abs(I3 * gd) if key == "p_alpha" else 0.0)
            assert abs(obs[key] - ref) <= 1e-12 * max(scale, 1e-300), key
            assert abs(obs_np[key] - ref) <= 1e-12 * max(scale, 1e-300), key
    assert refused >= N // 5


def test_heavy_top_reduced_keeps_full_precision_at_the_poles():
    """α̇, γ̇, β̈ and E of the reduced top vs the slides' formulas at 40 digits, with
    p_α = p_γ(1 + δ) (p_α = −p_γ(1 + δ) near π) and δ from 0 to 1e-6."""
    c = CModel("heavy_top_reduced")
    mp.mp.dps = 40
    betas = _betas(N)
    names = c.mod.OBSERVABLE_NAMES
    for i, b in enumerate(betas):
        I1, I3, M, g, l = RNG.uniform(0.5, 2), RNG.uniform(0.2, 1), RNG.uniform(0.1, 2), 9.81, RNG.uniform(0.01, 0.5)
        pg = RNG.uniform(1, 10)
        delta = 0.0 if i % 3 == 0 else RNG.uniform(-1, 1) * 10.0 ** RNG.uniform(-16, -6) * (b ** 2 if b < 1 else 1)
        pa = pg * (1 + delta) if b < np.pi / 2 else -pg * (1 + delta)
        y = np.array([0.3, b, -0.2, RNG.normal()])
        p = np.array([I1, I3, M, g, l, pa, pg])
        status, f = c.call("rhs", y, p, 4)
        _, obs = c.call("observables", y, p, len(names))
        assert status == 0 and np.all(np.isfinite(f))
        args = [mp.mpf(float(v)) for v in (b, pa, pg, I1, I3, M, g, l)]
        ad, gd, bdd = hw.reduced_rates(mp, *args)
        E = hw.energy_momenta(mp, args[0], mp.mpf(float(y[3])), *args[1:])
        ref = np.array([float(ad), y[3], float(gd), float(bdd)])
        assert close(f, ref, 1e-12), (b, delta, f, ref)
        assert abs(obs[names.index("energy")] - float(E)) <= 1e-12 * abs(float(E))
    f_np = c.mod.rhs(0.0, np.array([0.0, 1e-9, 0.0, 0.0]), np.array([1, 0.5, 1, 9.81, 0.1, 3.0, 3.0]))
    assert np.all(np.isfinite(f_np)), "NumPy kernel: removable 0·∞ at β → 0 with p_α = p_γ"


def test_rigid_body_matches_heavy_top_physics():
    """Quaternion model, centre of mass on axis 3, no damping: ω̃̇ equals the Euler-angle
    model's, mapped through ω̃ = B(q) q̇ (finite state set; exact same physics, other route)."""
    import sympy as sp
    from derive.symbolic.rotations import ANGLES, RATES, ZYZ

    rb = CModel("rigid_body")
    ht = CModel("heavy_top")
    w_of = sp.lambdify(ANGLES + RATES, list(ZYZ.omega_body_sum()))
    J_of = sp.lambdify(ANGLES + RATES, ZYZ.omega_body_sum().jacobian(sp.Matrix(ANGLES + RATES)))
    for _ in range(200):
        y = np.concatenate([RNG.uniform(0.2, 2.9, 3), RNG.normal(size=3) * [1, 1, 10]])
        I1, I3, M, g, l = RNG.uniform(1, 2), RNG.uniform(0.3, 1), 1.0, 9.81, RNG.uniform(0.05, 0.3)
        _, f = ht.call("rhs", y, [I1, I3, M, g, l], 6)
        wdot = np.asarray(J_of(*y), dtype=float) @ np.concatenate([y[3:], f[3:]])
        x = np.concatenate([quaternion(*y[:3]), w_of(*y)])
        _, frb = rb.call("rhs", x, [I1, I1, I3, M, g, 0.0, 0.0, l, 0.0], 7)
        assert close(frb[4:], wdot, 1e-11)


def test_jacobians_match_finite_differences(cmodel):
    mod = cmodel.mod
    ny, npar = mod.NY, mod.NP
    for _ in range(20):
        y = RNG.uniform(0.3, 1.2, ny)
        p = RNG.uniform(0.5, 1.5, npar)
        _, J = cmodel.call("jac", y, p, ny * ny)
        J = J.reshape(ny, ny)
        h = 1e-6
        fd = np.column_stack([(mod.rhs(0, y + h * e, p) - mod.rhs(0, y - h * e, p)) / (2 * h) for e in np.eye(ny)])
        np.testing.assert_allclose(J, fd, rtol=1e-6, atol=1e-6 * np.abs(fd).max())
        np.testing.assert_allclose(mod.jac(0, y, p), J, rtol=1e-13, atol=1e-14 * np.abs(J).max())


def test_numpy_kernels_vectorise_and_return_fresh_arrays(cmodel):
    from scipy.integrate import solve_ivp

    mod = cmodel.mod
    y = RNG.uniform(0.3, 1.2, (mod.NY, 5))
    p = RNG.uniform(0.5, 1.5, mod.NP)
    batch = mod.rhs(0.0, y, p)
    assert batch.shape == (mod.NY, 5)
    np.testing.assert_array_equal(batch[:, 2], mod.rhs(0.0, y[:, 2], p))
    a, b = mod.rhs(0.0, y[:, 0], p), mod.rhs(0.0, y[:, 0], p)
    assert a is not b and not np.shares_memory(a, b)
    sol = solve_ivp(mod.rhs, (0, 0.01), y[:, 0], args=(p,), rtol=1e-8)
    assert sol.success


def test_numpy_kernels_in_blocks_give_the_whole_batch_bit_for_bit(cmodel, monkeypatch):
    """A batch longer than BLOCK is evaluated block by block (cache-sized temporaries): the same
    values as in one go, for batched or shared states and parameters, a ragged last block and
    per-state times."""
    mod = cmodel.mod
    n = 2 * mod.BLOCK + 37
    y = RNG.uniform(0.3, 1.2, (mod.NY, n))
    p = RNG.uniform(0.5, 1.5, (mod.NP, n))
    t = RNG.uniform(0.0, 1.0, n)
    cases = [(0.0, y, p[:, 0]), (0.0, y, p), (t, y, p), (0.0, y[:, :1], p), (0.0, y[:, 0], p)]
    blocked = [[f(*args) for f in (mod.rhs, mod.jac, mod.observables)] for args in cases]
    monkeypatch.setattr(mod, "BLOCK", 10 * n)  # one go
    for args, got in zip(cases, blocked):
        for f, g in zip((mod.rhs, mod.jac, mod.observables), got):
            whole = f(*args)
            assert g.shape == whole.shape and g.shape[-1] == n
            np.testing.assert_array_equal(g, whole)


def test_numpy_printing_takes_common_array_factors_out_and_multiplies_scalars_first():
    import sympy as sp

    from derive.codegen.kernelspec import array_ops_first, np_expr

    a, b, c, x, y, z = sp.symbols("a b c x y z")
    scalars = frozenset({a, b, c})
    assert np_expr(a * x + b * x, scalars) == "x*(a + b)"  # one pass over the batch, not three
    assert np_expr(x * y - 2 * x * z + y, scalars) == "y + x*(y - 2*z)"
    assert np_expr(a * b * c * x * y, scalars) == "(a*b*c)*x*y"  # a scalar, then the arrays
    assert np_expr(-x * y + a, scalars) == "a - x*y"  # no leading negation of an array
    rng = np.random.default_rng(3)
    exprs = [a * x + b * x - c * x * y + sp.sin(x) * y - sp.sin(x) * z / a,
             (a - b) * x ** 2 * y - x * y * z + c * y * z + x]
    for e in exprs:
        vals = dict(zip((a, b, c, x, y, z), rng.uniform(0.5, 2.0, 6)))
        assert float(array_ops_first(e, scalars).subs(vals)) == pytest.approx(float(e.subs(vals)), rel=1e-14)


#: One generated file of each template at -O2 in the default suite (some warnings need the
#: optimiser); every file at -O2 in `make test-slow`.
O2_SAMPLE = ("heavy_top.c", "heavy_top_solvers.c", "heavy_top_taylor.c", "reduced_u_sym_gravity.c",
             "euler_poisson_asym_splitting.c", "euler_free.c")


def _compile_strictly(files, flags):
    """Each of ``files`` compiled strictly with ``flags``, as its own translation unit, in two
    compiler runs side by side, each given half of the files (one driver per half, not one per
    file); the outcome is kept for these exact sources, flags and compiler (tests/compile_once.py)."""
    from concurrent.futures import ThreadPoolExecutor

    cc = os.environ.get("CC", "cc")
    for c_file in files:
        assert "Python.h" not in c_file.read_text()

    def build(work):
        def compile_some(some):
            # (-c with several files and no -o: each file's object is written to the working folder)
            return some, subprocess.run(
                [cc, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", *flags, "-c",
                 *(str(c_file) for c_file in some), "-I", str(GENERATED / "c")],
                capture_output=True, text=True, cwd=work)

        halves = [half for half in (files[0::2], files[1::2]) if half]
        with ThreadPoolExecutor(max_workers=2) as pool:
            for some, r in pool.map(compile_some, halves):
                assert r.returncode == 0, f"{', '.join(c_file.name for c_file in some)}:\n{r.stderr}"
        for o in work.glob("*.o"):  # (only the outcome is kept)
            o.unlink()

    compile_once.once(["strict", *flags, *(f.name for f in files)], compile_once.files_in(GENERATED / "c"),
                      build, cc)


def test_generated_c_compiles_cleanly_with_strict_warnings():
    """Every generated C file, strict C99 with every warning an error (the front end's
    warnings: -fsyntax-only), and one file of each template at -O2, where the optimiser's
    warnings (maybe-uninitialized, array bounds) come in."""
    files = sorted((GENERATED / "c").glob("*.c"))
    assert len(files) >= 8
    _compile_strictly(files, ["-fsyntax-only"])
    sample = [GENERATED / "c" / name for name in O2_SAMPLE]
    assert all(f.is_file() for f in sample)
    _compile_strictly(sample, ["-O2"])


def test_the_lanes_drivers_compile_cleanly_with_strict_warnings():
    """The Taylor lanes drivers, compiled only in the lanes' build (-DDERIVE_LANES, GNU C's
    vector types), strict at that build's flags (-O3 -march=native ...: the optimiser's
    warnings), in a unity file as derive builds them: the heavy top reduced (every rule of
    the heavy tops) and the rigid body (the quaternion's)."""
    from concurrent.futures import ThreadPoolExecutor

    from derive.runtime.cbuild import DEFAULT_FLAGS, NATIVE_FLAGS, STRICT_FLAGS

    cc = os.environ.get("CC", "cc")
    names = ["heavy_top_reduced", "rigid_body"]
    flags = [*STRICT_FLAGS, *DEFAULT_FLAGS, *NATIVE_FLAGS, "-DDERIVE_SELECT", "-DDERIVE_WITH_TAYLOR"]

    def build(work):
        def compile_one(name):
            unity = work / f"{name}_unit.c"
            unity.write_text("".join(f'#include "{name}{part}.c"\n' for part in ("", "_solvers", "_taylor")))
            obj = work / f"{name}.o"
            r = subprocess.run([cc, *flags, "-I", str(GENERATED / "c"), "-c", str(unity), "-o", str(obj)],
                               capture_output=True, text=True)
            return name, r, obj

        with ThreadPoolExecutor(max_workers=2) as pool:
            for name, r, obj in pool.map(compile_one, names):
                assert r.returncode == 0, f"{name}:\n{r.stderr}"
                symbols = subprocess.run(["nm", str(obj)], capture_output=True, text=True).stdout
                (work / f"{name}.symbols").write_text(symbols)
                obj.unlink()

    done = compile_once.once(["lanes", *flags, *names], compile_once.files_in(GENERATED / "c"), build, cc)
    for name in names:
        assert f"{name}_taylor_lanes" in (done / f"{name}.symbols").read_text()  # (the lanes were compiled)


@pytest.mark.slow
def test_every_generated_c_file_compiles_cleanly_at_O2():
    """Every generated C file, strict, at -O2 (~25 s of compiling)."""
    _compile_strictly(sorted((GENERATED / "c").glob("*.c")), ["-O2"])


def test_generated_dir_is_what_generate_writes(generated_files):
    """Every model, every contact law and shape, the reports, and no file left over: the
    committed folder is what ``make derive`` writes."""
    assert generate.stale(generated_files, GENERATED) == []


def test_generation_is_independent_of_hash_seed(generated_files):
    """A fresh process with a fixed hash seed renders the same sources as the run's own
    generate_all (whose processes' seeds pytest left random, or set otherwise). With the seed
    fixed, that process's output is a function of the package, its libraries and the seed, as
    ``generated_files`` is of the sources: it is kept for exactly these (``compile_once.once``)
    and derived again after any change to one, when ``generated_files`` is too."""
    seed = "12345" if os.environ.get("PYTHONHASHSEED") != "12345" else "0"
    env = dict(os.environ, PYTHONHASHSEED=seed)
    code = ("from derive.codegen import sources; from derive.symbolic import models; import sys, json;"
            "sys.stdout.write(json.dumps(sources.model_sources(models.CATALOGUE['heavy_top_reduced']())))")

    def derive_with_the_seed(work):
        r = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, cwd=ROOT,
                           check=True)
        (work / "sources.json").write_text(r.stdout)

    inputs = compile_once.files_under(ROOT / "derive", ROOT / "templates")
    what = [code, f"PYTHONHASHSEED={seed}", sys.version,
            *(f"{dist} {metadata.version(dist)}" for dist in ("numpy", "sympy", "jinja2")),
            repr(sorted((k, v) for k, v in os.environ.items() if k.startswith("SYMPY_")))]
    theirs = json.loads((compile_once.once(what, inputs, derive_with_the_seed) / "sources.json").read_text())
    assert "c/heavy_top_reduced.c" in theirs
    assert theirs == {name: generated_files.get(name) for name in theirs}


def test_generate_check_cli_reports_stale_file(tmp_path, capsys, monkeypatch, generated_files):
    """``generate --check`` names a file edited after generation and passes once it is restored
    (generation itself is the run's one derivation of every file)."""
    monkeypatch.setattr(generate, "generate_all", lambda **kw: dict(generated_files))
    out = tmp_path / "gen"
    shutil.copytree(GENERATED, out)
    target = out / "c" / "heavy_top_reduced.c"
    target.write_text(target.read_text() + "/* edited */\n")
    from derive import cli

    assert cli.main(["generate", "--check", "--out", str(out)]) == 1
    assert "heavy_top_reduced.c" in capsys.readouterr().out
    (out / "c" / "heavy_top_reduced.c").write_text((GENERATED / "c" / "heavy_top_reduced.c").read_text())
    assert cli.main(["generate", "--check", "--out", str(out)]) == 0


def test_generated_kernels_run_clean_under_address_and_undefined_sanitizers(tmp_path):
    from derive.runtime.cbuild import SANITIZE_FLAGS, check_compiles
    from derive.errors import CompilerError

    names = ("heavy_top", "heavy_top_reduced")
    files = {}
    for n in names:
        for suffix in (".h", ".c", "_solvers.h", "_solvers.c"):
            files[n + suffix] = (GENERATED / "c" / (n + suffix)).read_text()
    files["generated_main.c"] = (ROOT / "tests" / "c" / "generated_main.c").read_text()
    mains = ["generated_main.c"] + [f"{n}{s}" for n in names for s in (".c", "_solvers.c")]
    try:
        exe = check_compiles(files, mains, SANITIZE_FLAGS, executable=tmp_path / "run")
    except CompilerError as exc:
        if "asan" in str(exc).lower() or "sanitize" in str(exc).lower():
            pytest.skip(f"no sanitizer runtime: {exc}")
        raise
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=1", UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1")
    proc = subprocess.run([str(exe)], capture_output=True, text=True, env=env, timeout=120)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "runtime error" not in proc.stderr


def quaternion(a, b, c) -> np.ndarray:
    """q of R = Rz(α) Ry(β) Rz(γ), scalar first (the quaternion model's init map, in NumPy)."""
    def mul(p, q):
        p0, pv, q0, qv = p[0], p[1:], q[0], q[1:]
        return np.concatenate([[p0 * q0 - pv @ qv], p0 * qv + q0 * pv + np.cross(pv, qv)])

    return mul(mul(np.array([np.cos(a / 2), 0.0, 0.0, np.sin(a / 2)]),
                   np.array([np.cos(b / 2), 0.0, np.sin(b / 2), 0.0])),
               np.array([np.cos(c / 2), 0.0, 0.0, np.sin(c / 2)]))
