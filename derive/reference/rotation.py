"""The orientation matrix of z-y-z Euler angles and back, in NumPy (nothing heavier).

R(α, β, γ) = Rz(α) Ry(β) Rz(γ) with active elementary rotations maps body components to
inertial ones (v_inertial = R v_body); its third column is the body axis ê₃. The closed-form
references (:mod:`derive.reference.exact`) and the drawing of a motion
(:mod:`derive.sim.animate`) both turn bodies with it.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["euler_matrix", "euler_angles", "body_omega"]


def _rz(a):
    a = np.asarray(a, dtype=float)
    c, s = np.cos(a), np.sin(a)
    o, z = np.ones_like(a), np.zeros_like(a)
    return np.stack([np.stack([c, -s, z], -1), np.stack([s, c, z], -1), np.stack([z, z, o], -1)], -2)


def _ry(b):
    b = np.asarray(b, dtype=float)
    c, s = np.cos(b), np.sin(b)
    o, z = np.ones_like(b), np.zeros_like(b)
    return np.stack([np.stack([c, z, s], -1), np.stack([z, o, z], -1), np.stack([-s, z, c], -1)], -2)


def euler_matrix(alpha, beta, gamma):
    """R = Rz(alpha) Ry(beta) Rz(gamma) (body -> inertial), broadcast over the angles."""
    return _rz(alpha) @ _ry(beta) @ _rz(gamma)


def euler_angles(R, unwrap=True):
    """z-y-z angles of rotation matrices R (..., 3, 3): beta = atan2(|R[:2, 2]|, R[2, 2]) in
    [0, pi], alpha = atan2(R[1, 2], R[0, 2]), gamma = atan2(R[2, 1], -R[2, 0]); where sin(beta)
    is zero only alpha + gamma is defined and alpha is set to 0. With unwrap (samples along the
    first axis, ordered in time) alpha and gamma are unwrapped; near beta = 0 they are
    ill-conditioned and may still jump by pi between samples."""
    R = np.asarray(R, dtype=float)
    sb = np.hypot(R[..., 0, 2], R[..., 1, 2])
    beta = np.arctan2(sb, R[..., 2, 2])
    degenerate = sb == 0.0
    alpha = np.where(degenerate, 0.0, np.arctan2(R[..., 1, 2], R[..., 0, 2]))
    gamma = np.where(degenerate, np.arctan2(R[..., 1, 0], R[..., 0, 0]),
                     np.arctan2(R[..., 2, 1], -R[..., 2, 0]))
    if unwrap and R.ndim == 3:
        alpha, gamma = np.unwrap(alpha), np.unwrap(gamma)
    return alpha, beta, gamma


def body_omega(beta, gamma, alpha_dot, beta_dot, gamma_dot):
    """Body-frame angular velocity (rad/s) from z-y-z Euler-angle rates (the notes' formula):

        w1 = -alpha_dot sin(beta) cos(gamma) + beta_dot sin(gamma)
        w2 =  alpha_dot sin(beta) sin(gamma) + beta_dot cos(gamma)
        w3 =  alpha_dot cos(beta) + gamma_dot

    The one place it is written: the validator calls it on floats, a sweep on its columns
    (NumPy arrays of N points). Either way the sines and cosines are the math module's (libm),
    element by element, so a point of a sweep gets the bits a scene of its own gets. Returns a
    tuple (w1, w2, w3) of floats or of arrays.
    """
    sin, cos = (math.sin, math.cos) if isinstance(beta, float) and isinstance(gamma, float) \
        else (_libm(math.sin), _libm(math.cos))
    sb, sg, cg = sin(beta), sin(gamma), cos(gamma)
    return (-alpha_dot * sb * cg + beta_dot * sg,
            alpha_dot * sb * sg + beta_dot * cg,
            alpha_dot * cos(beta) + gamma_dot)


def _libm(fn):
    """``fn`` (a function of the math module) of every element of an array (NumPy's own
    vectorised sin and cos may differ from libm in the last bit)."""
    def each(x):
        x = np.asarray(x, dtype=float)
        return np.fromiter(map(fn, x.reshape(-1).tolist()), dtype=float, count=x.size).reshape(x.shape)
    return each
