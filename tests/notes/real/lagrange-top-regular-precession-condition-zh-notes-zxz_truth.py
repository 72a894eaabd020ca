"""Independent SymPy truth table for lagrange-top-regular-precession-condition-zh-notes-zxz.md.

The text's own setting: the heavy symmetric top (Lagrange case), I_1 = I_2 about the fixed point O,
the centre of mass at distance l on the symmetry axis, z-x-z Euler angles (phi precession, theta
nutation, psi spin). The body rates are derived here from the z-x-z rotation matrix, the Lagrangian
and the momenta L_Z = p_phi, L_3 = p_psi from them; the worked example (a disc of radius 2r on a
massless axle of length r) is rebuilt from the inertia of a disc and a point mass. Nothing here
reads the text's later displays or the reader.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
c, s = sp.cos, sp.sin

t = sp.Symbol('t')
ph, th, ps = sp.symbols('phi theta psi', real=True)
phd, thd, psd = sp.symbols('phidot thetadot psidot', real=True)
I1, I3, M, g, l, E = sp.symbols('I_1 I_3 M g l E', positive=True)
LZ, L3 = sp.symbols('L_Z L_3', real=True)


def Rz(a):
    return sp.Matrix([[c(a), -s(a), 0], [s(a), c(a), 0], [0, 0, 1]])


def Rx(a):
    return sp.Matrix([[1, 0, 0], [0, c(a), -s(a)], [0, s(a), c(a)]])


f = {q: sp.Function(q.name)(t) for q in (ph, th, ps)}
R = Rz(f[ph]) * Rx(f[th]) * Rz(f[ps])                 # body -> space
S = R.T * R.diff(t)                                   # body-frame angular velocity, skew form
back = {f[ph].diff(t): phd, f[th].diff(t): thd, f[ps].diff(t): psd, f[ph]: ph, f[th]: th, f[ps]: ps}
w = [sp.simplify(S[i, j].subs(back)) for i, j in ((2, 1), (0, 2), (1, 0))]
T = sp.Rational(1, 2) * (I1 * w[0]**2 + I1 * w[1]**2 + I3 * w[2]**2)
V = M * g * l * c(th)
Lag = T - V
pphi, ppsi = sp.diff(Lag, phd), sp.diff(Lag, psd)
Hen = sp.expand(sum(q * sp.diff(Lag, q) for q in (phd, thd, psd)) - Lag)

# line 20: the rates from the two momentum integrals
sol = sp.solve([sp.Eq(pphi, LZ), sp.Eq(ppsi, L3)], [phd, psd], dict=True)[0]
check(20, zero(sol[phd] - (LZ - L3 * c(th)) / (I1 * s(th)**2))
      and zero(sol[psd] - (L3 / I3 - (LZ - L3 * c(th)) * c(th) / (I1 * s(th)**2))))
# line 27: the energy with the rates eliminated
Ered = Hen.subs({phd: sol[phd], psd: sol[psd]})
U = (LZ - L3 * c(th))**2 / (2 * I1 * s(th)**2) + L3**2 / (2 * I3) + M * g * l * c(th)
check(27, zero(Ered - (sp.Rational(1, 2) * I1 * thd**2 + U)))
# line 34 defines U (not a claim); line 40 restates the energy with it
check(40, zero(Ered - (sp.Rational(1, 2) * I1 * thd**2 + U)))
# line 48: U'(theta)
Up = sp.diff(U, th)
check(48, zero(Up - ((L3 - LZ * c(th)) * (LZ - L3 * c(th)) / (I1 * s(th)**3) - M * g * l * s(th))))
# line 55: with L_Z = L_3 cos + I_1 phidot sin^2 (the precession rate solved for L_Z), U' = 0 is the quadratic
LZ_of = L3 * c(th) + I1 * phd * s(th)**2
quad = I1 * phd**2 * c(th) - L3 * phd + M * g * l
check(55, zero(sp.expand(Up.subs(LZ, LZ_of) + quad * s(th))))
# line 62: a real root of the quadratic needs L_3^2 - 4 I_1 M g l cos >= 0 (its discriminant)
check(62, zero(sp.discriminant(quad, phd) - (L3**2 - 4 * M * g * l * I1 * c(th))))

# ---- the worked example: disc of radius 2r, axle r, omega along the bisector of alpha
m, r, om, al = sp.symbols('m r omega alpha', positive=True)
thv = sp.Symbol('theta', positive=True)
disc_C = sp.diag(m * (2 * r)**2 / 4, m * (2 * r)**2 / 4, m * (2 * r)**2 / 2)   # thin disc about its centre
check(81, zero(disc_C - sp.diag(m * r**2, m * r**2, 2 * m * r**2)))
X = sp.Matrix([0, 0, r])
point = m * (X.dot(X) * sp.eye(3) - X * X.T)                                    # the mass m at X_C, about O
check(87, zero(point - sp.diag(m * r**2, m * r**2, 0)))
I_O = point + disc_C
check(93, zero(I_O - 2 * m * r**2 * sp.eye(3)))
wx, wy, wz = sp.symbols('w_x w_y w_z', real=True)
wv = sp.Matrix([wx, wy, wz])
Lv = I_O * wv
check(99, zero(Lv - 2 * m * r**2 * wv) and zero(sp.Rational(1, 2) * wv.dot(Lv) - m * r**2 * wv.dot(wv)))
# the initial omega: the axle z at alpha from the vertical Z, omega along the bisector of the two
Zh, zh = sp.Matrix([0, 0, 1]), sp.Matrix([s(al), 0, c(al)])
omega0 = om * sp.Matrix([s(al / 2), 0, c(al / 2)])
L0 = I_O * omega0
I1e, I3e = I_O[0, 0], I_O[2, 2]
LZ0, L30 = sp.simplify(L0.dot(Zh)), sp.simplify(L0.dot(zh))
E0 = sp.Rational(1, 2) * omega0.dot(L0) + m * g * (r * zh).dot(Zh)     # kinetic + m g (height of C)
check(105, zero(sp.expand_trig(LZ0 - 2 * m * r**2 * om * c(al / 2)))
      and zero(sp.expand_trig(L30 - 2 * m * r**2 * om * c(al / 2)))
      and zero(E0 - (m * r**2 * om**2 + m * g * r * c(al))))
Ue = U.subs({LZ: LZ0, L3: L30, I1: I1e, I3: I3e, M: m, l: r, th: thv})
claim115 = m * r**2 * om**2 * c(al / 2)**2 * sp.sec(thv / 2)**2 + m * g * r * c(thv)
claim115b = m * g * r * (r * om**2 / g * c(al / 2)**2 * sp.sec(thv / 2)**2 + c(thv))
check(115, zero(sp.simplify(sp.expand_trig((Ue - claim115).rewrite(sp.cos)))) and zero(claim115 - claim115b))
check(121, zero(Ered - (sp.Rational(1, 2) * I1 * thd**2 + U)))     # the same nutation equation, read for the example
check(127, zero(sp.simplify((E0 - claim115.subs(thv, al)).rewrite(sp.cos))))
# line 133: dtheta/dt from the nutation equation, the negative root
thdot = -sp.sqrt(2 * (E - U) / I1)
check(133, zero(sp.Rational(1, 2) * I1 * thdot**2 + U - E))
# lines 73 and 139: the time to stand up; the integrands agree, and the limits flip with the sign
integrand = sp.sqrt(I1e / 2) / sp.sqrt(E0 - claim115)
target = 1 / (om * sp.sqrt(1 - c(al / 2)**2 * sp.sec(thv / 2)**2 + g / (r * om**2) * (c(al) - c(thv))))
same = all(abs(complex(sp.N((integrand - target).subs({m: 1.3, r: 0.7, om: 5.1, g: 9.8, al: a, thv: b}))))
           < 1e-12 for a, b in ((0.9, 0.3), (1.2, 0.8), (0.6, 0.1)))
check(139, same)
check(73, same)

# negative control: a sign slip in U' would be caught
assert not zero(Up - ((L3 - LZ * c(th)) * (LZ - L3 * c(th)) / (I1 * s(th)**3) + M * g * l * s(th)))

LINES = [11, 20, 27, 34, 40, 48, 55, 62, 73, 81, 87, 93, 99, 105, 115, 121, 127, 133, 139]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
