"""The `derive` command line (also `python -m derive`).

Exit status: 0 success; 1 `generate --check` found stale files or `verify` found an unexpected
verdict; 2 bad input (one line on stderr: ``error: <file>: <key or table>: <what is wrong>``);
3 numerical failure (one line saying where); 4 no working C compiler.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .errors import CompilerError, IntegrationError, SceneError

EXIT_OK, EXIT_DIFF, EXIT_INPUT, EXIT_NUMERIC, EXIT_COMPILER = 0, 1, 2, 3, 4


def _cmd_generate(args) -> int:
    from . import codegen
    from .render import GENERATED

    out = Path(args.out) if args.out else GENERATED
    files = codegen.generate_all()
    if args.check:
        stale = codegen.stale(files, out)
        for rel in stale:
            print(f"stale: {out / rel}")
        return EXIT_DIFF if stale else EXIT_OK
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


def _cmd_simulate(args) -> int:
    from .simulation import simulate, write_outputs

    overrides = {k: getattr(args, k) for k in ("method", "rtol", "atol", "formulation") if getattr(args, k) is not None}
    res = simulate(args.scene, **overrides)
    write_outputs(res, npz=args.output, png=args.plot)
    print(f"{res.method} / {res.formulation}: {len(res.t)} samples, {res.nfev} rhs evaluations"
          + (f" -> {args.output}" if args.output else "") + (f", {args.plot}" if args.plot else ""))
    return EXIT_OK


def _cmd_bench(args) -> int:
    from . import bench

    bench.main(out=Path(args.out), quick=args.quick)
    return EXIT_OK


def parser() -> argparse.ArgumentParser:
    from .scene import FORMULATIONS, METHODS

    p = argparse.ArgumentParser(prog="derive", description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="command", required=True)

    g = sub.add_parser("generate", help="write generated/ (C and NumPy kernels, reports)")
    g.add_argument("--out", help="output directory (default: the repository's generated/)")
    g.add_argument("--check", action="store_true", help="write nothing; exit 1 listing stale files")
    g.add_argument("--verify", action="store_true",
                   help="then print the lecture verification table (exit 1 on an unexpected verdict)")
    g.set_defaults(func=_cmd_generate)

    v = sub.add_parser("verify", help="check every formula of the lecture against the derivation")
    v.add_argument("--format", choices=("text", "markdown"), default="text")
    v.set_defaults(func=_cmd_verify)

    methods = "; ".join(f"{k}: {d}" for k, d in METHODS.items())
    s = sub.add_parser("simulate", help="simulate a scene file",
                       description=f"Simulate a scene. Methods: {methods}.")
    s.add_argument("scene", help="scene file (TOML)")
    s.add_argument("-o", "--output", help="output file (.npz)")
    s.add_argument("--plot", help="plot file (.png)")
    s.add_argument("--method", help=f"one of: {', '.join(METHODS)}")
    s.add_argument("--rtol", type=float)
    s.add_argument("--atol", type=float)
    s.add_argument("--formulation", help=f"one of: {', '.join(FORMULATIONS)}")
    s.set_defaults(func=_cmd_simulate)

    b = sub.add_parser("bench", help="work-precision report (Markdown table + PNG plots)")
    b.add_argument("-o", "--out", default="bench-out", help="output directory")
    b.add_argument("--quick", action="store_true", help="fewer tolerances and repeats")
    b.set_defaults(func=_cmd_bench)
    return p


def main(argv=None) -> int:
    p = parser()
    try:
        args = p.parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on bad flags already; keep its code
        return int(exc.code or 0)
    try:
        return args.func(args)
    except SceneError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_INPUT
    except IntegrationError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_NUMERIC
    except CompilerError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_COMPILER
