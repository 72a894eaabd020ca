"""The `derive` command line (also `python -m derive`).

Exit status: 0 success; 1 `generate --check` found stale files or `verify` found an unexpected
verdict (or, never expected, an internal error: ``error: internal error: <type>: <message>``);
2 bad input (one line on stderr: ``error: <file>: <key or table>: <what is wrong>``, also for an
output path that cannot be written); 3 numerical failure (one line saying where); 4 no working C
compiler; 130 interrupted (Ctrl-C: ``error: interrupted``); 143 terminated (SIGTERM during a
sweep: ``error: terminated``). Never a traceback. Warnings (NumPy's
RuntimeWarnings among them) are not shown: a numerical failure is the one exit-3 line.
"""
from __future__ import annotations

import argparse
import os
import sys
import warnings
from pathlib import Path

from .errors import CompilerError, IntegrationError, SceneError, Terminated

EXIT_OK, EXIT_DIFF, EXIT_INPUT, EXIT_NUMERIC, EXIT_COMPILER = 0, 1, 2, 3, 4
EXIT_INTERNAL, EXIT_INTERRUPTED, EXIT_TERMINATED = 1, 130, 143


def _cmd_generate(args) -> int:
    from . import codegen
    from .render import CHECKOUT, GENERATED

    if not args.out and CHECKOUT is None and not args.check:
        # Installed package: its generated/ copy lives in site-packages and is not ours to rewrite.
        print("error: derive generate: --out: required when derive runs from an installed package "
              "(no source checkout to write generated/ into)", file=sys.stderr)
        return EXIT_INPUT
    out = Path(args.out) if args.out else GENERATED
    files = codegen.generate_all()
    if args.check:
        stale = codegen.stale(files, out)
        for rel in stale:
            print(f"stale: {out / rel}")
        return EXIT_DIFF if stale else EXIT_OK
    if args.out and out.resolve() != GENERATED.resolve():
        # codegen.write removes files it no longer produces: in a directory of the user's
        # choosing that would delete their files. Refuse instead of deleting.
        foreign = [rel for rel in codegen.stale(files, out) if rel not in files]
        if foreign:
            shown = ", ".join(foreign[:3]) + (f" and {len(foreign) - 3} more" if len(foreign) > 3 else "")
            print(f"error: derive generate: --out: {out} holds {len(foreign)} files derive does not "
                  f"generate ({shown}); name an empty or new directory", file=sys.stderr)
            return EXIT_INPUT
    written = codegen.write(files, out)
    print(f"generated {len(files)} files in {out} ({len(written)} changed)")
    if args.verify:
        return _cmd_verify(argparse.Namespace(format="text"))
    return EXIT_OK


def _cmd_verify(args) -> int:
    from . import verify

    print(verify.table(args.format))
    wrong = verify.mismatches()
    for claim, expected, got in wrong:
        print(f"unexpected verdict: {claim}: {got} (expected {expected})", file=sys.stderr)
    return EXIT_DIFF if wrong else EXIT_OK


#: `derive simulate` flags that override the scene's [simulate] keys (flag dest -> scene key).
SIMULATE_OVERRIDES = ("method", "rtol", "atol", "formulation", "h", "max_steps")


def _cmd_simulate(args) -> int:
    import json
    import time

    from .outputs import check_paths
    from .simulation import simulate, write_outputs

    check_paths([args.output, args.plot])  # before the work: a bad path is known in advance
    overrides = {k: getattr(args, k) for k in SIMULATE_OVERRIDES if getattr(args, k) is not None}
    start = time.perf_counter()
    res = simulate(args.scene, **overrides)
    wall = time.perf_counter() - start
    write_outputs(res, npz=args.output, png=args.plot)
    if args.json:
        print(json.dumps(simulate_summary(res, wall, npz=args.output, png=args.plot)))
        return EXIT_OK
    print(f"{res.method} / {res.formulation}: {len(res.t)} samples, {res.nfev} rhs evaluations"
          + (f" -> {args.output}" if args.output else "") + (f", {args.plot}" if args.plot else ""))
    return EXIT_OK


def simulate_summary(res, wall_time: float, npz: str | None = None, png: str | None = None) -> dict:
    """The one-line summary of ``derive simulate --json``.

    ``energy_drift`` = max_t |E(t) − E(0)| / |E(0)| over the output samples (max |E(t) − E(0)|
    when E(0) = 0; then ``energy_drift_relative`` is false). With damping this is the energy
    lost, not an error. ``wall_time`` is the `simulate` call in seconds (scene loading, model,
    kernel from cache or compiled, solve, outputs computed), not the file writing.
    """
    import numpy as np

    e = np.asarray(res.energy, dtype=float)
    e0 = float(e[0])
    dev = float(np.max(np.abs(e - e0)))
    relative = e0 != 0.0
    s = res.scene.simulate if res.scene is not None else None
    return {"method": res.method, "formulation": res.formulation, "nfev": int(res.nfev),
            "energy_drift": dev / abs(e0) if relative else dev, "energy_drift_relative": relative,
            "wall_time": wall_time, "samples": int(len(res.t)), "t_end": float(res.t[-1]),
            "rtol": None if s is None else s.rtol, "atol": None if s is None else s.atol,
            "outputs": {"npz": npz, "png": png}}


def _cmd_analyze(args) -> int:
    from .analysis import render

    print(render(args.scene, args.format), end="" if args.format == "markdown" else "\n")
    return EXIT_OK


def _cmd_bench(args) -> int:
    from . import bench

    bench.main(out=Path(args.out), quick=args.quick)
    return EXIT_OK


def version() -> str:
    """The installed distribution's version; a bare checkout falls back to ``derive.__version__``."""
    from importlib.metadata import PackageNotFoundError
    from importlib.metadata import version as dist_version

    try:
        return dist_version("derive")
    except PackageNotFoundError:
        from . import __version__

        return __version__


class _Version(argparse.Action):
    """--version, looked up only when asked for (importlib.metadata costs a warm run ~10 ms)."""

    def __call__(self, parser, namespace, values, option_string=None):
        print(f"{parser.prog} {version()}")  # stdout, like argparse's own version action
        parser.exit(0)


class _Parser(argparse.ArgumentParser):
    """argparse with the contract's one-line error (exit 2), not usage + message."""

    def error(self, message):
        self.exit(EXIT_INPUT, f"error: {self.prog}: {message}\n")


def _cmd_cache(args) -> int:
    from . import cbuild

    root = cbuild.cache_dir()
    try:
        if args.clear:
            count, size = cbuild.clear_cache(root)
            print(f"removed {count} entries ({_bytes(size)}) from {root}")
            return EXIT_OK
        entries = cbuild.cache_entries(root)
    except OSError as exc:
        raise SceneError(f"{root}: cache: {exc.strerror or exc}") from None
    where = "DERIVE_CACHE" if os.environ.get("DERIVE_CACHE") else "default; DERIVE_CACHE moves it"
    print(f"compile cache: {root} ({where})")
    shown = [e for e in entries if e.status != "checksum"]  # counted in the total below
    width = max((len(e.name) for e in shown), default=0)
    for e in shown:
        print(f"  {e.name:<{width}}  {_bytes(e.size):>9}  {e.status}")
    libs = sum(e.name.endswith(".so") for e in entries)
    print(f"{libs} libraries, {_bytes(sum(e.size for e in entries))}" if entries else "empty")
    return EXIT_OK


def _bytes(n: int) -> str:
    for unit in ("B", "kB", "MB"):
        if n < 1000 or unit == "MB":
            return f"{n:.0f} {unit}" if unit == "B" else f"{n:.1f} {unit}"
        n /= 1000
    return f"{n:.1f} GB"


def parser() -> argparse.ArgumentParser:
    from .scene import FORMULATIONS, METHODS

    p = _Parser(prog="derive", description=__doc__.splitlines()[0])
    p.add_argument("--version", action=_Version, nargs=0, help="print the version and exit")
    sub = p.add_subparsers(dest="command", required=True)

    g = sub.add_parser("generate", help="write generated/ (C and NumPy kernels, reports)")
    g.add_argument("--out", help="output directory (default: the checkout's generated/; required when "
                                 "derive is installed, except with --check, which then compares the "
                                 "package's own copy)")
    g.add_argument("--check", action="store_true", help="write nothing; exit 1 listing stale files")
    g.add_argument("--verify", action="store_true",
                   help="then print the lecture verification table (exit 1 on an unexpected verdict)")
    g.set_defaults(func=_cmd_generate)

    v = sub.add_parser("verify", help="check every formula of the lecture against the derivation")
    v.add_argument("--format", choices=("text", "markdown"), default="text",
                   help="text (aligned columns, default) or markdown (a table)")
    v.set_defaults(func=_cmd_verify)

    methods = "; ".join(f"{k}: {d}" for k, d in METHODS.items())
    s = sub.add_parser("simulate", help="simulate a scene file",
                       description=f"Simulate a scene. Methods: {methods}.")
    s.add_argument("scene", help="scene file (TOML)")
    s.add_argument("-o", "--output", help="output file (.npz)")
    s.add_argument("--plot", help="plot file (.png)")
    s.add_argument("--method", help=f"overrides [simulate] method; one of: {', '.join(METHODS)}")
    s.add_argument("--rtol", type=float, metavar="R",
                   help="overrides [simulate] rtol: relative tolerance of the adaptive methods")
    s.add_argument("--atol", type=float, metavar="A",
                   help="overrides [simulate] atol: absolute tolerance of the adaptive methods")
    s.add_argument("--formulation", help=f"overrides [simulate] formulation; one of: {', '.join(FORMULATIONS)}")
    s.add_argument("--h", type=float, metavar="H",
                   help="overrides [simulate] h: the step of the fixed-step methods, in seconds "
                        "(default: chosen from the scene's fastest natural period)")
    s.add_argument("--max-steps", type=int, metavar="N",
                   help="overrides [simulate] max_steps: the step budget (exit 3 when spent; "
                        "fixed-step runs needing more are refused up front)")
    s.add_argument("--json", action="store_true",
                   help="print a one-line JSON summary instead: method, formulation, nfev, "
                        "energy_drift (max |E - E0| / |E0|), wall_time (s), samples, t_end, rtol, "
                        "atol, outputs")
    s.set_defaults(func=_cmd_simulate)

    a = sub.add_parser("analyze", help="the lecture's analysis for a scene's body: energies, equations, "
                                       "cyclic coordinates, integrable case, equilibria and stability")
    a.add_argument("scene", help="scene file (TOML)")
    a.add_argument("--format", choices=("markdown", "json"), default="markdown",
                   help="markdown (LaTeX formulas, default) or json (the contract in docs/analyze.md)")
    a.set_defaults(func=_cmd_analyze)

    b = sub.add_parser("bench", help="work-precision report (Markdown table + PNG plots)")
    b.add_argument("-o", "--out", default="bench-out", help="output directory")
    b.add_argument("--quick", action="store_true", help="fewer tolerances and repeats")
    b.set_defaults(func=_cmd_bench)

    w = sub.add_parser("sweep", help="a parameter sweep: many points of one scene, measured while "
                                     "integrating (docs/sweeps.md)")
    w.add_argument("sweep", help="sweep file (TOML)")
    w.add_argument("-o", "--output", required=True, help="results (.parquet, one row per point)")
    w.add_argument("--plot", default=None, help="map (2-D sweep) or line (1-D) as PNG")
    w.add_argument("--measure", default=None, help="the measure to plot (added if the file has not it)")
    engine = w.add_mutually_exclusive_group()
    engine.add_argument("--workers", type=int, default=None,
                        help="start a Dask LocalCluster with N worker processes (TLS, loopback "
                             "only; at most 4 per core and 256 MB of available memory each)")
    engine.add_argument("--scheduler", default=None, help="address of a running Dask scheduler "
                                                          "(tcp://host:port or tls://host:port)")
    w.add_argument("--scheduler-timeout", type=float, default=None, metavar="S",
                   help="seconds to reach --scheduler, and again for its first worker (default 5)")
    w.add_argument("--dashboard", action="store_true",
                   help="with --workers: serve Dask's dashboard on 127.0.0.1 (address on stderr)")
    w.set_defaults(func=lambda args: __import__("derive.sweeps", fromlist=["cli"]).cli(args))

    c = sub.add_parser("cache", help="where compiled kernels are cached (DERIVE_CACHE) and what is there")
    c.add_argument("--clear", action="store_true", help="remove every cached library")
    c.set_defaults(func=_cmd_cache)
    return p


def main(argv=None) -> int:
    """Run the command line; returns the exit status. Every failure is one ``error:`` line on
    stderr: warnings are silenced, Ctrl-C is exit 130, anything unforeseen exit 1."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return _main(argv)
    except Terminated:  # SIGTERM during a sweep, cleaned up as Ctrl-C is
        return _fail("terminated", EXIT_TERMINATED)
    except KeyboardInterrupt:
        return _fail("interrupted", EXIT_INTERRUPTED)
    except BrokenPipeError:  # e.g. `derive verify | head`: the reader left; stop quietly
        try:
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        except (OSError, ValueError, AttributeError):
            pass
        return EXIT_INTERNAL
    except MemoryError:
        return _fail("out of memory", EXIT_NUMERIC)
    except Exception as exc:  # last resort: a bug, but never a traceback
        return _fail(f"internal error: {type(exc).__name__}: {_one_line(exc)}", EXIT_INTERNAL)


def _one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split())
    return text if len(text) <= 300 else text[:297] + "..."


def _fail(message: str, code: int) -> int:
    try:
        print(f"error: {message}", file=sys.stderr, flush=True)
    except (OSError, ValueError):
        pass
    return code


def _main(argv) -> int:
    p = parser()
    try:
        args = p.parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on bad flags already; keep its code
        return int(exc.code or 0)
    try:
        return args.func(args)
    except SceneError as exc:
        return _fail(_one_line(exc), EXIT_INPUT)
    except IntegrationError as exc:
        return _fail(_one_line(exc), EXIT_NUMERIC)
    except CompilerError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_COMPILER
