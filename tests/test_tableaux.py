"""Butcher tableaux: the invariants and order conditions that catch a wrong coefficient.

Order conditions are Butcher's rooted-tree conditions, sum_i b_i Phi_i(t) = 1/gamma(t) for every
rooted tree t with |t| <= p, checked in exact rational arithmetic on the stored coefficients
(Fractions; DOP853's are its published 30-digit decimals, so there the residuals are ~1e-28).
"""
from __future__ import annotations

import functools
from fractions import Fraction as F
from pathlib import Path

import numpy as np
import pytest

from derive.methods.tableaux import DOP853, GAUSS4, GAUSS6, RK4, TABLEAUX, Tableau
from kept_results import kept

ALL = list(TABLEAUX.values())


# --- rooted trees ---------------------------------------------------------------------------
# A tree is the sorted tuple of its root's subtrees; the single node is ().

def _attach_leaf_everywhere(tree):
    """All trees obtained from ``tree`` by adding one leaf to one of its nodes."""
    out = {tuple(sorted(tree + ((),)))}
    for i, child in enumerate(tree):
        for grown in _attach_leaf_everywhere(child):
            out.add(tuple(sorted(tree[:i] + (grown,) + tree[i + 1:])))
    return out


@functools.lru_cache(maxsize=None)
def trees(order: int) -> tuple:
    if order == 1:
        return ((),)
    out = set()
    for t in trees(order - 1):
        out |= _attach_leaf_everywhere(t)
    return tuple(sorted(out))


def size(t) -> int:
    return 1 + sum(size(c) for c in t)


def gamma(t) -> int:
    g = size(t)
    for c in t:
        g *= gamma(c)
    return g


def test_tree_counts_match_oeis_a000081():
    assert [len(trees(n)) for n in range(1, 9)] == [1, 1, 2, 4, 9, 20, 48, 115]


class Weights:
    """Phi(t) (the stage vectors of elementary weights) for one coefficient matrix A."""

    def __init__(self, A):
        self.A = [list(r) for r in A]
        self.s = len(self.A)
        self._cache = {}

    def phi(self, t):
        if t not in self._cache:
            v = [F(1)] * self.s
            for child in t:
                w = self.phi(child)
                aw = [sum((a * x for a, x in zip(row, w) if a), F(0)) for row in self.A]
                v = [x * y for x, y in zip(v, aw)]
            self._cache[t] = v
        return self._cache[t]

    def residual(self, b, t, target=None):
        target = F(1, gamma(t)) if target is None else target
        return sum((bi * x for bi, x in zip(b, self.phi(t)) if bi), F(0)) - target


def max_residual(tab: Tableau, order: int, weights=None) -> float:
    w = Weights(tab.A)
    b = tab.b if weights is None else weights
    zero = weights is not None
    return max(abs(float(w.residual(b, t, F(0) if zero else None)))
               for n in range(1, order + 1) for t in trees(n))


# --- basic invariants -----------------------------------------------------------------------

@pytest.mark.parametrize("tab", ALL, ids=lambda t: t.name)
def test_weights_sum_to_one(tab):
    assert abs(float(sum(tab.b)) - 1) < 1e-28


@pytest.mark.parametrize("tab", ALL, ids=lambda t: t.name)
def test_row_sums_of_A_equal_c(tab):
    for row, c in zip(tab.A, tab.c):
        assert abs(float(sum(row) - c)) < 1e-28


@pytest.mark.parametrize("tab", [t for t in ALL if t.b_err is not None], ids=lambda t: t.name)
def test_error_estimator_weights_sum_to_zero(tab):
    for w in (tab.b_err, tab.b_err2):
        if w is not None:
            assert abs(float(sum(w))) < 1e-26  # E5 is published to 28 digits


def test_explicit_tableaux_are_strictly_lower_triangular():
    for tab in (RK4, DOP853):
        A = np.array(tab.A, dtype=float)
        assert not tab.implicit
        assert np.all(np.triu(A) == 0)


def test_floats_are_the_correctly_rounded_coefficients():
    mpmath = pytest.importorskip("mpmath")
    mpmath.mp.dps = 50
    r15 = mpmath.sqrt(15)
    arr = GAUSS6.arrays()
    assert arr["c"][1] == 0.5
    assert arr["c"][0] == float(mpmath.mpf(1) / 2 - r15 / 10)
    assert arr["A"][0, 1] == float(mpmath.mpf(2) / 9 - r15 / 15)
    assert arr["A"][0, 0] == 5 / 36


# --- order conditions -----------------------------------------------------------------------

def test_rk4_satisfies_exactly_the_order_4_conditions():
    w = Weights(RK4.A)
    for n in range(1, 5):
        for t in trees(n):
            assert w.residual(RK4.b, t) == 0  # exact rational arithmetic
    assert any(w.residual(RK4.b, t) != 0 for t in trees(5))


@pytest.mark.parametrize("tab", [GAUSS4, GAUSS6], ids=lambda t: t.name)
def test_gauss_legendre_order_conditions(tab):
    assert max_residual(tab, tab.order) < 1e-45
    w = Weights(tab.A)
    assert max(abs(float(w.residual(tab.b, t))) for t in trees(tab.order + 1)) > 1e-6


@pytest.mark.parametrize("tab", [GAUSS4, GAUSS6], ids=lambda t: t.name)
def test_gauss_legendre_simplifying_assumptions(tab):
    s = tab.stages
    # B(2s): sum_i b_i c_i^(k-1) = 1/k, k = 1..2s (Gauss quadrature of order 2s)
    for k in range(1, 2 * s + 1):
        assert abs(float(sum(b * c ** (k - 1) for b, c in zip(tab.b, tab.c)) - F(1, k))) < 1e-45
    # C(s): sum_j a_ij c_j^(k-1) = c_i^k / k, k = 1..s (collocation)
    for row, ci in zip(tab.A, tab.c):
        for k in range(1, s + 1):
            lhs = sum(a * c ** (k - 1) for a, c in zip(row, tab.c))
            assert abs(float(lhs - ci ** k / k)) < 1e-45
    # D(s): sum_i b_i c_i^(k-1) a_ij = b_j (1 - c_j^k) / k, k = 1..s
    for j in range(s):
        for k in range(1, s + 1):
            lhs = sum(tab.b[i] * tab.c[i] ** (k - 1) * tab.A[i][j] for i in range(s))
            assert abs(float(lhs - tab.b[j] * (1 - tab.c[j] ** k) / k)) < 1e-45


@pytest.mark.parametrize("order", range(1, 9))
def test_dop853_order_8_conditions(order):
    w = Weights(DOP853.A)
    worst = max(abs(float(w.residual(DOP853.b, t))) for t in trees(order))
    assert worst < 1e-25, f"order {order}: residual {worst:.3g}"


def _kept(what, compute):
    """``compute()``, residuals in exact arithmetic over rooted trees, kept between test runs
    (tests/kept_results.py) under ``what`` (every coefficient it is computed from, exact) and this
    file's bytes: the orders are checked against them on every run."""
    return kept("tableau-residuals", what, compute, [Path(__file__)])


def test_dop853_is_not_order_9():
    worst = _kept(("order 9", DOP853.A, DOP853.b),
                  lambda: max(abs(float(Weights(DOP853.A).residual(DOP853.b, t))) for t in trees(9)))
    assert worst > 1e-8


def test_dop853_error_estimators_have_their_orders():
    """err5 = y8 - y5hat vanishes on trees up to order 5, err3 up to order 3, not beyond."""
    assert max_residual(DOP853, 5, DOP853.b_err) < 1e-25
    assert max_residual(DOP853, 3, DOP853.b_err2) < 1e-25
    w = Weights(DOP853.A)
    assert max(abs(float(w.residual(DOP853.b_err, t, F(0)))) for t in trees(6)) > 1e-6
    assert max(abs(float(w.residual(DOP853.b_err2, t, F(0)))) for t in trees(4)) > 1e-6


def _dop853_extended():
    """The 16-stage tableau of the dense output: 12 stages, FSAL (row b), 3 extra stages."""
    s, d = DOP853.stages, DOP853.dense
    n = s + 1 + len(d.A_extra)
    A = [list(r) + [F(0)] * (n - s) for r in DOP853.A]
    A.append(list(DOP853.b) + [F(0)] * (n - s))
    A += [list(r) for r in d.A_extra]
    c = list(DOP853.c) + [F(1)] + list(d.c_extra)
    return A, c


def test_dop853_extended_stages_row_sums():
    A, c = _dop853_extended()
    for row, ci in zip(A, c):
        assert abs(float(sum(row) - ci)) < 1e-28


def _dop853_dense_weights(theta: F):
    """b_j(theta) with y(t_n + theta h) = y_n + h sum_j b_j(theta) k_j (DenseOutput formula)."""
    A, _ = _dop853_extended()
    n, s = len(A), DOP853.stages
    delta = list(DOP853.b) + [F(0)] * (n - s)
    e0 = [F(1) if j == 0 else F(0) for j in range(n)]
    efs = [F(1) if j == s else F(0) for j in range(n)]
    F0 = delta
    F1 = [a - d for a, d in zip(e0, delta)]
    F2 = [2 * d - a - f for d, a, f in zip(delta, e0, efs)]
    coeffs = [F0, F1, F2] + [list(r) for r in DOP853.dense.D]
    x, x1 = theta, 1 - theta
    acc = [F(0)] * n
    for i, f in enumerate(reversed(coeffs)):
        acc = [a + b for a, b in zip(acc, f)]
        acc = [a * (x if i % 2 == 0 else x1) for a in acc]
    return A, acc


@pytest.mark.parametrize("theta", [F(1, 5), F(1, 2), F(4, 5)])
def test_dop853_dense_output_has_order_7(theta):
    """sum_j b_j(theta) Phi_j(t) = theta^|t| / gamma(t) for all trees up to order 7."""
    A, bt = _dop853_dense_weights(theta)

    def residuals():
        w = Weights(A)
        up_to_order = [(n, t, float(w.residual(bt, t, theta ** n / gamma(t))))
                       for n in range(1, DOP853.dense.order + 1) for t in trees(n)]
        return up_to_order, max(abs(float(w.residual(bt, t, theta ** 8 / gamma(t)))) for t in trees(8))

    up_to_order, worst8 = _kept(("dense", A, bt, theta, DOP853.dense.order), residuals)
    for n, t, r in up_to_order:
        assert abs(r) < 1e-24, (n, t, r)
    assert worst8 > 1e-10


def test_dop853_dense_output_reproduces_the_step_at_theta_1():
    _, bt = _dop853_dense_weights(F(1))
    assert bt[:DOP853.stages] == list(DOP853.b) and not any(bt[DOP853.stages:])


def test_tableau_rejects_inconsistent_data():
    with pytest.raises(ValueError):
        Tableau("bad", 1, A=((F(0), F(1)), (F(0), F(0))), b=(F(1), F(0)), c=(F(0), F(0)))
    with pytest.raises(ValueError):
        Tableau("bad", 1, A=((F(0),),), b=(F(1),), c=(F(0), F(1)))
