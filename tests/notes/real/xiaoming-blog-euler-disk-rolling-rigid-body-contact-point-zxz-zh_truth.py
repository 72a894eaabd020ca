"""Independent SymPy truth table for xiaoming-blog-euler-disk-rolling-rigid-body-contact-point-zxz-zh.md.

The post's convention: A_t turns body components into fixed ones (q-hat = A_t Q), built from z-x-z
Euler angles as A_t = R_z(phi) R_x(theta) R_z(psi) (active, right-handed turns); Omega is the body
angular velocity (A_t^T A_t' = [Omega]x), omega = A_t Omega the same in fixed axes; [a, b] is the cross
product; n = (0, 0, 1) is the upward normal of the plane and N = A_t^{-1} n its body components; the
contact point is the lowest point of the body. The contact points are found here independently as the
lowest point of each shape: the rim point of the disk's lower face (or of the torus's centre circle)
that lies lowest, found from the symmetry axis k = A_t e_3, and the ellipsoid's point whose outward
normal points down. Run as a program it compares its verdicts with the table; ``--write`` writes it.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz, zero, numeric_zero

t = sp.symbols('t', real=True)
m, g, R, d, r, a, b, c = sp.symbols('m g R d r a b c', positive=True)
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
phi, theta, psi = (sp.Function(n)(t) for n in ('phi', 'theta', 'psi'))

A = Rz(phi) * Rx(theta) * Rz(psi)
S = sp.simplify(A.T * A.diff(t))
Om = sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])
om = sp.simplify(A * Om)
II = sp.diag(I1, I2, I3)
n = sp.Matrix([0, 0, 1])


def vec(name):
    return sp.Matrix([sp.Function(f'{name}{i}')(t) for i in (1, 2, 3)])


def cross(u, v):
    return u.cross(v)


CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# line 33: a vector fixed in the body, p-hat = A_t P with P constant, moves as omega x p-hat
P0 = sp.Matrix(sp.symbols('P1:4', real=True))
check(33, numeric_zero((A * P0).diff(t) - cross(om, A * P0), t))

# line 39: d/dt (A_t P) = A_t [Omega, P] + A_t P' for any P(t)
P = vec('P')
check(39, numeric_zero((A * P).diff(t) - A * cross(Om, P) - A * P.diff(t), t))

# line 61: f from m r'' = -m g n + f, with r' = -[omega, gamma] differentiated once
W, G = vec('w'), vec('gamma')
rdd = -(cross(W, G)).diff(t)
f = m * rdd + m * g * n
check(61, zero(cross(G, f) - cross(G, m * g * n - m * cross(W, G).diff(t))))

# line 65: d/dt (A_t I Omega) = A_t' I Omega + A_t I Omega' = A_t([Omega, I Omega] + I Omega')
lhs = (A * II * Om).diff(t)
mid = A.diff(t) * II * Om + A * II * Om.diff(t)
rhs = A * (cross(Om, II * Om) + II * Om.diff(t))
check(65, numeric_zero(lhs - mid, t) and numeric_zero(mid - rhs, t))

# line 71: (61) with its left side replaced by (65)
check(71, numeric_zero(lhs - rhs, t))

# line 77: the post's A_t against R_z(phi) R_x(theta) R_z(psi); its (1,3) entry reads sin phi sin psi
cph, sph, cth, sth, cps, sps = (sp.cos(phi), sp.sin(phi), sp.cos(theta), sp.sin(theta), sp.cos(psi), sp.sin(psi))
A_post = sp.Matrix([[cph * cps - cth * sph * sps, -cth * cps * sph - cph * sps, sph * sps],
                    [cps * sph + cth * cph * sps, cph * cth * cps - sph * sps, -cph * sth],
                    [sth * sps, cps * sth, cth]])
check(77, zero(A_post - A))
assert zero((A_post - A)[0, 2] - sph * (sps - sth)) and zero((A_post - A)[:, :2]) and zero((A_post - A)[1:, 2])

# line 86: Omega in the Euler angles
pd, td, sd = phi.diff(t), theta.diff(t), psi.diff(t)
Om_post = sp.Matrix([pd * sth * sps + td * cps, pd * sth * cps - td * sps, sd + pd * cth])
check(86, zero(Om - Om_post))

# line 95: omega = A_t Omega in the Euler angles (the z-x-z matrix, the one the post's own code uses)
om_post = sp.Matrix([td * cph + sd * sth * sph, td * sph - sd * sth * cph, pd + sd * cth])
check(95, zero(A * Om_post - om_post))

# line 110: with gamma-hat = A_t Gamma, d/dt [omega, gamma-hat] = d/dt A_t[Omega, Gamma]
#           = A_t[Omega, [Omega, Gamma]] + A_t d/dt [Omega, Gamma]
Gm = vec('Gamma')
e1 = cross(om, A * Gm) - A * cross(Om, Gm)
e2 = (A * cross(Om, Gm)).diff(t) - A * cross(Om, cross(Om, Gm)) - A * cross(Om, Gm).diff(t)
check(110, numeric_zero(e1, t) and numeric_zero(e2, t))

# line 116: (71) multiplied by A_t^{-1}: A_t^T [gamma-hat, m g n - m d/dt[omega, gamma-hat]] in body terms
Nb = A.T * n
lhs116 = A.T * cross(A * Gm, m * g * n - m * (cross(om, A * Gm)).diff(t))
rhs116 = cross(Gm, m * g * Nb - m * cross(Om, cross(Om, Gm)) - m * cross(Om, Gm).diff(t))
check(116, numeric_zero(lhs116 - rhs116, t))

# line 123: d/dt (A_t N) = A_t [Omega, N] + A_t N' for any N(t) (and A_t N = n is constant)
Nv = vec('N')
check(123, numeric_zero((A * Nv).diff(t) - A * cross(Om, Nv) - A * Nv.diff(t), t))

# line 129: N = A_t^T n obeys N' + [Omega, N] = 0
check(129, numeric_zero(Nb.diff(t) + cross(Om, Nb), t))

# The lowest point, found independently, for 0 < theta < pi/2: k = A_t e_3 is the symmetry axis; the
# lowest direction in the plane normal to k is u = (-n + (n.k) k)/|...|, of length sin theta.
k = A * sp.Matrix([0, 0, 1])
u = sp.simplify((-n + cth * k) / sth)
disk_low = R * u - d * k
torus_low = R * u - r * n


def Gamma_disk(N):
    return -R / sp.sqrt(N[0]**2 + N[1]**2) * sp.Matrix([N[0], N[1], 0]) - sp.Matrix([0, 0, d])


def sample(e):
    """Evaluate at a tilted pose (0 < theta < pi/2) with numbers for the lengths."""
    vals = {phi: sp.Rational(3, 10), theta: sp.Rational(7, 10), psi: sp.Rational(-11, 10),
            R: sp.Rational(3, 2), d: sp.Rational(1, 5), r: sp.Rational(2, 5)}
    return sp.N(e.subs(vals), 30)


# line 144: gamma-hat = A_t Gamma(A_t^{-1} n), with the disk's Gamma, is the lowest point
check(144, max(abs(x) for x in sample(A * Gamma_disk(A.T * n) - disk_low)) < 1e-20)

# line 155: the cylinder X^2 + Y^2 <= R has radius sqrt R, while the rim used by lines 161 and 165
# (Gamma(N) has X^2 + Y^2 = R^2) has radius R: the two agree only for R = 1
rim = Gamma_disk(A.T * n)
check(155, zero(rim[0]**2 + rim[1]**2 - R))

# line 161: the post's gamma-hat = (R cos theta sin phi, -R cos theta cos phi, -R sin theta) - d A_t N
post161 = R * sp.Matrix([cth * sph, -cth * cph, -sth]) - d * A * Nb
check(161, max(abs(x) for x in sample(post161 - disk_low)) < 1e-20)
assert max(abs(x) for x in sample(R * sp.Matrix([cth * sph, -cth * cph, -sth]) - d * k - disk_low)) < 1e-20

# line 165: Gamma(N) for the disk gives the lowest point once turned by A_t
check(165, max(abs(x) for x in sample(A * Gamma_disk(Nb) - disk_low)) < 1e-20)

# line 179: the ellipsoid's Gamma(N) is on the surface and its outward normal there is along -N
N1, N2, N3 = sp.symbols('N_1:4', real=True)
den = sp.sqrt(a**2 * N1**2 + b**2 * N2**2 + c**2 * N3**2)
X = -sp.Matrix([a**2 * N1, b**2 * N2, c**2 * N3]) / den
on_surface = zero(X[0]**2 / a**2 + X[1]**2 / b**2 + X[2]**2 / c**2 - 1)
normal = sp.Matrix([X[0] / a**2, X[1] / b**2, X[2] / c**2])
check(179, on_surface and zero(normal.cross(sp.Matrix([N1, N2, N3]))) and zero(normal[0] + N1 / den))

# line 187: the post's torus f(xi, eta) lies at distance r from the centre circle of radius R?
xi, eta = sp.symbols('xi eta', real=True)
fx, fy, fz = ((R + r * sp.cos(eta)) * sp.cos(xi), (R + r * sp.cos(eta)) * sp.sin(xi), sp.sin(eta))
check(187, zero((sp.sqrt(sp.simplify(fx**2 + fy**2)) - R)**2 + fz**2 - r**2))

# line 193: the torus's lowest point: the lowest point of the centre circle, then r down
post193 = sp.Matrix([R * cth * sph, -R * cth * cph, -r - R * sth])
check(193, max(abs(x) for x in sample(post193 - torus_low)) < 1e-20)

LINES = [33, 39, 48, 53, 57, 61, 65, 71, 77, 86, 95, 110, 116, 123, 129, 144, 155, 161, 165, 173, 179, 187, 193]

ROWS = {
    33: ("holds", "for p-hat = A_t P with P constant, p-hat' = A_t' P = A_t [Omega]x P = (A_t Omega) x (A_t P) = omega x p-hat (check 33)"),
    39: ("holds", "d/dt(A_t P) = A_t' P + A_t P' with A_t' = A_t [Omega]x, so A_t [Omega, P] + A_t P' (check 39)"),
    48: ("not a claim", "the theorem of the motion of the centre of mass, a premise of the model"),
    53: ("not a claim", "the theorem of angular momentum about the centre of mass, a premise of the model"),
    57: ("not a claim", "the rolling condition (the contact point has zero velocity), a premise of the model"),
    61: ("holds", "from m r'' = -m g n + f and r'' = -d/dt[omega, gamma-hat] (the rolling condition differentiated), f = m g n - m d/dt[omega, gamma-hat] (check 61)"),
    65: ("holds", "A_t' = A_t [Omega]x, so A_t' I Omega = A_t [Omega, I Omega] (check 65)"),
    71: ("holds", "line 61 with its left side rewritten by line 65 (check 71)"),
    77: ("typo", "R_z(phi) R_x(theta) R_z(psi) has (1,3) entry sin phi sin theta; the display writes sin phi sin psi; its other eight entries agree (check 77)",
         "\tA_t=\n\t\\begin{pmatrix}\n\t\t\\cos\\phi\\cos\\psi-\\cos\\theta\\sin\\phi\\sin\\psi&-\\cos\\theta\\cos\\psi\\sin\\phi-\\cos\\phi\\sin\\psi&\\sin\\phi\\sin\\theta\\\\\n\t\t\\cos\\psi\\sin\\phi+\\cos\\theta\\cos\\phi\\sin\\psi&\\cos\\phi\\cos\\theta\\cos\\psi-\\sin\\phi\\sin\\psi& -\\cos\\phi\\sin\\theta  \\\\\n\t\t\\sin\\theta\\sin\\psi&\\cos\\psi\\sin\\theta & \\cos\\theta  \\\\\n\t\\end{pmatrix}.",
         "algebra: the third column of R_z(phi) R_x(theta) R_z(psi) is R_z(phi) R_x(theta) e_3 (R_z(psi) fixes e_3) = R_z(phi) (0, -sin theta, cos theta) = (sin phi sin theta, -cos phi sin theta, cos theta); the display's second and third entries of that column agree, its first has psi for theta. The column must also be a unit vector: sin^2 phi sin^2 psi + cos^2 phi sin^2 theta + cos^2 theta is not 1 in general.",
         "numbers: phi = pi/2, theta = 0, psi = pi/2 is a turn by pi about z, the matrix diag(-1, -1, 1); the display's (1,3) entry gives sin(pi/2) sin(pi/2) = 1 there, and its first row (0 - 1, -0 - 0, 1) = (-1, 0, 1) is not a unit row, so the display is not a rotation"),
    86: ("holds", "the body angular velocity of the z-x-z angles: A_t^T A_t' = [Omega]x gives Omega = (phi' sin theta sin psi + theta' cos psi, phi' sin theta cos psi - theta' sin psi, psi' + phi' cos theta) (check 86)"),
    95: ("holds", "omega = A_t Omega with the z-x-z matrix: (theta' cos phi + psi' sin theta sin phi, theta' sin phi - psi' sin theta cos phi, phi' + psi' cos theta), the angular velocity in fixed axes (check 95)"),
    110: ("holds", "[A_t Omega, A_t Gamma] = A_t [Omega, Gamma] (a rotation keeps the cross product), and d/dt A_t X = A_t [Omega, X] + A_t X' (check 110)"),
    116: ("holds", "A_t^{-1} of line 71 with n = A_t N, gamma-hat = A_t Gamma and line 110 (check 116)"),
    123: ("holds", "d/dt(A_t N) = A_t [Omega, N] + A_t N', and A_t N = n is constant (check 123)"),
    129: ("holds", "N = A_t^T n with n constant: N' = A_t'^T n = -[Omega]x A_t^T n = -[Omega, N] (check 129)"),
    144: ("holds", "Gamma(N) is the body point with inward normal N, so A_t Gamma(A_t^{-1} n) is the contact point; for the disk's Gamma it is the lowest point found independently (check 144)"),
    155: ("typo", "the cylinder of radius R is X^2 + Y^2 <= R^2; X^2 + Y^2 <= R has radius sqrt R, while the contact point of lines 161 and 165 lies on the rim at distance R from the axis (check 155)",
          "U=\\{(X,Y,Z): X^2+Y^2\\leq R^2, |Z|\\leq d  \\}",
          "algebra: the disk's rim point of line 165, -R (N_1, N_2, 0)/sqrt(N_1^2 + N_2^2) - (0, 0, d), has X^2 + Y^2 = R^2; it lies on the boundary of U only if R^2 = R, that is R = 1. The set that the later lines use is X^2 + Y^2 <= R^2.",
          "numbers: R = 4: the rim point of line 165 with N = (1, 0, 1)/sqrt 2 is (-4, 0, -d), with X^2 + Y^2 = 16, far outside X^2 + Y^2 <= 4; the cylinder of line 155 has radius 2, not the 4 of the contact formulas"),
    161: ("typo", "the contact point of the lower face is the lowest rim point R u (u = (cos theta sin phi, -cos theta cos phi, -sin theta), the lowest direction in the disk's plane) minus d times the symmetry axis A_t e_3; the display writes d A_t N, and A_t N = n is the vertical (check 161)",
          "\\hat{\\gamma}=(R\\cos\\theta\\sin\\phi,-R\\cos\\theta\\cos\\phi,-R\\sin\\theta)-dA_t (0,0,1)^T.",
          "algebra: the next display gives Gamma(N) = -R (N_1, N_2, 0)/sqrt(N_1^2 + N_2^2) - (0, 0, d); with line 144, gamma-hat = A_t Gamma(N) = R (cos theta sin phi, -cos theta cos phi, -sin theta) - d A_t (0, 0, 1)^T. Since N = A_t^{-1} n, the display's -d A_t N is -d n = (0, 0, -d), which equals -d A_t (0, 0, 1)^T only when the disk lies flat (theta = 0).",
          "numbers: phi = 0, theta = pi/4, R = 1, d = 0.1: the lower face's centre is at -d A_t e_3 = -0.1 (0, -0.707, 0.707) = (0, 0.071, -0.071) and the contact point at (0, -0.707, -0.707) + (0, 0.071, -0.071) = (0, -0.636, -0.778); the display gives (0, -0.707, -0.707) - (0, 0, 0.1) = (0, -0.707, -0.807), the point 0.1 straight below the rim of the disk's middle plane, which lies at distance R + d sin theta = 1.07 from the axis, outside the disk"),
    165: ("holds", "the lowest rim point of the lower face in body axes: against the horizontal part of N, at distance R, on Z = -d; turned by A_t it is the lowest point found independently (check 165)"),
    173: ("not a claim", "the definition of the ellipsoid"),
    179: ("holds", "the point -(a^2 N_1, b^2 N_2, c^2 N_3)/sqrt(a^2 N_1^2 + b^2 N_2^2 + c^2 N_3^2) is on the ellipsoid and its outward normal (X/a^2, Y/b^2, Z/c^2) is along -N, so N is the inward normal there (check 179)"),
    187: ("typo", "a torus of tube radius r about a centre circle of radius R is ((R + r cos eta) cos xi, (R + r cos eta) sin xi, r sin eta); with sin eta the third component, the tube's cross-section is an ellipse of semi-axes r and 1 (check 187)",
          "f(\\xi,\\eta)=((R+r\\cos\\eta)\\cos\\xi,(R+r\\cos\\eta)\\sin\\xi,r\\sin\\eta),",
          "algebra: the distance of f(xi, eta) from the centre circle is sqrt((sqrt(x^2 + y^2) - R)^2 + z^2) = sqrt(r^2 cos^2 eta + sin^2 eta), which is the constant r only for r = 1; the next display's contact point (-r below the centre circle's lowest point) is that of the tube of radius r.",
          "numbers: r = 0.5, eta = pi/2: the display gives the point (R cos xi, R sin xi, 1), at distance 1 from the centre circle, while the torus of tube radius 0.5 has its top there at height 0.5"),
    193: ("holds", "the lowest point of a torus whose axis is A_t e_3: the lowest point of the centre circle, R (cos theta sin phi, -cos theta cos phi, -sin theta), then r down (check 193)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
