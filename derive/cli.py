"""The `derive` command line (also `python -m derive`).

Exit status: 0 success; 1 `generate --check` found stale files or `verify` found an unexpected
verdict (or, never expected, an internal error: ``error: internal error: <type>: <message>``);
2 bad input (one line on stderr: ``error: <file>: <key or table>: <what is wrong>``, also for an
output path that cannot be written); 3 numerical failure (one line saying where); 4 no working C
compiler; 130 interrupted (Ctrl-C: ``error: interrupted``); 143 terminated (SIGTERM during a
sweep: ``error: terminated``). Never a traceback. Warnings (NumPy's
RuntimeWarnings among them) are not shown: a numerical failure is the one exit-3 line.

A step that takes more than a second (deriving a model not shipped in generated/, compiling a
kernel, `analyze`, `verify`, `generate`) is announced by one line ``note: <what>`` on stderr
when stderr is a terminal, as git shows its progress: a pipe or a file (a script, CI) gets
nothing but the one ``error:`` line of a failure, and stdout only the result.
"""
from __future__ import annotations

import argparse
import gc
import os
import signal
import sys
import threading
import warnings
from pathlib import Path

from derive.errors import NOTE_STREAM, SIGNALLED, CompilerError, IntegrationError, SceneError, Terminated, note

EXIT_OK, EXIT_DIFF, EXIT_INPUT, EXIT_NUMERIC, EXIT_COMPILER = 0, 1, 2, 3, 4
EXIT_INTERNAL, EXIT_INTERRUPTED, EXIT_TERMINATED = 1, 130, 143


def _cmd_generate(args) -> int:
    from derive.codegen.render import CHECKOUT, GENERATED

    if not args.out and CHECKOUT is None and not args.check:
        # Installed package: its generated/ copy lives in site-packages and is not ours to rewrite
        # (refused before the generation's modules, SymPy among them, are imported).
        print("error: derive generate: --out: required when derive runs from an installed package "
              "(no source checkout to write generated/ into)", file=sys.stderr)
        return EXIT_INPUT
    from derive import generate
    out = Path(args.out) if args.out else GENERATED
    if args.out:
        _output_dir(out, "--out", create=not args.check)  # before the (slow) generation
    note(f"deriving every model and rendering every file, to {'compare with' if args.check else 'write'} "
         f"{out} (ten seconds or more)")
    files = generate.generate_all(cache=True)  # a fresh process: the cache's key covers its inputs
    if args.check:
        stale = generate.stale(files, out)
        for rel in stale:
            print(f"stale: {out / rel}")
        return EXIT_DIFF if stale else EXIT_OK
    if args.out and out.resolve() != GENERATED.resolve():
        # generate.write removes files it no longer produces: in a directory of the user's
        # choosing that would delete their files. Refuse instead of deleting.
        foreign = [rel for rel in generate.stale(files, out) if rel not in files]
        if foreign:
            shown = ", ".join(foreign[:3]) + (f" and {len(foreign) - 3} more" if len(foreign) > 3 else "")
            print(f"error: derive generate: --out: {out} holds {len(foreign)} files derive does not "
                  f"generate ({shown}); name an empty or new directory", file=sys.stderr)
            return EXIT_INPUT
    written = generate.write(files, out)
    print(f"generated {len(files)} files in {out} ({len(written)} changed)")
    if args.verify:
        return _cmd_verify(argparse.Namespace(format="text"))
    return EXIT_OK


def _cmd_verify(args) -> int:
    if getattr(args, "notes", None):
        return _cmd_verify_notes(args)
    for flag, value in (("--format", "json" if args.format == "json" else None),
                        ("--convention", getattr(args, "convention", None))):
        if value:
            raise SceneError(f"derive verify: {flag}: {value} needs a notes file (derive verify NOTES.md {flag} {value})")
    from derive.lecture import verify

    note("deriving the lecture's formulas with SymPy (a few seconds)")
    print(verify.table(args.format))
    wrong = verify.mismatches()
    for claim, expected, got in wrong:
        print(f"unexpected verdict: {claim}: {got} (expected {expected})", file=sys.stderr)
    return EXIT_DIFF if wrong else EXIT_OK


def _cmd_verify_notes(args) -> int:
    """``derive verify NOTES.md``: every formula of the notes against the derivation."""
    from derive.lecture import notes_check

    # The imported modules (SymPy's most of all) live as long as the command: kept out of the
    # collector's generations, they are not walked again by every full collection and at exit.
    gc.freeze()
    note("reading the notes and deriving their formulas with SymPy (a few seconds)")
    claims = notes_check.check_notes(args.notes, args.convention)
    sys.stdout.write(notes_check.render(claims, args.format, path=str(args.notes)))
    return notes_check.exit_status(claims)


#: `derive simulate` flags that override the scene's [simulate] keys (flag dest -> scene key).
SIMULATE_OVERRIDES = ("t_end", "samples", "method", "rtol", "atol", "formulation", "h", "max_steps")


def _cmd_simulate(args) -> int:
    import json
    import time

    from derive.sim.outputs import PLOT_FORMATS, RESULT_FORMATS, check_paths, output_format
    from derive.sim.simulation import simulate, write_outputs

    # Before the work: a bad path, one that would replace the scene, or an extension naming no
    # format we write is known in advance.
    check_paths([args.output, args.plot], inputs=[args.scene])
    output_format(args.output, "-o", RESULT_FORMATS)
    output_format(args.plot, "--plot", PLOT_FORMATS)
    overrides = {k: getattr(args, k) for k in SIMULATE_OVERRIDES if getattr(args, k) is not None}
    start = time.perf_counter()
    try:
        res = simulate(args.scene, **overrides)
    except SceneError as exc:
        raise _flag_named(exc, overrides) from None
    wall = time.perf_counter() - start
    write_outputs(res, npz=args.output, png=args.plot)
    if args.json:
        print(json.dumps(simulate_summary(res, wall, npz=args.output, png=args.plot)))
        return EXIT_OK
    print(f"{res.method} / {res.formulation}: {len(res.t)} samples, {res.nfev} rhs evaluations"
          + (f" -> {args.output}" if args.output else "") + (f", {args.plot}" if args.plot else ""))
    return EXIT_OK


def _flag_named(exc: SceneError, overrides) -> SceneError:
    """The scene's message for a bad override, naming the command-line flag it came from:
    ``... simulate.t_end: must be ... (given as --t-end)`` instead of "(given as an override)"."""
    import re

    text, suffix = str(exc), " (given as an override)"
    m = re.search(r": simulate\.(\w+): ", text)
    if text.endswith(suffix) and m and m.group(1) in overrides:
        return SceneError(f"{text[:-len(suffix)]} (given as --{m.group(1).replace('_', '-')})")
    return exc


def simulate_summary(res, wall_time: float, npz: str | None = None, png: str | None = None) -> dict:
    """The one-line summary of ``derive simulate --json``.

    ``energy_change`` = E(t_end) − E(0), J: the work the torques did over the run (a damping
    torque's is negative, a drive's what it supplied). ``energy_drift`` = max_t |E(t) − E(0)| /
    |E(0)| over the output samples (max |E(t) − E(0)| when E(0) = 0; then
    ``energy_drift_relative`` is false), the integration's error, reported only when the
    physics conserves the energy (every effect in the model has a potential and no torque);
    otherwise both are null, since E(t) − E(0) is then work done, not drift. ``wall_time`` is
    the `simulate` call in seconds (scene loading, model, kernel from cache or compiled, solve,
    outputs computed), not the file writing. ``model`` and ``effects`` name the kernel that ran
    and the effects in it (a table whose values make its effect vanish, ``[damping] c = 0``, is
    not among them).
    """
    import numpy as np

    from derive.symbolic import effects

    e = np.asarray(res.energy, dtype=float)
    e0 = float(e[0])
    dev = float(np.max(np.abs(e - e0)))
    relative = e0 != 0.0
    conserved = (res.conserves_energy if hasattr(res, "conserves_energy")  # contact hook: a top on a table
                 else all(effect.conservative for effect in effects.lookup(res.effects)))
    s = res.scene.simulate if res.scene is not None else None
    return {"method": res.method, "formulation": res.formulation, "model": res.model,
            "effects": list(res.effects), "nfev": int(res.nfev),
            "energy_drift": (dev / abs(e0) if relative else dev) if conserved else None,
            "energy_drift_relative": relative if conserved else None,
            "energy_change": float(e[-1] - e0),
            "wall_time": wall_time, "samples": int(len(res.t)), "t_end": float(res.t[-1]),
            "rtol": None if s is None else s.rtol, "atol": None if s is None else s.atol,
            "outputs": {"npz": npz, "png": png}}


def _cmd_analyze(args) -> int:
    from derive.lecture.analysis import render
    from derive.sim.scene import contact_data, load_scene

    found = contact_data(args.scene)  # -- contact hook: a top on a table, derive.contact's analysis --
    if found is not None:
        from derive.contact import analysis, scene as contact_scene

        sc = contact_scene.read(*found)
        note("deriving the contact's integrals and conditions with SymPy (a few seconds)")
        print(analysis.render(sc, args.format), end="" if args.format == "markdown" else "\n")
        return EXIT_OK  # -- end of the contact hook --
    scene = load_scene(args.scene)  # bad input is exit 2 at once, without the note
    note("deriving the equations, integrals and equilibria with SymPy (a few seconds)")
    print(render(scene, args.format), end="" if args.format == "markdown" else "\n")
    return EXIT_OK


def _cmd_export(args) -> int:
    if args.fmu is not None:
        from derive.export.fmu import export_fmu

        try:
            b = export_fmu(args.scene, args.fmu, method=args.method)
        except SceneError as exc:
            raise _flag_named(exc, {"method": args.method}) from None
        interfaces = getattr(b, "interfaces", "model exchange and co-simulation")  # contact hook
        print(f"exported {b.name} ({b.method}) as an FMI 2.0 FMU ({interfaces}) -> {args.fmu}")
        return EXIT_OK
    from derive.export.folder import export_folder
    from derive.sim.outputs import check_parent

    check_parent(args.out)  # the one rule of every output flag, before the work
    try:
        b = export_folder(args.scene, args.out, method=args.method)
    except SceneError as exc:
        raise _flag_named(exc, {"method": args.method}) from None
    print(f"exported {b.name} ({b.method}) -> {args.out} (make -C {args.out} builds ./example)")
    return EXIT_OK


def _cmd_animate(args) -> int:
    """``derive animate SCENE -o OUT``: the motion drawn in 3-D, as GIF, MP4 or HTML."""
    from derive.sim import animate
    from derive.sim.simulation import simulate

    # before the work: the suffix, ffmpeg for .mp4, the path, --fps and --speed
    animate.check_output(args.output, inputs=[args.scene])
    animate.motion.check_settings(args.fps, args.speed, names=("--fps", "--speed"))
    res = simulate(args.scene)
    fr = animate.write(res, args.output, fps=args.fps, speed=args.speed)
    print(f"{len(fr.t)} frames at {fr.fps} frames/s -> {args.output}")
    for line in fr.notes:
        print(f"  {line}")
    return EXIT_OK


def _cmd_bench(args) -> int:
    from derive.bench import suite as bench

    out = _output_dir(Path(args.out), "-o")  # before minutes of benchmarks, not after
    bench.main(out=out, quick=args.quick)
    return EXIT_OK


def _cmd_examples(args) -> int:
    from derive.sim import examples
    from derive.sim.outputs import check_parent

    if args.copy:
        check_parent(args.to)  # the one rule of every output flag
        try:
            made = examples.copy(args.copy, Path(args.to))
        except KeyError:
            hint = examples.did_you_mean(args.copy) or (
                f" (the examples: {', '.join(examples.names('scene') + examples.names('sweep'))})")
            raise SceneError(f"{args.copy}: --copy: not found among the examples{hint}") from None
        except FileExistsError as exc:
            raise SceneError(f"derive examples: --copy: {exc} exists; not overwritten") from None
        except OSError as exc:
            raise SceneError(f"derive examples: --to: {args.to}: {exc.strerror or exc}") from None
        print(f"copied {args.copy} to {made}")
        return EXIT_OK
    for kind, how in (("scene", "derive simulate NAME"), ("sweep", "derive sweep NAME -o out.parquet")):
        names = examples.names(kind)
        print(f"{kind}s ({how}):")
        width = max(map(len, names), default=0)
        for name in names:
            print(f"  {name:<{width}}  {examples.summary(examples.path(name, kind))}")
    print("copy one to edit: derive examples --copy NAME [--to DIR]")
    return EXIT_OK


def _output_dir(path: Path, flag: str, create: bool = True) -> Path:
    """``path`` as a directory the command may write into (made unless ``create`` is false);
    SceneError ``<path>: <flag>: <what>`` (exit 2) for a non-directory, a bad parent
    (:func:`derive.sim.outputs.check_parent`) or a directory that cannot be made or written."""
    from derive.sim.outputs import check_parent

    if "\0" in str(path):
        raise SceneError(f"{str(path)!r}: {flag}: not a directory name")
    check_parent(path)  # the one rule of every output flag: no folder above the output is made
    if path.exists() and not path.is_dir():
        raise SceneError(f"{path}: {flag}: not a directory (a file of that name exists)")
    if create:
        try:
            path.mkdir(exist_ok=True)
        except OSError as err:
            raise SceneError(f"{path}: {flag}: cannot create the directory "
                             f"({err.strerror or err})") from None
        if not os.access(path, os.W_OK | os.X_OK):
            raise SceneError(f"{path}: {flag}: permission denied (cannot write into it)")
    return path


def version() -> str:
    """The installed distribution's version; a bare checkout falls back to ``derive.__version__``."""
    from importlib.metadata import PackageNotFoundError
    from importlib.metadata import version as dist_version

    from derive import DISTRIBUTION, __version__

    try:
        return dist_version(DISTRIBUTION)
    except PackageNotFoundError:
        return __version__


class _Version(argparse.Action):
    """--version, looked up only when asked for (importlib.metadata is slow to import on a warm run)."""

    def __call__(self, parser, namespace, values, option_string=None):
        print(f"{parser.prog} {version()}")  # stdout, like argparse's own version action
        parser.exit(0)


class _Parser(argparse.ArgumentParser):
    """argparse with the contract's one-line error (exit 2), not usage + message."""

    def error(self, message):
        self.exit(EXIT_INPUT, f"error: {self.prog}: {message}\n")


def _cmd_cache(args) -> int:
    from derive.runtime import cache

    root = cache.cache_dir()
    try:
        if args.clear:
            count, size = cache.clear_cache(root)
            print(f"removed {count} entries ({_bytes(size)}) from {root}")
            return EXIT_OK
        entries = cache.cache_entries(root)
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


#: The commands whose help lists the methods, formulations or measures (their registries load
#: NumPy, the scene reader and the C toolchain's modules: the other commands' parsers skip them).
LISTING_COMMANDS = ("simulate", "export", "sweep")


def parser(command: str | None = None) -> argparse.ArgumentParser:
    """The command line's parser. With ``command`` (the first word of the command line) other
    than one of :data:`LISTING_COMMANDS`, the registries only those commands' help lists are not
    loaded (``derive verify`` starts without them); their parsers are not the one that runs."""
    if command is None or command in LISTING_COMMANDS:
        from derive.methods.registry import REFERENCE_METHODS
        from derive.sim.scene import FORMULATIONS, METHODS
        from derive.sweeps.measures import REGISTRY as MEASURES
    else:
        REFERENCE_METHODS, FORMULATIONS, METHODS, MEASURES = (), {}, {}, {}

    p = _Parser(prog="derive", description=__doc__.splitlines()[0])
    p.add_argument("--version", action=_Version, nargs=0, help="print the version and exit")
    sub = p.add_subparsers(dest="command", required=True)

    g = sub.add_parser("generate", help="derive every model and write generated/ (the C and NumPy "
                                        "kernels, the derivation and lecture reports)")
    g.add_argument("--out", metavar="DIR", help="output directory (default: the checkout's generated/; required when "
                                 "derive is installed, except with --check, which then compares the "
                                 "package's own copy)")
    g.add_argument("--check", action="store_true", help="write nothing; exit 1 listing stale files")
    g.add_argument("--verify", action="store_true",
                   help="then print the lecture verification table (exit 1 on an unexpected verdict)")
    g.set_defaults(func=_cmd_generate)

    v = sub.add_parser("verify", help="check every formula of the lecture (or of your own notes) against the derivation")
    v.add_argument("notes", nargs="?", default=None,
                   help="a Markdown file with LaTeX math to check (default: the lecture's curated table)")
    v.add_argument("--format", choices=("text", "markdown", "json"), default="text",
                   help="text (aligned columns, default), markdown (a table) or json (with a notes file)")
    v.add_argument("--convention", default=None, metavar="A-B-C",
                   help="the notes' angle sequence, any of the twelve proper Euler and Tait-Bryan ones "
                        "(z-y-z, z-x-z, z-y-x, ...; overrides their front matter; default z-y-z)")
    v.set_defaults(func=_cmd_verify)

    methods = "; ".join(f"{k}: {d}" for k, d in METHODS.items())
    s = sub.add_parser("simulate", help="simulate a scene: its motion as arrays (-o), a figure "
                                        "(--plot) or a one-line summary (--json)",
                       description=f"Simulate a scene. Methods: {methods}.")
    s.add_argument("scene", help="scene file (TOML), or the name of an example (derive examples)")
    s.add_argument("-o", "--output", help="output file: .npz (NumPy arrays) or .csv (a header row, "
                                          "a column per array component, the metadata as '# key: "
                                          "value' lines first), by its extension")
    s.add_argument("--plot", help="plot file: .png, .pdf or .svg, by its extension")
    s.add_argument("--t-end", type=float, metavar="T",
                   help="overrides [simulate] t_end: the end of the run, in seconds")
    s.add_argument("--samples", type=int, metavar="N",
                   help="overrides [simulate] samples: output times from 0 to t_end inclusive")
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
                        "energy_change (E(t_end) - E0: the work the torques did, J), energy_drift "
                        "(max |E - E0| / |E0|; null when the physics does not conserve E), "
                        "wall_time (s), samples, t_end, rtol, atol, outputs")
    s.set_defaults(func=_cmd_simulate)

    a = sub.add_parser("analyze", help="the lecture's analysis for a scene's body: energies, equations, "
                                       "cyclic coordinates, integrable case, equilibria and stability")
    a.add_argument("scene", help="scene file (TOML), or the name of an example (derive examples)")
    a.add_argument("--format", choices=("markdown", "json"), default="markdown",
                   help="markdown (LaTeX formulas, default) or json (the contract in docs/analyze.md)")
    a.set_defaults(func=_cmd_analyze)

    x = sub.add_parser("export", help="the scene's model as a self-contained C99 folder (--out) or an "
                                      "FMI 2.0 FMU (--fmu)", description="Export the model and method a "
                       "scene runs: --out DIR writes C99 sources, solvers, a Makefile, README.md, the JSON "
                       "description, the NumPy module and example.c (docs/export.md); --fmu OUT.fmu builds "
                       "an FMI 2.0 FMU for model exchange and co-simulation.")
    x.add_argument("scene", help="scene file (TOML), or the name of an example (derive examples)")
    where = x.add_mutually_exclusive_group(required=True)
    where.add_argument("--out", metavar="DIR", help="a new (or empty) directory to write the folder into")
    where.add_argument("--fmu", metavar="OUT.fmu", help="the FMU file to write")
    compiled = [m for m in METHODS if m not in REFERENCE_METHODS]  # export refuses SciPy's
    x.add_argument("--method", help=f"overrides [simulate] method; one of: {', '.join(compiled)}")
    x.set_defaults(func=_cmd_export)

    m = sub.add_parser("animate", help="watch the motion: the body turning in 3-D, as a GIF, an MP4 or "
                                       "a self-contained web page (docs/animate.md)",
                       description="Simulate a scene and draw its motion in 3-D: the body turning, the path "
                       "of its axis on the unit sphere, L, the vertical, the time and the angles. The "
                       "output's extension picks the format: .gif, .mp4 (ffmpeg) or .html (offline).")
    m.add_argument("scene", help="scene file (TOML), or the name of an example (derive examples)")
    m.add_argument("-o", "--output", required=True,
                   help="the animation: .gif, .mp4 (needs ffmpeg on PATH) or .html, by its extension")
    m.add_argument("--fps", type=int, metavar="N", help="frames per second, 1 to 50 (default 20)")
    m.add_argument("--speed", type=float, metavar="X",
                   help="simulated seconds per second on screen (default: chosen from the motion)")
    m.set_defaults(func=_cmd_animate)

    b = sub.add_parser("bench", help="the work-precision report: every method against SciPy on the "
                                     "example scenes (Markdown tables and PNG plots; minutes)")
    b.add_argument("-o", "--out", default="bench-out", metavar="DIR",
                   help="the directory to write the report into (made if missing; its parent must exist)")
    b.add_argument("--quick", action="store_true", help="fewer tolerances and repeats")
    b.set_defaults(func=_cmd_bench)

    w = sub.add_parser("sweep", help="a parameter sweep: many points of one scene, measured while "
                                     "integrating (docs/sweeps.md)")
    w.add_argument("sweep", help="sweep file (TOML), or the name of an example (derive examples)")
    w.add_argument("-o", "--output", required=True,
                   help="results, one row per point: .parquet or .csv, by its extension")
    w.add_argument("--plot", default=None,
                   help="map (2-D sweep) or line (1-D): .png, .pdf or .svg, by its extension")
    w.add_argument("--measure", default=None, metavar="NAME",
                   help="the measure to plot, also computed when the sweep file does not ask for it; "
                        f"one of: {', '.join(MEASURES)} (docs/sweeps.md)")
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
    w.set_defaults(func=lambda args: __import__("derive.sweeps.engine", fromlist=["cli"]).cli(args))

    e = sub.add_parser("examples", help="list the example scenes and sweeps (run one by its name), "
                                        "or copy one out to edit")
    e.add_argument("--copy", metavar="NAME", help="copy the example NAME (a sweep: with its scene)")
    e.add_argument("--to", default=".", metavar="DIR", help="where --copy puts it (default: here)")
    e.set_defaults(func=_cmd_examples)

    c = sub.add_parser("cache", help="where compiled kernels are cached (DERIVE_CACHE) and what is there")
    c.add_argument("--clear", action="store_true", help="remove every cached library")
    c.set_defaults(func=_cmd_cache)
    for action in sub._choices_actions:  # each command's --help opens with its one-line summary
        command = sub.choices[action.dest]
        if not command.description:
            command.description = action.help[:1].upper() + action.help[1:] + "."
    return p


def main(argv=None) -> int:
    """Run the command line; returns the exit status. Every failure is one ``error:`` line on
    stderr: warnings are silenced, Ctrl-C is exit 130, anything unforeseen exit 1."""
    SIGNALLED.clear()
    previous = _record_sigint()
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
        if SIGNALLED:  # a library turned the Ctrl-C into another error (NumPy's import does)
            return _fail("interrupted", EXIT_INTERRUPTED)
        return _fail(f"internal error: {type(exc).__name__}: {_one_line(exc)}", EXIT_INTERNAL)
    finally:
        if previous is not None:
            signal.signal(signal.SIGINT, previous)


def _on_sigint(signum, frame):
    SIGNALLED.append(signum)
    raise KeyboardInterrupt


def _record_sigint():
    """Install :func:`_on_sigint` (Python's own Ctrl-C plus a record of it) for the length of a
    command; returns the handler to restore. None off the main thread, or where SIGINT is not
    Python's default (ignored in a background job, or a host program's own handler)."""
    if threading.current_thread() is not threading.main_thread():
        return None
    previous = signal.getsignal(signal.SIGINT)
    if previous is not signal.default_int_handler:
        return None
    signal.signal(signal.SIGINT, _on_sigint)
    return previous


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
    words = sys.argv[1:] if argv is None else list(argv)
    p = parser(words[0] if words and not words[0].startswith("-") else None)
    try:
        args = p.parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on bad flags already; keep its code
        return int(exc.code or 0)
    # Notes only on a terminal (see the module docstring); reset after the command, since tests
    # and programs may call main() many times in one process with different streams.
    NOTE_STREAM[0] = sys.stderr if _is_terminal(sys.stderr) else None
    try:
        return args.func(args)
    except SceneError as exc:
        return _fail(_one_line(exc), EXIT_INPUT)
    except IntegrationError as exc:
        return _fail(_one_line(exc), EXIT_NUMERIC)
    except CompilerError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_COMPILER
    finally:
        NOTE_STREAM[0] = None


def _is_terminal(stream) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, OSError, ValueError):  # a closed or stream-less stderr
        return False
