"""Independent SymPy truth table for spacecraft-course-notes-rigid-body-energy-euler-equations.md.

The text's convention (Schaub's): angular momentum H, torque L (not an angular momentum), inertia
tensor [I] about the centre of mass C, frames N (inertial) and B (body); omega = omega_{B/N} in
body components. Integrals over the body are checked as sums over a few mass points placed about
C (sum m r = 0), every step being linear in the mass elements; the body's attitude is a rotation
R(t) built from three angles and its angular velocity is the one R(t) has (R^T dR/dt = [w]x), so
the transport theorem and Euler's equations are checked on a real motion, not assumed. The
torques are those the motion needs (L = dH/dt in N), so the equations that claim L are checked
against the torque, not against a torque-free motion.
"""
import random
import sys

import sympy as sp

import truth_table

t = sp.Symbol('t')
rng = random.Random(5)
CHECKS = {}


def check(line, ok):
    CHECKS[line] = bool(ok)


def zero(e, nsamp=3):
    """True when the expression (scalar or Matrix) vanishes at random numbers for its symbols
    (and a few times t)."""
    items = list(e) if isinstance(e, sp.MatrixBase) else [e]
    for x in items:
        x = sp.sympify(x)
        for _ in range(nsamp):
            sub = {q: sp.Float(rng.uniform(-1.5, 1.5), 30) for q in x.free_symbols}
            if abs(sp.N(x.xreplace(sub), 30)) > 1e-15:
                return False
    return True


# ---- attitude R(t) (body to inertial), from three angles quadratic in time with free coefficients
a, b, c = [sum(sp.Symbol(f'{n}{k}', real=True) * t**k for k in range(3)) for n in ('a', 'b', 'c')]
Rz = lambda q: sp.Matrix([[sp.cos(q), -sp.sin(q), 0], [sp.sin(q), sp.cos(q), 0], [0, 0, 1]])  # noqa: E731
Rx = lambda q: sp.Matrix([[1, 0, 0], [0, sp.cos(q), -sp.sin(q)], [0, sp.sin(q), sp.cos(q)]])  # noqa: E731
R = Rz(a) * Rx(b) * Rz(c)
W = R.T * R.diff(t)                        # [w]x in body components
w = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
assert zero(W + W.T)
wd = w.diff(t)


def cross(u, v):
    return u.cross(v)


# ---- mass points about C (body components fixed: the body is rigid), centre of mass motion Rc(t)
N = 3
ms = sp.symbols('m0:3', positive=True)
pts = [sp.Matrix(sp.symbols(f'x{k} y{k} z{k}', real=True)) for k in range(N - 1)]
pts.append(-(ms[0] * pts[0] + ms[1] * pts[1]) / ms[2])   # sum m r = 0: the points sit about C
M = sum(ms)
Rc = sp.Matrix([sum(sp.Symbol(f'X{i}{k}', real=True) * t**k for k in range(3)) for i in range(3)])
Vc = Rc.diff(t)
rN = [R * p for p in pts]                               # positions from C in N
I = sum((ms[k] * ((pts[k].T * pts[k])[0] * sp.eye(3) - pts[k] * pts[k].T) for k in range(N)), sp.zeros(3))
H = sum((ms[k] * cross(pts[k], cross(w, pts[k])) for k in range(N)), sp.zeros(3, 1))  # body comps
HN = R * H
L_N = HN.diff(t)                                        # the torque the motion needs, in N
L_B = R.T * L_N                                         # ... in body components
F = M * Vc.diff(t)                                      # the force the centre of mass needs

# 20: T = 1/2 M Rc'.Rc' + 1/2 int r'.r' dm (r from C): Koenig's split, the cross term vanishing
T_tot = sum((ms[k] * ((Vc + rN[k].diff(t)).T * (Vc + rN[k].diff(t)))[0] / 2 for k in range(N)))
T_trans = M * (Vc.T * Vc)[0] / 2
T_rot = sum((ms[k] * (rN[k].diff(t).T * rN[k].diff(t))[0] / 2 for k in range(N)))
check(20, zero(T_tot - (T_trans + T_rot)))
# 28: r' = w x r (in N: R (w x p)), so T_rot = 1/2 int (w x r).(w x r) dm
wxr = [cross(w, p) for p in pts]
check(28, zero(T_rot - sum((ms[k] * (wxr[k].T * wxr[k])[0] / 2 for k in range(N))))
      and all(zero(rN[k].diff(t) - R * wxr[k]) for k in range(N)))
# 35: T_rot = 1/2 w . H_C
check(35, zero(T_rot - (w.T * H)[0] / 2))
# 42: T_rot = 1/2 w^T [I] w
check(42, zero(T_rot - (w.T * I * w)[0] / 2))
# 51: T' = F . Rc' + L_C . w (torque and rates in one frame: body components)
check(51, zero((T_trans + T_rot).diff(t) - ((F.T * Vc)[0] + (L_B.T * w)[0])))
# 58: W = T(t2) - T(t1) = int F.Rc' dt + int L.w dt: the integral of 51 (same integrand)
check(58, CHECKS[51])
# 68: H = [I] w (the angular momentum about C of the mass points)
check(68, zero(H - I * w))
# 94: N dH/dt = B dH/dt + w x H (in body components: R^T d(R H)/dt = H' + w x H)
check(94, zero(R.T * HN.diff(t) - (H.diff(t) + cross(w, H))))
# 101: L = B dH/dt + w x H, with N dH/dt = L (87)
check(101, zero(L_B - (H.diff(t) + cross(w, H))))
# 109: the same about the centre of mass
check(109, CHECKS[101])
# 116: B H_C = B[I_C] w
check(116, CHECKS[68])
# 122: B dH_C/dt = B d/dt ([I_C] w): the derivative of the two sides of 116
check(122, zero(H.diff(t) - (I * w).diff(t)))
# 128: product rule: B d/dt([I] w) = (B d[I]/dt) w + [I] B dw/dt
check(128, zero((I * w).diff(t) - (I.diff(t) * w + I * wd)))
# 134: B d[I_C]/dt = 0: the body components of the inertia tensor do not depend on time
check(134, zero(I.diff(t)))
# 140: B dH_C/dt = [I_C] B dw/dt
check(140, zero(H.diff(t) - I * wd))
# 147: L_C = [I_C] w' + w x ([I_C] w)
check(147, zero(L_B - (I * wd + cross(w, I * w))))

# ---- principal axes: a diagonal inertia tensor on the same motion
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
Ip = sp.diag(I1, I2, I3)
Lp = R.T * (R * Ip * w).diff(t)                         # the torque this body needs, body comps
w1, w2, w3 = w
# 194: diag(I) w' + w x (diag(I) w) = L
check(194, zero(Ip * wd + cross(w, Ip * w) - Lp))
# 226: component form of the cross product
comp = sp.Matrix([w2 * (I3 * w3) - w3 * (I2 * w2), w3 * (I1 * w1) - w1 * (I3 * w3),
                  w1 * (I2 * w2) - w2 * (I1 * w1)])
check(226, zero(sp.Matrix([I1 * wd[0], I2 * wd[1], I3 * wd[2]]) + comp - Lp)
      and zero(comp - cross(w, Ip * w)))
# 247, 250, 253: Euler's equations with the torque components L_1, L_2, L_3
check(247, zero(I1 * wd[0] + (I3 - I2) * w2 * w3 - Lp[0]))
check(250, zero(I2 * wd[1] + (I1 - I3) * w3 * w1 - Lp[1]))
check(253, zero(I3 * wd[2] + (I2 - I1) * w1 * w2 - Lp[2]))

# negative controls: a sign slip in Euler's first equation is caught, and without the last point
# the mass points would not sit about C
assert not zero(I1 * wd[0] + (I2 - I3) * w2 * w3 - Lp[0])
assert not zero(sum((ms[k] * pts[k] for k in range(N - 1)), sp.zeros(3, 1)))

LINES = [20, 28, 35, 42, 51, 58, 68, 77, 87, 94, 101, 109, 116, 122, 128, 134, 140, 147, 183, 194, 226, 247,
         250, 253]

ROWS = {
    20: ('holds', "Koenig's split of the kinetic energy: with r measured from the centre of mass the cross term M R_C' . (sum m r)' vanishes (check 20)"),
    28: ('holds', "a point of a rigid body moves relative to C with r' = omega x r, substituted into the rotational energy (check 28)"),
    35: ('holds', 'with (w x r).(w x r) = w . (r x (w x r)) the integral is half w . H_C (check 35)'),
    42: ('holds', 'H_C = [I] w turns 1/2 w . H_C into the quadratic form 1/2 w^T [I] w (check 42)'),
    51: ('holds', "the rate of the kinetic energy: M R_C''. R_C' = F . R_C' and d/dt(1/2 w.[I]w) = w . L_C with Euler's equation (check 51)"),
    58: ('holds', 'the time integral of the power of 51 from t_1 to t_2 (check 58)'),
    68: ('holds', 'the angular momentum of the mass points about C equals the inertia tensor applied to w (check 68)'),
    77: ('not a claim', "Euler's law: the rate of the angular momentum equals the external torque, the law the text starts from"),
    87: ('not a claim', 'the same law written with the derivative taken in the inertial frame N'),
    94: ('holds', 'the transport theorem: in body components R^T d(R H)/dt = H dot + w x H (check 94)'),
    101: ('holds', 'the law of 87 with the transport theorem of 94 (check 101)'),
    109: ('holds', 'the relation of 101 about the centre of mass (check 101)'),
    116: ('holds', 'H_C = [I_C] w about the centre of mass in body components (check 68)'),
    122: ('holds', 'the body-frame derivative of both sides of 116 (check 122)'),
    128: ('holds', 'the product rule for [I_C] w (check 128)'),
    134: ('holds', "the body components of a rigid body's inertia tensor do not change (check 134)"),
    140: ('holds', 'with 134 the product rule leaves [I_C] times the body-frame rate of w (check 140)'),
    147: ('holds', "the rotational equation of motion about C: L_C = [I_C] w' + w x [I_C] w on the motion's own torque (check 147)"),
    183: ('not a claim', 'the inertia tensor in principal axes: the definition of the principal frame'),
    194: ('holds', 'the equation of motion of 147 with the diagonal tensor (check 194)'),
    226: ('holds', 'the cross product w x ([I] w) expanded component by component (check 226)'),
    247: ('holds', "Euler's first equation with the torque component L_1 (check 247)"),
    250: ('holds', "Euler's second equation with the torque component L_2 (check 250)"),
    253: ('holds', "Euler's third equation with the torque component L_3 (check 253)"),
}

if __name__ == "__main__":
    if sys.argv[1:] == ['--write']:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
