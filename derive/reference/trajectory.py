"""What the closed-form solutions share: the :class:`Trajectory` they return, the z-y-z rotation
matrix and its angles, and the checks of their arguments (conventions: :mod:`derive.reference.exact`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

import numpy as np

from derive.reference.rotation import euler_angles


_EPS = float(np.finfo(float).eps)


# Closest approach to a pole (in rad) below which p_alpha -+ p_gamma is treated as zero.
_POLE_SNAP = 16 * _EPS


@dataclass(frozen=True)
class Trajectory:
    """Samples of an exact solution at the times t (n samples).

    omega (n, 3) body angular velocity; R (n, 3, 3) body -> inertial; axis (n, 3) = R[:, :, 2];
    alpha, beta, gamma (n,) z-y-z Euler angles (continuous, see the module docstring);
    energy = 1/2 sum I_i w_i^2 + M g l axis_z, p_alpha = (R I omega)_z (inertial z component of
    the angular momentum), p_gamma = I3 w3 - all three computed from the returned omega and R,
    so their constancy is a check of the solution, not an assumption.
    inertia = (I1, I2, I3), mgl = M g l (0 for free bodies); info holds solution parameters
    (regime, elliptic parameter, periods, roots) for inspection.
    """

    t: np.ndarray
    omega: np.ndarray
    R: np.ndarray
    axis: np.ndarray
    alpha: np.ndarray
    beta: np.ndarray
    gamma: np.ndarray
    energy: np.ndarray
    p_alpha: np.ndarray
    p_gamma: np.ndarray
    inertia: tuple[float, float, float]
    mgl: float
    info: Mapping[str, object]


def _axis_angle(n, theta):
    """Rotation by theta (array) about the unit vector n: I + sin th [n]x + 2 sin^2(th/2) [n]x^2."""
    n = np.asarray(n, dtype=float)
    K = np.array([[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]])
    th = np.asarray(theta, dtype=float)[..., None, None]
    return np.eye(3) + np.sin(th) * K + 2.0 * np.sin(0.5 * th) ** 2 * (K @ K)


def _positive(**kw):
    out = []
    for name, v in kw.items():
        v = float(v)
        if not (math.isfinite(v) and v > 0):
            raise ValueError(f"{name} must be positive and finite, got {v!r}")
        out.append(v)
    return out


def _finite(**kw):
    out = []
    for name, v in kw.items():
        v = float(v)
        if not math.isfinite(v):
            raise ValueError(f"{name} must be finite, got {v!r}")
        out.append(v)
    return out


def _times(t):
    t = np.atleast_1d(np.asarray(t, dtype=float))
    if t.ndim != 1 or not np.all(np.isfinite(t)):
        raise ValueError("t must be a finite scalar or 1-d array")
    return t


def _vector(w, name="omega0"):
    w = np.asarray(w, dtype=float)
    if w.shape != (3,) or not np.all(np.isfinite(w)):
        raise ValueError(f"{name} must be 3 finite numbers")
    return w


def _rotation_matrix(R0):
    if R0 is None:
        return np.eye(3)
    R0 = np.asarray(R0, dtype=float)
    if R0.shape != (3, 3) or not np.all(np.isfinite(R0)):
        raise ValueError("R0 must be a finite 3x3 matrix")
    if np.max(np.abs(R0.T @ R0 - np.eye(3))) > 1e-9 or np.linalg.det(R0) < 0:
        raise ValueError("R0 must be a rotation matrix (orthogonal, det +1)")
    return R0


def _trajectory(t, omega, R, inertia, mgl, info, angles=None):
    inertia = tuple(float(x) for x in inertia)
    Iw = omega * np.asarray(inertia)
    energy = 0.5 * np.sum(Iw * omega, axis=1) + mgl * R[:, 2, 2]
    p_alpha = np.einsum("nj,nj->n", R[:, 2, :], Iw)
    alpha, beta, gamma = euler_angles(R) if angles is None else angles
    return Trajectory(t=t, omega=omega, R=R, axis=R[:, :, 2].copy(), alpha=alpha, beta=beta,
                      gamma=gamma, energy=energy, p_alpha=p_alpha, p_gamma=Iw[:, 2].copy(),
                      inertia=inertia, mgl=float(mgl), info=MappingProxyType(dict(info)))
