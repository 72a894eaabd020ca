"""Independent SymPy truth table for cline-rolling-wheel-tipping-stability.md
(Cline, Variational Principles in Classical Mechanics, ch. 13, section 13.24, MyST edition).

The text's convention: z-x-z Euler angles (phi, theta, psi); {lambda} = lambda_psi lambda_theta
lambda_phi is the PASSIVE matrix taking space axes to body axes. The moving frame (1, 2, 3) of the
section is the body frame without the spin: lambda_m = lambda_theta lambda_phi. A thin uniform disk
of mass M, radius R, its 1 and 2 axes in its plane, rolls on the floor z = 0 under gravity -Mg z.
Everything is built from that: the angular velocities from lambda, the contact point as the rim
point lowest along z, the rolling condition (contact point at rest), Newton's and Euler's laws in
the inertial frame carried into the moving frame; no formula of the text is assumed.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import pathlib
import sys

import sympy as sp

import truth_table
from truth_table import numeric_zero, zero

t = sp.Symbol('t', real=True)
ph, th, ps = [sp.Function(n)(t) for n in ('phi', 'theta', 'psi')]
M, R, g, I1, I2, I3, W3 = sp.symbols('M R g I_1 I_2 I_3 Omega_3c', positive=True)
eps = sp.Symbol('epsilon')
D = lambda e: sp.diff(e, t)  # noqa: E731

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def Pz(a):   # passive turn about the 3rd axis
    return sp.Matrix([[sp.cos(a), sp.sin(a), 0], [-sp.sin(a), sp.cos(a), 0], [0, 0, 1]])


def Px(a):   # passive turn about the 1st axis
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), sp.sin(a)], [0, -sp.sin(a), sp.cos(a)]])


def vee(S):
    return sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])


lam_m = Px(th) * Pz(ph)                     # space -> moving frame
lam = Pz(ps) * lam_m                        # space -> disk (body) frame
w = sp.simplify(vee(-D(lam_m) * lam_m.T))   # moving frame's angular velocity, moving components
Wb = sp.simplify(vee(-D(lam) * lam.T))      # disk's angular velocity, body components
W = sp.simplify(Pz(ps).T * Wb)              # ... in moving components
zhat = lam_m * sp.Matrix([0, 0, 1])         # the vertical in the moving frame
G = -M * g * zhat                           # weight
# contact point: the rim point (R cos a, R sin a, 0) lowest along z; for 0 < theta < pi that is -R e2
rP = sp.Matrix([0, -R, 0])
assert zero(zhat[0]) and zero(zhat[1] - sp.sin(th))
v = -W.cross(rP)                            # rolling: v_cm + Omega x r_P = 0
p = M * v
Ivec = sp.diag(I1, I1, I3)                  # the disk is symmetric: I_2 = I_1
L = Ivec * W
F = D(p) + w.cross(p) - G                   # floor reaction from Newton's law in the moving frame
E = rP.cross(F) - (D(L) + w.cross(L))       # Euler's law about the centre of mass, residual

# line 23: (13.191) the moving frame's angular velocity
check(23, zero(w - sp.Matrix([D(th), D(ph) * sp.sin(th), D(ph) * sp.cos(th)])))
# line 29: (13.192) the disk's, in the moving frame
check(29, zero(W - sp.Matrix([D(th), D(ph) * sp.sin(th), D(ph) * sp.cos(th) + D(ps)])))
# line 37: thin uniform disk: I_1 = I_2 = int y^2 dm, I_3 = int (x^2 + y^2) dm
r, a = sp.symbols('r a', positive=True)
sig = M / (sp.pi * R**2)
Ixx = sp.integrate(sp.integrate(sig * (r * sp.sin(a))**2 * r, (a, 0, 2 * sp.pi)), (r, 0, R))
Iyy = sp.integrate(sp.integrate(sig * (r * sp.cos(a))**2 * r, (a, 0, 2 * sp.pi)), (r, 0, R))
Izz = sp.integrate(sp.integrate(sig * r**2 * r, (a, 0, 2 * sp.pi)), (r, 0, R))
check(37, zero(Ixx + Iyy - Izz))
# lines 46, 62: the transport theorem for any vector q given by its moving components
q = sp.Matrix([sp.Function(f'q{i}')(t) for i in range(1, 4)])
transport = lam_m * D(lam_m.T * q) - (D(q) + w.cross(q))
check(46, numeric_zero(transport, t))
check(62, numeric_zero(transport, t))
# line 53: (13.194) Newton's law with the weight G in moving components: F + G = p' + w x p
rhs = D(q) + w.cross(q)
F1, F2, F3 = sp.symbols('F_1 F_2 F_3')
text54 = [F1 - rhs[0], F2 - M * g * sp.sin(th) - rhs[1], F3 - M * g * sp.cos(th) - rhs[2]]
true54 = sp.Matrix([F1, F2, F3]) + G - rhs
check(53, numeric_zero(sp.Matrix(text54) - true54, t))
# line 68: (13.196) N = r_P x F and N = L' + w x L with L_i = I_i Omega_i; the first row as
# printed has "I_2 \Omega 2 \omega_3": a bare Omega times 2 where the cross product gives I_2 Omega_2 omega_3
Fs = sp.Matrix([F1, F2, F3])
Om = sp.Symbol('Omega')
N = rP.cross(Fs)
Ld = D(L) + w.cross(L)
text69 = [N[0] - (-F3 * R), N[1], N[2] - F1 * R,
          Ld[0] - (I1 * D(W[0]) + I3 * W[2] * w[1] - I2 * Om * 2 * w[2]).subs(I2, I1),
          Ld[1] - (I1 * D(W[1]) + I1 * W[0] * w[2] - I3 * W[2] * w[0]),
          Ld[2] - (I3 * D(W[2]) + I2 * W[1] * w[0] - I1 * W[0] * w[1]).subs(I2, I1)]
check(68, numeric_zero(sp.Matrix(text69), t))
fixed69 = text69[:3] + [Ld[0] - (I1 * D(W[0]) + I3 * W[2] * w[1] - I1 * W[1] * w[2])] + text69[4:]
assert numeric_zero(sp.Matrix(fixed69), t)          # with Omega_2 the display holds
# line 75: (13.197) rolling
check(75, zero(sp.Matrix([p[0] + M * R * W[2], p[1], p[2] - M * R * W[0]])))
# line 82: (13.198) rows, with omega_i, Omega_i as derived and I_2 = I_1; each must be minus E_i
rows83 = [(I1 + M * R**2) * D(W[0]) + (I3 + M * R**2) * w[1] * W[2] - I2 * w[2] * W[1] + M * g * R * sp.cos(th),
          I1 * D(W[1]) + I1 * w[2] * W[0] - I3 * w[0] * W[2],
          (I3 + M * R**2) * D(W[2]) + I2 * w[0] * W[1] - (I1 + M * R**2) * w[1] * W[0]]
check(82, numeric_zero(sp.Matrix([r_.subs(I2, I1) + e for r_, e in zip(rows83, E)]), t))
# line 89: (13.199) in Euler angles
thd, phd, psd = D(th), D(ph), D(ps)
rows90 = [(I1 + M * R**2) * D(thd) + (I3 + M * R**2) * phd * sp.sin(th) * (phd * sp.cos(th) + psd)
          - I1 * phd**2 * sp.sin(th) * sp.cos(th) + M * g * R * sp.cos(th),
          I1 * D(phd) * sp.sin(th) + 2 * I1 * phd * thd * sp.cos(th) - I3 * thd * (phd * sp.cos(th) + psd),
          (I3 + M * R**2) * (D(phd) * sp.cos(th) - phd * thd * sp.sin(th) + D(psd)) - M * R**2 * thd * phd * sp.sin(th)]
check(89, numeric_zero(sp.Matrix([rows90[0] + E[0], rows90[1] + E[1], rows90[2] + E[2]]), t))
# line 98: the Lagrangian; the centre of mass stands (r_cm - r_P).z = R sin(theta) above the floor
T = sp.Rational(1, 2) * M * (v.dot(v)) + sp.Rational(1, 2) * I1 * (W[0]**2 + W[1]**2) + sp.Rational(1, 2) * I3 * W[2]**2
height = (-rP).dot(zhat)
assert zero(height - R * sp.sin(th))
Ltrue = T - M * g * height
Ltext = T - M * g * R * sp.cos(th)
check(98, zero(Ltext - Ltrue))
# lines 104, 108: the contact point's velocity on the floor, from r_P(space) = r_cm + lam_m^T r_P
vP = lam_m.T * v + D(lam_m.T) * rP
check(104, zero(vP[0] - R * sp.cos(ph) * psd))
check(108, zero(vP[1] - R * sp.sin(ph) * psd))
assert zero(vP[0] + R * sp.cos(ph) * psd) and zero(vP[1] + R * sp.sin(ph) * psd) and zero(vP[2])

# the example: theta = pi/2 + eps a(t), phi = eps f(t), psi' = Omega_3 - phi' cos(theta) (its (a))
af, ff = sp.Function('a')(t), sp.Function('f')(t)
small = {th: sp.pi / 2 + eps * af, ph: eps * ff}


def first_order(expr):
    e = expr.subs(D(psd), D(W3 - phd * sp.cos(th))).subs(psd, W3 - phd * sp.cos(th))
    e = e.subs(small).doit()
    e0 = sp.simplify(e.subs(eps, 0))
    return e0, sp.simplify(sp.diff(e, eps).subs(eps, 0))


# line 125: (a) Omega_3 = phi' cos(theta) + psi' is constant to first order: from the third equation
Om3dot = sp.solve(sp.Symbol('X') * (I3 + M * R**2) - M * R**2 * thd * phd * sp.sin(th), sp.Symbol('X'))[0]
assert numeric_zero(rows90[2] - ((I3 + M * R**2) * D(phd * sp.cos(th) + psd) - (I3 + M * R**2) * Om3dot), t)
o0 = Om3dot.subs(small).doit()
check(125, zero(o0.subs(eps, 0)) and zero(sp.diff(o0, eps).subs(eps, 0)))
# lines 131, 135: (b), (c) the first-order parts of the first two equations
e0, e1 = first_order(E[0])
text_b = (I1 + M * R**2) * D(D(af)) + (I3 + M * R**2) * D(ff) * W3 - M * g * R * af
check(131, zero(e0) and zero(e1 + text_b))
e0, e1 = first_order(E[1])
text_c = I1 * D(D(ff)) - I3 * W3 * D(af)
check(135, zero(e0) and zero(e1 + text_c))
# line 141: (d) integrates (c), the constant fixed by phi' = 0 when alpha = 0
check(141, zero(D(D(ff) - I3 * W3 / I1 * af) - text_c / I1))
# line 147: (e) is (b) with (d)
text_e = (I1 + M * R**2) * D(D(af)) + ((I3 + M * R**2) * I3 * W3**2 / I1 - M * g * R) * af
check(147, zero(text_e - text_b.subs(D(ff), I3 * W3 / I1 * af)))
# line 153: (f) the bracket of (e) is positive
X = sp.Symbol('X', positive=True)
thr = sp.solve(((I3 + M * R**2) * I3 * X / I1 - M * g * R), X)[0]
check(153, zero(thr - I1 * M * g * R / (I3 * (I3 + M * R**2))))
# line 160: (g) for a uniform disk I_3 = 2 I_1 = M R^2/2 the threshold is g/(3R), but the display
# prints no relation sign between Omega_3^2 and g/(3R), so it states nothing
disk = {I1: M * R**2 / 4, I3: M * R**2 / 2}
assert zero(thr.subs(disk) - g / (3 * R)) and zero(Ixx - M * R**2 / 4) and zero(Izz - M * R**2 / 2)
line160 = pathlib.Path(__file__).with_name('cline-rolling-wheel-tipping-stability.md').read_text().split('\n')[160]  # the display's content line, below its opening $$ on line 160
check(160, any(s in line160 for s in ('>', '<', '=', r'\geq', r'\leq')) and zero(thr.subs(disk) - g / (3 * R)))
# line 166: (h) the upright wheel's speed is R |Omega_3| and R sqrt(g/(3R)) = sqrt(gR/3)
# (v = R Omega_1... in general: |v|^2 = R^2 (Omega_1^2 + Omega_3^2); upright and steady, Omega_1 = theta' = 0)
check(166, zero(v.dot(v) - R**2 * (W[0]**2 + W[2]**2)) and zero(R * sp.sqrt(g / (3 * R)) - sp.sqrt(g * R / 3)))

LINES = [23, 29, 37, 46, 53, 62, 68, 75, 82, 89, 98, 104, 108, 125, 131, 135, 141, 147, 153, 160, 166]

ROWS = {
    23: ("holds", "the moving frame is the body frame without the spin, lambda_m = lambda_theta lambda_phi; -lambda_m' lambda_m^T gives omega = (theta', phi' sin theta, phi' cos theta) (check 23)"),
    29: ("holds", "the disk's angular velocity from the full lambda, carried into the moving frame by lambda_psi^T: (theta', phi' sin theta, phi' cos theta + psi'), that is omega plus psi' along the 3 axis (check 29)"),
    37: ("holds", "thin uniform disk: I_1 = I_2 = M R^2/4 and I_3 = M R^2/2 by integration over the disk, so I_1 + I_2 = I_3 (check 37)"),
    46: ("holds", "the transport theorem: for any vector given by moving components q, lambda_m d/dt(lambda_m^T q) = q' + omega x q (check 46)"),
    53: ("holds", "Newton's law F + weight = p' + omega x p in the moving frame, the vertical having moving components (0, sin theta, cos theta), so the weight is -Mg(0, sin theta, cos theta) (check 53)"),
    62: ("holds", "the same transport theorem for L (check 62)"),
    68: ("typo", "the torque of the floor's force at the contact point r_P = -R e_2 is (-R F_3, 0, R F_1), and L' + omega x L has first component I_1 Omega_1' + I_3 Omega_3 omega_2 - I_2 Omega_2 omega_3; the first row prints I_2 \\Omega 2 \\omega_3, a bare Omega times 2, in place of I_2 Omega_2 omega_3; the other rows hold (check 68)", "N_1 = −F_3 R = I_1 \\dot{\\Omega}_1 + I_3\\Omega_3\\omega_2 − I_2\\Omega_2\\omega_3", "omega x L, first component: omega_2 L_3 - omega_3 L_2 = I_3 Omega_3 omega_2 - I_2 Omega_2 omega_3. With omega = (0, 1, 2), Omega = (0, 1, 3), I_2 = 1, I_3 = 2: 1*6 - 2*1 = 4. The printed term I_2 Omega 2 omega_3 reads 1*Omega*2*2 = 4 Omega with Omega undefined (as |Omega| = sqrt 10 it gives 6 - 4 sqrt 10 = -6.65, not 4).", "The pattern of the other two rows, I_1 Omega_1 omega_3 and I_2 Omega_2 omega_1, and of the next display (13.198), whose first row has - I_2 omega_3 Omega_2, both show the index 2 belongs on Omega: the 2 is a dropped subscript."),
    75: ("holds", "rolling: the contact point r_P = -R e_2 is at rest, v = -Omega x r_P = R(-Omega_3, 0, Omega_1), so p_1 = -M R Omega_3, p_2 = 0, p_3 = M R Omega_1 (check 75)"),
    82: ("holds", "with p from (13.197) the force law gives F_1 = -M R Omega_3' + M R omega_2 Omega_1, F_3 = M g cos theta + M R Omega_1' + M R omega_2 Omega_3; put in (13.196) with I_2 = I_1 the rows are the three components of Euler's law (check 82)"),
    89: ("holds", "the rows of (13.198) with omega and Omega in Euler angles and I_2 = I_1 (check 89)"),
    98: ("typo", "T is right, but the centre of mass stands (r_cm - r_P).z = R e_2.(0, sin theta, cos theta) = R sin theta above the floor, so the potential is M g R sin theta, not M g R cos theta; only with sin does -dU/dtheta = -M g R cos theta give the right side of (13.199) (check 98)", "L = \\frac{1}{2} M ( v^2_1 + v^2_2 + v^2_3 ) + \\frac{1}{2} I_1 ( \\Omega^2_1 + \\Omega^2_2 ) + \\frac{1}{2} I_3\\Omega^2_3 − MgR \\sin \\theta", "Upright wheel theta = 90 deg: the centre is R above the floor, U = M g R; a wheel lying flat, theta = 0: the centre is on the floor, U = 0. M g R cos theta gives 0 upright and M g R flat, the wrong way round; M g R sin theta gives M g R and 0.", "The example's (b) needs the gravity term -M g R alpha near theta = 90 deg + alpha: from U = M g R sin theta, -dU/dtheta = -M g R cos theta = M g R sin alpha ~ M g R alpha, which matches (13.199) and (b); from U = M g R cos theta, -dU/dtheta = M g R sin theta ~ M g R, a constant torque that would topple an upright wheel at any speed."),
    104: ("fails", "from (13.197) the contact point moves along the floor with r_P' = -R psi' e_1, and e_1 is the line of nodes (cos phi, sin phi, 0), so dx + R cos phi dpsi = 0: the printed sign is the opposite of the text's own rolling condition (check 104)", "", "Upright wheel theta = 90 deg, phi = 0, psi' = 1, R = 1, theta' = phi' = 0: Omega = (0, 0, 1), and (13.197) gives p_1 = -M R Omega_3, so v = -1 along e_1 = x: x' = -1. The display gives x' = R cos phi psi' = +1.", "Geometry: with phi = 0 and theta = 90 deg, e_1 = x, e_2 = z, e_3 = e_1 x e_2 = -y; the contact point is R below the centre, and the centre moves with Omega x (R z) = psi'(-y) x (R z) = -R psi' x, again x' = -R psi' cos phi = -1, not +1."),
    108: ("fails", "the same contact-point velocity r_P' = -R psi' (cos phi, sin phi, 0) gives dy + R sin phi dpsi = 0; the printed sign is the opposite (check 108)", "", "Upright wheel theta = 90 deg, phi = 90 deg, psi' = 1, R = 1: e_1 = (cos phi, sin phi, 0) = y, and (13.197) gives v_1 = -R Omega_3 = -1, so y' = -1; the display gives y' = R sin phi psi' = +1.", "At phi = 90 deg: e_1 = y, e_2 = z, e_3 = e_1 x e_2 = x; the centre moves with Omega x (R z) = psi' x x (R z) = -R psi' y, so y' = -1, not +1."),
    125: ("holds", "the third equation gives Omega_3' = M R^2 theta' phi' sin theta/(I_3 + M R^2), of second order in the small alpha, phi: so Omega_3 = phi' cos theta + psi' is constant to first order (check 125)"),
    131: ("holds", "the first equation to first order in alpha and phi, theta = 90 deg + alpha, psi' = Omega_3 - phi' cos theta: (I_1 + M R^2) alpha'' + (I_3 + M R^2) phi' Omega_3 - M g R alpha = 0 (check 131)"),
    135: ("holds", "the second equation to first order: I_1 phi'' - I_3 Omega_3 alpha' = 0 (check 135)"),
    141: ("holds", "integrating (c) with phi' = 0 when alpha = 0: phi' = I_3 Omega_3 alpha/I_1 (check 141)"),
    147: ("holds", "(d) put in (b) (check 147)"),
    153: ("holds", "the bracket of (e) is positive exactly when Omega_3^2 > I_1 M g R/(I_3 (I_3 + M R^2)) (check 153)"),
    160: ("typo", "for a uniform disk I_1 = M R^2/4, I_3 = M R^2/2 the bound of (f) is g/(3R), but the display prints no relation between Omega_3^2 and g/(3R): the > sign is missing, so as printed it is a product and states nothing (check 160)", "\\Omega^2_3 > \\frac{g}{3R}", "I_1 M g R/(I_3 (I_3 + M R^2)) with I_1 = M R^2/4, I_3 = M R^2/2: (M^2 g R^3/4)/((M R^2/2)(3 M R^2/2)) = (1/4)/(3/4) g/R = g/(3R); for R = 0.35 m this is 9.81/1.05 = 9.34 s^-2. The display should read Omega_3^2 > g/(3R).", "The next display (h) squares back to it: R Omega_3 > sqrt(g R/3) means Omega_3^2 > g R/(3 R^2) = g/(3R), an inequality; the printed (g) has the two sides side by side with no > between them (R = 0.35 m: sqrt(9.81*0.35/3) = 1.07 m/s, as the text says)."),
    166: ("holds", "the centre's speed is R sqrt(Omega_1^2 + Omega_3^2) = R Omega_3 for the upright wheel (Omega_1 = theta' = 0), and R sqrt(g/(3R)) = sqrt(g R/3) (check 166)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
