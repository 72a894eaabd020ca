"""Runge–Kutta methods as data: Butcher tableaux.

A method is its tableau

    c | A          stage i:  Y_i = y_n + h * sum_j A[i][j] * f(t_n + c_i h, Y_j)
    --+----        step:     y_{n+1} = y_n + h * sum_i b_i * f(t_n + c_i h, Y_i)
      | b

plus, for adaptive methods, error-estimator weights (``err = h * sum_i b_err_i k_i``) and, for
dense output, the extra stages and interpolation coefficients. Nothing here is code that steps:
``templates/c/solvers.c.j2`` renders every tableau through one stepper (explicit stages unrolled
with these numbers as C literals, implicit ones solved by simplified Newton).

Coefficients are held exactly as :class:`fractions.Fraction` (``float(Fraction)`` rounds
correctly, so the C literals are the nearest doubles). Rational methods are exact; methods whose
coefficients involve square roots (Gauss–Legendre) are evaluated to 50 significant digits first;
DOP853's coefficients are the 30-digit decimals published with the method.
"""
from __future__ import annotations

import decimal
from dataclasses import dataclass, field
from fractions import Fraction as F

import numpy as np

Row = tuple[F, ...]


def _tuple(v) -> Row:
    return tuple(F(x) for x in v)


def _surd(a, b=0, k=0) -> F:
    """``a + b*sqrt(k)`` (a, b rational) as a Fraction correct to 50 significant digits."""
    a, b = F(a), F(b)
    if b == 0:
        return a
    with decimal.localcontext() as ctx:
        ctx.prec = 60
        root = decimal.Decimal(k).sqrt()
        val = (decimal.Decimal(a.numerator) / a.denominator
               + decimal.Decimal(b.numerator) / b.denominator * root)
        return F(+val)


@dataclass(frozen=True)
class DenseOutput:
    """Continuous extension of an explicit method.

    ``kind`` names the interpolation scheme rendered by the stepper template:

    ``"dop853"`` — Hairer's order-7 interpolant of DOP853. Extra stages ``A_extra``/``c_extra``
    follow the FSAL stage (index ``n_stages``: ``f(t+h, y_{n+1})``); with
    ``Δ = y_{n+1} - y_n`` and ``x = (t - t_n)/h``

        F0 = Δ,  F1 = h f_n - Δ,  F2 = 2Δ - h (f_n + f_{n+1}),  F_{3+r} = h * sum_j D[r][j] k_j
        y(t) = y_n + x(F0 + (1-x)(F1 + x(F2 + (1-x)(F3 + x(F4 + (1-x)(F5 + x F6))))))
    """

    kind: str
    order: int
    A_extra: tuple[Row, ...]
    c_extra: Row
    D: tuple[Row, ...]


@dataclass(frozen=True)
class Tableau:
    """A Butcher tableau.

    name       identifier (also used in generated C function names)
    order      classical order p of the propagating formula b
    A, b, c    the tableau; ``A`` is strictly lower triangular unless ``implicit``
    b_err      error-estimator weights: ``err = h * sum b_err_i k_i`` (b minus embedded b̂).
               For DOP853 this is the 5th-order estimator E5.
    b_err2     optional second estimator (DOP853's 3rd-order E3), combined with the first as
               ``|err5|^2 / sqrt(|err5|^2 + 0.01 |err3|^2)`` (Hairer & Wanner, DOP853)
    err_order  step-size exponent: the controlled error behaves like h^(err_order+1)
    implicit   stages coupled (A not strictly lower triangular): solved by Newton iteration
    dense      optional :class:`DenseOutput`
    """

    name: str
    order: int
    A: tuple[Row, ...]
    b: Row
    c: Row
    b_err: Row | None = None
    err_order: int | None = None
    implicit: bool = False
    dense: DenseOutput | None = None
    b_err2: Row | None = None
    reference: str = field(default="", compare=False)

    def __post_init__(self):
        s = len(self.b)
        if len(self.c) != s or len(self.A) != s or any(len(r) != s for r in self.A):
            raise ValueError(f"{self.name}: inconsistent tableau dimensions")
        if not self.implicit and any(self.A[i][j] != 0 for i in range(s) for j in range(i, s)):
            raise ValueError(f"{self.name}: explicit tableau with A[i][j] != 0 for j >= i")
        for w in (self.b_err, self.b_err2):
            if w is not None and len(w) != s:
                raise ValueError(f"{self.name}: error weights must have one entry per stage")

    @property
    def stages(self) -> int:
        return len(self.b)

    @property
    def adaptive(self) -> bool:
        return self.b_err is not None

    def arrays(self) -> dict[str, np.ndarray]:
        """The coefficients as float64 arrays (A, b, c and, if present, b_err, b_err2)."""
        out = {"A": np.array(self.A, dtype=float), "b": np.array(self.b, dtype=float),
               "c": np.array(self.c, dtype=float)}
        if self.b_err is not None:
            out["b_err"] = np.array(self.b_err, dtype=float)
        if self.b_err2 is not None:
            out["b_err2"] = np.array(self.b_err2, dtype=float)
        return out


# --------------------------------------------------------------------------------------------
# Classical Runge–Kutta, order 4 (Kutta 1901).
RK4 = Tableau(
    name="rk4",
    order=4,
    A=(_tuple([0, 0, 0, 0]),
       _tuple([F(1, 2), 0, 0, 0]),
       _tuple([0, F(1, 2), 0, 0]),
       _tuple([0, 0, 1, 0])),
    b=_tuple([F(1, 6), F(1, 3), F(1, 3), F(1, 6)]),
    c=_tuple([0, F(1, 2), F(1, 2), 1]),
    reference="W. Kutta, Z. Math. Phys. 46 (1901) 435-453",
)


# --------------------------------------------------------------------------------------------
# Gauss–Legendre collocation (Butcher 1964): s stages, order 2s, A-stable, symplectic.
# Nodes are the zeros of the shifted Legendre polynomial P_s(2c - 1).
_S3, _S15 = 3, 15
GAUSS4 = Tableau(
    name="gauss4",
    order=4,
    A=((_surd(F(1, 4)), _surd(F(1, 4), F(-1, 6), _S3)),
       (_surd(F(1, 4), F(1, 6), _S3), _surd(F(1, 4)))),
    b=_tuple([F(1, 2), F(1, 2)]),
    c=(_surd(F(1, 2), F(-1, 6), _S3), _surd(F(1, 2), F(1, 6), _S3)),
    implicit=True,
    reference="J. C. Butcher, Math. Comp. 18 (1964) 50-64",
)

GAUSS6 = Tableau(
    name="gauss6",
    order=6,
    A=((_surd(F(5, 36)), _surd(F(2, 9), F(-1, 15), _S15), _surd(F(5, 36), F(-1, 30), _S15)),
       (_surd(F(5, 36), F(1, 24), _S15), _surd(F(2, 9)), _surd(F(5, 36), F(-1, 24), _S15)),
       (_surd(F(5, 36), F(1, 30), _S15), _surd(F(2, 9), F(1, 15), _S15), _surd(F(5, 36)))),
    b=_tuple([F(5, 18), F(4, 9), F(5, 18)]),
    c=(_surd(F(1, 2), F(-1, 10), _S15), _surd(F(1, 2)), _surd(F(1, 2), F(1, 10), _S15)),
    implicit=True,
    reference="J. C. Butcher, Math. Comp. 18 (1964) 50-64",
)


# --------------------------------------------------------------------------------------------
# Dormand–Prince 8(5,3), the method of Hairer's DOP853.
#
# Coefficients copied from SciPy, scipy/integrate/_ivp/dop853_coefficients.py (BSD-3-Clause,
# Copyright (c) 2001-2002 Enthought, Inc. 2003-2024, SciPy Developers), which transcribes
# E. Hairer's Fortran dop853.f (http://www.unige.ch/~hairer/software.html). Reference:
# E. Hairer, S. P. Nørsett, G. Wanner, "Solving Ordinary Differential Equations I", 2nd ed.,
# Springer 1993, Sec. II.10. Decimal strings, kept verbatim, parsed exactly.
#
# Stages 0..11 are the method, stage 12 is the FSAL stage f(t+h, y_{n+1}) (its row of A is b),
# stages 13..15 are the extra stages of the dense output.
_DOP_C = ["0.0", "0.526001519587677318785587544488e-01", "0.789002279381515978178381316732e-01",
          "0.118350341907227396726757197510", "0.281649658092772603273242802490",
          "0.333333333333333333333333333333", "0.25", "0.307692307692307692307692307692",
          "0.651282051282051282051282051282", "0.6", "0.857142857142857142857142857142",
          "1.0", "1.0", "0.1", "0.2", "0.777777777777777777777777777778"]

_DOP_A = {
    (1, 0): "5.26001519587677318785587544488e-2",
    (2, 0): "1.97250569845378994544595329183e-2",
    (2, 1): "5.91751709536136983633785987549e-2",
    (3, 0): "2.95875854768068491816892993775e-2",
    (3, 2): "8.87627564304205475450678981324e-2",
    (4, 0): "2.41365134159266685502369798665e-1",
    (4, 2): "-8.84549479328286085344864962717e-1",
    (4, 3): "9.24834003261792003115737966543e-1",
    (5, 0): "3.7037037037037037037037037037e-2",
    (5, 3): "1.70828608729473871279604482173e-1",
    (5, 4): "1.25467687566822425016691814123e-1",
    (6, 0): "3.7109375e-2",
    (6, 3): "1.70252211019544039314978060272e-1",
    (6, 4): "6.02165389804559606850219397283e-2",
    (6, 5): "-1.7578125e-2",
    (7, 0): "3.70920001185047927108779319836e-2",
    (7, 3): "1.70383925712239993810214054705e-1",
    (7, 4): "1.07262030446373284651809199168e-1",
    (7, 5): "-1.53194377486244017527936158236e-2",
    (7, 6): "8.27378916381402288758473766002e-3",
    (8, 0): "6.24110958716075717114429577812e-1",
    (8, 3): "-3.36089262944694129406857109825",
    (8, 4): "-8.68219346841726006818189891453e-1",
    (8, 5): "2.75920996994467083049415600797e1",
    (8, 6): "2.01540675504778934086186788979e1",
    (8, 7): "-4.34898841810699588477366255144e1",
    (9, 0): "4.77662536438264365890433908527e-1",
    (9, 3): "-2.48811461997166764192642586468",
    (9, 4): "-5.90290826836842996371446475743e-1",
    (9, 5): "2.12300514481811942347288949897e1",
    (9, 6): "1.52792336328824235832596922938e1",
    (9, 7): "-3.32882109689848629194453265587e1",
    (9, 8): "-2.03312017085086261358222928593e-2",
    (10, 0): "-9.3714243008598732571704021658e-1",
    (10, 3): "5.18637242884406370830023853209",
    (10, 4): "1.09143734899672957818500254654",
    (10, 5): "-8.14978701074692612513997267357",
    (10, 6): "-1.85200656599969598641566180701e1",
    (10, 7): "2.27394870993505042818970056734e1",
    (10, 8): "2.49360555267965238987089396762",
    (10, 9): "-3.0467644718982195003823669022",
    (11, 0): "2.27331014751653820792359768449",
    (11, 3): "-1.05344954667372501984066689879e1",
    (11, 4): "-2.00087205822486249909675718444",
    (11, 5): "-1.79589318631187989172765950534e1",
    (11, 6): "2.79488845294199600508499808837e1",
    (11, 7): "-2.85899827713502369474065508674",
    (11, 8): "-8.87285693353062954433549289258",
    (11, 9): "1.23605671757943030647266201528e1",
    (11, 10): "6.43392746015763530355970484046e-1",
    (12, 0): "5.42937341165687622380535766363e-2",
    (12, 5): "4.45031289275240888144113950566",
    (12, 6): "1.89151789931450038304281599044",
    (12, 7): "-5.8012039600105847814672114227",
    (12, 8): "3.1116436695781989440891606237e-1",
    (12, 9): "-1.52160949662516078556178806805e-1",
    (12, 10): "2.01365400804030348374776537501e-1",
    (12, 11): "4.47106157277725905176885569043e-2",
    (13, 0): "5.61675022830479523392909219681e-2",
    (13, 6): "2.53500210216624811088794765333e-1",
    (13, 7): "-2.46239037470802489917441475441e-1",
    (13, 8): "-1.24191423263816360469010140626e-1",
    (13, 9): "1.5329179827876569731206322685e-1",
    (13, 10): "8.20105229563468988491666602057e-3",
    (13, 11): "7.56789766054569976138603589584e-3",
    (13, 12): "-8.298e-3",
    (14, 0): "3.18346481635021405060768473261e-2",
    (14, 5): "2.83009096723667755288322961402e-2",
    (14, 6): "5.35419883074385676223797384372e-2",
    (14, 7): "-5.49237485713909884646569340306e-2",
    (14, 10): "-1.08347328697249322858509316994e-4",
    (14, 11): "3.82571090835658412954920192323e-4",
    (14, 12): "-3.40465008687404560802977114492e-4",
    (14, 13): "1.41312443674632500278074618366e-1",
    (15, 0): "-4.28896301583791923408573538692e-1",
    (15, 5): "-4.69762141536116384314449447206",
    (15, 6): "7.68342119606259904184240953878",
    (15, 7): "4.06898981839711007970213554331",
    (15, 8): "3.56727187455281109270669543021e-1",
    (15, 12): "-1.39902416515901462129418009734e-3",
    (15, 13): "2.9475147891527723389556272149",
    (15, 14): "-9.15095847217987001081870187138",
}

# bhh1, bhh2, bhh3 of dop853.f: the 3rd-order estimator is E3 = b - bhh (stages 0, 8, 11).
_DOP_BHH = {0: "0.244094488188976377952755905512",
            8: "0.733846688281611857341361741547",
            11: "0.220588235294117647058823529412e-1"}

_DOP_E5 = {0: "0.1312004499419488073250102996e-1",
           5: "-0.1225156446376204440720569753e+1",
           6: "-0.4957589496572501915214079952",
           7: "0.1664377182454986536961530415e+1",
           8: "-0.3503288487499736816886487290",
           9: "0.3341791187130174790297318841",
           10: "0.8192320648511571246570742613e-1",
           11: "-0.2235530786388629525884427845e-1"}

# Dense output: rows d4..d7 of dop853.f (the first three interpolation coefficients are the
# Hermite-like combinations documented in DenseOutput).
_DOP_D = [
    {0: "-0.84289382761090128651353491142e+1", 5: "0.56671495351937776962531783590",
     6: "-0.30689499459498916912797304727e+1", 7: "0.23846676565120698287728149680e+1",
     8: "0.21170345824450282767155149946e+1", 9: "-0.87139158377797299206789907490",
     10: "0.22404374302607882758541771650e+1", 11: "0.63157877876946881815570249290",
     12: "-0.88990336451333310820698117400e-1", 13: "0.18148505520854727256656404962e+2",
     14: "-0.91946323924783554000451984436e+1", 15: "-0.44360363875948939664310572000e+1"},
    {0: "0.10427508642579134603413151009e+2", 5: "0.24228349177525818288430175319e+3",
     6: "0.16520045171727028198505394887e+3", 7: "-0.37454675472269020279518312152e+3",
     8: "-0.22113666853125306036270938578e+2", 9: "0.77334326684722638389603898808e+1",
     10: "-0.30674084731089398182061213626e+2", 11: "-0.93321305264302278729567221706e+1",
     12: "0.15697238121770843886131091075e+2", 13: "-0.31139403219565177677282850411e+2",
     14: "-0.93529243588444783865713862664e+1", 15: "0.35816841486394083752465898540e+2"},
    {0: "0.19985053242002433820987653617e+2", 5: "-0.38703730874935176555105901742e+3",
     6: "-0.18917813819516756882830838328e+3", 7: "0.52780815920542364900561016686e+3",
     8: "-0.11573902539959630126141871134e+2", 9: "0.68812326946963000169666922661e+1",
     10: "-0.10006050966910838403183860980e+1", 11: "0.77771377980534432092869265740",
     12: "-0.27782057523535084065932004339e+1", 13: "-0.60196695231264120758267380846e+2",
     14: "0.84320405506677161018159903784e+2", 15: "0.11992291136182789328035130030e+2"},
    {0: "-0.25693933462703749003312586129e+2", 5: "-0.15418974869023643374053993627e+3",
     6: "-0.23152937917604549567536039109e+3", 7: "0.35763911791061412378285349910e+3",
     8: "0.93405324183624310003907691704e+2", 9: "-0.37458323136451633156875139351e+2",
     10: "0.10409964950896230045147246184e+3", 11: "0.29840293426660503123344363579e+2",
     12: "-0.43533456590011143754432175058e+2", 13: "0.96324553959188282948394950600e+2",
     14: "-0.39177261675615439165231486172e+2", 15: "-0.14972683625798562581422125276e+3"},
]


def _sparse_row(entries: dict, length: int) -> list:
    """A row of ``length`` exact coefficients, zero but at the ``{index: decimal string}`` entries."""
    row = [F(0)] * length
    for j, v in entries.items():
        row[j] = F(v)
    return row


def _dop853() -> Tableau:
    n, n_ext = 12, 16
    A = [[F(0)] * n_ext for _ in range(n_ext)]
    for (i, j), v in _DOP_A.items():
        A[i][j] = F(v)
    c = [F(v) for v in _DOP_C]
    b = A[n][:n]
    e3 = list(b)
    for j, v in _DOP_BHH.items():
        e3[j] -= F(v)
    e5 = _sparse_row(_DOP_E5, n)
    D = [_sparse_row(row, n_ext) for row in _DOP_D]
    dense = DenseOutput(
        kind="dop853",
        order=7,
        A_extra=tuple(tuple(A[i]) for i in range(n + 1, n_ext)),
        c_extra=tuple(c[n + 1:]),
        D=tuple(tuple(r) for r in D),
    )
    return Tableau(
        name="dop853",
        order=8,
        A=tuple(tuple(A[i][:n]) for i in range(n)),
        b=tuple(b),
        c=tuple(c[:n]),
        b_err=tuple(e5),
        b_err2=tuple(e3),
        err_order=7,
        dense=dense,
        reference="Hairer, Nørsett, Wanner, Solving ODEs I (1993) II.10; dop853.f; SciPy",
    )


DOP853 = _dop853()

TABLEAUX: dict[str, Tableau] = {t.name: t for t in (RK4, DOP853, GAUSS4, GAUSS6)}
