"""`derive bench`'s report: the results of `derive.bench.runner` as Markdown (``report.md``)."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from derive.bench import runner as B
from derive.bench import targets as T
from derive.bench import tippe_race

FAMILY_NAMES = {"scipy": "SciPy (plain-Python rhs)", "casadi": "CasADi", "pydy": "PyDy (Cython) + odeint",
                "heyoka": "heyoka (Taylor, LLVM)", "numbalsoda": "numbalsoda DOP853 (numba rhs)"}


def _lanes_line(ba: dict) -> str:
    """The Taylor lanes' race of the batch section (derive.bench.peers._lanes_race), or nothing."""
    if "ratio_lanes_vs_final" not in ba:
        return ""
    return (f" With the Taylor method (error {_e(ba['lanes_derive_error'])}; driver `{ba['lanes_driver']}`), "
            f"`outputs=\"final\"` {_t(ba['derive_lanes_per_trajectory'])} per trajectory against heyoka's final "
            f"states at tol {ba['lanes_heyoka_tol']:.3g} (error {_e(ba['lanes_heyoka_error'])}) "
            f"{_t(ba['heyoka_final_lanes_per_trajectory'])}: **{ba['ratio_lanes_vs_final']:.3g}×**"
            + (f"; the same trajectories as arrays, `derive.prepare(scene).run_batch(initial=...)` (no scene "
               f"read per trajectory) {_t(ba['derive_prepared_lanes_per_trajectory'])}: "
               f"**{ba['ratio_prepared_lanes_vs_final']:.3g}×**" if "ratio_prepared_lanes_vs_final" in ba else "")
            + ".")


def _x(ratio) -> str:
    """A ratio, or a dash where there is none (a contender that did not reach the level)."""
    return "—" if ratio is None else f"{ratio:.3g}×"


def _t(seconds) -> str:
    """A wall time with a readable unit."""
    if seconds is None or not np.isfinite(seconds):
        return "—"
    if seconds < 1e-3:
        return f"{seconds * 1e6:.0f} µs"
    if seconds < 1:
        return f"{seconds * 1e3:.3g} ms"
    return f"{seconds:.3g} s"


def _e(x) -> str:
    return "—" if x is None or not np.isfinite(x) else f"{x:.2e}"


def _verdict(ok) -> str:
    return "—" if ok is None else "met" if ok else "**not met**"


def _ratio_cell(row: dict) -> str:
    if row["ratio"] is None:
        return row["kind"] or "—"
    prefix = "> " if row["kind"] == ">" else ""
    star = "\\*" if row["kind"] == "*" else ""
    return f"{prefix}{row['ratio']:.3g}×{star}"


def header(results: dict) -> list[str]:
    m, cfg = results["machine"], results["settings"]
    v = m["versions"]
    load = lambda x: ", ".join(f"{a:.2f}" for a in x) if x else "?"  # noqa: E731
    peers = ", ".join(f"{k} {v[k]}" if v.get(k) else f"{k} not installed" for k in ("casadi", "pydy", "cython", "heyoka",
                                                                                    "numbalsoda", "numba"))
    L = [f"# derive bench ({cfg['name']})", "",
         f"Machine: {m['cpu']}, {m['cores']} cores, {m['platform']}; {m['compiler']}. "
         f"Load average (1, 5, 15 min) at the start {load(m['load_average'])}, at the end "
         f"{load(m.get('load_average_end'))}. Total bench time {results['elapsed']:.0f} s. "
         f"derive {v.get('derive', '?')} (commit {m['commit']}); Python {v['python']}, NumPy {v['numpy']}, "
         f"SciPy {v['scipy']}, SymPy {v['sympy']}; peers: {peers}.", ""]
    if results["peers_missing"]:
        L += [f"Not raced (not installed): {', '.join(results['peers_missing'])} — "
              "`pip install -e '.[peers]'` or `make bench-peers`"
              + (" (numbalsoda builds from source and needs a Fortran compiler)"
                 if "numbalsoda" in results["peers_missing"] else "") + ".", ""]
    return L


def _cell(what: str, value) -> str:
    """A target's measured value: seconds, a fraction (scaling) or a ratio."""
    if value is None:
        return "—"
    if "[s]" in what:
        return f"{value:.3g} s"
    return f"{value:.0%}" if "scaling" in what else f"{value:.3g}×"


def _targets_table(t: dict) -> list[str]:
    """The targets' table: what, goal, the measured value and whether it is met."""
    return ["| target | goal | measured | |", "|---|---|---|---|"] + [
        f"| {what} | {goal} | {_cell(what, value)} | {_verdict(ok) if goal[0] in '≤≥' else ''} |"
        for what, goal, value, ok in T.summary(t)]


def targets_section(results: dict) -> list[str]:
    t = results["targets"]
    L = ["## Targets, measured side by side in this run", "", *_targets_table(t)]
    L += ["", "(stronger baseline): no goal was set against it; reported because `odeint` — LSODA whose "
          "stepping loop is Fortran, not Python — is the cheapest way SciPy offers to integrate a Python rhs.", ""]
    for key in ("reference", "fixed_cost", "batch", "processes", "lambdify", "sweeps", "verify_speed"):
        if isinstance(t.get(key), dict) and "error" in t[key]:
            L += [f"- {key}: not measured ({t[key]['error']})"]
    if isinstance(t.get("verify_speed"), dict) and "skipped" in t["verify_speed"]:
        L += [f"- verify_speed: not measured ({t['verify_speed']['skipped']})"]
    L.append("")

    ref = t.get("reference") or {}
    if "ours" in ref:
        o, sc = ref["ours"], ref["scene"]
        i = sc["initial"]
        L += ["### Reference scene", "",
              f"Symmetric heavy top I₁ = I₂ = {sc['body']['I1']:g}, I₃ = {sc['body']['I3']:g}, M = g = l = 1; "
              f"α₀ = {i['alpha']:g}, β₀ = {i['beta']:g}, γ₀ = {i['gamma']:g}, α̇₀ = {i['alpha_dot']:g}, "
              f"β̇₀ = {i['beta_dot']:g}, γ̇₀ = {i['gamma_dot']:g}; t ∈ [0, {sc['simulate']['t_end']:g}], "
              f"{sc['simulate']['samples']} samples. Error = max |ê₃ − ê₃,exact|. Ours: `derive.simulate` "
              f"at rtol {o['rtol']:g} (warm: model and library loaded); each contender at the loosest rtol "
              "(halved or doubled from 1e-10) whose error was no larger than ours (reached = yes), then timed "
              "in turns with ours (one contender call, then as many of ours as take about as long; the ratio "
              "is of those paired times, so a change of machine load hits both sides alike). One-off setup: "
              "building "
              "the CasADi integrator; PyDy's code generation and Cython compilation; nothing for SciPy.", "",
              "| solver | rtol | wall time | error | rhs evaluations | reached our error | contender / derive | "
              "one-off setup |",
              "|---|---|---|---|---|---|---|---|",
              f"| **derive** `simulate` ({o['method']}, {o['formulation']}, C) | {o['rtol']:g} | {_t(o['time'])} | "
              f"{_e(o['error'])} | {o['nfev']:,} | | 1× | see below |"]
        for r in ref["rows"]:
            reached = "" if r["reached"] is None else ("yes" if r["reached"] else "**no** (tightest rtol)")
            L.append(f"| {r['label']} | {r['rtol']:.3g} | {_t(r['time'])} | {_e(r['error'])} | {r['nfev']:,} | "
                     f"{reached} | {_x(r['ratio'])} | {_t(r.get('setup'))} |")
        L.append("")
        ph = t.get("phases") or {}
        cold, warm, der = (ph.get(k) or {} for k in ("cold", "warm", "derive"))

        def cell(d, k):
            return f"failed: {d['error']}" if "error" in d else _t(d.get(k))

        L += ["Where derive's time goes (reference scene):", "",
              "| part | time | how it is measured |", "|---|---|---|",
              f"| `import derive` | {cell(warm, 'import')} | fresh process |",
              f"| derivation (SymPy) | {cell(der, 'derivation')} | fresh process, `models` build of the scene's "
              "model (the cost of a model not in `generated/` or the cache) |",
              f"| code generation | {cell(der, 'codegen')} | the same process: CSE + templates |",
              f"| compilation | {_t(ph.get('compilation'))} | first `simulate` in a fresh process with an empty "
              f"`DERIVE_CACHE` ({cell(cold, 'first_simulate')}) minus the same with the cache filled "
              f"({cell(warm, 'first_simulate')}) |",
              f"| Python around the C call | {_t(o.get('overhead'))} | a warm `simulate` minus its C call "
              "(scene validation, formulation choice, arguments, the Result) |",
              f"| C call | {_t(o.get('own_call'))} | `simulate`'s one C call on prepared inputs: init map, "
              "integration, output map and its checks |",
              f"| of which the output map | {_t(o.get('output_map'))} | the compiled `outputs_at` alone on the "
              "call's states (every output at every sample: three sincos a sample), through ctypes |",
              f"| = warm `simulate` | {_t(o['time'])} | in-process, median |", ""]
        for key in ("output_map_error", "own_call_error"):
            if key in o:
                L += [f"Not isolated: {o[key]}", ""]
        row = ref["rows"][0] if ref["rows"] else {}
        if row.get("own_call_paired") and row.get("reached"):
            L += [f"The ceiling: `solve_ivp` DOP853 ({_t(row['time'])}) over derive's C call alone "
                  f"({_t(row['own_call_paired'])}, timed in the same turns) is **{row['time'] / row['own_call_paired']:.3g}×**: "
                  "the ratio `derive.simulate` would reach with no Python at all. Both run DOP853 with about "
                  f"the same number of rhs evaluations ({o['nfev']:,} and {row['nfev']:,}).", ""]

    fc, ba, pr, la = (t.get(k) or {} for k in ("fixed_cost", "batch", "processes", "lambdify"))
    L += ["### Fixed costs, batch, processes, NumPy", ""]
    if "ratio" in fc:
        L.append(f"- Fixed cost (reference scene, t_end = 1e-3, 2 samples, rtol 1e-10): `derive.prepare(...).run()` "
                 f"{_t(fc['prepared'])} per call, `solve_ivp` DOP853 (plain-Python rhs) {_t(fc['scipy'])}: "
                 f"**{fc['ratio']:.3g}×**; `odeint` {_t(fc['odeint'])}: {fc['ratio_odeint']:.3g}×; `derive.simulate(dict)`, "
                 f"which reads, checks and plans the scene on every call, {_t(fc['ours'])}: {fc['ratio_dict']:.3g}× "
                 "`solve_ivp` (medians of 15 interleaved blocks of calls).")
    if "time" in ba:
        raw = (f"; its own C call (init map, integration and outputs of every scene, inputs prepared) "
               f"{_t(ba['own_call'])}: {ba['own_call'] / ba['time']:.0%} of its throughput, and "
               f"**{ba['prepared_vs_own']:.0%}** of `derive.prepare(...).run_batch`'s ({_t(ba['prepared'])})"
               if "own_call" in ba else f"; its own C call: {ba.get('own_call_error')}")
        raw += (f" (the solve-only C loop, `Kernel.solve_batch` on prepared arrays, states only: {_t(ba['raw'])}, "
                f"{ba['vs_raw']:.0%})" if "raw" in ba else f" (solve-only C loop: {ba.get('raw_error')})")
        L.append(f"- `simulate_batch` of {ba['n']} variants of the reference scene (t ∈ [0, {ba['t_end']:g}], "
                 f"{ba.get('method', 'dop853')}, {ba['formulation']}): {_t(ba['time'])} ({_t(ba['per_scene'])} per scene){raw}. SciPy on the "
                 f"plain-Python rhs, each at the rtol that matched our error on the reference scene: `solve_ivp` "
                 f"DOP853 (rtol {ba['scipy_rtol']:.3g}) {_t(ba['scipy_per_trajectory'])} per trajectory (median of "
                 f"{ba['scipy_n']}, each the better of two runs): **{ba['vs_scipy']:.0f}×**; "
                 + (f"`odeint` (rtol {ba['odeint_rtol']:.3g}) {_t(ba['odeint_per_trajectory'])}: **{ba['vs_odeint']:.0f}×**"
                    if "vs_odeint" in ba else "`odeint`: not raced (it reached our error at no tolerance)")
                 + (f". Ceiling (SciPy over the C call alone, per trajectory): {ba['ceiling_vs_scipy']:.0f}×."
                    if ba.get("ceiling_vs_scipy") else "."))
    if "warm" in pr:
        cold = (f"; cold (fresh `DERIVE_CACHE`) {_t(pr['cold'])}, **{pr['cold_minus_warm']:.2f} s** more than warm"
                if "cold" in pr else "")
        L.append(f"- Processes: `python -m derive simulate scenes/looping_top.toml -o out.npz` warm "
                 f"{_t(pr['warm'])} (median of {len(pr['warm_runs'])}), `python -c \"import numpy\"` "
                 f"{_t(pr['import_numpy'])}: **{pr['warm_ratio']:.2f}×**{cold}.")
    if "ratio" in la:
        L.append(f"- NumPy rhs of the heavy top on N = {la['n']:,} states: generated `heavy_top.rhs` "
                 f"{la['generated_ns_per_state']:.1f} ns/state, `sympy.lambdify(..., cse=True)` of the same "
                 f"expressions, stacked into one (6, N) array as `rhs` returns, {la['lambdify_ns_per_state']:.1f} "
                 f"ns/state: **{la['ratio']:.2f}×** (against lambdify's raw list of rows, "
                 f"{la['lambdify_raw_ns_per_state']:.1f} ns/state: {la['ratio_raw']:.2f}×; max relative "
                 f"difference {la['max_rel_diff']:.1e}). The generated module evaluates a long batch in blocks "
                 f"of {la['block']:,} states, whose temporaries stay in the CPU cache; lambdify run in the same "
                 f"blocks by hand takes {la['lambdify_blocked_ns_per_state']:.1f} ns/state "
                 f"({la['ratio_blocked']:.2f}×).")
    L.append("")
    return L


def peers_section(results: dict) -> list[str]:
    """The races against heyoka and numbalsoda (:mod:`derive.bench.peers`): what each side
    ran, the tolerances that reached each error level, the times and ratios."""
    pe = (results.get("targets") or {}).get("peers") or {}
    L = ["## Against heyoka and numbalsoda", ""]
    if "skipped" in pe or "error" in pe:
        return L + [f"Not raced: {pe.get('skipped') or pe.get('error')}.", ""]
    if not pe:
        return []
    L += ["Reference scene (`scenes/reference_top.toml`), error = max |ê₃ − ê₃,exact| over the output times, "
          "the same measure for all. derive: `derive.simulate(dict)` (validation included) and "
          "`derive.prepare(dict).run()` (the prepared call), the method and formulation `auto` picks (the "
          "method column of the derive side says which), "
          "atol = 1e-2 rtol. heyoka: the Euler-angle equations of `scipy_baselines.py` as heyoka expressions in "
          "`taylor_adaptive` (built and JIT-compiled outside the timing; `tol` = the rtol column, heyoka has one "
          "tolerance), reset to t₀, y₀ and `propagate_grid` at the same output times (its dense output). "
          "numbalsoda: the same equations as a numba `cfunc`, `dop853` at the output times, atol = 1e-2 rtol. "
          "Each side at the loosest tolerance (halved or doubled from the level) whose error is no larger than "
          "the level, then timed in turns (blocks of calls alternating; medians). Ratios: derive's time / the "
          "peer's (< 1: derive is faster). The peer's call gives its states at the output times; derive's gives "
          "18 outputs (angles, ω̃, the axis, energy, momenta, n, L). \"peer + axis\": the peer's call and then the "
          "axis from its states in NumPy, what its user computes to get the quantity both are judged on; the "
          "goals are judged on the bare call.", ""]
    for part in ("reference", "long"):
        eq = pe.get(part) or {}
        if "error" in eq:
            L += [f"- {part}: not measured ({eq['error']})", ""]
            continue
        if not eq:
            continue
        L += [f"### t ∈ [0, {eq['t_end']:g}], {eq['samples']} samples", "",
              "| error level | derive rtol (error) | peer | peer tol (error, steps) | peer time | derive `simulate` "
              "| derive prepared | simulate / peer | prepared / peer | peer + axis | prepared / (peer + axis) |",
              "|---|---|---|---|---|---|---|---|---|---|---|"]
        for row in eq["rows"]:
            d = row["derive"]
            dcell = f"{d['rtol']:.3g} ({_e(d['error'])}" + (f", {d['method']}, {d['formulation']}" if "method" in d else "") \
                + ")" + ("" if d["reached"] else " **not reached**")
            if not row["peers"]:
                L.append(f"| {row['level']:.0e} | {dcell} | — | | | | | | | | |")
            for fam, e in row["peers"].items():
                pcell = f"{e['rtol']:.3g} ({_e(e['error'])}, {e['nfev']:,})" + ("" if e["reached"] else " **not reached**")
                ratio = lambda k: f"**{e[k]:.3g}×**" if k in e else "—"  # noqa: E731
                L.append(f"| {row['level']:.0e} | {dcell} | {FAMILY_NAMES[fam]} | {pcell} | {_t(e.get('time'))} | "
                         f"{_t(e.get('derive_simulate'))} | {_t(e.get('derive_prepared'))} | {ratio('ratio_simulate')} | "
                         f"{ratio('ratio_prepared')} | {_t(e.get('time_with_axis'))} | {ratio('ratio_prepared_with_axis')} |")
        L.append("")
    ba = pe.get("batch") or {}
    if "error" in ba or "skipped" in ba:
        L += [f"- batch: not measured ({ba.get('error') or ba.get('skipped')})", ""]
    elif ba:
        final = (f"`derive.simulate_batch(scenes, outputs=\"final\")` (the last sample of every output only) "
                 f"{_t(ba['derive_final_per_trajectory'])} per trajectory against heyoka's `propagate_until` "
                 f"t_end (final states only) {_t(ba['heyoka_final_per_trajectory'])}: "
                 f"**{ba['ratio_final_vs_final']:.3g}×**; as arrays, `derive.prepare(scene).run_batch(initial=...)` "
                 f"{_t(ba['derive_prepared_final_per_trajectory'])}: **{ba['ratio_prepared_final_vs_final']:.3g}×**; ")
        L += [f"### Batch of {ba['n']} variants of the reference scene (t ∈ [0, {ba['t_end']:g}])", "",
              f"derive at rtol {ba['rtol']:g} (error {_e(ba['derive_error'])} on the reference scene), heyoka's "
              f"batch mode (`taylor_adaptive_batch`, {ba['lanes']} SIMD lanes, one trajectory per lane) at tol "
              f"{ba['heyoka_tol']:.3g} (error {_e(ba['heyoka_error'])}), best of a few rounds in turns. " + final
              + f"`derive.simulate_batch(scenes)` (every output at all {ba['samples']} samples) "
              f"{_t(ba['derive_full_per_trajectory'])} against heyoka's `propagate_grid` (the states at every sample) "
              f"{_t(ba['heyoka_grid_per_trajectory'])}: **{ba['ratio_full_vs_grid']:.3g}×**"
              + f"; the axis alone at every sample, `derive.prepare(scene).run_batch(initial=..., "
                f"outputs=(\"axis\",))`, {_t(ba['derive_prepared_axis_per_trajectory'])}: "
                f"**{ba['ratio_prepared_axis_vs_grid']:.3g}×** heyoka's states, "
                f"**{ba['ratio_prepared_axis_vs_grid_axis']:.3g}×** its states and the axis computed from them "
                f"with NumPy ({_t(ba['heyoka_grid_axis_per_trajectory'])})"
                f"; the states alone at every sample (derive's formulation's, heyoka's equations'), "
                f"`outputs=(\"state\",)`, {_t(ba['derive_prepared_state_per_trajectory'])}: "
                f"**{ba['ratio_prepared_state_vs_grid']:.3g}×**"
              + f". The final axes of the two agree to {_e(ba['final_axis_difference'])}." + _lanes_line(ba), ""]
    fc = pe.get("fixed_cost") or {}
    if "error" in fc:
        L += [f"- fixed cost: not measured ({fc['error']})", ""]
    elif fc:
        peers = "; ".join(f"{FAMILY_NAMES[f]} {_t(fc[f])}: prepared / it **{fc[f'prepared_vs_{f}']:.3g}×**, "
                          f"simulate / it **{fc[f'simulate_vs_{f}']:.3g}×**, simulate of new numbers / it "
                          f"**{fc[f'simulate_new_vs_{f}']:.3g}×**" for f in ("heyoka", "numbalsoda") if f in fc)
        L += [f"### Fixed cost (t_end = 1e-3, 2 samples, rtol {fc['rtol']:g})", "",
              f"`derive.prepare(dict).run()` {_t(fc['derive_prepared'])}, `derive.simulate(dict)` "
              f"{_t(fc['derive_simulate'])} (the same scene again: validated, its plan kept from the call before)"
              f" and {_t(fc['derive_simulate_new'])} (a scene with new numbers every call: validated, planned "
              f"and its C call set up anew); {peers}. heyoka's call: reset time, state and parameters, "
              "`propagate_grid` over the two times; numbalsoda's: `dop853` over them.", ""]
    return L


def auto_choice_section(results: dict) -> list[str]:
    """The method choice (:mod:`derive.bench.autochoice`): the method auto chose against the
    faster of dop853 and taylor, per scene and tolerance."""
    ac = (results.get("targets") or {}).get("auto_choice") or {}
    if not ac:
        return []
    L = ["## What `method = \"auto\"` picks", ""]
    if "error" in ac:
        return L + [f"Not measured: {ac['error']}.", ""]
    L += ["Each scene prepared with `method` = dop853, taylor and auto (atol = rtol / 100), the three "
          "prepared runs timed in turns (medians). auto / best: auto's time over the faster method's "
          "(1: the right choice). A choice within 10 % of the faster counts as right. "
          f"**Right: {ac['right']} of {ac['total']}.**", "",
          "| scene | rtol | auto chose | faster | dop853 | taylor | auto / best |", "|---|---|---|---|---|---|---|"]
    for r in ac["rows"]:
        L.append(f"| {r['scene']} | {r['rtol']:.0e} | {r['chose']} | {r['faster']} | {_t(r['dop853'])} | "
                 f"{_t(r['taylor'])} | {r['auto_over_best']:.3g} |")
    L.append("")
    return L


def kernel_section(results: dict) -> list[str]:
    L = ["## Kernel speed", "",
         "`generated/c/heavy_top.c` (committed, generated) vs `derive/bench/baselines/handwritten_heavy_top.c` (the "
         "textbook equations by hand), each in its own translation unit, called through a pointer by "
         f"`derive/bench/baselines/rhs_loop.c` over 4096 rotating states; {results['c_loop'][0]['calls']:,} calls per timing, "
         f"{results['c_loop'][0]['repeats']} interleaved repeats, medians. Ratio = median of the per-repeat ratios.",
         "", "| flags | generated ns/call | hand-written ns/call | no-op ns/call | generated / hand | "
         f"goal ≤ {B.GOAL_KERNEL_RATIO:g} | max rel. difference |", "|---|---|---|---|---|---|---|"]
    for r in results["c_loop"]:
        L.append(f"| `{r['flags']}` | {r['generated_ns']:.2f} | {r['handwritten_ns']:.2f} | {r['noop_ns']:.2f} | "
                 f"{r['ratio']:.3f} | {_verdict(r['ratio'] <= B.GOAL_KERNEL_RATIO)} | {r['max_rel_diff']:.1e} |")
    L += ["", "Generated NumPy `rhs(t, y, p)` on a batch of shape (6, N); sin + cos = `np.sin`, `np.cos` of "
          "one row alone.", "", "| N | ns/state | of which sin + cos |", "|---|---|---|"]
    for r in results["numpy_batch"]:
        L.append(f"| {r['n']:,} | {r['ns_per_state']:.1f} | {r['sin_cos_ns_per_state']:.1f} |")
    pc = results["python_calls"]
    c_ns = results["c_loop"][-1]["generated_ns"]
    ct = f"compiled C through ctypes (`Kernel.rhs`) {pc['ctypes_us']:.2f} µs, " if pc.get("ctypes_us") else ""
    L += ["", f"One state through Python, per call: {ct}the hand-written plain-Python rhs "
          f"{pc['plain_python_us']:.2f} µs, the generated NumPy rhs {pc['numpy_us']:.2f} µs"
          + (f", PyDy's Cython-generated rhs {pc['pydy_us']:.2f} µs (its argument handling)" if pc.get("pydy_us") else "")
          + f"; the C call itself "
          f"{c_ns:.0f} ns — why derive's integration loops run in C.", ""]
    return L


def wp_section(results: dict) -> list[str]:
    cfg = results["settings"]
    fams = results["families"]
    L = ["## Work–precision", "",
         "Error = max over the output times of |ê₃ − ê₃,ref|, ref = the exact solution. **derive**: "
         "`derive.prepare(scene).run()` (the solve call alone, as the contenders' are timed: the scene read, "
         "validated and planned beforehand; `derive.simulate`'s cost per call on top of it is the fixed cost "
         f"below), dop853 and taylor over rtol {cfg['rtols'][0]:g} … {cfg['rtols'][-1]:g}, rk4 / gauss4 / "
         "gauss6 over h = Δt_out / 2^k, in "
         + ("every formulation that can run the scene" if cfg["other_formulations"] else "the auto formulation")
         + ". **SciPy**: `solve_ivp` DOP853, LSODA and Radau, and `odeint` (LSODA's Fortran driver; LSODA and "
         "Radau get the analytic Jacobian, also plain Python) on the hand-written plain-Python rhs of `derive/bench/baselines/scipy_baselines.py` (Euler angles for "
         "symmetric tops, quaternion + Euler's equations for any body; both where listed, and the best counts). "
         "**CasADi**: the same equations as SX, `integrator` cvodes (Adams, BDF) and idas on the output grid. "
         "**PyDy**: the same equations through `generate_ode_function(generator='cython')` + `odeint`. "
         "Contenders' times are the solve call alone (integrator built, rhs compiled beforehand). "
         f"atol = {B.ATOL_RATIO:g} · rtol. Median of {cfg['repeats']} runs for derive, {cfg['other_repeats']} for the "
         f"others; a run over {cfg['long_run']:g} s is timed once and ends its sweep past {cfg['cap']:g} s. Cost "
         "at an error level: log-log interpolation on each curve (`points.csv` has every run). Ratio = the "
         "contender's best / derive's best.", "",
         "\\* = the cheapest run of at least one side was already below the level (its time is an upper bound); "
         "> = the contender did not reach the level (ratio against its slowest run); n/a = no run reached it.", ""]
    fc = (results.get("targets") or {}).get("fixed_cost") or {}
    if "ours" in fc:
        L += [f"A whole `derive.simulate` call on the reference scene with t_end = 1e-3 costs ≈ {_t(fc['ours'])} "
              "(reading, checking and planning the scene, then the C call); the prepared call timed here leaves "
              "the reading, checking and planning out. derive's one-off costs "
              "(derivation, code generation, compilation) are in the targets section; the contenders' one-off "
              "costs are excluded alike.", ""]
    levels = " | ".join(f"{lv:.0e}" for lv in B.ERROR_LEVELS)
    tables = [("ratios", "scipy", "SciPy's best / derive's best (any formulation, any method):"),
              ("ratios_auto", "scipy", "SciPy's best / derive in the formulation `auto` picks (what "
                                       "`derive simulate` runs by default):")]
    tables += [("ratios", f, f"{FAMILY_NAMES[f]}'s best / derive's best:") for f in fams if f != "scipy"]
    for key, fam, what in tables:
        L += [what, "", f"| scene | auto formulation | {levels} |", "|" + "---|" * (2 + len(B.ERROR_LEVELS))]
        for wp in results["work_precision"]:
            L.append(f"| {wp['scene']} | {wp['auto']} | " + " | ".join(_ratio_cell(r) for r in wp[key][fam]) + " |")
        L.append("")
    L += ["| scene | reference | max difference exact vs derive dop853 rtol 1e-13 | baseline formulations | note |",
          "|---|---|---|---|---|"]
    for wp in results["work_precision"]:
        chk = "—" if wp["reference_check"] is None else f"{wp['reference_check']:.1e}"
        L.append(f"| {wp['scene']} | {wp['reference']} | {chk} | {', '.join(wp['baseline_formulations'])} | "
                 f"{wp['reference_note']} |")
    L.append("")
    for wp in results["work_precision"]:
        L += [f"### {wp['scene']} — {wp['title']}", "",
              f"t ∈ [0, {wp['t_end']:g}] s, {wp['samples']} samples; auto formulation: {wp['auto']}; "
              f"reference: {wp['reference']}.", "", f"![work-precision {wp['scene']}](wp_{wp['scene']}.png)", "",
              "| error ≤ | derive best | time | " + " | ".join(f"{FAMILY_NAMES[f]} best | time | ratio" for f in fams) + " |",
              "|---|---|---|" + "---|---|---|" * len(fams)]
        for i, lv in enumerate(B.ERROR_LEVELS):
            first = wp["ratios"][fams[0]][i]
            cells = [f"{lv:.0e}", first["ours"] or "—", ("≤ " if first["ours_bound"] else "") + _t(first["ours_time"])]
            for f in fams:
                r = wp["ratios"][f][i]
                cells += [r["other"] or "—", ("≤ " if r["other_bound"] else "") + _t(r["other_time"]), _ratio_cell(r)]
            L.append("| " + " | ".join(cells) + " |")
        L.append("")
    return L


def drift_section(results: dict) -> list[str]:
    d = results["drift"]
    L = ["## Drift of the invariants", "",
         f"Looping top in the **{d['formulation']}** formulation (energy, p_α and p_γ are all computed from the "
         f"state, none is built in), t ∈ [0, {d['t_end']:g}] s, through `derive.simulate`; fixed-step methods with "
         f"h = {d['h']:g} s, dop853 adaptive over the same span. Max over 1001 output times of the relative change.",
         "", "| method | setting | steps | rhs evaluations | wall time | max ΔE/E₀ | ΔE/E₀ at the end | "
         "max Δp_α/p_α₀ | max Δp_γ/p_γ₀ | max \\|\\|q\\| − 1\\| |", "|---|---|---|---|---|---|---|---|---|---|"]
    for r in d["rows"]:
        if "error" in r:
            L.append(f"| {r['method']} | failed: {r['error']} |||||||||")
            continue
        steps = "—" if r["steps"] is None else f"{r['steps']:,}"
        L.append(f"| {r['method']} | {r['setting']} | {steps} | {r['nfev']:,} | {_t(r['time'])} | {r['energy']:.2e} | "
                 f"{r['energy_end']:+.2e} | {r['p_alpha']:.2e} | {r['p_gamma']:.2e} | {_e(r['qnorm'])} |")
    L.append("")
    return L


def summary(results: dict) -> str:
    """The short version for the README's "Measured" section (``summary.md``): the machine, the
    targets and each contender's best against derive's best per scene and error level."""
    m, cfg = results["machine"], results["settings"]
    la = m["load_average"] or [float("nan")]
    cmd = "make bench" if cfg["name"] == "full" else f"derive bench --{cfg['name']}"
    L = [f"From one `{cmd}` run ({results['elapsed']:.0f} s; {m['cpu']}, {m['cores']} cores, load average "
         f"{la[0]:.2f} at the start; commit {m['commit']}; versions in the full report).", "",
         *_targets_table(results["targets"])]
    c = results["c_loop"][-1]
    L += ["", f"Generated C `heavy_top_rhs` {c['generated_ns']:.1f} ns/call against the same equations typed "
          f"by hand {c['handwritten_ns']:.1f} ns/call ({c['ratio']:.2f}×, `{c['flags']}`).", "",
          "Work–precision: each contender's best time to reach an error level (max axis error against the "
          "exact solution, same scenes, same measure) divided by derive's best (the prepared call "
          "`derive.prepare(scene).run()`, timed as the contenders' solve calls are). SciPy: `solve_ivp` DOP853 / LSODA / Radau (analytic Jacobian) and `odeint` on a "
          "hand-written plain-Python rhs."
          + (" CasADi: cvodes (Adams, BDF) / idas on the same equations; PyDy: Cython rhs + `odeint`."
             if len(results["families"]) > 1 else "")
          + " \\* = one side's cheapest run was already below the level (time is an upper bound); > = the "
          "contender never reached it; ours n/a = derive did not reach it.", ""]
    levels = " | ".join(f"{lv:.0e}" for lv in B.ERROR_LEVELS)
    L += [f"| scene | contender | {levels} |", "|" + "---|" * (2 + len(B.ERROR_LEVELS))]
    for wp in results["work_precision"]:
        for f in results["families"]:
            L.append(f"| {wp['scene']} | {FAMILY_NAMES[f]} | " + " | ".join(_ratio_cell(r) for r in wp["ratios"][f]) + " |")
    L.append("")
    return "\n".join(L)


def splitting_section(results: dict) -> list[str]:
    """Where the Lie–Poisson splitting (order 4) pays, against DOP853 and Gauss–Legendre 4."""
    rows = results.get("splitting") or []
    if not rows:
        return []
    methods = ("splitting4", "dop853", "gauss4")
    L = ["## Lie–Poisson splitting", "",
         "`derive.methods.splitting.bench_energy`: each method at its cheapest setting (step h, or rtol for "
         "DOP853) that keeps the error below the target over the whole run; best of the repeats. "
         "Cases: `fast-top` p_γ²/(I₁Mgl) = 1e6; `lagrange` a slow heavy symmetric top; "
         "`asymmetric` an off-axis asymmetric body. Measures: `energy` |E − E₀|/(Mg|r_c|); `axis` "
         "max |R ê₃ − reference| (exact for the Lagrange tops, DOP853 at rtol 1e-13 otherwise). In "
         "Euler–Poisson variables the energy is quadratic, which Gauss–Legendre keeps at any step: "
         "judge it by `axis`.", "",
         "| case | measure | periods | target | " + " | ".join(methods) + " | DOP853 / splitting4 |",
         "|---|---|---|---|" + "---|" * len(methods) + "---|"]
    for r in rows:
        if "failed" in r:
            L.append(f"| {r['case']} | {r['measure']} | failed: {r['failed']} |||||||")
            continue
        cells = []
        for m in methods:
            v = r.get(m)
            cells.append("not reached" if not v else f"{_t(v['seconds'])} (error {v['error']:.1e})")
        ratio = r.get("ratio_dop853")
        L.append(f"| {r['case']} | {r['measure']} | {r['periods']:g} | {r['target']:g} | "
                 + " | ".join(cells) + f" | {_x(ratio)} |")
    L.append("")
    return L


def write_report(results: dict, out: Path) -> str:
    L = header(results) + targets_section(results) + peers_section(results) + tippe_race.section(results) \
        + auto_choice_section(results) \
        + kernel_section(results) \
        + wp_section(results) \
        + drift_section(results) + splitting_section(results)
    text = "\n".join(L)
    (Path(out) / "report.md").write_text(text)
    (Path(out) / "summary.md").write_text(summary(results))
    return text
