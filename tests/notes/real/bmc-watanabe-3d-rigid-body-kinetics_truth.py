"""Independent SymPy truth table for bmc-watanabe-3d-rigid-body-kinetics.ipynb.

The text's convention: vectors in a fixed basis i, j, k and in a body basis e1, e2, e3 (principal
axes at the centre of mass); angular momentum H about the centre of mass, moments M; products of
inertia carry the minus sign of their integrand (I_xy = -int r_x r_y dm, as the step from the
integrals to I_xy shows). Integrals over the body are checked as sums over a few mass points
(every step is linear in the mass elements); the basis e_i(t) is a rotation R(t) built from three
angles, and the angular velocity is the one R(t) has (dR/dt R^T = [w]x), so the identities on the
basis derivatives are checked on a real motion, not assumed.
"""
import pathlib
import random
import sys
import tomllib

import sympy as sp

t = sp.Symbol('t')
rnd = random.Random(11)


def zero(e, nsamp=4):
    """True when the expression (scalar or Matrix) vanishes: simplify, then random numbers."""
    items = list(e) if isinstance(e, sp.MatrixBase) else [e]
    for x in items:
        x = sp.sympify(x)
        if x == 0:
            continue
        for _ in range(nsamp):
            sub = {q: sp.Float(rnd.uniform(-2, 2), 30) for q in x.free_symbols}
            if abs(sp.N(x.xreplace(sub), 30)) > 1e-18:
                return False
    return True


COMPUTED = {}


def check(line, ok, fix_ok=None, note=''):
    COMPUTED[line] = ('holds' if ok else ('typo' if fix_ok else 'fails'), note)


# ---- mass points standing in for the integral over the body (positions from the centre of mass)
N = 3
ms = sp.symbols(f'm0:{N}', positive=True)
R = [sp.Matrix(sp.symbols(f'x{k} y{k} z{k}', real=True)) for k in range(N)]
wx, wy, wz = sp.symbols('omega_x omega_y omega_z', real=True)
w = sp.Matrix([wx, wy, wz])
i_, j_, k_ = sp.eye(3)[:, 0], sp.eye(3)[:, 1], sp.eye(3)[:, 2]


def integral(f):
    """int f dm over the body, f a function of the position r (components r_x, r_y, r_z)."""
    return sum((ms[k] * f(R[k]) for k in range(N)), sp.zeros(3, 1) if isinstance(f(R[0]), sp.MatrixBase) else 0)


H = integral(lambda r: r.cross(w.cross(r)))          # int r x (w x r) dm, v = w x r about the centre of mass

# 57: F = sum_{i=1}^n F_n (the summand's index is n, not i)
Fs = [sp.Matrix(sp.symbols(f'F{k}x F{k}y F{k}z')) for k in range(1, 4)]
printed = sum((Fs[2] for _ in range(3)), sp.zeros(3, 1))  # n = 3: the summand does not change with i
meant = Fs[0] + Fs[1] + Fs[2]
check(57, zero(printed - meant), True, 'sum_{i=1}^n F_n is n F_n; the resultant is sum F_i')

# 83: H = int r x v dm = int r x (w x r) dm
check(83, zero(integral(lambda r: r.cross(w.cross(r))) - H))
# 89: a x (b x c) = (a.c) b - (a.b) c
a, b, c = (sp.Matrix(sp.symbols(f'{n}x {n}y {n}z')) for n in 'abc')
check(89, zero(a.cross(b.cross(c)) - (a.dot(c) * b - a.dot(b) * c)))
# 100: ... = int (r.r) w - (r.w) r dm
check(100, zero(H - integral(lambda r: r.dot(r) * w - r.dot(w) * r)))
# 115: components written out
check(115, zero(H - integral(lambda r: (r.dot(r) * wx - r.dot(w) * r[0]) * i_ + (r.dot(r) * wy - r.dot(w) * r[1]) * j_
                             + (r.dot(r) * wz - r.dot(w) * r[2]) * k_)))
# 129: collected by unit vector, one product per integral
c129 = (integral(lambda r: wx * (r[1]**2 + r[2]**2)) + integral(lambda r: -wy * r[0] * r[1]) + integral(lambda r: -wz * r[0] * r[2])) * i_ \
    + (integral(lambda r: -wx * r[0] * r[1]) + integral(lambda r: wy * (r[0]**2 + r[2]**2)) + integral(lambda r: -wz * r[1] * r[2])) * j_ \
    + (integral(lambda r: -wx * r[0] * r[2]) + integral(lambda r: -wy * r[1] * r[2]) + integral(lambda r: wz * (r[0]**2 + r[1]**2))) * k_
check(129, zero(H - c129))
# 143: omega's components taken out of the integrals
Ixx = integral(lambda r: r[1]**2 + r[2]**2); Iyy = integral(lambda r: r[0]**2 + r[2]**2); Izz = integral(lambda r: r[0]**2 + r[1]**2)
Ixy = integral(lambda r: -r[0] * r[1]); Ixz = integral(lambda r: -r[0] * r[2]); Iyz = integral(lambda r: -r[1] * r[2])
c143 = (wx * Ixx + wy * Ixy + wz * Ixz) * i_ + (wx * Ixy + wy * Iyy + wz * Iyz) * j_ + (wx * Ixz + wy * Iyz + wz * Izz) * k_
check(143, zero(H - c143))
# 157: the k component's first product is printed I_yz (it is I_xz)
p157 = (wx * Ixx + wy * Ixy + wz * Ixz) * i_ + (wx * Ixy + wy * Iyy + wz * Iyz) * j_ + (wx * Iyz + wy * Iyz + wz * Izz) * k_
check(157, zero(H - p157), zero(H - c143), 'k component: omega_x I_xz, not omega_x I_yz')
# 178: H = [[Ixx Ixy Ixz][Ixy Iyy Iyz][Ixz Iyz Izz]] w = I w
Imat = sp.Matrix([[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]])
check(178, zero(H - Imat * w))

# ---- the body basis: e_i(t) = columns of R(t); omega from dR/dt R^T
q1, q2, q3 = (sp.Function(n)(t) for n in ('q1', 'q2', 'q3'))
def rot(axis, q):
    cq, sq = sp.cos(q), sp.sin(q)
    return {0: sp.Matrix([[1, 0, 0], [0, cq, -sq], [0, sq, cq]]),
            1: sp.Matrix([[cq, 0, sq], [0, 1, 0], [-sq, 0, cq]]),
            2: sp.Matrix([[cq, -sq, 0], [sq, cq, 0], [0, 0, 1]])}[axis]
Rt = rot(2, q1) * rot(0, q2) * rot(1, q3)              # any proper rotation serves
e = [Rt[:, n] for n in range(3)]
de = [sp.diff(x, t) for x in e]
Wm = sp.diff(Rt, t) * Rt.T
wf = sp.Matrix([Wm[2, 1], Wm[0, 2], Wm[1, 0]])        # angular velocity, fixed components
wb = Rt.T * wf                                         # its body components omega_1..3
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
Hb = I1 * wb[0] * e[0] + I2 * wb[1] * e[1] + I3 * wb[2] * e[2]


def on_motion(x):
    """Replace q_i(t) and its derivatives by numbers so that zero() sees plain symbols."""
    names = {}
    for n, q in enumerate((q1, q2, q3)):
        for order in (3, 2, 1, 0):
            d = sp.diff(q, t, order) if order else q
            names[d] = sp.Symbol(f'q{n}_{order}')
    if isinstance(x, sp.MatrixBase):
        return x.applyfunc(lambda y: y.subs(names))
    return x.subs(names)


# 264: H = I w = I1 w1 e1 + I2 w2 e2 + I3 w3 e3 (principal axes; w = w1 e1 + w2 e2 + w3 e3)
Ib = sp.diag(I1, I2, I3)
check(264, zero(on_motion(Rt * Ib * Rt.T * wf - Hb)))
# 287: dH/dt by the product rule
w1, w2, w3 = wb
dH287 = I1 * sp.diff(w1, t) * e[0] + I2 * sp.diff(w2, t) * e[1] + I3 * sp.diff(w3, t) * e[2] \
    + I1 * w1 * de[0] + I2 * w2 * de[1] + I3 * w3 * de[2]
check(287, zero(on_motion(sp.diff(Hb, t) - dH287)))
# 311 (and 536): w = (de2.e3) e1 + (de3.e1) e2 + (de1.e2) e3
w311 = de[1].dot(e[2]) * e[0] + de[2].dot(e[0]) * e[1] + de[0].dot(e[1]) * e[2]
check(311, zero(on_motion(wf - w311)))
check(536, COMPUTED[311][0] == 'holds')
# 335: w x e1 = -(de3.e1) e3 + (de1.e2) e2
check(335, zero(on_motion(wf.cross(e[0]) - (-de[2].dot(e[0]) * e[2] + de[0].dot(e[1]) * e[1]))))
# 342: w x e1 = (de1.e3) e3 + (de1.e2) e2
check(342, zero(on_motion(wf.cross(e[0]) - (de[0].dot(e[2]) * e[2] + de[0].dot(e[1]) * e[1]))))
# 348: ... + (de1.e1) e1 added
check(348, zero(on_motion(wf.cross(e[0]) - (de[0].dot(e[0]) * e[0] + de[0].dot(e[2]) * e[2] + de[0].dot(e[1]) * e[1]))))
# 353, 358: de_i/dt = w x e_i
check(353, zero(on_motion(de[0] - wf.cross(e[0]))))
check(358, zero(on_motion(de[1] - wf.cross(e[1]))) and zero(on_motion(de[2] - wf.cross(e[2]))))
# 379: the chain down to I w' + w x (I w), in body components rotated back
dw = sp.Matrix([sp.diff(x, t) for x in wb])
wbody = Rt * (Ib * dw + wb.cross(Ib * wb))            # I w' + w x (I w), as a fixed-axes vector
steps = [dH287,
         I1 * sp.diff(w1, t) * e[0] + I2 * sp.diff(w2, t) * e[1] + I3 * sp.diff(w3, t) * e[2]
         + I1 * w1 * wf.cross(e[0]) + I2 * w2 * wf.cross(e[1]) + I3 * w3 * wf.cross(e[2]),
         I1 * sp.diff(w1, t) * e[0] + I2 * sp.diff(w2, t) * e[1] + I3 * sp.diff(w3, t) * e[2]
         + wf.cross(I1 * w1 * e[0] + I2 * w2 * e[1] + I3 * w3 * e[2]),
         wbody]
check(379, all(zero(on_motion(sp.diff(Hb, t) - s)) for s in steps))
# 393: component form of the cross product
cols = sp.Matrix([I1 * sp.diff(w1, t) + w2 * w3 * (I3 - I2), I2 * sp.diff(w2, t) + w1 * w3 * (I1 - I3),
                  I3 * sp.diff(w3, t) + w1 * w2 * (I2 - I1)])
check(393, zero(on_motion(Ib * dw + wb.cross(Ib * wb) - cols)))
# 429, 434, 439: M_cm_i = the body components of dH/dt (Euler's law about the centre of mass)
Mb = Rt.T * sp.diff(Hb, t)
for n, line in enumerate((429, 434, 439)):
    check(line, zero(on_motion(Mb[n] - cols[n])))
# 451: M = I w' + w x (I w) (vectors in local frame)
check(451, zero(on_motion(Mb - (Ib * dw + wb.cross(Ib * wb)))))

# ---- the examples: rearrangements of the component laws
m, g = sp.symbols('m g', positive=True)
ax_, ay_, az_ = sp.symbols('a_x a_y a_z', real=True)
Fox, Foy, Foz = sp.symbols('F_Ox F_Oy F_Oz', real=True)
# 491: F = F_O - m g k (z up) -> F_Ox = m a_x, F_Oy = m a_y, F_Oz - m g = m a_z <-> F_Oz = m a_z + m g
law = sp.Matrix([Fox, Foy, Foz - m * g]) - m * sp.Matrix([ax_, ay_, az_])
check(491, zero(law[2] - ((Foz) - (m * az_ + m * g))) and zero(law[0] - (Fox - m * ax_)))
# 517: M_O_i + MFocm_i = (Euler's right side) <-> M_O_i = (right side) - MFocm_i; the left side is the
# body component of M = M_O + r_{O/cm} x F_O, so the first form is 429-439
MO = sp.Matrix(sp.symbols('M_O1 M_O2 M_O3')); MF = sp.Matrix(sp.symbols('MF1 MF2 MF3'))
rhs = sp.Matrix(sp.symbols('E1 E2 E3'))
check(517, all(zero((MO[n] + MF[n] - rhs[n]) - (MO[n] - (rhs[n] - MF[n]))) for n in range(3))
      and all(COMPUTED[x][0] == 'holds' for x in (429, 434, 439)))
# 560: y vertical: F_Ay - m g = m a_y <-> F_Ay = m a_y + m g
FAy = sp.Symbol('F_Ay')
check(560, zero((FAy - m * g - m * ay_) - (FAy - (m * ay_ + m * g))))
# 579: M_A + MFacm = I w' + w x I w <-> M_A = I w' + w x I w - MFacm
MA = sp.Matrix(sp.symbols('M_A1 M_A2 M_A3'))
check(579, zero((MA + MF - (Ib * dw + wb.cross(Ib * wb))) - (MA - ((Ib * dw + wb.cross(Ib * wb)) - MF)))
      and COMPUTED[451][0] == 'holds')
# negative control: a sign slip in Euler's first equation is caught
assert not zero(on_motion(Mb[0] - (I1 * sp.diff(w1, t) + w2 * w3 * (I2 - I3))))

if __name__ == '__main__':
    here = pathlib.Path(__file__).resolve().parent
    slug = pathlib.Path(__file__).name[:-len('_truth.py')]
    table = tomllib.load(open(here / (slug + '.truth.toml'), 'rb'))['display']
    bad = 0
    seen = set()
    for row in table:
        ln = row['line']
        seen.add(ln)
        exp = row['verdict']
        got = COMPUTED.get(ln, ('not a claim' if exp == 'not a claim' else 'MISSING', ''))[0]
        ok = got == exp
        bad += not ok
        print(f"{ln:5d}  {got:12s} toml={exp:12s} {'ok' if ok else 'DISAGREE'}")
    for ln in sorted(set(COMPUTED) - seen):
        print(f"{ln:5d}  computed but not in toml")
        bad += 1
    print('ALL AGREE' if not bad else f'{bad} disagreements')
    sys.exit(1 if bad else 0)
