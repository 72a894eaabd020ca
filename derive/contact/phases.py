"""The phases slide, roll and flight as separate vector fields, joined by located events: the
switch rules, and the reference stepper ``scipy-dop853`` that applies them from Python.

The product path is C: ``derive simulate``'s compiled method, ``derive export`` and the FMU run
the phase driver ``contact_run.inc`` (:mod:`derive.contact.driver`), which integrates each phase
with the compiled phase loop and applies these rules between its located events. This module
states the rules and keeps them as the reference the targets compare with: :class:`Phases`
integrates each phase with SciPy's DOP853 calling the compiled right-hand side (the same step
control, so the same steps as the C loop), evaluates the phase's event functions at four points
of each accepted step's dense output and locates the first sign change with Brent's method (the
C loop uses Illinois), and applies the rules below in Python. The rules:

* slide → roll (exact Coulomb, event ``stick``): the slip u_t reverses along the direction it had
  at the step's start, g = u_t(t)·u_t(t_k)/|u_t(t_k)| + δ ≤ 0, δ = 1e-12 (|v| + |ω||a|) the
  slip's round-off floor (below it u_t has no direction: the event is armed once the slip at a
  step's start exceeds δ, and the sliding force keeps the direction it started with). A slip
  still below max(δ, rtol (|v| + |ω||a|)) at a step's end while the rolling force is inside
  the cone sticks there too (a slip that began on the cone's edge and did not grow, or one that
  spirals into zero, its direction turning without reversing). The slip is set to zero (the
  centre of mass's horizontal velocity takes the difference, so Jellett's J, which has no v,
  is untouched) and the rolling force is computed: inside the cone |F_t| ≤ μN the body
  rolls, outside it slides on in the predicted direction (below).
* roll → slide (event ``slip``): the rolling force leaves the cone, g = μN − |F_t| ≤ 0. It
  slides with d = −F_t/|F_t|: on the cone the sliding force −μN d is the rolling force, so the
  contact force is continuous and the slip grows from zero (a slip acceleration along d would
  need the cone to be left by a finite amount, which it is not at the event).
* slide → slide (a slip reversal where rolling would leave the cone): the slip restarts in the
  predicted direction d along which −μN d makes it grow, found by a fixed point
  d ← u̇_t(d)/|u̇_t(d)| from d = −F_t/|F_t|.
* slide or roll → flight (event ``lift-off``): N ≤ 0. The body flies as a free body.
* flight → contact (event ``landing``): the gap z + a·n ≤ 0. An impact law changes the
  velocities at once: a normal impulse P ẑ with restitution e (u_n⁺ = −e u_n⁻) on a frictionless
  or sliding contact, the whole impulse that stops the contact point (u⁺ = 0) for rolling;
  then the contact phase is chosen as at the start.
* ball ↔ stem (event ``touch``, a body with a second sphere, the tippe top's stem): the other
  sphere's gap z + s₂ n₃ − r₂ ≤ 0, in any phase. The spheres change roles (the kernel's r, s
  become the other sphere's: both are spheres under the same law), the new contact takes the
  impact above, and the contact phase is chosen as at the start; the sphere that touched
  before leaves the plane with no impulse of its own (a contact on both spheres at once is not
  modelled: the run would switch back at once, and ``max_switches`` ends it).

A run records every switch (time, from, to, event) and refuses more than ``max_switches``.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from derive.contact.kernel import OUTPUTS, PARAM_NAMES, PHASES, Kernel
from derive.contact.laws import Law
from derive.errors import IntegrationError

_O = {name: i for i, name in enumerate(OUTPUTS)}
SLIDE, ROLL, FLIGHT = PHASES["slide"], PHASES["roll"], PHASES["flight"]
PHASE_NAMES = {v: k for k, v in PHASES.items()}


@dataclass
class Switch:
    """One phase change: when, from what to what, by which event, and the energy across it."""

    t: float
    before: str
    after: str
    event: str
    energy_before: float
    energy_after: float


@dataclass
class Run:
    """What the event-driven integration gives: the samples, their phases and the switches."""

    t: np.ndarray
    y: np.ndarray
    phase: np.ndarray
    direction: np.ndarray
    switches: list[Switch] = field(default_factory=list)
    #: Which sphere touches at each sample (0 the first, 1 the stem); None without a stem.
    sphere: np.ndarray | None = None
    nfev: int = 0
    nstep: int = 0


def quaternion_matrix(q: np.ndarray) -> np.ndarray:
    """R(q), body → inertial, for a quaternion (normalised here), or (n, 3, 3) for n of them."""
    q = np.asarray(q, dtype=float)
    q0, q1, q2, q3 = np.moveaxis(q / np.linalg.norm(q, axis=-1, keepdims=True), -1, 0)
    R = np.stack([
        1 - 2 * (q2 * q2 + q3 * q3), 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2),
        2 * (q1 * q2 + q0 * q3), 1 - 2 * (q1 * q1 + q3 * q3), 2 * (q2 * q3 - q0 * q1),
        2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), 1 - 2 * (q1 * q1 + q2 * q2)], axis=-1)
    return R.reshape(q.shape[:-1] + (3, 3))


class Phases:
    """The event-driven integrator of one scene's model (a kernel, a law and its numbers)."""

    def __init__(self, k: Kernel, law: Law, p: np.ndarray, restitution: float = 0.0,
                 rtol: float = 1e-10, atol: float = 1e-12, max_steps: int = 1_000_000,
                 max_switches: int = 10_000, stem=None):
        self.k, self.law = k, law
        #: (radius, offset) of each sphere the body may touch with; the kernel's p[5:7] is the
        #: touching one's, the two after the model's parameters the other's (read by the
        #: ``touch`` event)
        self.spheres = [(float(p[5]), float(p[6]))] + ([tuple(map(float, stem))] if stem else [])
        self.base = np.array(p[:len(PARAM_NAMES)], dtype=float)
        self.active = 0
        self.p = self.params(0)
        self.e, self.rtol, self.atol = restitution, rtol, atol
        self.max_steps, self.max_switches = max_steps, max_switches
        self.mu = p[7]

    def params(self, i: int) -> np.ndarray:
        """The kernel's parameters with sphere ``i`` touching (the other's after them)."""
        p = self.base.copy()
        p[5:7] = self.spheres[i]
        if len(self.spheres) > 1:
            p = np.concatenate([p, self.spheres[1 - i]])
        return np.ascontiguousarray(p)

    def lowest(self, y: np.ndarray) -> int:
        """The sphere whose lowest point is lower (the one the body stands on)."""
        n3 = quaternion_matrix(y[:4])[2, 2]
        return int(np.argmin([s * n3 - r for r, s in self.spheres]))

    # ---- what the kernel says at a state
    def out(self, phase, y, d):
        return self.k.outputs(phase, y, self.p, d)

    def slip(self, phase, y, d):
        """The slip u_t, inertial, of the body touching the plane (kinematic: any contact phase)."""
        o = self.out(SLIDE if self.law.slides else ROLL, y, d)
        return o[_O["slip_x"]:_O["slip_z"] + 1]

    # ---- events: name -> g(phase, y, d, ref); an event fires when g goes from ≥ 0 to < 0
    def events(self, phase: int) -> list[str]:
        touch = ["touch"] if len(self.spheres) > 1 else []
        if phase == FLIGHT:
            return ["landing"] + touch
        names = ["lift-off"]
        if self.law.switches:
            names.append("stick" if phase == SLIDE else "slip")
        return names + touch

    def g(self, name, phase, y, d, ref):
        o = self.out(phase, y, d)
        if name == "landing":
            return o[_O["gap"]]
        if name == "lift-off":
            return o[_O["N"]]
        if name == "slip":
            return self.mu * o[_O["N"]] - np.linalg.norm(o[_O["ft_x"]:_O["ft_z"] + 1])
        if name == "touch":
            r, s = self.spheres[1 - self.active]
            return o[_O["z"]] + s * quaternion_matrix(y[:4])[2, 2] - r
        return float(o[_O["slip_x"]:_O["slip_z"] + 1] @ ref) + o[_O["slip_floor"]]  # stick

    def stick_reference(self, phase, y, d) -> np.ndarray:
        """The slip's direction at a step's start, which the stick event watches reverse; zero
        (the event not armed) while the slip is below its round-off floor, as just after it
        starts from zero, when it has no direction of its own yet."""
        o = self.out(phase, y, d)
        s = o[_O["slip_x"]:_O["slip_z"] + 1]
        n = np.linalg.norm(s)
        return s / n if n > max(1.0, self.rtol * 1e12) * o[_O["slip_floor"]] else np.zeros(3)

    def rolls_inside_cone(self, y, d) -> bool:
        """Whether the rolling force at ``y`` is inside the friction cone, |F_t| ≤ μN."""
        o = self.out(ROLL, y, d)
        return bool(np.linalg.norm(o[_O["ft_x"]:_O["ft_z"] + 1]) <= self.mu * o[_O["N"]])

    # ---- the switch rules
    def predicted_direction(self, y: np.ndarray, ft: np.ndarray) -> np.ndarray:
        """The slip direction d at zero slip along which −μN d makes the slip grow."""
        d = -ft / np.linalg.norm(ft)
        for _ in range(30):
            dy = self.k.rhs(SLIDE, y, self.p, d)
            h = 1e-7 * max(1.0, 1.0 / max(np.linalg.norm(y[4:7]), 1e-300))
            acc = (self.slip(SLIDE, y + h * dy, d) - self.slip(SLIDE, y - h * dy, d)) / (2 * h)
            new = acc / np.linalg.norm(acc)
            if np.linalg.norm(new - d) < 1e-12:
                return new
            d = new
        return d

    def touching(self, y: np.ndarray, phase: int, d: np.ndarray) -> np.ndarray:
        """The state with z and v_z those the contact sets, and rolling the whole velocity
        v = −ω × a (the values the phase reads in place of the integrated ones)."""
        o = self.out(phase, y, d)
        y = y.copy()
        y[9:13] = o[_O["z"]:_O["vz"] + 1]
        return y

    def stop_slip(self, y: np.ndarray, d: np.ndarray) -> np.ndarray:
        """The state with the contact point's slip removed (the horizontal velocity adjusted)."""
        y = y.copy()
        y[10:13] -= self.slip(SLIDE, y, d)
        return y

    def contact_phase(self, y: np.ndarray, d: np.ndarray) -> tuple[int, np.ndarray]:
        """The phase a body touching the plane takes at ``y``, and its slip direction."""
        if not self.law.rolls:
            return SLIDE, d
        if self.law.slides:
            o = self.out(SLIDE, y, d)
            s = o[_O["slip_x"]:_O["slip_z"] + 1]
            if np.linalg.norm(s) > o[_O["slip_floor"]]:
                return SLIDE, s / np.linalg.norm(s)
            y[:] = self.stop_slip(y, d)
            o = self.out(ROLL, y, d)
            ft = o[_O["ft_x"]:_O["ft_z"] + 1]
            if np.linalg.norm(ft) <= self.mu * o[_O["N"]]:
                return ROLL, d
            return SLIDE, self.predicted_direction(y, ft)
        y[:] = self.stop_slip(y, d)
        return ROLL, d

    def impact(self, y: np.ndarray) -> np.ndarray:
        """The velocities just after landing (the impact law), positions unchanged."""
        y = y.copy()
        o = self.out(FLIGHT, y, np.zeros(3))
        a = o[_O["a_x"]:_O["a_z"] + 1]
        R = quaternion_matrix(y[:4])
        inertia = np.diag(self.p[:3])
        inv_in = R @ np.linalg.inv(inertia) @ R.T
        ax = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
        K = np.eye(3) / self.p[3] - ax @ inv_in @ ax
        u = y[10:13] + np.cross(R @ y[4:7], a)
        if self.law.name == "rolling":
            P = -np.linalg.solve(K, u)
        else:
            P = np.array([0.0, 0.0, -(1 + self.e) * u[2] / K[2, 2]])
        y[10:13] += P / self.p[3]
        y[4:7] += np.linalg.solve(inertia, R.T @ np.cross(a, P))
        return y

    # ---- the integration
    def run(self, y0: np.ndarray, t_out: np.ndarray, direction=(1.0, 0.0, 0.0)) -> Run:
        """Integrate from the state ``y0`` at t = 0, sampling at ``t_out`` (ascending, last = t_end).

        Parameters
        ----------
        y0 : ndarray, shape (13,)
            q (body → inertial quaternion), ω̃ (body), the centre of mass and its velocity
            (inertial), touching the plane (z = −a·n, v_z = −(ω × a)·ẑ).
        t_out : ndarray
            The sample times.
        direction : sequence of 3 floats
            The slip direction (inertial) exact Coulomb friction starts with when the slip is
            zero and the body cannot roll.

        Returns
        -------
        Run
            The sampled states with their phase and slip direction, every switch, the counts.

        Raises
        ------
        IntegrationError
            Step budget spent, step size underflow, a singular contact, a non-finite state, or
            more than ``max_switches`` switches, with the time.
        """
        t_end = float(t_out[-1])
        d = np.asarray(direction, dtype=float)
        y = np.array(y0, dtype=float)
        phase, d = self.start(y, d)
        ys = np.empty((len(t_out), len(y)))
        phases = np.empty(len(t_out), dtype=int)
        dirs = np.empty((len(t_out), 3))
        nxt = 0
        while nxt < len(t_out) and t_out[nxt] <= 0.0:
            ys[nxt], phases[nxt], dirs[nxt] = y, phase, d
            nxt += 1
        run = Run(t_out, ys, phases, dirs, sphere=np.full(len(t_out), self.active))
        t = 0.0
        while t < t_end:
            t, y, new = self._phase(run, phase, t, y, d, t_end, nxt)
            nxt = new[0]
            if new[1] is None:
                break
            event = new[1]
            e0 = self.out(phase, y, d)[_O["energy"]]
            before = PHASE_NAMES[phase]
            if event == "lift-off":  # the height and its rate the contact set become states
                y = self.touching(y, phase, d)
                phase = FLIGHT
            elif event in ("landing", "touch"):
                if event == "touch":  # the other sphere meets the plane: it becomes the contact
                    self.active = 1 - self.active
                    self.p = self.params(self.active)
                    event = "stem" if self.active else "ball"
                y = self.impact(y)
                phase, d = self.contact_phase(y, d)
                if phase != FLIGHT and self.out(phase, y, d)[_O["N"]] < 0:
                    phase = FLIGHT
            elif event == "stick":
                phase, d = self.contact_phase(self.stop_slip(y, d), d)
                y = self.stop_slip(y, d)
            else:  # slip: on the cone, the sliding force −μN d takes over the rolling force
                ft = self.out(ROLL, y, d)[_O["ft_x"]:_O["ft_z"] + 1]
                d = -ft / np.linalg.norm(ft)
                phase = SLIDE
            run.switches.append(Switch(t, before, PHASE_NAMES[phase], event, float(e0),
                                       float(self.out(phase, y, d)[_O["energy"]])))
            if len(run.switches) > self.max_switches:
                raise IntegrationError(f"more than {self.max_switches} phase switches by t = {t:.8g} "
                                       f"(last: {event})")
        run.nfev += self.k.nfev
        return run

    def start(self, y: np.ndarray, d: np.ndarray) -> tuple[int, np.ndarray]:
        self.active = self.lowest(y)
        self.p = self.params(self.active)
        phase, d = self.contact_phase(y, d)
        if self.out(phase, y, d)[_O["N"]] < 0:
            return FLIGHT, d
        return phase, d

    def _phase(self, run: Run, phase, t0, y0, d, t_end, nxt):
        """Integrate one phase from (t0, y0) until an event or t_end; fills the samples."""
        # SciPy is the reference stepper's alone: the compiled method never loads it.
        from scipy.integrate import DOP853
        from scipy.optimize import brentq

        k, p = self.k, self.p
        events = self.events(phase)
        solver = DOP853(lambda t, y: k.rhs(phase, y, p, d), t0, y0, t_end, rtol=self.rtol,
                        atol=self.atol)
        ref = self.stick_reference(phase, y0, d)
        g_old = {name: self.g(name, phase, y0, d, ref) for name in events}
        while solver.status == "running":
            try:
                msg = solver.step()
            except FloatingPointError as err:
                raise IntegrationError(f"t = {solver.t:.8g}: {err}") from None
            if solver.status == "failed":
                raise IntegrationError(f"t = {solver.t:.8g}: {msg}")
            run.nstep += 1
            if run.nstep > self.max_steps:
                raise IntegrationError(f"t = {solver.t:.8g}: step budget of {self.max_steps} spent")
            if not np.all(np.isfinite(solver.y)):
                raise IntegrationError(f"t = {solver.t:.8g}: non-finite state")
            ta, tb = solver.t_old, solver.t
            dense = solver.dense_output()
            hit = None
            for name in events:
                g = lambda t, name=name: self.g(name, phase, dense(t), d, ref)
                ts = np.linspace(ta, tb, 5)[1:]
                prev_t, prev = ta, g_old[name]
                for tt in ts:
                    cur = g(tt)
                    if prev >= 0 and cur < 0:
                        if prev == 0.0:
                            root = prev_t
                        else:
                            root = brentq(g, prev_t, tt, xtol=1e-15 * max(1.0, abs(tt)), rtol=1e-15)
                        if hit is None or root < hit[0]:
                            hit = (root, name)
                        break
                    prev_t, prev = tt, cur
            stop = hit[0] if hit else tb
            while nxt < len(run.t) and run.t[nxt] <= stop:
                ys = dense(run.t[nxt])
                run.y[nxt] = ys if phase == FLIGHT else self.touching(ys, phase, d)
                run.phase[nxt], run.direction[nxt], run.sphere[nxt] = phase, d, self.active
                nxt += 1
            if hit:
                y_hit = dense(hit[0])
                return hit[0], y_hit if phase == FLIGHT else self.touching(y_hit, phase, d), (nxt, hit[1])
            y_new = solver.y
            g_old = {name: self.g(name, phase, y_new, d, ref) for name in events}
            if "stick" in events:
                ref = self.stick_reference(phase, y_new, d)
                if not ref.any() and self.rolls_inside_cone(y_new, d):
                    return solver.t, self.touching(y_new, phase, d), (nxt, "stick")
                g_old["stick"] = self.g("stick", phase, y_new, d, ref)
        return solver.t, solver.y, (nxt, None)
