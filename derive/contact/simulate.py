"""Simulate a top on a table: a validated contact scene in, a :class:`ContactResult` out.

The initial state: the quaternion of the z-y-z angles, ω̃ from the rates (or ``omega``), the
centre of mass over the origin at the height the contact sets, z = −a·n, its horizontal velocity
(vx, vy) — or, rolling, v = −ω × a — and its vertical velocity from the constraint,
v_z = −(ω × a)·ẑ.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from derive.contact.kernel import OUTPUTS, kernel
from derive.contact.laws import EXTENSIONS, LAWS
from derive.contact import driver, reduced
from derive.contact.phases import PHASE_NAMES, Phases, Run, Switch, quaternion_matrix
from derive.reference.rotation import body_omega
from derive.contact.scene import COMPILED, GRAVITY, METHOD, ContactScene, integrals_held, read

_O = {name: i for i, name in enumerate(OUTPUTS)}


def _qaxis(axis: int, angle: float) -> np.ndarray:
    q = np.zeros(4)
    q[0], q[1 + axis] = np.cos(angle / 2), np.sin(angle / 2)
    return q


def _qmul(p, q):
    return np.concatenate([[p[0] * q[0] - p[1:] @ q[1:]], p[0] * q[1:] + q[0] * p[1:] + np.cross(p[1:], q[1:])])


def quaternion(alpha: float, beta: float, gamma: float) -> np.ndarray:
    """The unit quaternion of R = R_z(α) R_y(β) R_z(γ) (z-y-z, body → inertial)."""
    return _qmul(_qmul(_qaxis(2, alpha), _qaxis(1, beta)), _qaxis(2, gamma))


def params(sc: ContactScene) -> np.ndarray:
    """The parameter vector in the kernel's order (I1, I2, I3, M, g, r, s, μ, ε, then the law's
    extensions' lengths δ, r_s: :data:`~derive.contact.layout.PARAM_NAMES`)."""
    return np.array([sc.I1, sc.I2, sc.I3, sc.M, sc.g, sc.radius, sc.offset, sc.mu,
                     sc.regularization or 0.0] + [sc.extension(k) for k in EXTENSIONS])


def initial_state(sc: ContactScene) -> np.ndarray:
    q = quaternion(*sc.angles)
    w = np.array(sc.omega if sc.omega is not None else body_omega(sc.angles[1], sc.angles[2], *sc.rates))
    y = np.concatenate([q, w, np.zeros(6)])
    k = kernel(sc.shape, sc.law)
    p = params(sc)
    n3 = quaternion_matrix(q)[2, 2]
    if sc.stem is not None and sc.stem[1] * n3 - sc.stem[0] < sc.offset * n3 - sc.radius:
        p[5:7] = sc.stem  # the stem is the lower sphere: the body stands on it
    a = k.outputs(2, y, p, np.zeros(3))[_O["a_x"]:_O["a_z"] + 1]
    y[9] = -a[2]
    wi = quaternion_matrix(q) @ w
    v = -np.cross(wi, a)
    y[10:13] = v if sc.friction == "rolling" else (sc.vx, sc.vy, v[2])
    return y


@dataclass
class ContactResult:
    """The arrays of a contact run (the output file's), its phase history and its switches."""

    scene: ContactScene
    t: np.ndarray
    alpha: np.ndarray
    beta: np.ndarray
    gamma: np.ndarray
    omega: np.ndarray
    axis: np.ndarray
    energy: np.ndarray
    com: np.ndarray
    contact: np.ndarray
    normal_force: np.ndarray
    slip_speed: np.ndarray
    phase: np.ndarray
    gap: np.ndarray
    p_alpha: np.ndarray
    p_gamma: np.ndarray
    integrals: dict[str, np.ndarray]
    switches: list[Switch] = field(default_factory=list)
    nfev: int = 0
    method: str = COMPILED
    formulation: str = "contact"
    model: str = ""
    effects: tuple = (GRAVITY, "contact")

    @property
    def conserves_energy(self) -> bool:
        """Whether the physics keeps E (frictionless or rolling): then its change is drift."""
        return "energy" in self.integrals

    def plot_to(self, f, fmt: str = "png") -> None:
        """Draw the result's page (:func:`plot_page`) into the file object ``f``."""
        plot_page(self, f, fmt)

    def arrays(self) -> dict:
        """The output file's arrays (``integral_<name>`` for each integral the case has)."""
        out = {k: getattr(self, k) for k in ("t", "alpha", "beta", "gamma", "omega", "axis", "energy",
                                             "com", "contact", "normal_force", "slip_speed", "gap",
                                             "p_alpha", "p_gamma")}
        out["phase"] = self.phase.astype(str)
        out.update({f"integral_{k}": v for k, v in self.integrals.items()})
        out["switch_t"] = np.array([s.t for s in self.switches])
        out["switch_event"] = np.array([s.event for s in self.switches], dtype=str)
        out.update(method=np.array(self.method), formulation=np.array(self.formulation),
                   nfev=np.array(self.nfev))
        return out


def result(sc: ContactScene, run: Run, k, p, params_of=None) -> ContactResult:
    """The output arrays from a run's sampled states (``params_of(i)``: the kernel's parameters
    with sphere i touching, for a body with a stem)."""
    outs = k.outputs_many(run.phase, run.y, p, run.direction)
    if run.sphere is not None and params_of is not None and run.sphere.any():
        on = run.sphere == 1
        outs[on] = k.outputs_many(run.phase[on], run.y[on], params_of(1), run.direction[on])
        outs[~on] = k.outputs_many(run.phase[~on], run.y[~on], params_of(0), run.direction[~on])
    R = quaternion_matrix(run.y[:, :4])
    beta = np.arccos(np.clip(R[:, 2, 2], -1.0, 1.0))
    alpha = np.unwrap(np.arctan2(R[:, 1, 2], R[:, 0, 2]))
    gamma = np.unwrap(np.arctan2(R[:, 2, 1], -R[:, 2, 0]))
    com = run.y[:, 7:10]
    names = integrals_held(sc.shape, sc.law, sc.symmetric, sc.moments)
    return ContactResult(
        scene=sc, t=run.t, alpha=alpha, beta=beta, gamma=gamma, omega=run.y[:, 4:7].copy(),
        axis=R[:, :, 2].copy(), energy=outs[:, _O["energy"]], com=com.copy(),
        contact=com + outs[:, _O["a_x"]:_O["a_z"] + 1], normal_force=outs[:, _O["N"]],
        slip_speed=np.linalg.norm(outs[:, _O["slip_x"]:_O["slip_z"] + 1], axis=1),
        phase=np.array([PHASE_NAMES[i] for i in range(len(PHASE_NAMES))])[run.phase], gap=outs[:, _O["gap"]],
        p_alpha=outs[:, _O["p_alpha"]], p_gamma=outs[:, _O["p_gamma"]],
        integrals={n: outs[:, _O[n]] for n in names}, switches=run.switches, nfev=run.nfev,
        model=f"contact_{sc.shape}_{sc.law}", method=METHOD if sc.method == METHOD else COMPILED)


def simulate(sc: ContactScene) -> ContactResult:
    """Run a validated contact scene: the compiled method by the C phase driver
    (:mod:`derive.contact.driver`, one call), ``scipy-dop853`` by the reference stepper
    (:mod:`derive.contact.phases`, which states the switch rules). A frictionless axisymmetric
    body runs in the reduced formulation of :mod:`derive.contact.reduced` (p_α and p_γ held as
    parameters) while it serves, else in the full one."""
    k = kernel(sc.shape, sc.law)
    p = params(sc)
    t_out = np.linspace(0.0, sc.t_end, sc.samples)
    if reduced.eligible(sc):
        y0 = initial_state(sc)
        got = reduced.run(sc, y0, t_out, p, k)
        if got is not None:
            ys, nfev, nstep = got
            n = len(t_out)
            run = Run(t_out, ys, np.zeros(n, dtype=int), np.zeros((n, 3)), nfev=nfev, nstep=nstep)
            res = result(sc, run, k, p)
            res.formulation = reduced.FORMULATION
            return res
    if sc.method != METHOD:  # the C driver, the one an export ships, in one call
        run = driver.run(sc.shape, sc.law, p, sc.stem, initial_state(sc), t_out,
                         restitution=sc.restitution, rtol=sc.rtol, atol=sc.atol, max_steps=sc.max_steps)
        return result(sc, run, k, p, lambda i: sphere_params(p, sc.stem, i))
    ph = Phases(k, LAWS[sc.law], p, restitution=sc.restitution, rtol=sc.rtol, atol=sc.atol,
                max_steps=sc.max_steps, stem=sc.stem)
    k.nfev = 0
    run = ph.run(initial_state(sc), t_out)
    return result(sc, run, k, p, ph.params)


def sphere_params(p: np.ndarray, stem, i: int) -> np.ndarray:
    """The kernel's parameters with sphere ``i`` touching (1: the stem's radius and offset)."""
    q = np.array(p, dtype=float)
    if i == 1:
        q[5:7] = stem
    return q


def run_scene(data: dict, source: str = "<dict>", **overrides) -> ContactResult:
    """Validate a contact scene's dict and simulate it.

    Parameters
    ----------
    data : dict
        The scene, shaped like the TOML (``[body]``, ``[gravity]``, ``[contact]``, ``[initial]``,
        ``[simulate]``).
    source : str
        What names the scene in error messages (its file, or ``"<dict>"``).
    **overrides
        Replace keys of ``[simulate]`` (None: not given).

    Returns
    -------
    ContactResult
        The sampled motion (z-y-z angles, ω̃ in body axes, the centre of mass and contact point in
        inertial axes, N, the slip speed, the phase), the integrals the case has, the switches.

    Raises
    ------
    SceneError
        Bad input, naming the key. IntegrationError: numerical failure, saying where.
    """
    return simulate(read(data, source, **overrides))


def plot_page(res: ContactResult, f, fmt: str = "png") -> None:
    """One page: the tracks of the centre of mass and the contact on the table, the tilt β(t),
    N(t), the slip speed, the phase, and the relative change of E and of the integrals."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(2, 3, figsize=(13, 7.5))
    ax[0, 0].plot(res.contact[:, 0], res.contact[:, 1], lw=0.6, label="contact")
    ax[0, 0].plot(res.com[:, 0], res.com[:, 1], lw=1.0, label="centre of mass")
    ax[0, 0].set(xlabel="x (m)", ylabel="y (m)", title="tracks on the table", aspect="equal")
    ax[0, 0].legend(fontsize=8)
    ax[0, 1].plot(res.t, res.beta)
    ax[0, 1].set(xlabel="t (s)", ylabel="β (rad)", title="tilt")
    ax[0, 2].plot(res.t, res.normal_force)
    ax[0, 2].set(xlabel="t (s)", ylabel="N (N)", title="normal force")
    ax[1, 0].semilogy(res.t, np.maximum(res.slip_speed, 1e-18))
    ax[1, 0].set(xlabel="t (s)", ylabel="|u_t| (m/s)", title="slip speed")
    codes = {"slide": 0, "roll": 1, "flight": 2}
    ax[1, 1].step(res.t, [codes[str(p)] for p in res.phase], where="post")
    ax[1, 1].set(yticks=[0, 1, 2], yticklabels=list(codes), xlabel="t (s)", title="phase")
    for name, v in {"energy": res.energy, **res.integrals}.items():
        if name != "energy" or "energy" not in res.integrals:
            scale = abs(v[0]) if v[0] != 0 else 1.0
            ax[1, 2].plot(res.t, (v - v[0]) / scale, label=name)
    ax[1, 2].set(xlabel="t (s)", title="relative change")
    ax[1, 2].legend(fontsize=8)
    fig.suptitle(res.scene.title or f"{res.scene.shape}, {res.scene.law}")
    fig.tight_layout()
    fig.savefig(f, format=fmt)
    plt.close(fig)

