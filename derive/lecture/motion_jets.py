"""A rigid body's motion at one instant, as Taylor jets: what a text in operator notation is read against.

Takes: the convention's three axes and the text's principal moments (numbers). Gives: `Jet`, a
truncated Taylor series f(t₀ + h) = Σₖ aₖ hᵏ (k < `ORDER`) with exact arithmetic on it, and
`Instant`, the body's state along one motion — the orientation matrix **M**(t) = R(q(t)) of the
convention (body → inertial components), the principal-axis angular velocity 𝛚′ from
**M**ᵀ D**M** = 𝒜(𝛚′), the torque **T**′ = **I**′ D𝛚′ + 𝛚′ × **I**′𝛚′ it implies (Euler's
equations with a torque, in principal axes) and the generalised forces Q_k = **T**·∂𝛚/∂q̇_k of
the angles. A free body's instant has q̈ chosen so that **T**′ = 0.
May import: the standard library, mpmath.

The time derivative D of a jet is exact up to the order it keeps; a coefficient it cannot know is
NaN, so a formula that differentiates more often than the jet allows evaluates to NaN (and is
not judged) instead of to a wrong number.
"""
from __future__ import annotations

import random

import mpmath

ORDER = 4
"""Taylor coefficients kept: enough for D applied three times."""

_NAN = float("nan")


class Jet:
    """f(t₀ + h) = Σ aₖ hᵏ, k < ORDER (aₖ = f⁽ᵏ⁾(t₀)/k!).

    The coefficients are binary64 floats: a sum, product or quotient of two of them is the value
    mpmath gives at its default 53-bit precision (both round to nearest, ties to even), so the jets
    compute what mpf jets would, bit for bit, without mpmath's per-operation overhead; sin and cos
    of a coefficient still come from mpmath.
    """

    __slots__ = ("a",)

    def __init__(self, coefficients):
        a = [float(x) for x in coefficients][:ORDER]
        self.a = a + [0.0] * (ORDER - len(a))

    @classmethod
    def _of(cls, a: list) -> "Jet":
        """The jet of ``ORDER`` coefficients that are already floats (what arithmetic on jets
        gives): no conversion."""
        out = cls.__new__(cls)
        out.a = a
        return out

    @staticmethod
    def lift(x) -> "Jet":
        return x if isinstance(x, Jet) else Jet([x])

    def __add__(self, other):
        if isinstance(other, Array):
            return NotImplemented
        o = Jet.lift(other)
        return Jet._of([x + y for x, y in zip(self.a, o.a)])

    __radd__ = __add__

    def __neg__(self):
        return Jet._of([-x for x in self.a])

    def __sub__(self, other):
        if isinstance(other, Array):
            return NotImplemented
        return self + (-Jet.lift(other))

    def __rsub__(self, other):
        return Jet.lift(other) - self

    def __mul__(self, other):
        if isinstance(other, Array):
            return NotImplemented
        a, b = self.a, other.a if isinstance(other, Jet) else Jet.lift(other).a
        if ORDER == 4:            # the Cauchy product below, written out (same terms, same order)
            a0, a1, a2, a3 = a
            b0, b1, b2, b3 = b
            return Jet._of([a0 * b0, a0 * b1 + a1 * b0, a0 * b2 + a1 * b1 + a2 * b0,
                            a0 * b3 + a1 * b2 + a2 * b1 + a3 * b0])
        out = []
        for n in range(ORDER):
            term = a[0] * b[n]
            for k in range(1, n + 1):
                term = term + a[k] * b[n - k]
            out.append(term)
        return Jet._of(out)

    __rmul__ = __mul__

    def reciprocal(self) -> "Jet":
        """1/f by the recursion b₀ = 1/a₀, bₙ = −(Σ_{k≥1} aₖ bₙ₋ₖ)/a₀."""
        if self.a[0] == 0:
            raise ZeroDivisionError("division by a quantity that vanishes here")
        b = [1 / self.a[0]]
        for n in range(1, ORDER):
            b.append(-sum(self.a[k] * b[n - k] for k in range(1, n + 1)) / self.a[0])
        return Jet(b)

    def __truediv__(self, other):
        return self * Jet.lift(other).reciprocal()

    def __rtruediv__(self, other):
        return Jet.lift(other) * self.reciprocal()

    def __pow__(self, n):
        if not isinstance(n, int) or n < -8 or n > 8:
            raise ValueError("only small whole powers")
        out = Jet([1])
        for _ in range(abs(n)):
            out = out * self
        return out if n >= 0 else out.reciprocal()

    def derivative(self) -> "Jet":
        """D f: the coefficients shift down; the last is unknown (NaN)."""
        return Jet([(k + 1) * self.a[k + 1] for k in range(ORDER - 1)] + [_NAN])

    @property
    def value(self):
        return self.a[0]


def sin_cos(x: Jet) -> tuple[Jet, Jet]:
    """sin and cos of a jet: with x = x₀ + h, sin x = sin x₀ cos h + cos x₀ sin h (h has no constant)."""
    h = Jet([0] + x.a[1:])
    s0, c0 = float(mpmath.sin(x.a[0])), float(mpmath.cos(x.a[0]))
    sin_h, cos_h, power = Jet([0]), Jet([1]), Jet([1])
    for k in range(1, ORDER):
        power = power * h / k                     # hᵏ/k!
        if k % 2:
            sin_h = sin_h + power * (-1) ** ((k - 1) // 2)
        else:
            cos_h = cos_h + power * (-1) ** (k // 2)
    return s0 * cos_h + c0 * sin_h, c0 * cos_h - s0 * sin_h


class Array:
    """A vector (shape (n,)) or matrix (shape (n, m)) of jets, row-major: what the operator
    notation's vectors and matrices evaluate to. ``@`` sums a row's products left to right,
    a[i, 0]·b[0, j] first (a product of jets is not commutative to the last bit, so the order is
    fixed); +, −, · with a jet or a number act entry by entry, and a vector against a matrix
    acts on each of its rows; shapes that do not fit raise ValueError."""

    __slots__ = ("e", "shape")

    def __init__(self, e: list, shape: tuple):
        self.e, self.shape = e, shape

    @classmethod
    def of(cls, values) -> "Array":
        """A vector from a list, a matrix from a list of equal rows (their entries as they are)."""
        if values and isinstance(values[0], (list, tuple)):
            if len({len(r) for r in values}) != 1:
                raise ValueError("a ragged matrix")
            return cls([x for r in values for x in r], (len(values), len(values[0])))
        return cls(list(values), (len(values),))

    @property
    def ndim(self) -> int:
        return len(self.shape)

    def ravel(self) -> list:
        return list(self.e)

    def map(self, f) -> "Array":
        return Array([f(x) for x in self.e], self.shape)

    def _at(self, key):
        i, j = key
        n, m = self.shape
        if not (-n <= i < n and -m <= j < m):
            raise IndexError("index out of range")
        return (i % n) * m + j % m

    def __getitem__(self, key):
        if self.ndim == 1:
            return self.e[key]
        n, m = self.shape
        if isinstance(key, tuple) and key[0] == slice(None):
            return Array([self[i, key[1]] for i in range(n)], (n,))
        if isinstance(key, tuple):
            return self.e[self._at(key)]
        if not -n <= key < n:
            raise IndexError("index out of range")
        return Array(self.e[(key % n) * m:(key % n + 1) * m], (m,))

    def __setitem__(self, key, value):
        self.e[self._at(key)] = value

    @property
    def T(self) -> "Array":
        if self.ndim == 1:
            return self
        n, m = self.shape
        return Array([self.e[i * m + j] for j in range(m) for i in range(n)], (m, n))

    def __matmul__(self, other):
        if not isinstance(other, Array):
            return NotImplemented
        a = self if self.ndim == 2 else Array(self.e, (1, self.shape[0]))
        b = other if other.ndim == 2 else Array(other.e, (other.shape[0], 1))
        (n, k), (k2, m) = a.shape, b.shape
        if k != k2 or k == 0:
            raise ValueError("shapes that do not fit a product")
        out = []
        for i in range(n):
            for j in range(m):
                total = a.e[i * k] * b.e[j]
                for r in range(1, k):
                    total = total + a.e[i * k + r] * b.e[r * m + j]
                out.append(total)
        if self.ndim == 1 and other.ndim == 1:
            return out[0]
        if self.ndim == 1 or other.ndim == 1:
            return Array(out, (n * m,))
        return Array(out, (n, m))

    def _paired(self, other, op):
        """``op`` entry by entry (a scalar against each entry; a vector against each row)."""
        if not isinstance(other, Array):
            return Array([op(x, other) for x in self.e], self.shape)
        if self.shape == other.shape:
            return Array([op(x, y) for x, y in zip(self.e, other.e)], self.shape)
        if self.ndim == 2 and other.ndim == 1 and other.shape[0] == self.shape[1]:
            m = self.shape[1]
            return Array([op(x, other.e[n % m]) for n, x in enumerate(self.e)], self.shape)
        if self.ndim == 1 and other.ndim == 2 and self.shape[0] == other.shape[1]:
            m = other.shape[1]
            return Array([op(self.e[n % m], y) for n, y in enumerate(other.e)], other.shape)
        raise ValueError("shapes that do not fit entry by entry")

    def __add__(self, other):
        return self._paired(other, lambda x, y: x + y)

    def __radd__(self, other):
        return self._paired(other, lambda x, y: y + x)

    def __sub__(self, other):
        return self._paired(other, lambda x, y: x - y)

    def __rsub__(self, other):
        return self._paired(other, lambda x, y: y - x)

    def __mul__(self, other):
        return self._paired(other, lambda x, y: x * y)

    def __rmul__(self, other):
        return self._paired(other, lambda x, y: y * x)

    def __truediv__(self, other):
        return self._paired(other, lambda x, y: x / y)

    def __neg__(self):
        return self.map(lambda x: -x)


def jet_array(values) -> Array:
    """The vector or matrix of jets of a list or a list of rows of numbers (or jets)."""
    if values and isinstance(values[0], (list, tuple)):
        return Array.of([[Jet.lift(v) for v in r] for r in values])
    return Array.of([Jet.lift(v) for v in values])


def eye() -> list:
    return [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]


def derivative(x):
    """D of a jet, a vector or a matrix of jets."""
    if isinstance(x, Array):
        return x.map(lambda e: Jet.lift(e).derivative())
    return Jet.lift(x).derivative()


def hat(v) -> Array:
    """𝒜(v): the antisymmetric matrix with 𝒜(v) w = v × w."""
    zero = Jet([0])
    return Array.of([[zero, -v[2], v[1]], [v[2], zero, -v[0]], [-v[1], v[0], zero]])


def vee(m) -> Array:
    """𝒜⁻¹: the vector of an antisymmetric matrix (its antisymmetric part)."""
    return Array.of([(m[2, 1] - m[1, 2]) / 2, (m[0, 2] - m[2, 0]) / 2, (m[1, 0] - m[0, 1]) / 2])


def cross(u, v) -> Array:
    return Array.of([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]])


def active(axis: str, angle: Jet) -> Array:
    """The active right-handed turn about x, y or z by the angle (as `derive.symbolic.rotations.active`)."""
    s, c = sin_cos(angle)
    i = "xyz".index(axis)
    j, k = (i + 1) % 3, (i + 2) % 3
    m = jet_array(eye())
    m[j, j], m[j, k], m[k, j], m[k, k] = c, -s, s, c
    return m


def rotation(axes, angles) -> Array:
    """R = active(a₁, q₁) active(a₂, q₂) active(a₃, q₃): body → inertial components."""
    return active(axes[0], angles[0]) @ active(axes[1], angles[1]) @ active(axes[2], angles[2])


class Instant:
    """One instant of one motion of a body with principal moments ``moments`` (see the module
    docstring). ``free``: the motion is torque-free (q̈ from Euler's equations); otherwise q̈ is
    random and the torque is what the motion implies."""

    def __init__(self, axes, moments, seed, free: bool):
        rng = random.Random(seed)
        self.axes = axes
        self.moments = [float(m) for m in moments]
        q0 = [rng.uniform(0.3, 1.2) for _ in range(3)]
        q1 = [rng.uniform(-1, 1) for _ in range(3)]
        q3 = [rng.uniform(-1, 1) for _ in range(3)]
        q2 = [rng.uniform(-1, 1) for _ in range(3)]
        if free:
            q2 = self._free_acceleration(q0, q1, q3)
        self.angles = [Jet([q0[k], q1[k], q2[k] / 2, q3[k] / 6]) for k in range(3)]
        self.M = rotation(axes, self.angles)
        self.inertia = jet_array([[m if i == j else 0.0 for j, _ in enumerate(self.moments)] for i, m in enumerate(self.moments)])
        self.omega = vee(self.M.T @ derivative(self.M))              # 𝛚′, principal axes
        self.torque = self.inertia @ derivative(self.omega) + cross(self.omega, self.inertia @ self.omega)
        self.q1 = q1

    def _omega_rate(self, q0, q1, q2, q3):
        angles = [Jet([q0[k], q1[k], q2[k] / 2, q3[k] / 6]) for k in range(3)]
        M = rotation(self.axes, angles)
        w = vee(M.T @ derivative(M))
        return [x.a[1] for x in w], [x.a[0] for x in w]

    def _free_acceleration(self, q0, q1, q3):
        """q̈ with I′ D𝛚′ = −𝛚′ × I′𝛚′ (D𝛚′ is affine in q̈: solved from four evaluations)."""
        zero = [0.0] * 3
        base, w = self._omega_rate(q0, q1, zero, q3)
        cols = []
        for k in range(3):
            e = list(zero)
            e[k] = 1.0
            rate, _ = self._omega_rate(q0, q1, e, q3)
            cols.append([rate[i] - base[i] for i in range(3)])
        Iw = [self.moments[i] * w[i] for i in range(3)]
        want = [-(w[(i + 1) % 3] * Iw[(i + 2) % 3] - w[(i + 2) % 3] * Iw[(i + 1) % 3]) / self.moments[i]
                for i in range(3)]
        A = mpmath.matrix([[cols[k][i] for k in range(3)] for i in range(3)])
        rhs = mpmath.matrix([want[i] - base[i] for i in range(3)])
        return [float(x) for x in mpmath.lu_solve(A, rhs)]

    def rates_matrix(self) -> Array:
        """B⁰: the inertial angular velocity 𝛚 = B⁰ q̇ (column k: the axis of the k-th turn)."""
        s = [active(self.axes[0], self.angles[0]), active(self.axes[1], self.angles[1])]
        e = [jet_array([row["xyz".index(a)] for row in eye()]) for a in self.axes]
        cols = [e[0], s[0] @ e[1], s[0] @ s[1] @ e[2]]
        return Array.of([[cols[k][i] for k in range(3)] for i in range(3)])

    def generalised_forces(self) -> Array:
        """Q_k = 𝐓·(axis of the k-th turn): the torque's power per unit rate of each angle."""
        return self.rates_matrix().T @ (self.M @ self.torque)

    def momenta(self) -> Array:
        """p_k = ∂T/∂q̇_k = 𝐋·(axis of the k-th turn)."""
        return self.rates_matrix().T @ (self.M @ (self.inertia @ self.omega))
