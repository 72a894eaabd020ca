"""Independent SymPy truth table for zhao-ucas-notes-euler-equations-intermediate-axis.tex.

The text's own setting: a frame turning with angular velocity omega (its unit vectors i', j', k'
carried by a rotation R(t), so d/dt (R e) = omega x (R e)); ( )_r is the rate of the components in
that frame. A rigid body of uniform density rho turns about a fixed point with omega; its inertia
tensor is the I of L = I . omega, with principal moments I_11, I_22, I_33 (the text writes them
upright, \\mathrm I_{11}) and external torque M. The intermediate-axis section is torque-free with
I_11 > I_22 > I_33 and a spin Omega about one principal axis, the other components small (first
order). Every check is built here from these definitions, never from the text's later displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero

t = sp.symbols("t", real=True)
x, y, z, rho = sp.symbols("x y z rho", real=True)
w0 = sp.Matrix(sp.symbols("w0_1:4", real=True))
r = sp.Matrix([x, y, z])

# 21: curl (omega_0 x r) = 2 omega_0
v = w0.cross(r)
curl = sp.Matrix([sp.diff(v[2], y) - sp.diff(v[1], z), sp.diff(v[0], z) - sp.diff(v[2], x),
                  sp.diff(v[1], x) - sp.diff(v[0], y)])
check(21, zero(curl - 2 * w0))

# the turning frame: R(t) about k' by theta(t), omega = (0, 0, thetadot)
th = sp.Function("theta")(t)
R = sp.Matrix([[sp.cos(th), -sp.sin(th), 0], [sp.sin(th), sp.cos(th), 0], [0, 0, 1]])
om = sp.Matrix([0, 0, th.diff(t)])
e = [R[:, k] for k in range(3)]                       # i', j', k' in the fixed frame
# 26: d rhat/dt = omega x rhat, for each unit vector of the frame
check(26, all(zero(ek.diff(t) - om.cross(ek)) for ek in e))
# 29, 36: the determinants |i' j' k'; 0 0 w; 1 0 0| = w j' and |i' j' k'; 0 0 w; 0 1 0| = -w i'
w = sp.symbols("omega", real=True)


def det_row(a, b):
    """The determinant with rows (i', j', k'), a, b: components in the frame's basis."""
    return sp.Matrix(a).cross(sp.Matrix(b))


check(29, zero(det_row([0, 0, w], [1, 0, 0]) - sp.Matrix([0, w, 0]))
      and zero(e[0].diff(t) - th.diff(t) * e[1]))
check(36, zero(det_row([0, 0, w], [0, 1, 0]) - sp.Matrix([-w, 0, 0]))
      and zero(e[1].diff(t) + th.diff(t) * e[0]))
# 44: df/dt = (df/dt)_r + omega x f, f = R f_b
fb = sp.Matrix([sp.Function(f"f_{c}")(t) for c in "xyz"])
f = R * fb
check(44, zero(f.diff(t) - (R * fb.diff(t) + om.cross(f))))
# 51: v = dr/dt = (dr/dt)_r + omega   -- the frame term is omega x r
rb = sp.Matrix([sp.Function(f"r_{c}")(t) for c in "xyz"])
rr = R * rb
check(51, zero(rr.diff(t) - (R * rb.diff(t) + om)))
assert zero(rr.diff(t) - (R * rb.diff(t) + om.cross(rr)))          # the corrected form holds
# 54: a = (d2r/dt2)_r + (domega/dt)_r x r + 2 omega x (dr/dt)_r + omega x (omega x r)
a_text = R * rb.diff(t, 2) + om.diff(t).cross(rr) + 2 * om.cross(R * rb.diff(t)) + om.cross(om.cross(rr))
check(54, zero(rr.diff(t, 2) - a_text))

# a body of particles m_a at body points s_a turning with a general R(t); omega from Rdot R^T
phi, psi, the = [sp.Function(n)(t) for n in ("phi", "psi", "vartheta")]


def rot(axis, q):
    c, s = sp.cos(q), sp.sin(q)
    return {"z": sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
            "x": sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])}[axis]


Rg = rot("z", phi) * rot("x", the) * rot("z", psi)
W = sp.simplify(Rg.diff(t) * Rg.T)
om_s = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])          # space components of omega
om_b = sp.simplify(Rg.T * om_s)                          # body components
masses = [(2, sp.Matrix([1, 0, 0])), (3, sp.Matrix([0, 1, 1])), (5, sp.Matrix([1, -1, 2]))]
L_s = sum((m * (Rg * s).cross((Rg * s).diff(t)) for m, s in masses), sp.zeros(3, 1))
I_b = sum((m * ((s.T * s)[0] * sp.eye(3) - s * s.T) for m, s in masses), sp.zeros(3, 3))
# 63: L = I . omega (body components: R^T L = I_b omega_b)
check(63, zero(sp.simplify(Rg.T * L_s) - I_b * om_b))
# 66: dL/dt = M with M = sum r x F, F = m rddot (Newton for each particle, internal forces central)
M_s = sum((m * (Rg * s).cross((Rg * s).diff(t, 2)) for m, s in masses), sp.zeros(3, 1))
check(66, zero(L_s.diff(t) - M_s))
# 69: [d(I omega)/dt]_r + omega x (I omega) = M  (body components)
M_b = sp.simplify(Rg.T * M_s)
lhs69 = (I_b * om_b).diff(t) + om_b.cross(I_b * om_b)
check(69, zero(sp.simplify(lhs69 - M_b)))
# 72: I (domega/dt)_r + |i j k; w1 w2 w3; I11 w1 I22 w2 I33 w3| = M, principal axes
I11, I22, I33 = sp.symbols("I_11 I_22 I_33", positive=True)
wv = sp.Matrix([sp.Function(f"omega_{k}")(t) for k in (1, 2, 3)])
Mv = sp.Matrix(sp.symbols("M_1:4"))
Ip = sp.diag(I11, I22, I33)
det72 = wv.cross(Ip * wv)                                # the determinant's expansion
euler = Ip * wv.diff(t) + wv.cross(Ip * wv) - Mv         # Euler's law (from 69) in principal axes
check(72, zero(Ip * wv.diff(t) + det72 - Mv - euler))
# 81: the three components
rows81 = sp.Matrix([I11 * wv[0].diff(t) + (I33 - I22) * wv[1] * wv[2] - Mv[0],
                    I22 * wv[1].diff(t) + (I11 - I33) * wv[0] * wv[2] - Mv[1],
                    I33 * wv[2].diff(t) + (I22 - I11) * wv[0] * wv[1] - Mv[2]])
check(81, zero(rows81 - euler))
# 90: L = int r x dp = int r x rho v dV = rho int r x (omega x r) dV  (uniform rho, v = omega x r)
wo = sp.Matrix(sp.symbols("w_1:4", real=True))
check(90, zero(r.cross(rho * wo.cross(r)) - rho * r.cross(wo.cross(r))))
# 97: = rho int [omega r^2 - r (r.omega)] = rho int [omega r^2 - (r (x) r) omega] = [rho int (r^2 e - r (x) r)] . omega
E3 = sp.eye(3)
check(97, zero(r.cross(wo.cross(r)) - (wo * (r.T * r)[0] - r * (r.T * wo)[0]))
      and zero(wo * (r.T * r)[0] - r * (r.T * wo)[0] - ((r.T * r)[0] * E3 - r * r.T) * wo)
      and zero(((r.T * r)[0] * E3 - r * r.T) * wo - (wo.T * ((r.T * r)[0] * E3 - r * r.T)).T))
# 104: I = rho int (r^2 e - r (x) r) dV: the tensor of 97's last line
Itens = rho * ((r.T * r)[0] * E3 - r * r.T)
check(104, zero(rho * r.cross(wo.cross(r)) - Itens * wo))
# 107: I_ij = rho int [(x^2 + y^2 + z^2) delta_ij - x_i x_j] dV
check(107, zero(sp.Matrix(3, 3, lambda i, j: rho * ((x**2 + y**2 + z**2) * sp.KroneckerDelta(i, j) - r[i] * r[j]))
                - Itens))
# 110: the Cartesian entries: I_xx = rho int (y^2 + z^2), ..., I_xy = rho int xy  -- the tensor has -rho int xy
diag_ok = zero(sp.Matrix([Itens[0, 0] - rho * (y**2 + z**2), Itens[1, 1] - rho * (x**2 + z**2),
                          Itens[2, 2] - rho * (x**2 + y**2)]))
off_text = sp.Matrix([rho * x * y, rho * y * z, rho * x * z])
off_tens = sp.Matrix([Itens[0, 1], Itens[1, 2], Itens[0, 2]])
check(110, diag_ok and zero(off_tens - off_text))
assert diag_ok and zero(off_tens + off_text)               # the entries are minus the text's
# 129, 132, 135, 145: the same laws again in the Euler's-equations section
CHECKS[129] = CHECKS[66]
check(132, CHECKS[69])
check(135, CHECKS[72])
check(145, CHECKS[81])

# the intermediate axis: torque-free, one component Omega, the others small (order eps)
Om, eps = sp.symbols("Omega epsilon", positive=True)
u = [sp.Function(f"u_{k}")(t) for k in (1, 2, 3)]


def linear(axis):
    """Torque-free Euler's equations I w' = (I w) x w with w = Omega e_axis + eps u, to first order."""
    wl = sp.Matrix([Om if k == axis else 0 for k in range(3)]) + eps * sp.Matrix(u)
    rhs = Ip.inv() * (Ip * wl).cross(wl)
    return [sp.expand(sp.series(rhs[k], eps, 0, 2).removeO()) for k in range(3)]


d1 = linear(0)       # omega_1 = Omega: rates of (omega_1, omega_2, omega_3) = (Omega + eps u_1, eps u_2, eps u_3)
# 158: I11 w1' = (I22 - I33) w2 w3 ~ 0; I22 w2' = (I33 - I11) Omega w3; I33 w3' = (I11 - I22) Omega w2
check(158, sp.simplify(d1[0]) == 0 and zero(sp.Matrix([I22 * d1[1] - (I33 - I11) * Om * eps * u[2],
                                                        I33 * d1[2] - (I11 - I22) * Om * eps * u[1]])))
# 167: second derivatives from the linear system: u2'' = (I33-I11)Om/I22 * u3', u3' = (I11-I22)Om/I33 u2 ...
a2 = (I33 - I11) * Om / I22      # u2' = a2 u3
a3 = (I11 - I22) * Om / I33      # u3' = a3 u2
u2dd, u3dd = a2 * a3 * u[1], a3 * a2 * u[2]
rows167_text = [I22 * u2dd - (I33 - I11) * (I11 - I22) / I33 * Om**2 * u[1],
                I33 * u3dd - (I33 - I11) * (I11 - I22) / I33 * Om**2 * u[2]]
check(167, all(sp.simplify(q) == 0 for q in rows167_text))
assert sp.simplify(I33 * u3dd - (I33 - I11) * (I11 - I22) / I22 * Om**2 * u[2]) == 0   # I_22 in the last row
# 176: w2'' + (I11 - I33)(I11 - I22)/(I22 I33) Omega^2 w2 = 0
alpha2 = (I11 - I33) * (I11 - I22) / (I22 * I33) * Om**2
check(176, sp.simplify(u2dd + alpha2 * u[1]) == 0)
# 179: w2 = C1 sin(sqrt(alpha2) t) + C2 cos(sqrt(alpha2) t) solves it (alpha2 > 0 for I11 > I22 > I33)
C1, C2 = sp.symbols("C_1 C_2")
s2 = C1 * sp.sin(sp.sqrt(alpha2) * t) + C2 * sp.cos(sp.sqrt(alpha2) * t)
check(179, sp.simplify(s2.diff(t, 2) + alpha2 * s2) == 0)
# 184: case 2, omega_2 = Omega: w1'' = (I11 - I22)(I22 - I33)/(I11 I33) Omega^2 w1
d2 = linear(1)
b1 = sp.simplify(d2[0] / (eps * u[2]))           # u1' = b1 u3
b3 = sp.simplify(d2[2] / (eps * u[0]))           # u3' = b3 u1
alpha1 = (I11 - I22) * (I22 - I33) / (I11 * I33) * Om**2
check(184, sp.simplify(b1 * b3 - alpha1) == 0)
# 187: w1 = C1 exp(sqrt(alpha1) t) + C2 exp(-sqrt(alpha1) t) solves w1'' = alpha1 w1
s1 = C1 * sp.exp(sp.sqrt(alpha1) * t) + C2 * sp.exp(-sp.sqrt(alpha1) * t)
check(187, sp.simplify(s1.diff(t, 2) - alpha1 * s1) == 0)

# negative controls: the checks above can fail
assert not zero(rr.diff(t) - (R * rb.diff(t) + om))
assert sp.simplify(b1 * b3 + alpha1) != 0

LINES = [21, 26, 29, 36, 44, 51, 54, 63, 66, 69, 72, 81, 90, 97, 104, 107, 110, 129, 132, 135, 145, 158, 167,
         176, 179, 184, 187]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
