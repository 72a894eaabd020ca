"""Independent SymPy truth table for kanamesasaki-blog-rigid-body-lagrange-inertia-tensor-euler-equations-ja.md.

The text's convention (Hughes' vectrix): a frame is the column of its basis vectors, so with the
basis vectors' reference components as the rows of a matrix F, the vector with frame components
r is F^T r. Here the body frame is F_b = R^T for an attitude R(t) built from three angles with
free coefficients, its angular velocity (reference components) the one R has (R' R^T = [w]x), and
the rigid body is a few mass points with fixed body components; the motion's data (angles'
coefficients, masses, points) are random rationals, time a symbol. A vector of the reference frame
(an arrow in the text) is a column of reference components. The still frame F_a is a constant
rotation. Identities are checked at random numbers (and three times t) with 30 digits.
"""
import random
import sys

import sympy as sp

import truth_table

t = sp.Symbol('t')
rng = random.Random(7)
CHECKS = {}


def check(line, ok):
    CHECKS[line] = bool(ok)


def zero(e, nsamp=3):
    """True when the expression (scalar or Matrix) vanishes at random numbers for its symbols."""
    items = list(e) if isinstance(e, sp.MatrixBase) else [e]
    for x in items:
        x = sp.sympify(x)
        for _ in range(nsamp):
            sub = {q: sp.Float(rng.uniform(-1.5, 1.5), 30) for q in x.free_symbols}
            if abs(sp.N(x.xreplace(sub), 30)) > 1e-15:
                return False
    return True


def skew(u):
    return sp.Matrix([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])


def dot(u, v):
    return (u.T * v)[0]


E = sp.eye(3)
def num(pos=False):
    """A random rational (positive when asked): the body's data are numbers, time stays a symbol."""
    return sp.Rational(rng.randint(1, 9), rng.randint(2, 7)) * (1 if pos else rng.choice((-1, 1)))


a, b, c = [sum(num() * t**k for k in range(3)) for n in ('a', 'b', 'c')]
R = truth_table.Rz(a) * truth_table.Rx(b) * truth_table.Rz(c)
Fb = R.T                                    # rows: the body basis vectors in reference components
W = R.diff(t) * R.T
w = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])  # angular velocity, reference components
assert zero(W + W.T)
N = 3
ms = [num(pos=True) for _ in range(N)]
m = sum(ms)
pb = [sp.Matrix([num() for _ in range(3)]) for k in range(N)]   # body components
Ro = sp.Matrix([sum(num() * t**k for k in range(3)) for i in range(3)])
Vo = Ro.diff(t)
rv = [Fb.T * p for p in pb]                 # the arrows r_n
Vn = [Vo + r.diff(t) for r in rv]
cv = sum((ms[k] * rv[k] for k in range(N)), sp.zeros(3, 1))
Jv = sum((ms[k] * (E * dot(rv[k], rv[k]) - rv[k] * rv[k].T) for k in range(N)), sp.zeros(3))
T = sum(ms[k] * dot(Vn[k], Vn[k]) for k in range(N)) / 2

# 48: R_n' = V_o + F_b^T r_n' + F_b'^T r_n, and F_b'^T r = (w x F_b^T) r, for components r_n(t)
rt = sp.Matrix([sp.Function(f'r{i}')(t) for i in range(3)])
lhs = (Ro + Fb.T * rt).diff(t)
check(48, zero((lhs - (Vo + Fb.T * rt.diff(t) + Fb.diff(t).T * rt)).subs({q.diff(t): 0.3 * (i + 1) for i, q in enumerate(rt)}).subs({q: 0.7 - i for i, q in enumerate(rt)}))
      and zero(Fb.diff(t).T - skew(w) * Fb.T))
# 57: rigid body: V_n = V_o + w x r_n
check(57, all(zero(Vn[k] - (Vo + w.cross(rv[k]))) for k in range(N)))
# 66: the chain for T, line by line (c the first moment sum m_n r_n, as the text defines it)
l1 = sum(ms[k] * dot(Vo + w.cross(rv[k]), Vo + w.cross(rv[k])) for k in range(N)) / 2
l2 = m * dot(Vo, Vo) / 2 + sum(dot(Vo, w.cross(ms[k] * rv[k])) for k in range(N)) \
    + sum(ms[k] * dot(rv[k].cross(w), rv[k].cross(w)) for k in range(N)) / 2
l3 = m * dot(Vo, Vo) / 2 + dot(Vo, w.cross(cv)) \
    + (w.T * sum((ms[k] * skew(rv[k]).T * skew(rv[k]) for k in range(N)), sp.zeros(3)) * w)[0] / 2
l4 = m * dot(Vo, Vo) / 2 + dot(Vo, w.cross(cv)) + (w.T * Jv * w)[0] / 2
check(66, zero(T - l1) and zero(l1 - l2) and zero(l2 - l3) and zero(l3 - l4))
# 79: T with the moment of inertia J named
check(79, zero(T - l4))
# 115: in a still orthonormal frame F_a (rows a_i): the arrows are F_a^T times their components;
# checked at three times, the motion's vectors evaluated there first
A = truth_table.Rz(sp.Rational(3, 7)) * truth_table.Rx(sp.Rational(-5, 9)) * truth_table.Rz(sp.Rational(2, 3))
Fa = A.T.evalf(30)
ok115 = ok131 = True
for t0 in (sp.Rational(31, 100), sp.Rational(77, 100), sp.Rational(7, 5)):
    at = lambda e: e.subs(t, t0).evalf(30)  # noqa: E731
    Vo0, w0, cv0, Jv0, T0 = at(Vo), at(w), at(cv), at(Jv), at(sp.Matrix([T]))[0]
    vo, om, cc = Fa * Vo0, Fa * w0, Fa * cv0          # components in F_a
    Ja = Fa * Jv0 * Fa.T                              # J in F_a: \vec J = F_a^T J F_a
    m1 = m * dot(Fa.T * vo, Fa.T * vo) / 2 + dot(Fa.T * vo, Fa.T * om.cross(cc)) + ((Fa.T * om).T * (Fa.T * Ja * Fa) * (Fa.T * om))[0] / 2
    m2 = m * (vo.T * Fa * Fa.T * vo)[0] / 2 + (vo.T * Fa * Fa.T * om.cross(cc))[0] + (om.T * Fa * Fa.T * Ja * Fa * Fa.T * om)[0] / 2
    m3 = m * dot(vo, vo) / 2 + dot(vo, om.cross(cc)) + (om.T * Ja * om)[0] / 2
    ok115 = ok115 and zero(T0 - m1) and zero(m1 - m2) and zero(m2 - m3)
    # 131: \vec J = F_a^T J F_a, each step of the chain
    ra = [Fa * at(r) for r in rv]
    j1 = sum((ms[k] * (E * dot(ra[k], ra[k]) - (Fa.T * ra[k]) * (Fa.T * ra[k]).T) for k in range(N)), sp.zeros(3))
    j2 = sum((ms[k] * (E * dot(ra[k], ra[k]) - Fa.T * ra[k] * ra[k].T * Fa) for k in range(N)), sp.zeros(3))
    j3 = Fa.T * sum((ms[k] * (E * dot(ra[k], ra[k]) - ra[k] * ra[k].T) for k in range(N)), sp.zeros(3)) * Fa
    ok131 = ok131 and zero(Jv0 - j1) and zero(j1 - j2) and zero(j2 - j3) and zero(j3 - Fa.T * Ja * Fa)
check(115, ok115)
check(131, ok131)
# 145: with the origin at the centre of mass (sum m r = 0) T = 1/2 m v^T v + 1/2 w^T J w
pc = pb[:2] + [-(ms[0] * pb[0] + ms[1] * pb[1]) / ms[2]]
rc = [Fb.T * p for p in pc]
Jc = sum((ms[k] * (E * dot(rc[k], rc[k]) - rc[k] * rc[k].T) for k in range(N)), sp.zeros(3))
Tc = sum(ms[k] * dot(Vo + rc[k].diff(t), Vo + rc[k].diff(t)) for k in range(N)) / 2
check(145, zero(Tc - (m * dot(Vo, Vo) / 2 + (w.T * Jc * w)[0] / 2)))
# 163: dL/dv of 1/2 m v^T v - U is m v, dL/dr is -dU/dr: m dv/dt = -dU/dr
v = sp.Matrix(sp.symbols('v1:4', real=True))
om_s = sp.Matrix(sp.symbols('o1:4', real=True))
Js = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f'J{min(i, j)}{max(i, j)}', real=True))
Ls = m * dot(v, v) / 2 + (om_s.T * Js * om_s)[0] / 2
check(163, zero(sp.Matrix([sp.diff(Ls, q) for q in v]) - m * v))
# 172: dL/dw = J w (J symmetric), so the rotational equation reads d(J w)/dt = -dU/dtheta
check(172, zero(sp.Matrix([sp.diff(Ls, q) for q in om_s]) - Js * om_s))
# 182: d(J w)/dt = J' w + J w' = w^x J w + J w', with J the reference components of the body's tensor
check(182, zero((Jv * w).diff(t) - (Jv.diff(t) * w + Jv * w.diff(t))) and zero(Jv.diff(t) * w - skew(w) * Jv * w))
# 193, 199: J + dJ from the points moved by w^x r dt, and its first-order part step by step
dt = sp.Symbol('dt')
rs = [sp.Matrix(sp.symbols(f'p{k}_1:4', real=True)) for k in range(N)]
Ws = skew(om_s)
Jr = sum((ms[k] * (E * dot(rs[k], rs[k]) - rs[k] * rs[k].T) for k in range(N)), sp.zeros(3))
mv = [r + Ws * r * dt for r in rs]
JdJ = sum((ms[k] * (E * dot(mv[k], mv[k]) - mv[k] * mv[k].T) for k in range(N)), sp.zeros(3))
check(193, zero(JdJ - sum((ms[k] * (E * dot(rs[k] + Ws * rs[k] * dt, rs[k] + Ws * rs[k] * dt)
                                    - (rs[k] + Ws * rs[k] * dt) * (rs[k] + Ws * rs[k] * dt).T) for k in range(N)), sp.zeros(3))))
dJ = (JdJ - Jr).applyfunc(lambda e: sp.expand(e).coeff(dt, 1)) * dt
d1 = sum((ms[k] * (E * (dot(rs[k], Ws * rs[k] * dt) + dot(Ws * rs[k] * dt, rs[k])) - rs[k] * (Ws * rs[k] * dt).T - (Ws * rs[k] * dt) * rs[k].T) for k in range(N)), sp.zeros(3))
d2 = sum((ms[k] * (E * ((rs[k].T * Ws * rs[k] * dt)[0] - (rs[k].T * Ws * rs[k] * dt)[0]) + rs[k] * rs[k].T * Ws * dt - Ws * rs[k] * rs[k].T * dt) for k in range(N)), sp.zeros(3))
d3 = sum((ms[k] * (rs[k] * rs[k].T * Ws - Ws * rs[k] * rs[k].T) * dt for k in range(N)), sp.zeros(3))
check(199, zero(dJ - d1) and zero(d1 - d2) and zero(d2 - d3))
# 208: (dJ/dt) w = w^x (-sum m r r^T) w, and w^x J w equals the same
S = sum((ms[k] * rs[k] * rs[k].T for k in range(N)), sp.zeros(3))
check(208, zero((d3 / dt) * om_s - Ws * (-S) * om_s) and zero(Ws * Jr * om_s - Ws * (-S) * om_s))
# 218: with d(J w)/dt = 0 and 182, w' = -J^-1 w^x J w: d(J w)/dt = J (w' + J^-1 w^x J w) identically
# (J is positive definite, so it is invertible and the factor J may be taken off)
check(218, zero((Jv * w).diff(t) - (Jv * w.diff(t) + skew(w) * Jv * w)))
# 238: with J = diag(J1, J2, J3) the components of -J^-1 w^x J w
J1, J2, J3 = sp.symbols('J1 J2 J3', positive=True)
Jd = sp.diag(J1, J2, J3)
rhs = -Jd.inv() * skew(om_s) * Jd * om_s
o1, o2, o3 = om_s
check(238, zero(rhs - sp.Matrix([-(J3 - J2) / J1 * o2 * o3, -(J1 - J3) / J2 * o3 * o1, -(J2 - J1) / J3 * o1 * o2])))

LINES = [25, 39, 48, 57, 66, 79, 89, 99, 107, 115, 131, 145, 154, 163, 172, 182, 193, 199, 208, 218, 229, 238]

ROWS = {
    25: ('not a claim', 'the body frame written as the column of its basis vectors: a definition'),
    39: ('not a claim', 'the position of a mass point as the origin plus its offset, whose body components define r_n'),
    48: ('holds', "the product rule for V_o + F_b^T r_n, with the basis vectors' rate w x b_i (check 48)"),
    57: ('holds', 'with fixed body components the velocity is V_o + w x r_n (check 57)'),
    66: ('holds', 'each step of the kinetic energy: the square expanded, (w x r).(w x r) = w^T (r^x)^T r^x w, and (r^x)^T r^x = 1 (r.r) - r r^T; c is the first moment sum m_n r_n as the text defines it (check 66)'),
    79: ('holds', 'the last line of 66 with the bracket named J (check 79)'),
    89: ('not a claim', 'the skew-symmetric matrix of a column: a definition'),
    99: ('not a claim', 'a vector as the components in the still frame F_a times its basis: a definition'),
    107: ('not a claim', 'the components v_o of V_o in F_a: a definition, written in both orders'),
    115: ('holds', 'the energy in the still frame: F_a F_a^T = 1 removes the frames, each step (check 115)'),
    131: ('holds', 'the change of frame of the moment of inertia, each step, with F_a^T F_a the unit tensor (check 131)'),
    145: ('holds', 'with the origin at the centre of mass the cross term vanishes (check 145)'),
    154: ('not a claim', "Lagrange's equations for translation and rotation, named"),
    163: ('holds', 'dL/dv of the Lagrangian of 145 is m v, dL/dr is -dU/dr (check 163)'),
    172: ('holds', 'dL/dw of the Lagrangian of 145 is J w, the angular momentum (check 172)'),
    182: ('holds', "the product rule, and J' w = w^x J w for the reference components of the body's tensor (check 182)"),
    193: ('holds', 'the moment of inertia of the points moved by w^x r dt (check 193)'),
    199: ('holds', 'the first-order part of 193 in dt, each step, with (w^x r)^T r = -r^T w^x r (check 199)'),
    208: ('holds', 'r r^T w^x w = 0 and w^x w (r.r) = 0 leave both sides w^x (-sum m r r^T) w (check 208)'),
    218: ('holds', 'with no moment d(J w)/dt = 0, and by 182 J w + w^x J w = 0 (check 218)'),
    229: ('not a claim', 'the moment of inertia in principal axes: the definition of the principal frame'),
    238: ('holds', "the components of 218 with the diagonal tensor: Euler's equations (check 238)"),
}

if __name__ == "__main__":
    if sys.argv[1:] == ['--write']:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
