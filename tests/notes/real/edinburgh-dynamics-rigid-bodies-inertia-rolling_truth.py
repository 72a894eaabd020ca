"""Independent SymPy truth table for edinburgh-dynamics-rigid-bodies-inertia-rolling.tex.

The text's own setting: moments of inertia as integrals of the squared distance from an axis,
weighted by the density; the inertia tensor I_ij = int (delta_ij r^2 - x_i x_j) rho dV; a ball of
radius R and mass M (moment 2/5 M R^2) that rolls on a plane with normal k when v = R (omega x k),
struck by a cue or sliding under friction -F i along x. Every check is built here from these
definitions (the moments integrated, the rolling ball's equations derived from Newton's laws for
force and torque), never from the text's later displays. Run with --write to regenerate the table.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
M, R, H, L, d, rho, b = sp.symbols("M R H L d rho b", positive=True)
r, z, th, ph, x, y = sp.symbols("r z theta phi x y", real=True)
integ = sp.integrate

# 43: a hoop, every element at distance R: I = R^2 int rho dV = M R^2
lam = M / (2 * sp.pi * R)                                   # line density
check(43, sp.simplify(integ(R**2 * lam * R, (ph, 0, 2 * sp.pi)) - M * R**2) == 0)
# 47: the cylinder in rings: H rho int_0^R r^2 2 pi r dr = 2 pi H rho R^4/4
Icyl = integ(r**2 * rho * r, (r, 0, R), (ph, 0, 2 * sp.pi), (z, 0, H))
check(47, sp.simplify(Icyl - H * rho * integ(r**2 * 2 * sp.pi * r, (r, 0, R))) == 0
      and sp.simplify(Icyl - 2 * sp.pi * H * rho * R**4 / 4) == 0)
# 49: the volume is H int_0^R 2 pi r dr = pi R^2 H; the text's integral has lost its H
Vcyl = integ(r, (r, 0, R), (ph, 0, 2 * sp.pi), (z, 0, H))
assert sp.simplify(Vcyl - 2 * sp.pi * H * R**2 / 2) == 0
check(49, sp.simplify(integ(2 * sp.pi * r, (r, 0, R)) - 2 * sp.pi * H * R**2 / 2) == 0)
# 51: I = rho V R^2 / 2 = M R^2 / 2 with M = rho V
check(51, sp.simplify(Icyl - rho * Vcyl * R**2 / 2) == 0
      and sp.simplify((Icyl - M * R**2 / 2).subs(rho, M / Vcyl)) == 0)
# 54: the solid ball about a diameter
rb = M / (sp.Rational(4, 3) * sp.pi * R**3)
Iball = integ(rb * (r * sp.sin(th))**2 * r**2 * sp.sin(th), (r, 0, R), (th, 0, sp.pi), (ph, 0, 2 * sp.pi))
check(54, sp.simplify(Iball - sp.Rational(2, 5) * M * R**2) == 0)
# 57: the thin shell about a diameter
sig = M / (4 * sp.pi * R**2)
Ishell = integ(sig * (R * sp.sin(th))**2 * R**2 * sp.sin(th), (th, 0, sp.pi), (ph, 0, 2 * sp.pi))
check(57, sp.simplify(Ishell - sp.Rational(2, 3) * M * R**2) == 0)
# 60: the thin rod about its centre
check(60, sp.simplify(integ((M / L) * x**2, (x, -L / 2, L / 2)) - M * L**2 / 12) == 0)
# 64: with k_A^2 = (1/M) int |r_A|^2 rho dV, I_A = M k_A^2 (the same integral)
IA, kA = sp.symbols("I_A k_A", positive=True)
check(64, sp.simplify(M * (IA / M) - IA) == 0)

# a body of point masses, its centre of mass at the origin, for the axis theorems and the tensor
pts = [(2, (1, 2, -1)), (3, (-2, 1, 1)), (1, (4, -7, -1))]
mt = sum(m for m, _ in pts)
assert all(sum(m * p[k] for m, p in pts) == 0 for k in range(3))
E3 = sp.eye(3)
Itens = sum((m * (sp.Matrix(p).dot(sp.Matrix(p)) * E3 - sp.Matrix(p) * sp.Matrix(p).T) for m, p in pts),
            sp.zeros(3, 3))
# 69: about the z-axis shifted by d along x, I_A' = I_A + M d^2 (the axis A through the centre of mass)
IzA = sum(m * (p[0]**2 + p[1]**2) for m, p in pts)
IzA2 = sum(m * ((p[0] - d)**2 + p[1]**2) for m, p in pts)
check(69, sp.expand(IzA2 - (IzA + mt * d**2)) == 0)
# 71: the mass-weighted perpendicular offsets from an axis through the centre of mass sum to zero
check(71, all(sum(m * p[k] for m, p in pts) == 0 for k in (0, 1)))
# 80: the hoop about a diameter in its plane: half of M R^2
check(80, sp.simplify(integ(lam * (R * sp.sin(ph))**2 * R, (ph, 0, 2 * sp.pi)) - M * R**2 / 2) == 0)
# 82: the cylinder about a diameter through its centre
rc = M / (sp.pi * R**2 * H)
Iperp = integ(rc * ((r * sp.sin(ph))**2 + z**2) * r, (r, 0, R), (ph, 0, 2 * sp.pi), (z, -H / 2, H / 2))
check(82, sp.simplify(Iperp - (M * R**2 / 4 + M * H**2 / 12)) == 0)
# 89, 91: the entries of delta_ij (x^2 + y^2 + z^2) - x_i x_j
X = sp.Matrix([x, y, z])
T = (X.dot(X)) * E3 - X * X.T
check(89, sp.expand(T[0, 0] - (y**2 + z**2)) == 0 and sp.expand(T[1, 1] - (x**2 + z**2)) == 0
      and sp.expand(T[2, 2] - (x**2 + y**2)) == 0)
check(91, T[0, 1] == -x * y and T[1, 0] == -x * y and T[1, 2] == -y * z and T[2, 1] == -y * z
      and T[2, 0] == -x * z and T[0, 2] == -x * z)
# 93: with M's rows the unit eigenvectors of I, M I M^T is diagonal (and M is a rotation or a reflection)
Inum = sp.Matrix([[2, 1, 0], [1, 3, 1], [0, 1, 4]])
vecs = [v.normalized() for val, mult, vs in Inum.eigenvects() for v in vs]
Mrot = sp.Matrix.vstack(*[v.T for v in vecs])
D = sp.simplify(Mrot * Inum * Mrot.T)
check(93, zero(D - sp.diag(D[0, 0], D[1, 1], D[2, 2])) and zero(sp.simplify(Mrot * Mrot.T) - E3))
# 98, 100, 102, 103: L = sum m r x (omega x r) = I omega, T = sum m |omega x r|^2/2 = omega^T I omega/2
w1, w2, w3 = sp.symbols("omega_1 omega_2 omega_3", real=True)
w = sp.Matrix([w1, w2, w3])
Lv = sum((m * sp.Matrix(p).cross(w.cross(sp.Matrix(p))) for m, p in pts), sp.zeros(3, 1))
Tk = sum(m * (w.cross(sp.Matrix(p))).dot(w.cross(sp.Matrix(p))) for m, p in pts) / 2
check(102, zero(Lv - Itens * w))
check(103, sp.expand(Tk - (w.T * Itens * w)[0] / 2) == 0)
# about a principal axis (the body's eigenvector u, moment lambda): L = lambda omega along u, T = lambda omega^2/2
val, _, vs = Itens.eigenvects()[0]
u = vs[0].normalized()
wa = sp.symbols("omega_A", real=True)
check(98, zero(sp.simplify(Itens * (wa * u) - val * wa * u)))
check(100, sp.simplify((wa * u).T * Itens * (wa * u) / 2 - sp.Matrix([val * wa**2 / 2]))[0] == 0)
# 105: v = dx/dt = R dtheta/dt = R omega; the middle member divides by t, not by Delta t
t, dt, dth, w0 = sp.symbols("t Delta_t Delta_vartheta omega", positive=True)
check(105, sp.simplify((R * dth / t - R * dth / dt).subs(dth, w0 * dt)) == 0)
# 107: the contact point, -R k from the centre, is at rest: v + omega x (-R k) = 0
kk = sp.Matrix([0, 0, 1])
vv = R * w.cross(kk)
check(107, zero(vv + w.cross(-R * kk)))
# 114-119: struck at height b above the centre with a force F along x: M vdot = F, I omegadot = b F,
# and rolling from the start (v = R omega, so vdot = R omegadot) needs b = I/(M R)
vd, od, F = sp.symbols("vdot omegadot F", real=True)
I = sp.Rational(2, 5) * M * R**2
check(114, sp.simplify((M * vd - M * R * od).subs(vd, R * od)) == 0)
check(116, sp.simplify((b * F - b * M * R * od).subs(F, M * vd).subs(vd, R * od)) == 0)
check(118, sp.simplify(I - sp.Rational(2, 5) * M * R**2) == 0)
check(119, sp.solve(sp.Eq(b * M * R * od, I * od), b) == [sp.Rational(2, 5) * R])
# the hollow sphere and the cylinder of the prose: b = I/(M R)
assert sp.simplify(sp.Rational(2, 3) * M * R**2 / (M * R) - 2 * R / 3) == 0
# 126-136: friction -F i at the contact point -R k while the ball slides
Ff = sp.symbols("F_frict", positive=True)
vdot = sp.Matrix([-Ff / M, 0, 0])                           # M vdot = -F i
check(126, zero(M * vdot - sp.Matrix([-Ff, 0, 0])))
torque = (-R * kk).cross(sp.Matrix([-Ff, 0, 0]))
odot = torque / I                                           # I omegadot = r x F
check(128, zero(I * odot - torque) and zero(torque - (-R * kk).cross(M * vdot)))
check(129, zero(I * odot + M * R * kk.cross(vdot)))
check(131, sp.simplify(vdot[0] + sp.Rational(2, 5) * R * odot[1]) == 0)
# integrate from v = V, omega = 0: v_x(t) = V - F t/M, omega_y(t) = (F R/I) t
V = sp.symbols("V", positive=True)
vx = V + vdot[0] * t
wy = odot[1] * t
check(133, sp.simplify(vx - V + sp.Rational(2, 5) * R * wy) == 0)
check(134, sp.simplify(vx - V - sp.Rational(2, 5) * R * wy) == 0)
# rolling when v_x = R omega_y: v_x = 5V/7 (the text's first member has lost its minus sign)
tr = sp.solve(sp.Eq(vx, R * wy), t)[0]
assert sp.simplify(vx.subs(t, tr) - sp.Rational(5, 7) * V) == 0
vroll = sp.symbols("v_roll", positive=True)
check(136, sp.solve(sp.Eq(vroll - V, sp.Rational(2, 5) * vroll), vroll) == [sp.Rational(5, 7) * V])

ROWS = {
    39: ("not a claim", "the definition of the moment of inertia about an axis"),
    43: ("holds", "every element of the hoop is at distance R, and int rho dV = M (check 43)"),
    47: ("holds", "rings of radius r_A, circumference 2 pi r_A and height H: 2 pi H rho R^4/4 (check 47)"),
    49: ("typo", "the volume of the cylinder is pi R^2 H; the integral as written, int_0^R 2 pi r_A dr_A, is pi R^2, "
                 "the factor H of the rings' height left out of it though kept on the right (check 49)",
         r"V = H\int_0^R2\pi r_A\,\dd r_A = 2\pi H\frac{R^2}{2}",
         "int_0^R 2 pi r dr = pi R^2, an area, not a volume; the right-hand side 2 pi H R^2/2 = pi R^2 H is the cylinder's "
         "volume, so the two members differ by the factor H.",
         "The display before integrates the rings with H rho in front of the integral; the same H must stand in front here "
         "for V = pi R^2 H, which the next display uses (I = rho V R^2/2 = M R^2/2 holds only with that V)."),
    51: ("holds", "with V = pi R^2 H, 2 pi H rho R^4/4 = rho V R^2/2 and M = rho V (check 51)"),
    54: ("holds", "the integral over a uniform ball of the squared distance from a diameter (check 54)"),
    57: ("holds", "the integral over a uniform thin shell (check 57)"),
    60: ("holds", "int_{-L/2}^{L/2} (M/L) x^2 dx = M L^2/12 (check 60)"),
    63: ("not a claim", "the definition of the radius of gyration"),
    64: ("holds", "M k_A^2 is the integral defining I_A (check 64)"),
    69: ("holds", "the parallel axes theorem, checked on a body whose centre of mass is on the axis A (check 69)"),
    71: ("holds", "an axis through the centre of mass: the mass-weighted perpendicular offsets sum to zero (check 71)"),
    74: ("not a claim", "the perpendicular axes theorem stated without its setting (a flat body, I about the axis normal to "
                        "both) and with I not named; no relation among the text's quantities to check"),
    80: ("holds", "the hoop about a diameter: int (R sin phi)^2 dm = M R^2/2 (check 80)"),
    82: ("holds", "the uniform cylinder about a diameter through its centre (check 82)"),
    87: ("not a claim", "the definition of the inertia tensor"),
    89: ("holds", "the diagonal of delta_ij (x^2 + y^2 + z^2) - x_i x_j (check 89)"),
    91: ("holds", "the off-diagonal entries -x_i x_j, symmetric (check 91)"),
    93: ("holds", "with M's rows the unit eigenvectors of the symmetric I, M I M^T is diagonal and M orthogonal (check 93)"),
    98: ("holds", "about a principal axis I omega is the moment times omega along the axis (check 98)"),
    100: ("holds", "about a principal axis omega^T I omega/2 = I_A omega_A^2/2 (check 100)"),
    102: ("holds", "L = sum m r x (omega x r) = I omega, componentwise I_ij omega_j (check 102)"),
    103: ("holds", "T = sum m |omega x r|^2/2 = omega^T I omega/2 (check 103)"),
    105: ("typo", "the middle member divides the turn by the time t, not by the interval Delta t; R Delta vartheta/Delta t "
                  "is R omega (check 105)",
          r"v = \frac{\Delta x}{\Delta t} = R\frac{\Delta\vartheta}{\Delta t} = R\omega",
          "Dividing Delta x = R Delta vartheta by Delta t gives Delta x/Delta t = R Delta vartheta/Delta t, and "
          "Delta vartheta/Delta t is the angular velocity omega; Delta vartheta/t is not (it depends on when the clock started).",
          "The text's own words: 'dividing by Delta t'; the left member is Delta x/Delta t and the right R omega, so the middle "
          "must be R Delta vartheta/Delta t for the chain to hold."),
    107: ("holds", "the contact point -R k from the centre is at rest: v + omega x (-R k) = 0 (check 107)"),
    114: ("holds", "M dv/dt with v = R omega (check 114)"),
    116: ("holds", "the blow's torque about the centre is b F, and F = M R domega/dt (check 116)"),
    118: ("holds", "the ball's moment 2/5 M R^2 (check 118)"),
    119: ("holds", "b M R omegadot = (2/5) M R^2 omegadot gives b = 2R/5 (check 119)"),
    126: ("holds", "Newton's law for the sliding ball under friction (check 126)"),
    128: ("holds", "(-R k) x (-F i) = R F j, and -F i = M dv/dt (check 128)"),
    129: ("holds", "(-R k) x (M vdot) = -M R (k x vdot) (check 129)"),
    131: ("holds", "the j components: (2/5) M R^2 omegadot_y = -M R vdot_x (check 131)"),
    133: ("holds", "integrating from v_x = V, omega_y = 0 (check 133)"),
    134: ("typo", "the line above ends in -(2/5) R omega_y(t); the minus sign is lost (check 134)",
          r"v_x(t) - V = -\frac{2}{5}R\omega_y(t)",
          "The chain on the line before ends in v_x(t) - V = ... = -(2/5) R omega_y(t); this line copies it without the "
          "minus sign.",
          "Friction slows the ball (v_x(t) < V) while it spins it up (omega_y > 0 for friction backwards at the bottom), so "
          "v_x(t) - V is negative and (2/5) R omega_y(t) positive: they cannot be equal."),
    136: ("typo", "with the sign lost above, v - V = (2/5) v gives v = 5V/3, not 5V/7; the intended v - V = -(2/5) v gives "
                  "the stated 5V/7 (check 136)",
          r"v_x(\tau) - V = -\frac{2}{5}v_x(\tau)\implies v_x(\tau) = \frac{5}{7}V",
          "Solving v - V = (2/5) v: (3/5) v = V, v = 5V/3; solving v - V = -(2/5) v: (7/5) v = V, v = 5V/7.",
          "A sliding ball cannot speed up under friction (5V/3 > V); integrating the equations of motion directly "
          "(v = V - F t/M, omega = 5 F t/(2 M R)) and setting v = R omega gives t = 2 M V/(7 F) and v = 5V/7."),
}

LINES = sorted(ROWS)


if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
