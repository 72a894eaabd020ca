"""The right-hand sides a SciPy user writes by hand: the baselines of `derive bench`.

Plain Python, scalar, the ``math`` module, a list returned: the fastest right-hand side
``scipy.integrate.solve_ivp`` can be given without compiling anything. Two formulations, the
ones most favourable to SciPy:

* **Euler angles** (z-y-z, α about inertial z, β about y′, γ about body 3), for the symmetric top
  with its centre of mass on the symmetry axis at distance l from the pivot. From the Lagrangian
  L = ½ I₁ (α̇² sin²β + β̇²) + ½ I₃ ω̃₃² − M g l cos β, ω̃₃ = α̇ cos β + γ̇, the Euler–Lagrange
  equations solved for the accelerations::

      α̈ = β̇ (I₃ ω̃₃ − 2 I₁ α̇ cos β) / (I₁ sin β)
      β̈ = (I₁ α̇² sin β cos β − I₃ ω̃₃ α̇ sin β + M g l sin β) / I₁
      γ̈ = −α̈ cos β + α̇ β̇ sin β

  y = (α, β, γ, α̇, β̇, γ̇). Six states, two trig calls. M g l = 0 is the free symmetric body.
* **Quaternion + Euler's equations** for any body (I₁, I₂, I₃ principal moments about the
  pivot), gravity optional (centre of mass on body axis 3 at distance l): q scalar first, body
  to inertial, q̇ = ½ q ⊗ (0, ω̃); I ω̃̇ = (I ω̃) × ω̃ + τ̃ with the gravity torque
  τ̃ = M g l (k₂, −k₁, 0), k = Rᵀ ẑ the vertical in body axes. y = (q₀, q₁, q₂, q₃, ω̃₁, ω̃₂, ω̃₃);
  no trig call, no singularity.

Each ``*_rhs`` factory returns ``rhs(t, y)`` with the parameters bound in a closure (the
fastest call SciPy can make: no ``args`` tuple) and the state unpacked to Python floats
(``values``, default ``y.tolist()``); ``sin``/``cos`` and ``values`` are arguments of the factory
so the same equations can be built as CasADi or SymPy expressions for the peers of the bench
(`derive.bench.peers`) — written once, used by every contender. ``*_jac`` factories return the
analytic Jacobian ∂f/∂y (a list of rows) for Radau and LSODA, written out by the chain rule.

``tests/test_bench.py`` checks every function here against the generated kernels at random
states, to 1e-12, so the baselines compute the same equations as derive.
"""
from __future__ import annotations

import math
import operator

#: SciPy hands the rhs a NumPy array; its elements as Python floats (one ``tolist``) make the
#: scalar arithmetic cheaper than on NumPy scalars. Symbolic callers pass ``values=list``.
AS_FLOATS = operator.methodcaller("tolist")


# ---------------------------------------------------------------------------------------------
# Euler angles, symmetric top


def euler_top_rhs(I1, I3, mgl, sin=math.sin, cos=math.cos, values=AS_FLOATS):
    """f(t, y) of the symmetric top in z-y-z Euler angles (mgl = M g l; 0 for a free body)."""
    def rhs(t, y):
        _, b, _, ad, bd, gd = values(y)
        sb = sin(b)
        cb = cos(b)
        w3 = ad * cb + gd
        add = bd * (I3 * w3 - 2.0 * I1 * ad * cb) / (I1 * sb)
        bdd = (I1 * ad * ad * sb * cb - I3 * w3 * ad * sb + mgl * sb) / I1
        return [ad, bd, gd, add, bdd, -add * cb + ad * bd * sb]

    return rhs


def euler_top_jac(I1, I3, mgl, sin=math.sin, cos=math.cos, values=AS_FLOATS):
    """∂f/∂y of `euler_top_rhs` (6 × 6; the α and γ columns are zero: both are cyclic)."""
    def jac(t, y):
        _, b, _, ad, bd, gd = values(y)
        sb = sin(b)
        cb = cos(b)
        w3 = ad * cb + gd
        n = I3 * w3 - 2.0 * I1 * ad * cb          # α̈ = β̇ n / (I₁ sin β)
        n_b = ad * sb * (2.0 * I1 - I3)            # ∂n/∂β
        n_ad = cb * (I3 - 2.0 * I1)                # ∂n/∂α̇ (∂n/∂γ̇ = I₃)
        k = 1.0 / (I1 * sb)
        add = bd * n * k
        add_b = bd * (n_b * sb - n * cb) * k / sb
        add_ad = bd * n_ad * k
        add_bd = n * k
        add_gd = bd * I3 * k
        bdd_b = (I1 * ad * ad * (cb * cb - sb * sb) - I3 * ad * (w3 * cb - ad * sb * sb) + mgl * cb) / I1
        bdd_ad = (2.0 * I1 * ad * sb * cb - I3 * (w3 + ad * cb) * sb) / I1
        bdd_gd = -I3 * ad * sb / I1
        return [
            [0.0, 0.0, 0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 0.0, 0.0, 1.0],
            [0.0, add_b, 0.0, add_ad, add_bd, add_gd],
            [0.0, bdd_b, 0.0, bdd_ad, 0.0, bdd_gd],
            [0.0, -add_b * cb + add * sb + ad * bd * cb, 0.0, -add_ad * cb + bd * sb,
             -add_bd * cb + ad * sb, -add_gd * cb],
        ]

    return jac


def euler_top_axis(y, sin=math.sin, cos=math.cos):
    """The symmetry axis ê₃ = R ê₃ = (sin β cos α, sin β sin α, cos β) of a state."""
    a, b = y[0], y[1]
    return [sin(b) * cos(a), sin(b) * sin(a), cos(b)]


# ---------------------------------------------------------------------------------------------
# quaternion + Euler's equations, any body


def quaternion_rhs(I1, I2, I3, mgl=0.0, values=AS_FLOATS):
    """f(t, y) of a rigid body about a fixed point (or its centre of mass: mgl = 0)."""
    a1 = (I2 - I3) / I1
    a2 = (I3 - I1) / I2
    a3 = (I1 - I2) / I3
    g1 = mgl / I1
    g2 = mgl / I2

    def rhs(t, y):
        q0, q1, q2, q3, w1, w2, w3 = values(y)
        k1 = 2.0 * (q1 * q3 - q0 * q2)  # the vertical ẑ in body axes (third row of R)
        k2 = 2.0 * (q2 * q3 + q0 * q1)
        return [
            -0.5 * (q1 * w1 + q2 * w2 + q3 * w3),
            0.5 * (q0 * w1 + q2 * w3 - q3 * w2),
            0.5 * (q0 * w2 + q3 * w1 - q1 * w3),
            0.5 * (q0 * w3 + q1 * w2 - q2 * w1),
            a1 * w2 * w3 + g1 * k2,
            a2 * w3 * w1 - g2 * k1,
            a3 * w1 * w2,
        ]

    return rhs


def quaternion_jac(I1, I2, I3, mgl=0.0, values=AS_FLOATS):
    """∂f/∂y of `quaternion_rhs` (7 × 7)."""
    a1 = (I2 - I3) / I1
    a2 = (I3 - I1) / I2
    a3 = (I1 - I2) / I3
    g1 = 2.0 * mgl / I1
    g2 = 2.0 * mgl / I2

    def jac(t, y):
        q0, q1, q2, q3, w1, w2, w3 = values(y)
        return [
            [0.0, -0.5 * w1, -0.5 * w2, -0.5 * w3, -0.5 * q1, -0.5 * q2, -0.5 * q3],
            [0.5 * w1, 0.0, 0.5 * w3, -0.5 * w2, 0.5 * q0, -0.5 * q3, 0.5 * q2],
            [0.5 * w2, -0.5 * w3, 0.0, 0.5 * w1, 0.5 * q3, 0.5 * q0, -0.5 * q1],
            [0.5 * w3, 0.5 * w2, -0.5 * w1, 0.0, -0.5 * q2, 0.5 * q1, 0.5 * q0],
            [g1 * q1, g1 * q0, g1 * q3, g1 * q2, 0.0, a1 * w3, a1 * w2],
            [g2 * q2, -g2 * q3, g2 * q0, -g2 * q1, a2 * w3, 0.0, a2 * w1],
            [0.0, 0.0, 0.0, 0.0, a3 * w2, a3 * w1, 0.0],
        ]

    return jac


def quaternion_axis(y):
    """ê₃ in inertial axes: the third column of R(q), (2(q₁q₃ + q₀q₂), 2(q₂q₃ − q₀q₁), q₀² − q₁² − q₂² + q₃²)."""
    q0, q1, q2, q3 = y[0], y[1], y[2], y[3]
    return [2.0 * (q1 * q3 + q0 * q2), 2.0 * (q2 * q3 - q0 * q1), q0 * q0 - q1 * q1 - q2 * q2 + q3 * q3]


# ---------------------------------------------------------------------------------------------
# initial states


def body_rates(beta, gamma, alpha_dot, beta_dot, gamma_dot):
    """ω̃ from the z-y-z Euler rates: (−α̇ sin β cos γ + β̇ sin γ, α̇ sin β sin γ + β̇ cos γ, α̇ cos β + γ̇)."""
    sb = math.sin(beta)
    return [-alpha_dot * sb * math.cos(gamma) + beta_dot * math.sin(gamma),
            alpha_dot * sb * math.sin(gamma) + beta_dot * math.cos(gamma),
            alpha_dot * math.cos(beta) + gamma_dot]


def euler_rates(beta, gamma, w1, w2, w3):
    """(α̇, β̇, γ̇) from ω̃, the inverse of `body_rates` (undefined at sin β = 0)."""
    sb = math.sin(beta)
    ad = (-w1 * math.cos(gamma) + w2 * math.sin(gamma)) / sb
    return [ad, w1 * math.sin(gamma) + w2 * math.cos(gamma), w3 - ad * math.cos(beta)]


def quaternion_from_angles(alpha, beta, gamma):
    """q of R = Rz(α) Ry(β) Rz(γ), scalar first: the product of the three half-angle rotations,
    (cos(β/2) cos((α+γ)/2), −sin(β/2) sin((α−γ)/2), sin(β/2) cos((α−γ)/2), cos(β/2) sin((α+γ)/2))."""
    cb, sb = math.cos(beta / 2), math.sin(beta / 2)
    return [cb * math.cos((alpha + gamma) / 2), -sb * math.sin((alpha - gamma) / 2),
            sb * math.cos((alpha - gamma) / 2), cb * math.sin((alpha + gamma) / 2)]
