"""Independent SymPy truth table for euler-angles-kinematic-equations-gimbal-lock-zh-notes-zxz.tex.

The text's own setting: z-x-z Euler angles (precession phi about OZ, nutation theta about the line
of nodes ON, spin psi about Oz); U = U1(phi) U2(theta) U3(psi) takes body coordinates to the
translating frame's, and the body components of the angular velocity are read off the
antisymmetric U^T dU/dt = [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]] (the chapter's definition).
The example: a disk of radius a rolling upright (theta = pi/2) with its centre C on a circle of
radius R about the fixed point O, precession rate omega_1, spin rate omega_2 (sizes, positive);
body vectors r_C = -R e_z, r_Q = -a sin psi e_x - a cos psi e_y - R e_z (the contact point), and
the rim point r_P = a e_x + R e_z as the text states it. Every check is built here from these
definitions, never from the text's later displays.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero

t = sp.symbols("t", real=True)
ph, th, ps = (sp.Function(n)(t) for n in ("phi", "theta", "psi"))


U1, U2, U3 = Rz(ph), Rx(th), Rz(ps)
U = U1 * U2 * U3
c, s = sp.cos, sp.sin
# 36: U = U1 U2 U3 written out
U_text = sp.Matrix([
    [c(ph) * c(ps) - s(ph) * c(th) * s(ps), -c(ph) * s(ps) - s(ph) * c(th) * c(ps), s(ph) * s(th)],
    [s(ph) * c(ps) + c(ph) * c(th) * s(ps), -s(ph) * s(ps) + c(ph) * c(th) * c(ps), -c(ph) * s(th)],
    [s(th) * s(ps), s(th) * c(ps), c(th)]])
check(36, zero(U - U_text))
# 48: Ui^T dUi/dt
pd, tdot, sd = ph.diff(t), th.diff(t), ps.diff(t)
check(48, zero(U1.T * U1.diff(t) - sp.Matrix([[0, -pd, 0], [pd, 0, 0], [0, 0, 0]]))
      and zero(U2.T * U2.diff(t) - sp.Matrix([[0, 0, 0], [0, 0, -tdot], [0, tdot, 0]]))
      and zero(U3.T * U3.diff(t) - sp.Matrix([[0, -sd, 0], [sd, 0, 0], [0, 0, 0]])))
# 54: U^T dU/dt: the product rule holds, but the middle member ends in U1^T dU1/dt where the third
# factor's term is U3^T dU3/dt; the final matrix is the true U^T dU/dt
W = sp.simplify(U.T * U.diff(t))
first = U3.T * U2.T * U1.T * (U1.diff(t) * U2 * U3 + U1 * U2.diff(t) * U3 + U1 * U2 * U3.diff(t))
middle_text = (U3.T * U2.T * U1.T * U1.diff(t) * U2 * U3 + U3.T * U2.T * U2.diff(t) * U3
               + U1.T * U1.diff(t))
final_text = sp.Matrix([
    [0, -pd * c(th) - sd, pd * s(th) * c(ps) - tdot * s(ps)],
    [pd * c(th) + sd, 0, -pd * s(th) * s(ps) - tdot * c(ps)],
    [-pd * s(th) * c(ps) + tdot * s(ps), pd * s(th) * s(ps) + tdot * c(ps), 0]])
check(54, zero(first - W) and zero(middle_text - W) and zero(final_text - W))
middle_fixed = middle_text - U1.T * U1.diff(t) + U3.T * U3.diff(t)
assert zero(middle_fixed - W) and zero(final_text - W) and not zero(middle_text - W)
# 66: Euler's kinematic equations read off U^T dU/dt
w = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
w_text = sp.Matrix([pd * s(th) * s(ps) + tdot * c(ps), pd * s(th) * c(ps) - tdot * s(ps), pd * c(th) + sd])
check(66, zero(w - w_text))

# the rolling disk: theta = pi/2, thetadot = 0; in body components the vertical e_Z is U's third row
a, R, w1 = sp.symbols("a R omega_1", positive=True)
p, q = sp.symbols("p q", real=True)            # phidot, psidot
psi = sp.symbols("psi", real=True)
sub = {th: sp.pi / 2, tdot: 0}
wb = sp.Matrix([e.subs(tdot, 0).subs(th, sp.pi / 2) for e in w_text]).subs({pd: p, sd: q, ps: psi})
eZ = U_text[2, :].T.subs(th, sp.pi / 2).subs(ps, psi)
assert zero(eZ - sp.Matrix([s(psi), c(psi), 0]))
rC = sp.Matrix([0, 0, -R])
rQ = sp.Matrix([-a * s(psi), -a * c(psi), -R])
assert zero(rQ - (rC - a * eZ))                 # Q is a below C
# rolling: v_Q = 0 fixes the spin: q = R p / a; the precession rate is p = omega_1
qsol = sp.solve(wb.cross(rQ)[0], q)[0]
assert sp.simplify(qsol - R * p / a) == 0
w2 = R * w1 / a                                 # the spin rate's size
# 81, 87: omega_1/omega_2 = a/R, omega_2 = R omega_1/a (axis OQ: omega parallel to r_Q)
wroll = wb.subs({p: w1, q: qsol.subs(p, w1)})
check(81, zero(wroll.cross(rQ)) and sp.simplify(w1 / w2 - a / R) == 0)
check(87, sp.simplify(w2 - R / a * w1) == 0)
# 93: omega = w1 (sin psi e_x + cos psi e_y) - omega_2 e_z = w1 (...) + R/a w1 e_z: the two members
# differ in the sign of the spin term (the rolling gives +R/a w1 along e_z)
m1 = sp.Matrix([w1 * s(psi), w1 * c(psi), -w2])
m2 = sp.Matrix([w1 * s(psi), w1 * c(psi), R / a * w1])
check(93, zero(m1 - m2) and zero(m2 - wroll))
assert zero(m2 - wroll) and not zero(m1 - m2)
# 99 and 145: v_P = omega x r_P with r_P = a e_x + R e_z as stated
rP = sp.Matrix([a, 0, R])
vP_text = sp.Matrix([w1 * R * c(psi), -w1 * R * (1 + s(psi)), w1 * a * c(psi)])
vP = wroll.cross(rP)
vP_minus = m1.cross(rP)                       # with the first member's -omega_2 e_z
check(99, zero(vP - vP_text) or zero(vP_minus - vP_text))
check(145, zero(vP - vP_text))
# the rim point of the disk (centre C = -R e_z) at a e_x moves with the opposite of the text's result
assert zero(wroll.cross(rC + sp.Matrix([a, 0, 0])) + vP_text)
# 105, 115: at theta = pi/2 the kinematic equations give (phidot sin psi, phidot cos psi, psidot)
check(105, zero(wb - sp.Matrix([p * s(psi), p * c(psi), q])))
check(115, zero(wb - sp.Matrix([p * s(psi), p * c(psi), q])))
# 121: v_C = omega x r_C = -R phidot cos psi e_x + R phidot sin psi e_y
check(121, zero(wb.cross(rC) - sp.Matrix([-R * p * c(psi), R * p * s(psi), 0])))
# 127: |v_C| = R phidot equals the given speed omega_1 R
check(127, sp.simplify(sp.sqrt(sp.expand((wb.cross(rC).T * wb.cross(rC))[0])).subs(p, w1) - w1 * R) == 0)
# 133: v_Q = omega x r_Q
check(133, zero(wb.cross(rQ) - sp.Matrix([(a * q - R * p) * c(psi), -(a * q - R * p) * s(psi), 0])))
# 139: psidot = R phidot / a = R omega_1 / a
check(139, sp.simplify(qsol - R / a * p) == 0)
# 151: U at theta = 0 or pi: rot_z(phi + psi) at 0; at pi the matrix is diag-flipped, not rot_z(phi - psi)
U0 = U_text.subs(th, 0)
Upi = U_text.subs(th, sp.pi)
check(151, zero(U0 - Rz(ph + ps)) and zero(Upi - Rz(ph - ps)))
assert zero(U0 - Rz(ph + ps)) and zero(Upi - sp.Matrix([[c(ph - ps), s(ph - ps), 0],
                                                       [s(ph - ps), -c(ph - ps), 0], [0, 0, -1]]))
# 161: the kinematic equations as a matrix on (thetadot, phidot, psidot)
Mtext = sp.Matrix([[s(th) * c(ps), -s(ps), 0], [s(th) * s(ps), c(ps), 0], [c(th), 0, 1]])
check(161, zero(Mtext * sp.Matrix([tdot, pd, sd]) - w_text))
Mtrue = sp.Matrix([[c(ps), s(th) * s(ps), 0], [-s(ps), s(th) * c(ps), 0], [0, c(th), 1]])
assert zero(Mtrue * sp.Matrix([tdot, pd, sd]) - w_text) and sp.simplify(Mtrue.det() - s(th)) == 0

LINES = [30, 36, 48, 54, 66, 81, 87, 93, 99, 105, 115, 121, 127, 133, 139, 145, 151, 161]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
