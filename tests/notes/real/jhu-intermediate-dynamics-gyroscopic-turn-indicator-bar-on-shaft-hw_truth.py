"""Independent SymPy truth table for jhu-intermediate-dynamics-gyroscopic-turn-indicator-bar-on-shaft-hw.tex.

The solutions' conventions. Exercise 5.26: x along the shaft, x'y'z' along the bar, turned through theta
about z by the matrix R the text gives (components in x'y'z' are R times components in xyz); the bar is a
thin rod along x' (centroidal moments 0, m L^2/12, m L^2/12) and C lies L/6 from the centroid along x'. The
bar turns with the shaft at the constant rate Omega about x; its angular momentum about C is I_C omega.
Exercise 6.8: the vehicle turns at Omega_2 about the fixed vertical k; the gimbal frame x'y'z' is turned from
the vehicle's frame through beta about y = y', so that its orientation is R_z(psi) R_y(-beta) with
psi-dot = Omega_2 and the fixed k has gimbal components (sin beta, 0, cos beta); the flywheel spins at
Omega_1 about -i' (R_x(-phi) after the gimbal, phi-dot = Omega_1). Its moments about its centre are I_1
about the spin axis x' and I_2 across it; the spring's restoring torque -k beta about the beta axis (-j')
is +k beta along j'.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Ry, Rz

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


def vee(W):
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


t = sp.Symbol('t')
# ---- exercise 5.26 ----
th, Om, m, Lb = sp.symbols('theta Omega m L', positive=True)
R = sp.Matrix([[sp.cos(-th), sp.sin(-th), 0], [-sp.sin(-th), sp.cos(-th), 0], [0, 0, 1]])   # as the text gives it
w_bar = R * sp.Matrix([Om, 0, 0])
check(42, zero(w_bar - sp.Matrix([Om * sp.cos(th), Om * sp.sin(th), 0])))
IG = sp.diag(0, m * Lb**2 / 12, m * Lb**2 / 12)
d = sp.Matrix([Lb / 6, 0, 0])
Ipat = m * (d.dot(d) * sp.eye(3) - d * d.T)
check(71, zero(Ipat - m * sp.diag(0, Lb**2 / 36, Lb**2 / 36)))
IC = IG + Ipat
check(76, zero(IC - m * sp.diag(0, Lb**2 / 9, Lb**2 / 9)))
H_bar = IC * w_bar
check(82, zero(H_bar - sp.Matrix([0, m * Lb**2 * Om * sp.sin(th) / 9, 0])))
# the bar's axes in the fixed frame turn with the shaft: Q(t) = R_x(Omega t) R^T; H is fixed in the bar's frame
Q = Rx(Om * t) * R.T
Hdot_bar = sp.simplify(Q.T * (Q * H_bar).diff(t))
want = sp.Matrix([0, 0, m * Lb**2 * Om**2 * sp.cos(th) * sp.sin(th) / 9])
check(88, zero(Hdot_bar - want))
check(93, zero(Hdot_bar - (sp.zeros(3, 1) + w_bar.cross(H_bar))))
check(96, zero(Hdot_bar - want))
# ---- exercise 6.8 ----
I1, I2, kk = sp.symbols('I_1 I_2 k', positive=True)
beta, psi = sp.Function('beta')(t), sp.Function('psi')(t)
Om1 = sp.Symbol('Omega_1', positive=True)                 # held constant by the servomotor
Om2 = psi.diff(t)
Rg = Rz(psi) * Ry(-beta)
Rf = Rg * Rx(-Om1 * t)
wg_in = vee(sp.simplify(Rg.diff(t) * Rg.T))               # the gimbal frame's rate, fixed components
wf_in = vee(sp.simplify(Rf.diff(t) * Rf.T))               # the flywheel's rate, fixed components
to_g = lambda v: sp.simplify(Rg.T * v)                    # noqa: E731  components in the gimbal frame
kdisp = sp.Matrix([[sp.cos(beta), 0, sp.sin(beta)], [0, 1, 0], [-sp.sin(beta), 0, sp.cos(beta)]]) * sp.Matrix([0, 0, 1])
check(126, zero(kdisp - sp.Matrix([sp.sin(beta), 0, sp.cos(beta)]))
      and zero(to_g(sp.Matrix([0, 0, 1])) - sp.Matrix([sp.sin(beta), 0, sp.cos(beta)])))
bd = beta.diff(t)
w_g = to_g(wf_in)
w_shown = sp.Matrix([sp.sin(beta) * Om2 - Om1, -bd, sp.cos(beta) * Om2])
check(131, zero(w_g - (Om2 * sp.Matrix([sp.sin(beta), 0, sp.cos(beta)]) - bd * sp.Matrix([0, 1, 0])
                       - Om1 * sp.Matrix([1, 0, 0]))))
check(137, zero(w_g - w_shown))
alpha_g = to_g(wf_in.diff(t))
Om2d = Om2.diff(t)
alpha_shown = sp.Matrix([Om2d * sp.sin(beta) + Om2 * bd * sp.cos(beta),     # the source's "+," read as +
                         -beta.diff(t, 2) - Om1 * Om2 * sp.cos(beta),
                         Om2d * sp.cos(beta) - Om2 * bd * sp.sin(beta) - Om1 * bd])
check(161, zero(alpha_g - alpha_shown))
# 170: the Euler equation about the y axis for a body with principal moments I_xx, I_yy, I_zz and body rates w
Ixx, Iyy, Izz = sp.symbols('I_xx I_yy I_zz', positive=True)
wb = sp.Matrix([sp.Function(f'w{c}')(t) for c in 'xyz'])
Mb = sp.diag(Ixx, Iyy, Izz) * wb.diff(t) + wb.cross(sp.diag(Ixx, Iyy, Izz) * wb)
check(170, zero(Mb[1] - (Iyy * wb[1].diff(t) + (Izz - Ixx) * wb[0] * wb[2])))
check(175, zero(to_g(wg_in) - sp.Matrix([Om2 * sp.sin(beta), -bd, Om2 * sp.cos(beta)])))
# 194: the gimbal axis component of dH/dt, H = I w about the flywheel's centre, must equal the spring's k beta
Ifly = Rg * sp.diag(I1, I2, I2) * Rg.T
H_in = Ifly * wf_in
My = sp.simplify(to_g(H_in.diff(t))[1])
rhs = (sp.cos(beta) * sp.sin(beta) * Om2**2 * (I1 - I2) - I2 * beta.diff(t, 2) - I2 * Om1 * sp.cos(beta) * Om2)
check(194, zero(My - rhs))
assert zero(My - ((I1 - I2) * Om2**2 * sp.sin(beta) * sp.cos(beta) - I2 * beta.diff(t, 2)
                  - I1 * Om1 * Om2 * sp.cos(beta)))

LINES = [34, 38, 42, 49, 59, 67, 71, 76, 82, 88, 93, 96, 115, 119, 124, 126, 131, 137, 146, 151, 161, 170, 175,
         184, 194]
NC, H_ = "not a claim", "holds"
ROWS = {
    34: (NC, "the rotation matrix from the shaft's frame to the bar's (a definition)"),
    38: (NC, "the bar turns with the shaft: omega = Omega i (given)"),
    42: (H_, "R (Omega, 0, 0) = (Omega cos theta, Omega sin theta, 0) in the bar's frame (check 42)"),
    49: (NC, "the thin bar's centroidal moments, quoted from the textbook's appendix"),
    59: (NC, "the same moments written as the inertia tensor"),
    67: (NC, "the offset of C from the centroid, read from the figure"),
    71: (H_, "the parallel-axis term m(d^2 1 - d d^T) for d = (L/6, 0, 0) (check 71)"),
    76: (H_, "I_C = I_G + I_pat = m diag(0, L^2/9, L^2/9), since 1/12 + 1/36 = 1/9 (check 76)"),
    82: (H_, "H_C = I_C omega = (1/9) m L^2 Omega sin(theta) j'; the source's ',\\sin' is a stray comma for a "
              "thin space (check 82)"),
    88: (H_, "the momentum, fixed in the bar, turns with the shaft: its rate is (1/9) m L^2 Omega^2 cos(theta) "
              "sin(theta) k' (check 88)"),
    93: (H_, "the transport theorem with no rate relative to the bar: dH/dt = omega x H (check 93)"),
    96: (H_, "omega x H written out: only the k' component, (1/9) m L^2 Omega^2 cos(theta) sin(theta) (check 96)"),
    115: (NC, "the angular velocity as the sum of the simple rotation rates (the rule stated)"),
    119: (NC, "the three rates of the turn indicator read from the figure: Omega_2 about k, beta-dot about -j', "
               "Omega_1 about -i'"),
    124: (NC, "the rotation matrix the solution uses to carry k into the gimbal frame (a definition)"),
    126: (H_, "R(-beta) (0, 0, 1) = (sin beta, 0, cos beta): the fixed vertical in the gimbal frame (check 126)"),
    131: (H_, "the angular velocity with k substituted (check 131)"),
    137: (H_, "the same, component by component: (sin(beta) Omega_2 - Omega_1, -beta-dot, cos(beta) Omega_2) "
               "(check 137)"),
    146: (NC, "the rule for the angular acceleration of a sum of simple rates, stated"),
    151: (NC, "the terms of the sum: each simple rate, its own derivative and the rate that turns its axis"),
    161: (H_, "the flywheel's angular acceleration in the gimbal frame; the source's '+,' in the first row is a "
               "stray comma after the plus (check 161)"),
    170: ("typo",
          "Euler's equation about the y axis is M_y = I_yy alpha_y + (I_xx - I_zz) omega_x omega_z; the display "
          "writes the difference of moments the other way round (check 170)",
          "\\sum \\bar{M}_{cg} \\ j' = k \\beta = I_{yy} \\alpha_y + \\left( I_{xx} - I_{zz} \\right) \\omega_x \\omega_z",
          "By hand: dL/dt + omega x L = M in principal axes; the y component of omega x (I omega) is "
          "omega_z I_xx omega_x - omega_x I_zz omega_z = (I_xx - I_zz) omega_x omega_z, so "
          "M_y = I_yy omega-dot_y + (I_xx - I_zz) omega_x omega_z.",
          "Numbers: I_xx = 1, I_yy = 2, I_zz = 3, torque-free, omega = (1, 0, 1) at an instant: L = (1, 0, 3), "
          "(omega x L)_y = 1*1 - 1*3 = -2, so 2 omega-dot_y = 2 and omega-dot_y = 1; the true law gives "
          "M_y = 2*1 + (1 - 3)*1 = 0, the display gives 2*1 + (3 - 1)*1 = 4."),
    175: (H_, "the gimbal frame's own rate, Omega_2 k - beta-dot j' = (Omega_2 sin beta, -beta-dot, Omega_2 cos beta) "
               "(check 175)"),
    184: (NC, "the flywheel's moments: I_1 about the spin axis, I_2 across it"),
    194: ("fails",
          "the gimbal-axis component of the flywheel's dH/dt is (I_1 - I_2) Omega_2^2 sin(beta) cos(beta) - I_2 "
          "beta-ddot - I_1 Omega_1 Omega_2 cos(beta); the display has I_2 in the gyroscopic term, where the spin "
          "momentum I_1 Omega_1 belongs (check 194)",
          "",
          "By hand: in the gimbal frame H = (I_1 omega_x, I_2 omega_y, I_2 omega_z) with the flywheel's rates "
          "omega = (Omega_2 sin(beta) - Omega_1, -beta-dot, Omega_2 cos(beta)); the frame turns at "
          "Omega_f = (Omega_2 sin(beta), -beta-dot, Omega_2 cos(beta)), so (dH/dt)_y = I_2 omega-dot_y + Omega_f,z H_x "
          "- Omega_f,x H_z = -I_2 beta-ddot + I_1 Omega_2 cos(beta) (Omega_2 sin(beta) - Omega_1) - I_2 Omega_2^2 "
          "sin(beta) cos(beta); the Omega_1 term carries I_1.",
          "Numbers: I_1 = 2, I_2 = 1, beta = 0 held (beta-dot = beta-ddot = 0), Omega_1 = 10, Omega_2 = 1: the "
          "gimbal needs the torque -I_1 Omega_1 Omega_2 = -20 along j' to hold beta = 0 (the spin momentum "
          "I_1 Omega_1 = 20 turning at Omega_2 = 1), while the display's right side gives -I_2 Omega_1 Omega_2 = -10."),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
