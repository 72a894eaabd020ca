"""Independent SymPy truth table for physics-taxonomies-rigid-body-rotation-precession-gyroscope-equation-sheets.md.

The sheets' own setting: a rigid body (or a set of point masses) with inertia tensor I = sum m (r.r E - r r^T)
about its centre of mass or a fixed pivot; Euler's equations on principal axes; the z-x-z rotation the
sheet writes as R = R_z(psi) R_x(theta) R_z(phi) (Goldstein's passive matrix, space to body), so that the
active turn body to space is Q = Rz(phi) Rx(theta) Rz(psi) and the body angular velocity is vect(Q^T Qdot);
a spinning top of mass M whose centre is at distance r (or d) from its pivot on its axis, spin moment
I_z (I_s) and transverse moment I_x (I_perp); a precessing angular momentum Ldot = Omega_p x L with
Omega_p across L. Every check is built from these definitions, never from the sheets' other displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
t = sp.Symbol('t', real=True)
E3 = sp.eye(3)


def vec(name):
    return sp.Matrix(sp.symbols(f'{name}1:4', real=True))


def skew(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def unskew(S):
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


# two particles with positions r_i(t), masses m_i, external forces F_i and a central internal pair force
m1, m2, k = sp.symbols('m_1 m_2 k', positive=True)
r1 = sp.Matrix([sp.Function(f'x1{c}')(t) for c in 'abc'])
r2 = sp.Matrix([sp.Function(f'x2{c}')(t) for c in 'abc'])
F1, F2 = vec('F'), vec('G')
f12 = k * (r1 - r2)                                   # force on 1 from 2, central
a1 = (F1 + f12) / m1
a2 = (F2 - f12) / m2
Lp = m1 * r1.cross(r1.diff(t)) + m2 * r2.cross(r2.diff(t))
Ldot = Lp.diff(t).subs({r1.diff(t, 2)[i]: a1[i] for i in range(3)}).subs({r2.diff(t, 2)[i]: a2[i] for i in range(3)})
tau = r1.cross(F1) + r2.cross(F2)
check(28, zero(Ldot - tau))                           # tau = dL/dt
check(88, zero(Ldot - tau))

# rotation matrix kinematics: Rdot R^T is skew, so Rdot = Omega R
ph, th, ps = [sp.Function(n)(t) for n in ('phi', 'theta', 'psi')]
Q = truth_table.Rz(ph) * truth_table.Rx(th) * truth_table.Rz(ps)   # active, body to space
Om = Q.diff(t) * Q.T
check(34, zero(Om + Om.T) and zero(Q.diff(t) - Om * Q))

# unit quaternion rate with the body angular velocity (Hamilton product, q body to space)


def qmul(p, q):
    p0, pv = p[0], sp.Matrix(p[1:])
    q0, qv = q[0], sp.Matrix(q[1:])
    return [p0 * q0 - pv.dot(qv)] + list(p0 * qv + q0 * pv + pv.cross(qv))


def qaxis(ax, a):
    v = [0, 0, 0]
    v[ax] = sp.sin(a / 2)
    return [sp.cos(a / 2)] + v


q = qmul(qmul(qaxis(2, ph), qaxis(0, th)), qaxis(2, ps))
wb = unskew(sp.simplify(Q.T * Q.diff(t)))             # body angular velocity
rhs = [sp.Rational(1, 2) * c for c in qmul(q, [0] + list(wb))]
check(38, truth_table.numeric_zero(sp.Matrix([sp.diff(c, t) for c in q]) - sp.Matrix(rhs), t))

# the body's inertia tensor from point masses; the sheet's integrand rho (r.r) I_3 - r r^T
rho = sp.Symbol('rho', positive=True)
x = vec('x')
written = rho * x.dot(x) * E3 - x * x.T
meant = rho * (x.dot(x) * E3 - x * x.T)
check(44, zero(written - meant))
SLIP_44_FIXED = zero(meant - rho * (x.dot(x) * E3 - x * x.T))

# Euler's equations from I wdot + w x (I w) = M on principal axes
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
w = vec('omega')
wd = vec('omegadot')
M = vec('M')
Ib = sp.diag(I1, I2, I3)
euler = Ib * wd + w.cross(Ib * w)                     # equals the torque
sheet = sp.Matrix([I1 * wd[0] + (I3 - I2) * w[1] * w[2], I2 * wd[1] + (I1 - I3) * w[2] * w[0],
                   I3 * wd[2] + (I2 - I1) * w[0] * w[1]])
check(48, zero(euler - sheet))                        # torque-free: both sides 0 together
check(82, zero(euler - sheet))
check(168, zero(euler[0] - sheet[0]))

# precession: Ldot = Omega x L with Omega across L, tau = Ldot
Lv = sp.Matrix([sp.Symbol('L', positive=True), 0, 0])
Omv = sp.Matrix([0, sp.Symbol('a', real=True), sp.Symbol('b', real=True)])
tq = Omv.cross(Lv)
Lsq = Lv.dot(Lv)
check(56, zero(tq.cross(Lv) / Lsq - Omv))
check(110, zero(tq - Omv.cross(Lv)))
check(134, zero(-tq - (-Omv.cross(Lv))))              # the supports take the opposite torque
check(92, zero(tq.dot(tq) - (Omv.dot(Omv) * Lsq)))    # |tau| = Omega_p L
check(148, zero(tq.cross(Lv) / Lsq - Omv))
SLIP_56_FIXED = zero(Lv.cross(tq) / Lsq - Omv)

# the parallel-axis theorem for a moment about the z axis: masses about their centre, shifted by d
X = [vec('p'), vec('q')]
ms = [m1, m2]
cm_cond = {X[1][i]: -m1 * X[0][i] / m2 for i in range(3)}
dvec = sp.Matrix([sp.Symbol('d', positive=True), 0, 0])
Izz = lambda pts: sum(m * (p[0] ** 2 + p[1] ** 2) for m, p in zip(ms, pts))
check(62, zero((Izz([p + dvec for p in X]) - Izz(X) - (m1 + m2) * dvec.dot(dvec)).subs(cm_cond)))

# rate of the angular momentum about a moving point A
rA = sp.Matrix([sp.Function(f'A{c}')(t) for c in 'abc'])
LA = m1 * (r1 - rA).cross(r1.diff(t)) + m2 * (r2 - rA).cross(r2.diff(t))
LAdot = LA.diff(t).subs({r1.diff(t, 2)[i]: a1[i] for i in range(3)}).subs({r2.diff(t, 2)[i]: a2[i] for i in range(3)})
MA = (r1 - rA).cross(F1) + (r2 - rA).cross(F2)
Pm = m1 * r1.diff(t) + m2 * r2.diff(t)               # M v_cm
check(66, zero(LAdot - (MA + rA.diff(t).cross(Pm))))
SLIP_66_FIXED = zero(LAdot - (MA - rA.diff(t).cross(Pm)))

# kinetic energy and angular momentum of point masses turning with omega
Iten = sum((m * (p.dot(p) * E3 - p * p.T) for m, p in zip(ms, X)), sp.zeros(3))
check(70, zero(sum(m * (w.cross(p)).dot(w.cross(p)) for m, p in zip(ms, X)) / 2 - (w.T * Iten * w)[0] / 2))
check(78, zero(sum((m * p.cross(w.cross(p)) for m, p in zip(ms, X)), sp.zeros(3, 1)) - Iten * w))

# z-x-z body angular velocity (the sheet's R is Q^T)
pd, tdt, sd = sp.diff(ph, t), sp.diff(th, t), sp.diff(ps, t)
sheet_w = sp.Matrix([pd * sp.sin(th) * sp.sin(ps) + tdt * sp.cos(ps), pd * sp.sin(th) * sp.cos(ps) - tdt * sp.sin(ps),
                     pd * sp.cos(th) + sd])
check(102, zero(wb - sheet_w))

# transport theorem: d(Q Lb)/dt = Q (Lbdot + wb x Lb)
Lb = sp.Matrix([sp.Function(f'l{c}')(t) for c in 'abc'])
check(130, truth_table.numeric_zero(Q.T * (Q * Lb).diff(t) - (Lb.diff(t) + wb.cross(Lb)), t))

# the fast top: L = I_z omega_s s along its axis s, weight M g at r s, steady precession Omega_p about z
Mm, g, rr, Iz, Ix, ws, thc, phc = sp.symbols('M g r I_z I_x omega_s theta_0 phi_0', positive=True)
s = sp.Matrix([sp.sin(thc) * sp.cos(phc), sp.sin(thc) * sp.sin(phc), sp.cos(thc)])
Om_p = sp.Symbol('Omega_p')
sol = sp.solve(sp.Matrix([0, 0, Om_p]).cross(Iz * ws * s)[0] - (rr * s).cross(sp.Matrix([0, 0, -Mm * g]))[0], Om_p)
check(114, len(sol) == 1 and zero(sol[0] - Mm * g * rr / (Iz * ws)))

# torque-free symmetric body spinning at omega_s about z: the linearised Euler equations' frequency
lam = sp.Symbol('lambda')
A = sp.Matrix([[0, -(Iz - Ix) / Ix * ws], [(Iz - Ix) / Ix * ws, 0]])
freq_body = sp.sqrt(-sp.prod(sp.solve((A - lam * sp.eye(2)).det(), lam)))        # |eigenvalue|
freq_space = Iz * ws / Ix                              # the axis about L, small tilt
check(120, zero(ws * sp.sqrt((Iz - Ix) / Ix) - freq_body) or zero(ws * sp.sqrt((Iz - Ix) / Ix) - freq_space))

# steady precession of the heavy top at tilt theta: the theta equation with thetadot = 0,
# I_x cos(theta) phidot^2 - I_z omega_3 phidot + M g r = 0, real only when (I_z omega_3)^2 >= 4 I_x M g r cos(theta)
pdot, thv = sp.symbols('phidot theta', real=True)
w3 = sp.Symbol('omega_3', positive=True)
Lag_theta = Ix * pdot ** 2 * sp.sin(thv) * sp.cos(thv) - Iz * w3 * pdot * sp.sin(thv) + Mm * g * rr * sp.sin(thv)
quad = sp.expand(Lag_theta / sp.sin(thv))
disc = sp.discriminant(quad, pdot)
threshold = sp.sqrt(4 * Ix * Mm * g * rr) / Iz
check(124, zero(disc.subs(thv, 0).subs(w3, threshold)) and zero(threshold - sp.sqrt(Mm * g * rr / Iz)))

# a rotor spinning about its symmetry (principal) axis
Is, Ip = sp.symbols('I_s I_perp', positive=True)
check(142, zero(sp.diag(Ip, Ip, Is) * sp.Matrix([0, 0, ws]) - Is * ws * sp.Matrix([0, 0, 1])))

# the sleeping top's small oscillations: n = (x, y, 1), L = I_perp n x ndot + I_s omega_s n, tau = d n x (-M g z)
d = sp.Symbol('d', positive=True)
xs, ys = sp.Function('x')(t), sp.Function('y')(t)
n = sp.Matrix([xs, ys, 1])
Lt = Ip * n.cross(n.diff(t)) + Is * ws * n
eqs = (Lt.diff(t) - (d * n).cross(sp.Matrix([0, 0, -Mm * g])))[:2]
sv = sp.Symbol('s')
X0, Y0 = sp.symbols('X0 Y0')
lin = [sp.expand(sp.simplify(e.subs({xs: X0 * sp.exp(sv * t), ys: Y0 * sp.exp(sv * t)}).doit() / sp.exp(sv * t)))
       for e in eqs]
lin = [sp.expand(e).subs({X0 * Y0: 0}) for e in lin]
Mlin = sp.Matrix([[sp.diff(e, X0) for e in lin], [sp.diff(e, Y0) for e in lin]]).T
char = Mlin.subs({X0: 0, Y0: 0}).det()
lam_fast = (Is * ws + sp.sqrt(Is ** 2 * ws ** 2 - 4 * Ip * Mm * g * d)) / (2 * Ip)
nut = sp.sqrt(Is ** 2 * ws ** 2 - 4 * Ip * Mm * g * d) / Ip            # difference of the two rates
check(154, zero(sp.sqrt(Mm * g * d / Is + ws ** 2) - nut))
SLIP_154_CONTROL = zero(sp.expand(char.subs(sv, sp.I * lam_fast)))                # the fast precession rate is a root

# a reaction wheel under a steady disturbance torque: H(t) = H_0 + tau t reaches H_max
H0, Hmax, td, tt = sp.symbols('H_0 H_max tau_dist t_s', positive=True)
check(174, zero(sp.solve(H0 + td * tt - Hmax, tt)[0] - (Hmax - H0) / td))

# negative controls: the checks can fail, and each slip's correction holds
assert SLIP_44_FIXED and SLIP_56_FIXED and SLIP_66_FIXED and SLIP_154_CONTROL
assert not zero(euler[0] - (I1 * wd[0] + (I2 - I3) * w[1] * w[2]))

LINES = [24, 28, 34, 38, 44, 48, 56, 62, 66, 70, 78, 82, 88, 92, 98, 102, 110, 114, 120, 124, 130, 134, 142,
         148, 154, 162, 168, 174]

ROWS = {
    24: ("not a claim", "defines the total angular momentum of a set of masses"),
    28: ("holds", "d/dt sum r x m v = sum r x F with central internal forces (check 28)"),
    34: ("holds", "Rdot R^T is skew-symmetric for any rotation R(t), so Rdot = Omega R (check 34)"),
    38: ("holds", "qdot = q (x) (0, omega)/2 with omega in body axes, q carrying body to space (check 38, numeric)"),
    44: ("typo", "as written the density multiplies only (r.r) I_3: the integrand rho (r.r) I_3 - r r^T adds a term without rho",
         "I = \\int_{V} \\rho \\left( (\\mathbf{r} \\cdot \\mathbf{r}) I_{3} - \\mathbf{r} \\mathbf{r}^{T} \\right) dV",
         "hand-checked twice: the inertia tensor is int rho (r^2 E - r r^T) dV; the display's rho stands before (r.r) I_3 only, so the second term, - r r^T dV, has units m^5 where the first has kg m^2: the sides cannot be equal",
         "hand-checked twice: for a uniform unit cube about a corner with rho = 2, the written integrand gives I_xx = int (2(x^2+y^2+z^2) - x^2) dV = 2 - 1/3 = 5/3, the tensor's I_xx = 2 int (y^2 + z^2) dV = 4/3"),
    48: ("holds", "Euler's equations without torque from I omegadot + omega x I omega = 0 (check 48)"),
    56: ("typo", "with Ldot = Omega_p x L and Omega_p across L, tau x L / L^2 = -Omega_p: the sign is reversed",
         "\\boldsymbol{\\Omega}_{\\text{p}} = \\frac{\\mathbf{L} \\times \\boldsymbol{\\tau}}{L^{2}}",
         "hand-checked twice: tau = Omega x L, so tau x L = (Omega x L) x L = L (Omega . L) - Omega L^2 = -Omega L^2 when Omega . L = 0; hence Omega = -tau x L / L^2 = L x tau / L^2",
         "hand-checked twice: a horizontal axle along x with L = L x-hat and a weight at +x gives tau = r x-hat x (-mg z-hat) = m g r y-hat; L turns toward +y, precession about +z; tau x L / L^2 = (m g r / L) y-hat x x-hat = -(m g r / L) z-hat, the wrong way"),
    62: ("holds", "moment about a parallel axis = moment about the centre of mass + M d^2 (check 62)"),
    66: ("typo", "for L_A = sum (r - r_A) x m v, dL_A/dt = M_A - v_A x M v_cm: the sign of the transport term is reversed",
         "\\frac{d \\mathbf{L}}{dt}\\Big|_{A} = \\mathbf{M}_{A} - \\mathbf{v}_{A} \\times M \\mathbf{v}_{\\text{cm}}",
         "hand-checked twice: d/dt sum (r_i - r_A) x m_i v_i = sum (v_i - v_A) x m_i v_i + sum (r_i - r_A) x m_i a_i = -v_A x sum m_i v_i + M_A, and sum m_i v_i = M v_cm",
         "hand-checked twice: a free particle of mass m with constant velocity v and A moving with constant v_A: M_A = 0 and dL_A/dt = (v - v_A) x m v = -v_A x m v, while the display gives M_A + v_A x m v = +v_A x m v"),
    70: ("holds", "T = sum m |omega x r|^2 / 2 = omega^T I omega / 2 (check 70)"),
    78: ("holds", "sum m r x (omega x r) = I omega (check 78)"),
    82: ("holds", "Euler's equations with torque from I omegadot + omega x I omega = M (check 82)"),
    88: ("holds", "the same law as the first sheet's (check 88)"),
    92: ("holds", "for a torque across L, |Ldot| = Omega_p L (check 92)"),
    98: ("not a claim", "defines R as the z-x-z product (the sheet's names yaw, pitch, roll are the prose's)"),
    102: ("holds", "z-x-z body angular velocity, vect(Q^T Qdot) with Q = Rz(phi) Rx(theta) Rz(psi) (check 102)"),
    110: ("holds", "Ldot = Omega_p x L for an angular momentum precessing at Omega_p, and tau = Ldot (check 110)"),
    114: ("holds", "steady precession of the fast top: Omega_p z x I_z omega_s s = r s x (-M g z) gives Omega_p = M g r / (I_z omega_s) (check 114)"),
    120: ("fails", "the free symmetric top's nutation rate is omega_s (I_z - I_x)/I_x in the body (I_z omega_s / I_x for the axis about L), not omega_s sqrt((I_z - I_x)/I_x)",
          None,
          "hand-checked twice: the linearised Euler equations omegadot_x = -(I_z - I_x) omega_s omega_y / I_x, omegadot_y = (I_z - I_x) omega_s omega_x / I_x give omegadouble_x = -((I_z - I_x) omega_s / I_x)^2 omega_x: frequency omega_s (I_z - I_x)/I_x, the square root's square",
          "hand-checked twice: with I_z = 2 I_x (a flat disc) the true rate is omega_s, the display gives omega_s sqrt(1) = omega_s too; with I_z = 5 I_x the true rate is 4 omega_s, the display gives 2 omega_s"),
    124: ("fails", "steady precession needs (I_z omega_s)^2 >= 4 I_x M g r cos(theta) (the sleeping top I_z omega_s > 2 sqrt(I_x M g r)), not omega_s > sqrt(M g r / I_z)",
          None,
          "hand-checked twice: the theta equation with thetadot = 0 gives I_x cos(theta) phidot^2 - I_z omega_3 phidot + M g r = 0, real phidot only when I_z^2 omega_3^2 >= 4 I_x M g r cos(theta); at theta = 0 the threshold is 2 sqrt(I_x M g r)/I_z",
          "hand-checked twice: the display's threshold sqrt(M g r / I_z) over the true one 2 sqrt(I_x M g r)/I_z is sqrt(I_z / (4 I_x)): equal only when I_z = 4 I_x; for a disc on a short axle (I_z = 2 I_x) the display's threshold is 0.71 of the true one"),
    130: ("holds", "transport theorem: Q^T d(Q L_b)/dt = L_bdot + omega_b x L_b (check 130, numeric)"),
    134: ("holds", "the supports take the opposite of the torque Omega_p x L that turns the gyroscope (check 134)"),
    142: ("holds", "I (omega_s s) = I_s omega_s s for s the symmetry (principal) axis (check 142)"),
    148: ("typo", "the vector relation has the sign of the first sheet's: tau x L / L^2 = -Omega_p (its magnitude tau / L holds)",
          "\\boldsymbol{\\Omega}_{p} = \\frac{\\mathbf{L} \\times \\boldsymbol{\\tau}}{L^{2}} \\Rightarrow \\Omega_{p} = \\frac{\\tau}{L}",
          "hand-checked twice: from tau = Ldot = Omega_p x L with Omega_p . L = 0, tau x L = -Omega_p L^2, so Omega_p = L x tau / L^2; the display's tau x L / L^2 points opposite",
          "hand-checked twice: a wheel on a horizontal axle along x, weight at +x, precesses about +z (tau = m g r y-hat turns L toward +y); tau x L / L^2 = -(m g r / L) z-hat"),
    154: ("fails", "the sleeping top's nutation (the difference of its two precession rates) is sqrt(I_s^2 omega_s^2 - 4 I_perp M g d)/I_perp, about I_s omega_s / I_perp when fast; the display's sqrt(M g d / I_s + omega_s^2) grows with the weight",
          None,
          "hand-checked twice: linearising L = I_perp n x ndot + I_s omega_s n, Ldot = d n x (-M g z) for n = (x, y, 1) gives I_perp s^2 + ... with roots i [I_s omega_s +- sqrt(I_s^2 omega_s^2 - 4 I_perp M g d)]/(2 I_perp); their difference is sqrt(I_s^2 omega_s^2 - 4 I_perp M g d)/I_perp",
          "hand-checked twice: at M g d = 0 the true frequency is I_s omega_s / I_perp, the display gives omega_s: equal only for I_s = I_perp; and the true frequency falls as the weight grows, the display's rises"),
    162: ("not a claim", "names a device's torque in a sign convention (torque on the rotor or on the craft) the sheet leaves open, with the gimbal rate a scalar"),
    168: ("holds", "the first of Euler's equations with torque (check 168)"),
    174: ("holds", "H_0 + tau_dist t = H_max at t = (H_max - H_0)/tau_dist (check 174)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, {k: (v[0], v[1], v[2] if len(v) > 2 else None, *(v[3:5] if len(v) > 3 else ()))
                                           for k, v in ROWS.items()}, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
