"""The frictionless plane reduced by its symmetries: α and γ cyclic, their momenta held exactly.

On a frictionless plane the contact force is vertical, so the centre of mass drifts uniformly
in x, y and its height is the constraint's z(β); for an axisymmetric body (I₁ = I₂, every shape
here is a body of revolution about ê₃) the Lagrangian

    L = ½ M ż² + ½ I₁ (β̇² + α̇² sin²β) + ½ I₃ (γ̇ + α̇ cos β)² − M g z(β),  ż = z′(β) β̇,

has α and γ cyclic: p_α = ∂L/∂α̇ = L·ẑ and p_γ = ∂L/∂γ̇ = I₃ ω₃ are constants of the motion.
Routh's reduction keeps them as parameters and leaves one degree of freedom,

    α̇ = (p_α − p_γ cos β)/(I₁ sin²β),   γ̇ = p_γ/I₃ − α̇ cos β,
    d/dt ∂R/∂β̇ = ∂R/∂β  (R = L − p_α α̇ − p_γ γ̇, solved for β̈),
    N = M (g + z̈) = M (g + z″ β̇² + z′ β̈),

derived (:mod:`derive.contact.sources`) from the shape's z(β) (:func:`derive.contact.geometry.height_in_angles`). The state
(cos α, sin α, β, cos γ, sin γ, β̇) is integrated by the same compiled phase loop, with the
lift-off event N = 0: α and γ as points on the unit circle, bounded, so that the loop's
relative error control holds them as tightly at every time (as angles they grow without bound
and a relative tolerance on them would loosen with time). p_α and p_γ are not states, so no
step can move them: what the symmetry keeps, the formulation keeps. The chart is singular where sin β = 0, which a motion reaches only when p_α = ±p_γ;
:func:`run` declines a start near it, a motion that comes near it, and a lift-off (the full
formulation, the phase driver of :mod:`derive.contact.driver`, then runs the scene from the
start).
"""
from __future__ import annotations

import ctypes
import functools

import numpy as np

from derive.contact.kernel import OUTPUTS, reduced_sources
from derive.contact.phases import quaternion_matrix
from derive.contact.scene import METHOD
from derive.errors import IntegrationError
from derive.methods.status import Status
from derive.reference.rotation import body_omega
from derive.runtime.cbuild import compile_library
from derive.runtime.records import bind, guarded, sigint_guard

#: The parameters, in order (:data:`derive.contact.sources.REDUCED_PARAMS`, the symbols' names).
PARAM_NAMES = ("I1", "I3", "M", "g", "r", "s", "p_alpha", "p_gamma")
STATE = ("cos_alpha", "sin_alpha", "beta", "cos_gamma", "sin_gamma", "beta_dot")
#: The result's ``formulation`` when this chart ran.
FORMULATION = "contact-reduced"
#: sin β below this (a start or a sample) hands the scene to the full formulation.
POLE = 1e-2


class ReducedKernel:
    """The loaded reduced evaluator and its phase loop."""

    def __init__(self, shape: str):
        name = f"contact_{shape}_reduced"
        lib = compile_library(name, reduced_sources(shape), f"{name}.c")
        self.fn = bind(lib, f"{name}_eval", [ctypes.c_int] + [ctypes.c_void_p] * 5)
        self.many = bind(lib, f"{name}_many", [ctypes.c_long] + [ctypes.c_void_p] * 4, ctypes.c_long)
        vp, cd = ctypes.c_void_p, ctypes.c_double
        self.step = bind(lib, f"{name}_advance", [ctypes.c_int, vp, vp, cd, vp, vp, cd, cd, vp, ctypes.c_long,
                                                  ctypes.c_int, vp, vp, ctypes.c_long] + [vp] * 5)
        self.lib = lib

    def rates(self, y: np.ndarray, p: np.ndarray) -> np.ndarray:
        """(α̇, β̇, γ̇, β̈) and (N, z, ż) at each row of ``y``."""
        y = np.ascontiguousarray(y, dtype=float)
        dy, out = np.empty_like(y), np.empty((len(y), len(OUTPUTS)))
        if self.many(len(y), y.ctypes.data, p.ctypes.data, dy.ctypes.data, out.ctypes.data):
            raise FloatingPointError("the reduced chart is singular here (sin β = 0)")
        res = np.empty((len(y), 7))
        # a rate on the unit circle: θ̇ = (c ṡ − s ċ)/(c² + s²)
        res[:, 0] = (y[:, 0] * dy[:, 1] - y[:, 1] * dy[:, 0]) / (y[:, 0] ** 2 + y[:, 1] ** 2)
        res[:, 2] = (y[:, 3] * dy[:, 4] - y[:, 4] * dy[:, 3]) / (y[:, 3] ** 2 + y[:, 4] ** 2)
        res[:, 1], res[:, 3] = dy[:, 2], dy[:, 5]
        res[:, 4:] = out[:, [OUTPUTS.index("N"), OUTPUTS.index("z"), OUTPUTS.index("vz")]]
        return res


@functools.lru_cache(maxsize=None)
def kernel(shape: str) -> ReducedKernel:
    return ReducedKernel(shape)


def quaternions(alpha, beta, gamma) -> np.ndarray:
    """(n, 4) unit quaternions of R_z(α) R_y(β) R_z(γ) (z-y-z, body → inertial)."""
    c, s_ = np.cos(beta / 2), np.sin(beta / 2)
    return np.column_stack([c * np.cos((alpha + gamma) / 2), -s_ * np.sin((alpha - gamma) / 2),
                            s_ * np.cos((alpha - gamma) / 2), c * np.sin((alpha + gamma) / 2)])


def eligible(sc) -> bool:
    """Whether a scene is the reduced problem's: frictionless, axisymmetric, one contact surface,
    the compiled loop."""
    return sc.law == "none" and sc.symmetric and sc.stem is None and sc.method != METHOD


def run(sc, y0: np.ndarray, t_out: np.ndarray, p_full: np.ndarray, full):
    """The reduced integration of a frictionless axisymmetric scene from the full state ``y0``
    (quaternion, body ω, centre of mass and its velocity), sampled at ``t_out``, as full states
    ((n, 13), with nfev and the accepted steps), or None where the reduced chart does not serve
    (sin β below :data:`POLE` at the start or a sample, N < 0 at the start, or a lift-off): then
    the full formulation runs the scene.

    ``full`` is the full kernel with its parameters ``p_full`` (its outputs give p_α and p_γ at
    the start)."""
    R0 = quaternion_matrix(y0[:4])
    b0 = float(np.arccos(np.clip(R0[2, 2], -1.0, 1.0)))
    if np.sin(b0) < POLE:
        return None
    a0, g0 = float(np.arctan2(R0[1, 2], R0[0, 2])), float(np.arctan2(R0[2, 1], -R0[2, 0]))
    w = y0[4:7]
    bd0 = w[0] * np.sin(g0) + w[1] * np.cos(g0)
    o = full.outputs(0, y0, p_full, np.zeros(3))
    if o[OUTPUTS.index("N")] < 0:
        return None  # it leaves the table at once
    pa, pg = o[OUTPUTS.index("p_alpha")], o[OUTPUTS.index("p_gamma")]
    p = np.array([sc.I1, sc.I3, sc.M, sc.g, sc.radius, sc.offset, pa, pg])
    k = kernel(sc.shape)
    y = np.array([np.cos(a0), np.sin(a0), b0, np.cos(g0), np.sin(g0), bd0])
    ys = np.empty((len(t_out), len(STATE)))
    ys[0] = y
    t, h, its, which = ctypes.c_double(0.0), ctypes.c_double(0.0), ctypes.c_long(1), ctypes.c_int(-1)
    counts = np.zeros(2, dtype=np.int_)
    events, ref, d = np.array([1], dtype=np.intc), np.zeros(3), np.zeros(3)
    ts = np.ascontiguousarray(t_out, dtype=float)
    code = guarded(sigint_guard(k.lib), k.step, 0, ctypes.addressof(t), y.ctypes.data, float(t_out[-1]),
                   p.ctypes.data, d.ctypes.data, sc.rtol, sc.atol, ctypes.addressof(h), sc.max_steps, 1,
                   events.ctypes.data, ref.ctypes.data, len(ts), ts.ctypes.data, ctypes.addressof(its),
                   ys.ctypes.data, ctypes.addressof(which), counts.ctypes.data)
    if code == Status.INTERRUPTED:  # a request from another thread, unguarded
        raise KeyboardInterrupt
    if code == 1 or (code == 4 and np.sin(y[2]) < POLE):
        return None  # lift-off, or the chart's pole: the full formulation runs it
    if code == 2:
        raise IntegrationError(f"t = {t.value:.8g}: the step budget is spent (slide)")
    if code == 3:
        raise IntegrationError(f"t = {t.value:.8g}: the step size fell below the spacing of doubles (slide)")
    if code == 4:
        raise IntegrationError(f"t = {t.value:.8g}: the state is not finite (slide)")
    if np.min(np.sin(ys[:, 2])) < POLE:
        return None
    r = k.rates(ys, p)
    a, b, g = np.arctan2(ys[:, 1], ys[:, 0]), ys[:, 2], np.arctan2(ys[:, 4], ys[:, 3])
    om = np.column_stack(body_omega(b, g, r[:, 0], r[:, 1], r[:, 2]))
    n = len(ts)
    com = np.column_stack([y0[7] + y0[10] * ts, y0[8] + y0[11] * ts, r[:, 5]])
    vel = np.column_stack([np.full(n, y0[10]), np.full(n, y0[11]), r[:, 6]])
    return np.column_stack([quaternions(a, b, g), om, com, vel]), int(counts[1]), int(counts[0])
