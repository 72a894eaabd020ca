"""The tippe top against MuJoCo, side by side in one process: Jellett's integral and the final spin.

The scene is the shipped ``tippe_top`` (Leine & Glocker: M = 6 g, I₁ = I₂ = 8·10⁻⁷,
I₃ = 7·10⁻⁷ kg m², a ball of radius R = 15 mm whose centre is αR = 3 mm above the centre of mass
along ê₃, θ₀ = 0.1 rad, spin n₀ = 180 rad/s about ê₃, centre of mass at rest). MuJoCo gets the
same numbers as an MJCF model written here (:func:`mjcf`): a free body with that inertia, a sphere
geom at (0, 0, αR), a plane; ``condim = 3`` (sliding friction μ, no torsional or rolling friction:
the contact force has no moment about the contact point beyond a × f, as in derive's model).

The two sides run different contact laws, and say so: derive the scene's law (viscous friction,
μ = 0.3 N s/m, the contact held on the plane by the derived normal force), MuJoCo its soft contact
(penetration and a spring-damper set by ``solref``, Coulomb friction μ = 0.3 on its pyramidal
cone, its semi-implicit Euler step). What is compared holds for any contact law:

* **Jellett's integral** J = L·a (L about the centre of mass, a from it to the contact point) is
  conserved by the exact motion for any force at the contact of an axisymmetric body with a
  spherical contact: its drift max |J − J₀|/|J₀| over the run measures the integrator alone.
* **The final spin**: a top that turns over ends spinning at Jellett's
  ω₃ = n₀(α − cos θ₀)/(1 + α) whatever the law; each side's ω₃ where θ comes closest to π
  (sampled every millisecond) against it.

Timing, in turns (best of a few rounds): derive's public ``derive.simulate(dict)`` (validation,
the phase loop and every output, sampled every millisecond), against MuJoCo's bare ``mj_step(model, data,
nstep)`` from the initial state (no output at all, the fastest MuJoCo can run it). The measures
of MuJoCo come from a second, untimed run of the same steps recording every millisecond (MuJoCo
is deterministic: the same states). Goals (:data:`derive.bench.targets.GOALS`): at equal wall
time (derive at its most accurate tolerance whose run is no slower than MuJoCo's), J kept at
least 1000× better; at equal final-spin error (derive at its fastest tolerance whose error is no
larger than MuJoCo's), derive's time / MuJoCo's ≤ 1.
"""
from __future__ import annotations

import math
import tomllib

import numpy as np

import derive
from derive.bench import timing
from derive.codegen.render import data_dir

#: The goals' keys in :data:`derive.bench.targets.GOALS`.
JELLETT_GOAL, SPIN_GOAL = "mujoco_jellett_at_equal_time", "mujoco_time_at_equal_spin"
#: What each setting races: derive's tolerances; MuJoCo's steps and ``solref`` (None: its default).
SETTINGS = {
    "full": {"rtols": (1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12), "dts": (1e-3, 1e-4, 1e-5),
             "solrefs": (None, (0.002, 1.0)), "rounds": 3},
    "quick": {"rtols": (1e-5, 1e-7, 1e-9), "dts": (1e-3, 1e-4), "solrefs": (None,), "rounds": 3},
    "smoke": {"rtols": (1e-6,), "dts": (1e-3,), "solrefs": (None,), "rounds": 1, "t_end": 0.2},
}
T_END = 4.0
EVERY = 1e-3


def tippe_scene(t_end: float = T_END, rtol: float = 1e-10) -> dict:
    """The shipped ``tippe_top`` scene as a dict, over [0, ``t_end``] sampled every millisecond."""
    data = tomllib.loads((data_dir("scenes") / "contact" / "tippe_top.toml").read_text(encoding="utf-8"))
    data["simulate"].update(t_end=t_end, samples=int(round(t_end / EVERY)) + 1, rtol=rtol, atol=1e-2 * rtol)
    return data


def numbers(data: dict) -> dict:
    """The scene's numbers both sides are built from (SI units)."""
    b, g, c, i = data["body"], data["gravity"], data["contact"], data["initial"]
    return {"I1": b["I1"], "I2": b.get("I2", b["I1"]), "I3": b["I3"], "M": g["M"], "g": g["g"],
            "R": c["radius"], "s": c["offset"], "mu": c["mu"], "theta0": i["beta"], "n0": i["omega"][2]}


def jellett_spin(n: dict) -> float:
    """The spin ω₃ of the turned-over top from Jellett's J: n₀(α − cos θ₀)/(1 + α), α = s/R.

    J = L·a with a = s ê₃ − R n̂ (n̂ the vertical in body axes): at the start
    J = I₃ n₀ (s − R cos θ₀), upside down (n̂ = −ê₃) J = I₃ ω₃ (s + R)."""
    alpha = n["s"] / n["R"]
    return n["n0"] * (alpha - math.cos(n["theta0"])) / (1 + alpha)


def mjcf(n: dict, dt: float, solref=None) -> str:
    """The MJCF text of the tippe top: a free body (inertia about its centre of mass at the body
    origin), a sphere geom of radius R at (0, 0, s), a plane; friction μ on both geoms, condim 3."""
    ref = f' solref="{solref[0]:g} {solref[1]:g}"' if solref else ""
    return (f'<mujoco model="tippe_top"><option timestep="{dt:g}" gravity="0 0 {-n["g"]:.17g}"/>'
            f'<worldbody><geom type="plane" size="1 1 0.1" friction="{n["mu"]:g} 0 0" condim="3"{ref}/>'
            f'<body name="top"><freejoint/><inertial pos="0 0 0" mass="{n["M"]:.17g}" '
            f'diaginertia="{n["I1"]:.17g} {n["I2"]:.17g} {n["I3"]:.17g}"/>'
            f'<geom type="sphere" size="{n["R"]:.17g}" pos="0 0 {n["s"]:.17g}" friction="{n["mu"]:g} 0 0" '
            f'condim="3"{ref}/></body></worldbody></mujoco>')


class MuJoCoTop:
    """The tippe top in MuJoCo at one time step and ``solref``: the timed call and the measures."""

    def __init__(self, n: dict, dt: float, solref=None, t_end: float = T_END):
        import mujoco

        self.mj, self.n, self.dt, self.solref = mujoco, n, dt, solref
        self.model = mujoco.MjModel.from_xml_string(mjcf(n, dt, solref))
        self.data = mujoco.MjData(self.model)
        self.nstep = int(round(t_end / dt))

    def start(self) -> None:
        """The initial state: tilted θ₀ about y, the ball touching the plane, spin n₀ about ê₃
        (a free joint's angular velocity is in body axes), the centre of mass at rest."""
        mj, d, n = self.mj, self.data, self.n
        mj.mj_resetData(self.model, d)
        th = n["theta0"]
        d.qpos[:3] = (0.0, 0.0, n["R"] - n["s"] * math.cos(th))
        d.qpos[3:7] = (math.cos(th / 2), 0.0, math.sin(th / 2), 0.0)
        d.qvel[5] = n["n0"]

    def run(self) -> None:
        """The timed call: every step in one ``mj_step(..., nstep)``, no output."""
        self.start()
        self.mj.mj_step(self.model, self.data, nstep=self.nstep)

    def record(self, every: float = EVERY) -> dict:
        """The same steps again, the state every ``every`` seconds: (t, θ, ω (body), J)."""
        mj, d, n = self.mj, self.data, self.n
        k = max(1, int(round(every / self.dt)))
        self.start()
        R = np.zeros(9)
        inertia = np.array([n["I1"], n["I2"], n["I3"]])
        ts, th, w, J = [], [], [], []
        for i in range(self.nstep // k + 1):
            if i:
                mj.mj_step(self.model, d, nstep=k)
            mj.mju_quat2Mat(R, d.qpos[3:7])
            up = R[6:9]  # the vertical in body axes: the third row of R (body -> world)
            om = d.qvel[3:6].copy()
            ts.append(i * k * self.dt)
            th.append(math.acos(max(-1.0, min(1.0, R[8]))))
            w.append(om)
            J.append(float((inertia * om) @ (np.array([0.0, 0.0, n["s"]]) - n["R"] * up)))
        return {"t": np.array(ts), "theta": np.array(th), "omega": np.array(w), "jellett": np.array(J)}


def measures(t, theta, omega, J, spin: float) -> dict:
    """J's drift, the spin where θ comes closest to π and its error against Jellett's, the time θ
    first passes 90°."""
    i = int(np.argmax(theta))
    above = np.nonzero(theta > math.pi / 2)[0]
    return {"jellett_drift": float(np.max(np.abs(J - J[0])) / abs(J[0])),
            "theta_max": float(theta[i]), "t_theta_max": float(t[i]), "spin": float(omega[i, 2]),
            "spin_error": float(abs(omega[i, 2] - spin) / abs(spin)),
            "t90": float(t[above[0]]) if len(above) else None}


def derive_side(data: dict, spin: float) -> dict:
    """derive's run of ``data``: its measures and the call to time."""
    r = derive.simulate(data)
    out = measures(r.t, r.beta, r.omega, r.integrals["jellett"], spin)
    out.update(rtol=data["simulate"]["rtol"], law=r.scene.law, nfev=int(r.nfev), switches=len(r.switches))
    return out


def _match(mj: dict, ours: list[dict]) -> dict:
    """Each goal's derive run against one MuJoCo run: at equal time, the best J among derive's
    runs no slower; at equal spin error, the fastest of derive's runs no less accurate."""
    fast = [o for o in ours if o["time"] <= mj["time"]]
    good = [o for o in ours if o["spin_error"] <= mj["spin_error"]]
    out = {}
    if fast:
        best = min(fast, key=lambda o: o["jellett_drift"])
        out.update(equal_time_rtol=best["rtol"], equal_time_jellett=best["jellett_drift"],
                   jellett_ratio=mj["jellett_drift"] / max(best["jellett_drift"], 1e-300))
    if good:
        best = min(good, key=lambda o: o["time"])
        out.update(equal_spin_rtol=best["rtol"], equal_spin_time=best["time"],
                   time_ratio=best["time"] / mj["time"])
    return out


def run(cfg) -> dict:
    """The race (:data:`SETTINGS` by ``cfg.name``); ``{"skipped": ...}`` without MuJoCo."""
    try:
        import mujoco
    except ImportError:
        return {"skipped": "MuJoCo is not installed (pip install -e '.[contact-peers]')"}
    st = SETTINGS.get(cfg.name, SETTINGS["full"])
    t_end = st.get("t_end", T_END)
    data = tippe_scene(t_end)
    n = numbers(data)
    spin = jellett_spin(n)
    scenes = {r: tippe_scene(t_end, r) for r in st["rtols"]}
    ours = {r: derive_side(d, spin) for r, d in scenes.items()}
    tops = {(dt, sr): MuJoCoTop(n, dt, sr, t_end) for dt in st["dts"] for sr in st["solrefs"]}
    theirs = {}
    for key, top in tops.items():
        rec = top.record()
        theirs[key] = measures(rec["t"], rec["theta"], rec["omega"], rec["jellett"], spin)
    fns = {("derive", r): (lambda d=d: derive.simulate(d)) for r, d in scenes.items()}
    fns.update({("mujoco", k): top.run for k, top in tops.items()})
    best = timing.best_in_turns(fns, st["rounds"])
    for r in ours:
        ours[r]["time"] = best[("derive", r)]
    rows = []
    for (dt, sr), m in theirs.items():
        m.update(dt=dt, solref=list(sr) if sr else None, time=best[("mujoco", (dt, sr))])
        m.update(_match(m, list(ours.values())))
        rows.append(m)
    jr = [m["jellett_ratio"] for m in rows if "jellett_ratio" in m]
    tr = [m["time_ratio"] for m in rows if "time_ratio" in m]
    return {"mujoco": mujoco.__version__, "t_end": t_end, "every": EVERY, "jellett_spin": spin,
            "derive_law": ours[st["rtols"][0]]["law"], "derive": list(ours.values()), "mujoco_runs": rows,
            # the worst over MuJoCo's settings; None when some setting had no match at all
            "jellett_ratio": min(jr) if len(jr) == len(rows) else None,
            "time_ratio": max(tr) if len(tr) == len(rows) else None}


def rows(tt: dict) -> list[tuple[str, str, float | None]]:
    """The targets table's rows (what, goal key, value)."""
    if not tt or "skipped" in tt or "error" in tt:
        return []
    return [("tippe top vs MuJoCo (its soft contact, every dt and `solref` raced): MuJoCo's Jellett drift / "
             "derive's at equal or smaller wall time, the worst setting", JELLETT_GOAL, tt.get("jellett_ratio")),
            ("tippe top vs MuJoCo: derive's wall time / MuJoCo's at equal or smaller final-spin error, "
             "the worst setting", SPIN_GOAL, tt.get("time_ratio"))]


def _t90(m: dict) -> str:
    return "never" if m["t90"] is None else f"{m['t90']:.3f}"


def _sr(s) -> str:
    return "default (0.02, 1)" if not s else f"({s[0]:g}, {s[1]:g})"


def section(results: dict) -> list[str]:
    """The report's section: what each side ran and every run's figures."""
    tt = (results.get("targets") or {}).get("tippe_top") or {}
    L = ["## The tippe top against MuJoCo", ""]
    if "skipped" in tt or "error" in tt:
        return L + [f"Not raced: {tt.get('skipped') or tt.get('error')}.", ""]
    if not tt:
        return []
    L += [f"The shipped `tippe_top` over t ∈ [0, {tt['t_end']:g}] s, both sides built from its numbers. "
          f"derive: `derive.simulate(dict)`, law `{tt['derive_law']}` (the scene's), its outputs every "
          f"{tt['every'] * 1e3:g} ms. MuJoCo {tt['mujoco']}: soft contact (its spring-damper `solref`), "
          "Coulomb friction μ = 0.3 on the pyramidal cone, condim 3, semi-implicit Euler; timed as a bare "
          "`mj_step(model, data, nstep)` with no output. The laws differ; Jellett's J and the final spin "
          f"ω₃ = n₀(α − cos θ₀)/(1 + α) = {tt['jellett_spin']:.5g} rad/s hold for any contact law. Spin: ω₃ "
          "where θ comes closest to π.", "",
          "| side | setting | wall (s) | J drift | θ max | spin error | θ = 90° at (s) |", "|---|---|---|---|---|---|---|"]
    for o in tt["derive"]:
        L.append(f"| derive | rtol {o['rtol']:.0e} | {o['time']:.4f} | {o['jellett_drift']:.1e} | "
                 f"{o['theta_max']:.4f} | {o['spin_error']:.1e} | {_t90(o)} |")
    for m in tt["mujoco_runs"]:
        L.append(f"| MuJoCo | dt {m['dt']:.0e}, solref {_sr(m['solref'])} | {m['time']:.4f} | "
                 f"{m['jellett_drift']:.1e} | {m['theta_max']:.4f} | {m['spin_error']:.1e} | {_t90(m)} |")
    L += ["", "| MuJoCo setting | derive at equal or less time | J: MuJoCo / derive | derive at equal or smaller "
          "spin error | time: derive / MuJoCo |", "|---|---|---|---|---|"]
    for m in tt["mujoco_runs"]:
        a = (f"rtol {m['equal_time_rtol']:.0e}", f"{m['jellett_ratio']:.3g}×") if "jellett_ratio" in m \
            else ("none as fast", "—")
        b = (f"rtol {m['equal_spin_rtol']:.0e}", f"{m['time_ratio']:.3g}×") if "time_ratio" in m \
            else ("none as accurate", "—")
        L.append(f"| dt {m['dt']:.0e}, solref {_sr(m['solref'])} | {a[0]} | {a[1]} | {b[0]} | {b[1]} |")
    return L + [""]
