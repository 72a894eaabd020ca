"""Independent SymPy truth table for verga-polytech-rolling-cone-angular-momentum-fr.ipynb.

The notebook's own setting: a solid homogeneous cone of mass M, height h and base radius a, apex O
at the origin, axis of symmetry z; its half-angle alpha has tan(alpha) = a / h. The moments are
computed here from the volume integrals (r dr dphi dz, r from 0 to a z / h), about the centre of
mass at distance R from the apex.

Rolling: the cone lies on the fixed plane XY (Z up), touching it along the segment OA at angle psi
from X; its axis rises at the angle alpha above OA. Body frame: z the axis, x in the plane OAz
perpendicular to z (towards OA), y = z x x. The motion is built from psi(t) alone: the rotation
matrix of the body is assembled from these vectors, the angular velocity is the vector of
dR/dt R^T, and rolling without slipping is the contact segment at rest, so no relation of the text is
assumed. The text writes speeds and rates as magnitudes with psi-dot > 0 (omega > 0 along n = OA
direction), which is the sense checked.

Rotation: the Euler construction of the text, R = R_Z(phi) R_x(theta) R_z(psi) (z-x-z), with
theta-dot = 0; the frame 2 is R_Z(phi) R_x(theta). The angular momentum of a symmetric body with
I_x = I_y = I and I_z about a point of its axis, L = R diag(I, I, I_z) Omega_body, and its rate in
the fixed frame, expressed in frame 2. A display's line is the notebook file's line of its first row.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


z0 = truth_table.zero

M, h, a = sp.symbols('M h a', positive=True)
r, ph, z = sp.symbols('r phi z', real=True)


def over_cone(f):
    """The integral of f over the cone's volume, r dr dphi dz."""
    return sp.integrate(sp.integrate(sp.integrate(r * f, (ph, 0, 2 * sp.pi)), (r, 0, a * z / h)), (z, 0, h))


rho = M / over_cone(1)
R = sp.simplify(rho * over_cone(z) / M)
Ix = sp.simplify(rho * over_cone(r**2 * sp.sin(ph)**2 + (z - R)**2))
Iy = sp.simplify(rho * over_cone(r**2 * sp.cos(ph)**2 + (z - R)**2))
Iz = sp.simplify(rho * over_cone(r**2))

# 49: I_x = I_y = 3M/20 (a^2 + h^2/4), I_z = 3M/10 a^2 (about the centre of mass)
check(49, z0(Ix - sp.Rational(3, 20) * M * (a**2 + h**2 / 4)) and z0(Iy - Ix) and z0(Iz - sp.Rational(3, 10) * M * a**2))
# 51: R = 3h/4
check(51, z0(R - 3 * h / 4))

# -- rolling ----------------------------------------------------------------------------------
t = sp.symbols('t', real=True)
al = sp.symbols('alpha', positive=True)          # 0 < alpha < pi/2
psi = sp.Function('psi')(t)
Zh = sp.Matrix([0, 0, 1])
u = sp.Matrix([sp.cos(psi), sp.sin(psi), 0])     # along OA, in the plane
ez = sp.cos(al) * u + sp.sin(al) * Zh            # the cone's axis
ex = sp.sin(al) * u - sp.cos(al) * Zh            # in the plane OAz, perpendicular to z, towards OA
ey = ez.cross(ex)
F = sp.Matrix.hstack(ex, ey, ez)                 # the text's frame (x, y, z) -> fixed
chi = sp.Function('chi')(t)                      # the cone's turn about its own axis


def rz(q):
    return sp.Matrix([[sp.cos(q), -sp.sin(q), 0], [sp.sin(q), sp.cos(q), 0], [0, 0, 1]])


Rb = F * rz(chi)                                 # body -> fixed
S = Rb.diff(t) * Rb.T
Om_fixed = sp.simplify(sp.Matrix([S[2, 1], S[0, 2], S[1, 0]]))
# rolling without slipping: the contact segment OA, every point s u, is at rest; that fixes chi-dot
s_ = sp.symbols('s', positive=True)
cd = sp.symbols('chidot')
sol = sp.solve(list(Om_fixed.subs(sp.Derivative(chi, t), cd).cross(s_ * u)), cd, dict=True)
assert len(sol) == 1
Om_fixed = sp.simplify(Om_fixed.subs(sp.Derivative(chi, t), sol[0][cd]))
assert z0(sp.simplify(Om_fixed.cross(s_ * u)))
Om_body = sp.simplify(F.T * Om_fixed)            # components along the text's (x, y, z)
Rc = sp.symbols('R', positive=True)              # the centre's distance, a symbol here
cm = Rc * ez
V = sp.simplify(cm.diff(t))
assert z0(sp.simplify(V - Om_fixed.cross(cm)))   # the centre moves as a point of the body
pd = sp.symbols('psidot', positive=True)
# speeds compared through their squares: both sides are positive for 0 < alpha < pi/2, psi-dot > 0
V2 = sp.simplify(V.dot(V)).subs(sp.Derivative(psi, t), pd)
# 74: V = psi-dot R cos(alpha)
check(74, z0(sp.simplify(V2 - (pd * Rc * sp.cos(al))**2)))
# 77: R omega sin(alpha) = V, omega = psi-dot cot(alpha): |Omega| and the distance of the centre from OA
om2 = sp.simplify(Om_body.dot(Om_body)).subs(sp.Derivative(psi, t), pd)
dist2 = sp.simplify(cm.cross(u).dot(cm.cross(u)))  # squared distance of the centre from the axis OA
check(77, z0(sp.simplify(Rc**2 * om2 * sp.sin(al)**2 - V2)) and z0(sp.simplify(om2 - (pd * sp.cot(al))**2))
      and z0(sp.simplify(dist2 - (Rc * sp.sin(al))**2)))
# 80: Omega = (omega sin(alpha), 0, omega cos(alpha)): along n = OA, in body components
n_body = sp.simplify(F.T * u)
omega_signed = sp.simplify(Om_body.dot(n_body))
check(80, z0(sp.simplify(n_body - sp.Matrix([sp.sin(al), 0, sp.cos(al)])))
      and z0(sp.simplify(Om_body - omega_signed * n_body)))
# the sense: psi-dot > 0 turns the cone so that Omega points along -OA; the text's magnitudes take
# omega > 0 along n, i.e. psi measured the other way round: |omega| = psi-dot cot(alpha) either way
assert z0(sp.simplify(omega_signed.subs(sp.Derivative(psi, t), pd)**2 - (pd * sp.cot(al))**2))
Om_text = sp.Matrix([pd * sp.cos(al), 0, pd * sp.cos(al)**2 / sp.sin(al)])
# 82: Omega = (psi-dot cos(alpha), 0, psi-dot cos^2(alpha)/sin(alpha)) = omega n with omega = psi-dot cot(alpha)
check(82, z0(sp.simplify(Om_text - pd * sp.cot(al) * sp.Matrix([sp.sin(al), 0, sp.cos(al)]))))
# 93: L = (I_x Omega_x, I_y Omega_y, I_z Omega_z) with the moments of line 49 and Omega of line 82
L_true = sp.Matrix([Ix * Om_text[0], Iy * Om_text[1], Iz * Om_text[2]])
L_text = sp.Matrix([pd * sp.Rational(3, 20) * M * (Rc**2 + h**2 / 4) * sp.cos(al), 0,
                    pd * sp.Rational(3, 10) * M * Rc**2 * sp.cot(al) * sp.cos(al)])
L_fixed = sp.Matrix([pd * sp.Rational(3, 20) * M * (a**2 + h**2 / 4) * sp.cos(al), 0,
                     pd * sp.Rational(3, 10) * M * a**2 * sp.cot(al) * sp.cos(al)])
assert z0(sp.simplify(L_fixed - L_true))
check(93, z0(sp.simplify((L_text - L_true).subs(Rc, R))))

# 110, 115, 120: the Euler construction, x1 = R_Z(phi) X, ..., a definition (not a claim)

# -- rotation with theta-dot = 0 ----------------------------------------------------------------
phi_, psi_ = sp.Function('phi')(t), sp.Function('psi')(t)
th = sp.symbols('theta', real=True)              # constant


def rx(q):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(q), -sp.sin(q)], [0, sp.sin(q), sp.cos(q)]])


R2 = rz(phi_) * rx(th)                           # frame 2 -> fixed
Rfull = R2 * rz(psi_)                            # body -> fixed
W = sp.simplify(Rfull.diff(t) * Rfull.T)
Om_f = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
Om_2 = sp.simplify(R2.T * Om_f)                  # in frame 2
dph, dps = sp.Derivative(phi_, t), sp.Derivative(psi_, t)
e2 = sp.eye(3)
# 137: Omega = phi-dot sin(theta) y2 + (psi-dot + phi-dot cos(theta)) z2
check(137, z0(sp.simplify(Om_2 - (dph * sp.sin(th) * e2[:, 1] + (dps + dph * sp.cos(th)) * e2[:, 2]))))
I, Izs = sp.symbols('I I_z', positive=True)
Ibody = sp.diag(I, I, Izs)
Om_b = sp.simplify(Rfull.T * Om_f)
L_f = sp.simplify(Rfull * Ibody * Om_b)          # in the fixed frame
L_2 = sp.simplify(R2.T * L_f)
# 141: L = I phi-dot sin(theta) y2 + (I psi-dot + I_z phi-dot cos(theta)) z2
check(141, z0(sp.simplify(L_2 - (I * dph * sp.sin(th) * e2[:, 1] + (I * dps + Izs * dph * sp.cos(th)) * e2[:, 2]))))
assert z0(sp.simplify(L_2 - (I * dph * sp.sin(th) * e2[:, 1] + Izs * (dps + dph * sp.cos(th)) * e2[:, 2])))
# 145: dL/dt (the rate in the fixed frame, in frame 2 components)
dL_2 = sp.simplify(R2.T * L_f.diff(t))
ddph, ddps = sp.Derivative(phi_, (t, 2)), sp.Derivative(psi_, (t, 2))
dL_text = ((Izs - I) * dph * sp.sin(th) * (dps + dph * sp.cos(th)) * e2[:, 0]
           + I * ddps * sp.sin(th) * e2[:, 1] + Izs * (ddps + ddph * sp.cos(th)) * e2[:, 2])
check(145, z0(sp.simplify(dL_2 - dL_text)))
dL_right = ((Izs * (dps + dph * sp.cos(th)) - I * dph * sp.cos(th)) * dph * sp.sin(th) * e2[:, 0]
            + I * ddph * sp.sin(th) * e2[:, 1] + Izs * (ddps + ddph * sp.cos(th)) * e2[:, 2])
assert z0(sp.simplify(dL_2 - dL_right))
# the text's x2 row is what the body's Omega, not the frame's rotation phi-dot Z, crossed with L gives
assert z0(sp.simplify((Om_2.cross(L_2))[0] - (Izs - I) * dph * sp.sin(th) * (dps + dph * sp.cos(th))))

LINES = [49, 51, 74, 77, 80, 82, 93, 110, 115, 120, 137, 141, 145]
assert LINES == truth_table.notebook_display_lines(
    __file__.removesuffix("_truth.py") + ".ipynb")

ROWS = {
    49: ("holds", "the solid cone about its centre of mass: I_x = I_y = 3M/20 (a^2 + h^2/4), I_z = 3 M a^2/10, from the volume integrals (check 49)"),
    51: ("holds", "the centre of mass lies at 3h/4 from the apex on the axis (check 51)"),
    74: ("holds", "the centre, at R along the axis risen by alpha, turns about Z on a circle of radius R cos(alpha) at the rate psi-dot (check 74)"),
    77: ("holds", "rolling without slipping makes OA the instantaneous axis; the centre's distance from OA is R sin(alpha), so |Omega| R sin(alpha) = V and |Omega| = psi-dot cot(alpha) (check 77)"),
    80: ("holds", "Omega lies along OA, whose body components are (sin(alpha), 0, cos(alpha)) with x in the plane OAz (check 80)"),
    82: ("holds", "omega = psi-dot cot(alpha) put into (omega sin(alpha), 0, omega cos(alpha)) (check 82)"),
    93: ("typo", "L = (I_x Omega_x, 0, I_z Omega_z) with the moments of the text's line 49 has a^2, the base radius squared, where the display writes R^2, the squared distance of the centre of mass (R = 3h/4), in both rows (check 93)",
         "\\bm L = \\begin{pmatrix} \\dot\\psi\\frac{3M}{20} \\bigg(a^2 + \\frac{h^2}{4} \\bigg) \\cos \\alpha \\\\ 0 \\\\ \\dot \\psi \\frac{3M}{10} a^2 \\cot \\alpha \\cos \\alpha \\end{pmatrix}",
         "I_x Omega_x = 3M/20 (a^2 + h^2/4) psi-dot cos(alpha) and I_z Omega_z = 3M/10 a^2 psi-dot cos^2(alpha)/sin(alpha) = 3M/10 a^2 psi-dot cot(alpha) cos(alpha): the moments of line 49 hold a, the base radius, never R.",
         "With a = 1, h = 2 (so R = 3/2), M = 1, psi-dot = 1, alpha = pi/4: the x row is 3/20 (1 + 1) 0.7071 = 0.2121, the display's 3/20 (2.25 + 1) 0.7071 = 0.3447; the z row 0.3 x 1 x 0.7071 = 0.2121 against 0.3 x 2.25 x 0.7071 = 0.4773. The notation of Landau and Lifshitz, where R is the base radius, is the likely source."),
    110: ("not a claim", "defines the first intermediate frame of the Euler construction, x1 = R_Z(phi) X, y1 = R_Z(phi) Y"),
    115: ("not a claim", "defines the second intermediate frame, y2 = R_x1(theta) y1, z2 = R_x1(theta) z1"),
    120: ("not a claim", "defines the body frame by the spin psi about z"),
    137: ("holds", "with theta-dot = 0 the angular velocity phi-dot Z + psi-dot z has the frame-2 components (0, phi-dot sin(theta), psi-dot + phi-dot cos(theta)) (check 137)"),
    141: ("typo", "L = diag(I, I, I_z) Omega in frame 2 gives I_z (psi-dot + phi-dot cos(theta)) along z2: the display's I psi-dot should be I_z psi-dot (check 141)",
          "\\bm L = I\\dot\\phi \\sin \\theta \\hat{\\bm y}_2 + I_z(\\dot\\psi + \\dot\\phi \\cos \\theta) \\hat{\\bm z}_2",
          "Omega has z2 component psi-dot + phi-dot cos(theta) and the moment about the axis is I_z, so L_z2 = I_z psi-dot + I_z phi-dot cos(theta); the display mixes I psi-dot with I_z phi-dot cos(theta).",
          "A pure spin (phi-dot = 0, psi-dot = 1) about the axis of a body with I = 2, I_z = 1: the angular momentum is 1 along z2 (I_z times the spin), the display gives 2. The notebook's own code computes L2 = I2 o2 with I2 = diag(I_1, I_1, I_3), which has I_3 psi-dot."),
    145: ("fails", "the rate of L in the fixed frame, in frame-2 components, is ((I_z (psi-dot + phi-dot cos(theta)) - I phi-dot cos(theta)) phi-dot sin(theta), I phi-double-dot sin(theta), I_z (psi-double-dot + phi-double-dot cos(theta))): frame 2 turns at phi-dot Z only, while the display's x2 row crosses the body's whole Omega with L, adding -I phi-dot psi-dot sin(theta), and its y2 row has psi-double-dot for phi-double-dot (check 145)",
          "",
          "Frame 2 rotates at phi-dot Z = phi-dot (sin(theta) y2 + cos(theta) z2) (theta fixed), and L = (0, I phi-dot s, I_z (psi-dot + phi-dot c)); the x2 row of that rotation crossed with L is phi-dot s I_z (psi-dot + phi-dot c) - phi-dot c I phi-dot s, while Omega x L, with Omega's z2 row psi-dot + phi-dot c, gives (I_z - I) phi-dot s (psi-dot + phi-dot c): they differ by I phi-dot psi-dot s. The y2 row: d/dt of I phi-dot s is I phi-double-dot s, and the rotation adds nothing there.",
          "A symmetric top in steady precession with I = 2, I_z = 1, theta = pi/2, phi-dot = 1, psi-dot = 3: the rate of L is horizontal with x2 row (1 x (3 + 0) - 0) x 1 = 3; the display gives (1 - 2) x 1 x 3 = -3. With phi-double-dot = 0 and psi-double-dot = 1 the display's y2 row is 2, the true one 0."),
}


if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
