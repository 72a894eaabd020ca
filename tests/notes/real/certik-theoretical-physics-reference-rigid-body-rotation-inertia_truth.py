"""Independent SymPy truth table for certik-theoretical-physics-reference-rigid-body-rotation-inertia.md.

The reference's convention: a rigid body with density rho(r) turns with angular velocity omega, so the
point at r moves with v = omega x r; T = int rho v^2 / 2 d^3r, L = int rho r x v d^3r and the inertia
tensor I = int rho (1 r^2 - r r) d^3r. Chains of equalities run across displays: a display that
begins with '=' continues the one before it, so its first member is compared with the last member
of that display (as the source means it). The identities are checked on the integrands, pointwise,
with r, omega and v as symbols; the cylinder's and the sphere's integrals are done here in
cylindrical and spherical coordinates with uniform density m/V.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
r = sp.Matrix(sp.symbols('x y z', real=True))
w = sp.Matrix(sp.symbols('w1:4', real=True))
dens = sp.Symbol('rho_d', positive=True)                 # the density at r
v = w.cross(r)
r2 = r.dot(r)

# the kinetic energy chain (lines 45-61), integrand by integrand
e41 = dens * v.dot(v) / 2
e45 = dens * v.dot(v) / 2                                # v^2 = v . v
e49 = dens * v.dot(w.cross(r)) / 2                       # v = omega x r
e53 = dens * w.dot(r.cross(v)) / 2                       # the triple product turned round
e57 = w.dot(dens * r.cross(v)) / 2                       # omega taken out of the integral
Lint = dens * r.cross(v)                                 # the integrand of L
e61 = w.dot(Lint) / 2
check(45, zero(e41 - e45))
check(49, zero(e45 - e49))
check(53, zero(e49 - e53))
check(57, zero(e53 - e57))
check(61, zero(e57 - e61))

# the angular momentum chain (lines 80-95)
one = sp.eye(3)
Iint = dens * (one * r2 - r * r.T)                       # the integrand of the inertia tensor
check(80, zero(Lint - dens * r.cross(w.cross(r))))
check(85, zero(dens * r.cross(w.cross(r)) - dens * (w * r2 - r * r.dot(w))))
check(90, zero(dens * (w * r2 - r * r.dot(w)) - Iint * w))
check(95, zero(Iint * w - Lint))                         # = I . omega, the integral of the same integrand

# the components of the tensor (line 113)
comp = sp.Matrix(3, 3, lambda i, j: dens * ((1 if i == j else 0) * sum(r[k] ** 2 for k in range(3)) - r[i] * r[j]))
check(113, zero(Iint - comp))

# T = omega . L / 2 = omega . I . omega / 2 = n . I . n omega^2 / 2 = I omega^2 / 2 (line 119)
a, b, om = sp.symbols('alpha beta omega', real=True)
n = sp.Matrix([sp.sin(a) * sp.cos(b), sp.sin(a) * sp.sin(b), sp.cos(a)])     # a unit vector
Ig = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f'I{min(i, j)}{max(i, j)}'))     # a symmetric tensor
wn = om * n
first = wn.dot(Ig * wn) / 2
check(119, zero(first - (n.T * Ig * n)[0] * om ** 2 / 2)
      and zero(e61 - (w.T * Iint * w)[0] / 2))           # omega . L = omega . I . omega on the integrand

# I = n . I . n = n . int rho (1 r^2 - r r) d^3r . n = int rho (r^2 - (r . n)^2) d^3r (lines 132, 137)
Iint_n = dens * (one * r2 - r * r.T)
check(132, zero((n.T * Iint_n * n)[0] - (n.T * comp * n)[0]))        # the tensor written out in components
check(137, zero((n.T * Iint_n * n)[0] - dens * (r2 - r.dot(n) ** 2)))

# the cylinder (lines 147-228): cylindrical coordinates rho, phi, z, uniform density m/V
R, h, m = sp.symbols('R h m', positive=True)
rho, phi, zz = sp.symbols('rho phi z', real=True)
V = sp.Symbol('V', positive=True)
pos = sp.Matrix([rho * sp.cos(phi), rho * sp.sin(phi), zz])
jac = rho                                               # d^3r = rho d rho d phi d z


def cyl(f):
    """The integral of f over the cylinder, d^3r = rho d rho d phi d z."""
    return sp.integrate(f * jac, (rho, 0, R), (phi, 0, 2 * sp.pi), (zz, -h / 2, h / 2))


check(147, sp.simplify(cyl(1) - sp.pi * R ** 2 * h) == 0)
nz = sp.Matrix([0, 0, 1])
check(159, zero(pos.dot(nz) - zz))
check(163, zero(pos.dot(pos) - (rho ** 2 + zz ** 2)))
# line 167: I = int rho (r^2 - (r.n)^2) = int m/V (rho^2 + z^2 - z^2)
check(167, zero(pos.dot(pos) - pos.dot(nz) ** 2 - (rho ** 2 + zz ** 2 - zz ** 2)))
intended_z = m / V * cyl(rho ** 2)                       # m/V int rho^2 d^3r, the integrand rho^2 rho
Rp = sp.Symbol('Rp', positive=True)                      # the dummy the display integrates over: d R
literal_z = m / V * sp.integrate(rho ** 2 * rho, (Rp, 0, R), (phi, 0, 2 * sp.pi), (zz, -h / 2, h / 2))
check(172, sp.simplify(intended_z - literal_z) == 0)
check(179, sp.simplify(intended_z - m / V * 2 * sp.pi * R ** 4 / 4 * h) == 0
      and sp.simplify((m / V * 2 * sp.pi * R ** 4 / 4 * h).subs(V, sp.pi * R ** 2 * h) - m * R ** 2 / 2) == 0)

nx = sp.Matrix([1, 0, 0])
check(196, zero(pos.dot(nx) - rho * sp.cos(phi)))
check(200, zero(pos.dot(pos) - (rho ** 2 + zz ** 2)))
gx = rho ** 2 + zz ** 2 - rho ** 2 * sp.cos(phi) ** 2
check(204, zero(pos.dot(pos) - pos.dot(nx) ** 2 - gx))
intended_x = m / V * cyl(gx)
literal_x = m / V * sp.integrate(gx * rho, (Rp, 0, R), (phi, 0, 2 * sp.pi), (zz, -h / 2, h / 2))
check(209, sp.simplify(intended_x - literal_x) == 0)
bracket = sp.pi * R ** 4 * h / 2 + sp.pi * R ** 2 * h ** 3 / 12 - sp.pi * R ** 4 * h / 4
check(214, sp.simplify(intended_x - m / V * bracket) == 0)
at_V = m / (sp.pi * R ** 2 * h) * bracket
check(219, sp.simplify((m / V * bracket).subs(V, sp.pi * R ** 2 * h) - at_V) == 0)
check(224, sp.simplify(at_V - m / 12 * (6 * R ** 2 + h ** 2 - 3 * R ** 2)) == 0)
check(228, sp.simplify(m / 12 * (6 * R ** 2 + h ** 2 - 3 * R ** 2) - m / 12 * (3 * R ** 2 + h ** 2)) == 0)

# the sphere (lines 240-281): spherical coordinates rho, theta, phi
th = sp.Symbol('theta', real=True)
spos = sp.Matrix([rho * sp.cos(phi) * sp.sin(th), rho * sp.sin(phi) * sp.sin(th), rho * sp.cos(th)])


def ball(f):
    """The integral of f over the ball, d^3r = rho^2 sin theta d rho d phi d theta."""
    return sp.integrate(f * rho ** 2 * sp.sin(th), (rho, 0, R), (phi, 0, 2 * sp.pi), (th, 0, sp.pi))


check(240, sp.simplify(ball(1) - sp.Rational(4, 3) * sp.pi * R ** 3) == 0)
check(252, zero(spos.dot(nz) - rho * sp.cos(th)))
check(256, zero(spos.dot(spos) - rho ** 2))
gs = rho ** 2 - rho ** 2 * sp.cos(th) ** 2
check(260, zero(spos.dot(spos) - spos.dot(nz) ** 2 - gs))
intended_s = m / V * ball(gs)
lit1 = m / V * sp.integrate(rho ** 2 * (1 - sp.cos(th) ** 2) * rho ** 2 * sp.sin(th),
                            (Rp, 0, R), (phi, 0, 2 * sp.pi), (th, 0, sp.pi))
check(265, sp.simplify(intended_s - lit1) == 0)
lit2 = m / V * sp.integrate(rho ** 4 * sp.sin(th) ** 3, (Rp, 0, R), (phi, 0, 2 * sp.pi), (th, 0, sp.pi))
check(271, sp.simplify(intended_s - lit2) == 0)
check(277, sp.simplify(intended_s - m / V * 2 * sp.pi * R ** 5 / 5 * sp.Rational(4, 3)) == 0)
check(281, sp.simplify(m / V * 2 * sp.pi * R ** 5 / 5 * sp.Rational(4, 3) - m / V * sp.Rational(8, 15) * sp.pi * R ** 5) == 0
      and sp.simplify((m / V * sp.Rational(8, 15) * sp.pi * R ** 5).subs(V, sp.Rational(4, 3) * sp.pi * R ** 3)
                      - sp.Rational(2, 5) * m * R ** 2) == 0)

LINES = [17, 33, 41, 45, 49, 53, 57, 61, 67, 75, 80, 85, 90, 95, 101, 109, 113, 119, 128, 132, 137,
         147, 151, 155, 159, 163, 167, 172, 179, 188, 192, 196, 200, 204, 209, 214, 219, 224, 228,
         240, 244, 248, 252, 256, 260, 265, 271, 277, 281]

NC = "not a claim"
H = "holds"
DR_Z = ("the integral over the cylinder is taken over rho, from 0 to R, but the display writes the differential \\d R, "
        "the radius itself: read as written the radial integral runs over R with an integrand free of it, "
        "m/V 2 pi R h rho^3, which is not m/V 2 pi R^4 h/4; with \\d\\rho the member is the integral the next display "
        "evaluates (check 172)")
ROWS = {
    17: (NC, "the macros of the web edition's page template (src/_templates/layout.html)"),
    33: (NC, "the velocity of a point of a rigid body turning with angular velocity omega, the premise of the section"),
    41: (NC, "the kinetic energy of the body defined as the integral of rho v^2/2; the chain goes on in the next display"),
    45: (H, "v^2 = v . v (check 45)"),
    49: (H, "v = omega x r put into one factor (check 49)"),
    53: (H, "v . (omega x r) = omega . (r x v), the cyclic triple product (check 53)"),
    57: (H, "the constant omega taken out of the integral (check 57)"),
    61: (H, "the integral is L, defined in the next display (check 61)"),
    67: (NC, "defines the total angular momentum L"),
    75: (NC, "the angular momentum L by its definition again; the chain goes on in the next display"),
    80: (H, "v = omega x r (check 80)"),
    85: (H, "r x (omega x r) = omega r^2 - r (r . omega) (check 85)"),
    90: (H, "omega r^2 - r (r . omega) = (1 r^2 - r r) . omega (check 90)"),
    95: (H, "the integral of (1 r^2 - r r) rho is the tensor I the next display defines, so L = I . omega (check 95)"),
    101: (NC, "defines the moment of inertia tensor I"),
    109: (NC, "the definition of I repeated"),
    113: (H, "the components of rho (1 r^2 - r r) are rho (delta^ij r_k r^k - r^i r^j) (check 113)"),
    119: (H, "omega . L = omega . I . omega, and with omega = omega n this is n . I . n omega^2, which is I omega^2 with I = n . I . n as the next display defines (check 119)"),
    128: (NC, "defines the moment of inertia about the axis n, I = n . I . n; the chain goes on in the next display"),
    132: (H, "the tensor's definition put in (check 132)"),
    137: (H, "n . (1 r^2 - r r) . n = r^2 - (r . n)^2 for a unit vector n (check 137)"),
    147: (H, "the volume of the cylinder, the integral of rho d rho d phi d z (check 147)"),
    151: (NC, "chooses the axis of rotation, the z axis"),
    155: (NC, "the position in cylindrical coordinates"),
    159: (H, "r . n = z (check 159)"),
    163: (H, "r^2 = rho^2 + z^2 (check 163)"),
    167: (H, "the uniform density m/V and r^2 - (r . n)^2 = rho^2 + z^2 - z^2 (check 167)"),
    172: ("typo", DR_Z,
          "= \\int {m\\over V} \\rho^2 \\d^3 r = {m\\over V} \\int_0^{2\\pi}\\d\\phi \\int_0^R\\d \\rho \\int_{-{h\\over2}}^{h\\over2} \\d z \\rho^2 \\rho =",
          "By hand: d^3r = rho d rho d phi d z in cylindrical coordinates, so the radial integral must run over rho; "
          "written over R (with R also its upper limit) it gives int_0^R dR = R times rho^3, a member still holding rho, "
          "while the next display's m/V 2 pi R^4/4 h is what int_0^R rho^3 d rho gives.",
          "Dimensions and values: with R = 1, h = 1, m/V = 1 the intended member is 2 pi/4 = 1.571; the display's member as written "
          "is 2 pi rho^3, which depends on the point rho and is not a number. The first equality (the integral of rho^2 d^3r) holds."),
    179: (H, "m/V 2 pi R^4/4 h is the radial, polar and axial integral, and with V = pi R^2 h it is m R^2/2 (check 179)"),
    188: (NC, "chooses the axis of rotation, the x axis"),
    192: (NC, "the position in cylindrical coordinates"),
    196: (H, "r . n = rho cos phi (check 196)"),
    200: (H, "r^2 = rho^2 + z^2 (check 200)"),
    204: (H, "r^2 - (r . n)^2 = rho^2 + z^2 - rho^2 cos^2 phi with the density m/V (check 204)"),
    209: ("typo", DR_Z.replace("m/V 2 pi R h rho^3, which is not m/V 2 pi R^4 h/4", "a member still holding rho and phi").replace("check 172", "check 209"),
          "= {m\\over V} \\int_0^{2\\pi}\\d\\phi \\int_0^R\\d \\rho \\int_{-{h\\over2}}^{h\\over2} \\d z (\\rho^2+z^2 - \\rho^2\\cos^2\\phi)\\rho =",
          "By hand: the radial integral over rho of (rho^2 + z^2 - rho^2 cos^2 phi) rho gives R^4/4 + z^2 R^2/2 - R^4 cos^2 phi/4, "
          "which the next display's pi R^4 h/2 + pi R^2 h^3/12 - pi R^4 h/4 integrates further; written with d R the radial "
          "integral is R (rho^2 + z^2 - rho^2 cos^2 phi) rho instead, still a function of rho.",
          "Values: R = h = m/V = 1: the intended member is pi/2 + pi/12 - pi/4 = 1.309; the member as written is 2 pi rho^3 + ... "
          "with rho free, not a number. The equality before it (the integrand) holds."),
    214: (H, "the three integrals: pi R^4 h/2, pi R^2 h^3/12 and -pi R^4 h/4 (check 214)"),
    219: (H, "V = pi R^2 h put in (check 219)"),
    224: (H, "the bracket divided by pi R^2 h is (6 R^2 + h^2 - 3 R^2)/12 (check 224)"),
    228: (H, "6 R^2 - 3 R^2 = 3 R^2 (check 228)"),
    240: (H, "the volume of the ball, the integral of rho^2 sin theta (check 240)"),
    244: (NC, "chooses the axis of rotation, the z axis"),
    248: (NC, "the position in spherical coordinates"),
    252: (H, "r . n = rho cos theta (check 252)"),
    256: (H, "r^2 = rho^2 (check 256)"),
    260: (H, "r^2 - (r . n)^2 = rho^2 - rho^2 cos^2 theta with the density m/V (check 260)"),
    265: ("typo", DR_Z.replace("m/V 2 pi R h rho^3, which is not m/V 2 pi R^4 h/4", "a member still holding rho").replace("the cylinder", "the ball").replace("check 172", "check 265"),
          "= {m\\over V} \\int_0^{2\\pi}\\d\\phi \\int_0^R\\d \\rho \\int_0^\\pi \\d \\theta \\rho^2(1-\\cos^2\\theta) \\rho^2\\sin\\theta =",
          "By hand: d^3r = rho^2 sin theta d rho d phi d theta, so the radial integral of rho^4 runs over rho and gives R^5/5, "
          "the factor the display two further on writes; over d R (R also the limit) it gives R rho^4 instead.",
          "Values: R = m/V = 1: the intended member is 2 pi (1/5)(4/3) = 1.676; the member as written is 2 pi (4/3) rho^4, "
          "which depends on rho. The integrand rho^2 (1 - cos^2 theta) rho^2 sin theta is right."),
    271: ("typo", DR_Z.replace("m/V 2 pi R h rho^3, which is not m/V 2 pi R^4 h/4", "a member still holding rho").replace("the cylinder", "the ball").replace("check 172", "check 271"),
          "= {m\\over V} \\int_0^{2\\pi}\\d\\phi \\int_0^R\\d \\rho \\int_0^\\pi \\d \\theta \\rho^4\\sin^3\\theta =",
          "By hand: the display repeats the previous one's differential d R while simplifying the integrand to rho^4 sin^3 theta "
          "(right: (1 - cos^2) sin = sin^3); the radial integral must run over rho to give R^5/5.",
          "Values: R = m/V = 1: int sin^3 = 4/3, so the intended member is 2 pi (4/3)/5 = 1.676, the next display's value; as written "
          "the member is 2 pi (4/3) rho^4 R = 8.378 rho^4, a function of rho."),
    277: (H, "2 pi times R^5/5 times 4/3, the three integrals (check 277)"),
    281: (H, "2 pi (4/3)/5 = 8/15 pi, and with V = 4 pi R^3/3 the moment is 2 m R^2/5 (check 281)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
