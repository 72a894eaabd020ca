"""Independent SymPy truth table for unlam-analytical-mechanics-euler-equations-misaligned-gear-zxz.ipynb.

The text's own setting. First notebook: the z-x-z Euler angles of Landau (phi about Z, theta about
the line of nodes, psi about x_3), the body axes x_i along the principal axes with moments I_i, the
body components Omega_i of the angular velocity, T = sum I_i Omega_i^2 / 2, torques tau_i on the body
axes. Second notebook: a gear on a shaft turning at omega about the bench axis Z; the gear's axes
x, y, z are the bench's axes X, Y, Z turned by theta about X; bearings at A (r = d_GA Z from the
gear's centre G) and B (r = -d_GB Z) with reactions (A_X, A_Y, A_Z) and (B_X, B_Y, 0).

The body angular velocity is derived from R^T dR/dt with R = R_z(phi) R_x(theta) R_z(psi), Euler's
equations from dL/dt + Omega x L = tau with L = I Omega, the frame change from the rotation matrix
about X, and the torque from r x F; never from the text's displays. SymPy only.
"""
import pathlib
import sys
import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = CHECKS.get(key, True) and bool(ok)


t = sp.symbols('t', real=True)
ph, th, ps = [sp.Function(n)(t) for n in ('varphi', 'theta', 'psi')]
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)


def rot(axis, a):
    c, s = sp.cos(a), sp.sin(a)
    if axis == 'x':
        return sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])
    return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


# ---- 32: body components of the angular velocity for the z-x-z angles
R = rot('z', ph) * rot('x', th) * rot('z', ps)
S = sp.simplify(R.T * R.diff(t))
Om = sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])
dph, dth, dps = ph.diff(t), th.diff(t), ps.diff(t)
Om_text = sp.Matrix([dph * sp.sin(th) * sp.sin(ps) + dth * sp.cos(ps),
                     dph * sp.sin(th) * sp.cos(ps) - dth * sp.sin(ps),
                     dph * sp.cos(th) + dps])
check(32, truth_table.zero(Om - Om_text))
assert not truth_table.zero(Om - sp.Matrix([Om_text[1], Om_text[0], Om_text[2]]))

# ---- 65: the kinetic energy of rotation in the principal axes
O1, O2, O3 = sp.symbols('Omega_1:4', real=True)
Ov = sp.Matrix([O1, O2, O3])
T_O = (Ov.T * sp.diag(I1, I2, I3) * Ov)[0] / 2
check(65, sp.expand(T_O - (I1 * O1 ** 2 + I2 * O2 ** 2 + I3 * O3 ** 2) / 2) == 0)

# ---- 85, 93, 110, 124: Lagrange's equation for psi through the components Omega_i
q = sp.symbols('q_phi q_theta q_psi')
qd = sp.symbols('qd_phi qd_theta qd_psi')
to_sym = {dph: qd[0], dth: qd[1], dps: qd[2]}
to_sym2 = {ph: q[0], th: q[1], ps: q[2]}
Om_sym = Om_text.subs(to_sym).subs(to_sym2)
T_q = T_O.subs(dict(zip((O1, O2, O3), Om_sym)))
back = {q[0]: ph, q[1]: th, q[2]: ps, qd[0]: dph, qd[1]: dth, qd[2]: dps}
EL_direct = sp.diff(T_q, qd[2]).subs(back).diff(t) - sp.diff(T_q, q[2]).subs(back)
dT_dO = [sp.diff(T_O, o) for o in (O1, O2, O3)]
on_q = dict(zip((O1, O2, O3), Om_sym))
chain = (sum(dT_dO[i].subs(on_q) * sp.diff(Om_sym[i], qd[2]) for i in range(3)).subs(back).diff(t)
         - sum(dT_dO[i].subs(on_q) * sp.diff(Om_sym[i], q[2]) for i in range(3)).subs(back))
check(85, truth_table.zero(EL_direct - chain))
dO_dpsi = [sp.diff(Om_sym[i], q[2]) for i in range(3)]
check(93, truth_table.zero(sp.Matrix(dO_dpsi) - sp.Matrix([Om_sym[1], -Om_sym[0], 0])))
check(110, truth_table.zero(sp.Matrix([sp.diff(Om_sym[i], qd[2]) for i in range(3)]) - sp.Matrix([0, 0, 1])))
Om_t = Om_text
written = (I3 * Om_t[2]).diff(t) - (I1 * Om_t[0] * Om_t[1] + I2 * Om_t[1] * (-Om_t[0]))
euler3 = I3 * Om_t[2].diff(t) - (I1 - I2) * Om_t[0] * Om_t[1]
check(124, truth_table.zero(EL_direct - written) and truth_table.zero(written - euler3))

# ---- 152, 162, 196, 210: Euler's equations with torque from dL/dt + Omega x L = tau
W = sp.Matrix([sp.Function(f'W_{i}')(t) for i in (1, 2, 3)])
tau = sp.Matrix(sp.symbols('tau_1:4', real=True))
L = sp.diag(I1, I2, I3) * W
lhs = L.diff(t) + W.cross(L)                       # = tau
text_sys = sp.Matrix([I1 * W[0].diff(t) - (I2 - I3) * W[1] * W[2],
                      I2 * W[1].diff(t) - (I3 - I1) * W[2] * W[0],
                      I3 * W[2].diff(t) - (I1 - I2) * W[0] * W[1]])
euler_ok = truth_table.zero(lhs - text_sys)
cyc_ok = all(truth_table.zero(text_sys[i] - (sp.diag(I1, I2, I3)[i, i] * W[i].diff(t)
                                             - (sp.diag(I1, I2, I3)[j, j] - sp.diag(I1, I2, I3)[k, k]) * W[j] * W[k]))
             for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1)))
for key in (152, 162, 196, 210):
    check(key, euler_ok and cyc_ok)
assert not truth_table.zero(lhs - sp.Matrix([I1 * W[0].diff(t) - (I3 - I2) * W[1] * W[2], text_sys[1], text_sys[2]]))

# ---- 236, 268: the gear's axes are the bench's axes turned by theta about X; their unit vectors
# in bench components are the columns of R_x(theta)
a = sp.symbols('theta', real=True)
Rx = rot('x', a)
xh, yh, zh = Rx[:, 0], Rx[:, 1], Rx[:, 2]
Xh, Yh, Zh = sp.eye(3)[:, 0], sp.eye(3)[:, 1], sp.eye(3)[:, 2]
check(236, truth_table.zero(Zh - (sp.cos(a) * zh + sp.sin(a) * yh)))
check(268, truth_table.zero(Xh - xh) and truth_table.zero(Yh - (sp.cos(a) * yh - sp.sin(a) * zh)))
assert not truth_table.zero(Zh - (sp.cos(a) * zh - sp.sin(a) * yh))

# ---- 250, 281: the torque about G of the bearing reactions, on the bench's axes and the gear's
dA, dB = sp.symbols('d_GA d_GB', positive=True)
AX, AY, AZ, BX, BY = sp.symbols('A_X A_Y A_Z B_X B_Y', real=True)
FA = AX * Xh + AY * Yh + AZ * Zh
FB = BX * Xh + BY * Yh
tauG = (dA * Zh).cross(FA) + (-dB * Zh).cross(FB)
steps = [(dA * Zh).cross(AX * Xh) + (dA * Zh).cross(AY * Yh) + (-dB * Zh).cross(BX * Xh) + (-dB * Zh).cross(BY * Yh),
         dA * AX * Yh - dA * AY * Xh - dB * BX * Yh + dB * BY * Xh,
         (-dA * AY + dB * BY) * Xh + (dA * AX - dB * BX) * Yh]
check(250, all(truth_table.zero(tauG - s_) for s_ in steps))
tau_xyz = Rx.T * tauG                               # components on the gear's axes
written281 = (-dA * AY + dB * BY) * Xh + (dA * AX - dB * BX) * (sp.cos(a) * Yh - sp.sin(a) * Zh)
check(281, truth_table.zero(tau_xyz - written281))

KEYS = [32, 65, 77, 85, 93, 110, 124, 143, 152, 162, 196, 210, 236, 250, 268, 281, 300]
here = pathlib.Path(__file__)
assert truth_table.notebook_display_lines(here.with_name('unlam-analytical-mechanics-euler-equations-misaligned-gear-zxz.ipynb')) == KEYS
LINES = KEYS

ROWS = {
    32: ("holds", "the body components of the angular velocity for the z-x-z angles (phi about Z, theta about the line of nodes, psi about x_3), from R^T dR/dt with R = R_z(phi) R_x(theta) R_z(psi) (check 32)"),
    65: ("holds", "the kinetic energy of rotation in the principal axes, Omega . I Omega / 2 with I diagonal (check 65)"),
    77: ("not a claim", "states Lagrange's equation for psi with no torque, the starting point of the derivation"),
    85: ("holds", "the chain rule through the components Omega_i turns d/dt dT/d psi-dot - dT/d psi into the written sums (check 85)"),
    93: ("holds", "d Omega_1/d psi = Omega_2, d Omega_2/d psi = -Omega_1, d Omega_3/d psi = 0 (check 93)"),
    110: ("holds", "d Omega_i/d psi-dot = (0, 0, 1) (check 110)"),
    124: ("holds", "with dT/d Omega_i = I_i Omega_i the sums give d(I_3 Omega_3)/dt - (I_1 - I_2) Omega_1 Omega_2, Euler's third equation (check 124)"),
    143: ("not a claim", "states Lagrange's equation with a generalised force Q_i"),
    152: ("holds", "Euler's equations with torque in the principal axes, from dL/dt + Omega x L = tau with L_i = I_i Omega_i, (i, j, k) cyclic (check 152)"),
    162: ("holds", "the three equations of the system, (1, 2, 3) and its cyclic shifts (check 162)"),
    196: ("holds", "the same equation as before, for the gear (check 196)"),
    210: ("holds", "Euler's equations with torque on the gear's axes x, y, z (check 210)"),
    236: ("holds", "the gear's axes are the bench's turned by theta about X (y = cos Y + sin Z, z = -sin Y + cos Z), so Z = cos theta z + sin theta y (check 236)"),
    250: ("holds", "the torque about G of the bearing reactions, r_GA = d_GA Z and r_GB = -d_GB Z, term by term (check 250)"),
    268: ("holds", "X = x and Y = cos theta y - sin theta z for the same turn about X (check 268)"),
    281: ("holds", "the torque's components on the gear's axes, by putting X and Y in the gear's unit vectors (check 281)"),
    300: ("not a claim", "Newton's second law for the gear on the bench axes with the accelerations of its centre set to zero, the notebook's model (weight along -Y)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
