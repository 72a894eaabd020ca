"""Independent SymPy truth table for maithripala-rolling-disk-gimbal-312-313.ipynb.

The notebook's own setting: frames b = e R with active (counter-clockwise) single-axis rotations
R_1, R_2, R_3 (the notes' definition: R_3(t) = [[cos, -sin, 0], [sin, cos, 0], [0, 0, 1]]), body
angular velocity hat(Omega) = R^T Rdot. Particles of mass m_i at X_i in b, b's origin at o.
Rolling disk: 3-1-2 angles R = R_3(theta) R_1(alpha) R_2(phi), the disk's axis the second body
axis, radius r, centre at height r cos(alpha), inertia diag(I_i, I_r, I_i). Gimbal: 3-1-3 angles
R = R_3(theta_1) R_1(theta_2) R_3(theta_3). Every check is built here from these definitions.
A display's line is the notebook file's line of its first row.
"""
import sys
import json
import pathlib
import sympy as sp

import truth_table

CHECKS = {}
def check(key, ok):
    CHECKS[key] = bool(ok)

def R1(a):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])
def R2(a):
    return sp.Matrix([[sp.cos(a), 0, sp.sin(a)], [0, 1, 0], [-sp.sin(a), 0, sp.cos(a)]])
def R3(a):
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])
def hat(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
def vee(M):
    return sp.Matrix([M[2, 1], M[0, 2], M[1, 0]])
def z(M):
    return sp.simplify(M) == (sp.zeros(*M.shape) if hasattr(M, 'shape') else 0)

# --- kinetic energy of a rigid body: particle i at o + R X_i, velocity odot + R hat(Omega) X_i
mi = sp.symbols('m_i', positive=True)
od = sp.Matrix(sp.symbols('odot_1:4', real=True))
Om = sp.Matrix(sp.symbols('Omega_1:4', real=True))
Xi = sp.Matrix(sp.symbols('X_1:4', real=True))
q = sp.symbols('q1:4', real=True)
Rn = R3(q[0]) * R1(q[1]) * R3(q[2])        # any rotation matrix
v = od + Rn * hat(Om) * Xi
Ii = mi * ((Xi.T * Xi)[0] * sp.eye(3) - Xi * Xi.T)
KEi = sp.Rational(1, 2) * mi * (v.T * v)[0]
# 29: KE_i = 1/2(m|odot|^2 + 2 m_i odot^T R hat(Omega) X_i + Omega^T I_i Omega), m read as the particle's m_i
check(29, z(KEi - sp.Rational(1, 2) * (mi * (od.T * od)[0] + 2 * mi * (od.T * Rn * hat(Om) * Xi)[0] + (Om.T * Ii * Om)[0])))
# 34: I_i := m_i(|X_i|^2 I - X_i X_i^T) defines the particle's inertia: not a claim
# 38: the sum over two particles (linearity in m_i X_i; M = sum m_i, M Xbar = sum m_i X_i)
m2 = sp.symbols('m_2', positive=True)
X2 = sp.Matrix(sp.symbols('Y_1:4', real=True))
M = mi + m2
Xbar = (mi * Xi + m2 * X2) / M
I_tot = Ii + m2 * ((X2.T * X2)[0] * sp.eye(3) - X2 * X2.T)
v2 = od + Rn * hat(Om) * X2
KE_sum = KEi + sp.Rational(1, 2) * m2 * (v2.T * v2)[0]
check(38, z(KE_sum - sp.Rational(1, 2) * (M * (od.T * od)[0] + 2 * M * (od.T * Rn * hat(Om) * Xbar)[0] + (Om.T * I_tot * Om)[0])))
# 44: with b's origin at the centre of mass (Xbar = 0) the cross term vanishes
check(44, z((KE_sum - sp.Rational(1, 2) * (M * (od.T * od)[0] + (Om.T * I_tot * Om)[0])).subs(
    dict(zip(X2, -mi / m2 * Xi)))))
# 51: dKE/dt with M oddot = f and I Omegadot = I Omega x Omega + T (symmetric I)
t = sp.symbols('t')
Ic = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f'J{min(i, j)}{max(i, j)}'))
odt = sp.Matrix([sp.Function(f'o{k}')(t) for k in range(3)]).diff(t)
Omt = sp.Matrix([sp.Function(f'W{k}')(t) for k in range(3)])
Mm = sp.symbols('M', positive=True)
fe = sp.Matrix(sp.symbols('f1:4')); Te = sp.Matrix(sp.symbols('T1:4'))
KEt = sp.Rational(1, 2) * (Mm * (odt.T * odt)[0] + (Omt.T * Ic * Omt)[0])
dKE = KEt.diff(t)
subs_eom = {**{odt[k].diff(t): fe[k] / Mm for k in range(3)},
            **{Omt[k].diff(t): (Ic.inv() * ((Ic * Omt).cross(Omt) + Te))[k] for k in range(3)}}
check(51, z(dKE.subs(subs_eom) - ((odt.T * fe)[0] + (Omt.T * Te)[0]))
      and z(dKE - (Mm * (odt.T * odt.diff(t))[0] + (Omt.T * Ic * Omt.diff(t))[0])))
# --- rolling disk, 3-1-2 angles
th, al, ph = [sp.Function(n)(t) for n in ('theta', 'alpha', 'phi')]
Rd = R3(th) * R1(al) * R2(ph)
c, s = sp.cos, sp.sin
Rd_text = sp.Matrix([[c(th) * c(ph) - s(th) * s(al) * s(ph), -s(th) * c(al), c(th) * s(ph) + s(th) * s(al) * c(ph)],
                     [s(th) * c(ph) + c(th) * s(al) * s(ph), c(th) * c(al), s(th) * s(ph) - c(th) * s(al) * c(ph)],
                     [-c(al) * s(ph), s(al), c(al) * c(ph)]])
check(77, z(Rd_text - Rd))
Omd = vee(sp.simplify(Rd.T * Rd.diff(t)))
Omd_text = sp.Matrix([al.diff(t) * c(ph) - th.diff(t) * c(al) * s(ph), ph.diff(t) - th.diff(t) * s(al),
                      th.diff(t) * c(al) * c(ph) + al.diff(t) * s(ph)])
check(85, z(Omd_text - Omd))
Omd_fix = sp.Matrix([Omd_text[0], ph.diff(t) + th.diff(t) * s(al), Omd_text[2]])
assert z(Omd_fix - Omd)      # the sign of theta-dot sin(alpha) in Omega_2 repairs it
# 92: the centre's height above the floor is r times the vertical extent of the disk's plane,
# sqrt(1 - (b_2 . e_3)^2) = cos(alpha): its rate is -r alphadot sin(alpha)
r = sp.symbols('r', positive=True)
b2 = Rd[:, 1]
check(92, z(1 - b2[2] ** 2 - c(al) ** 2) and z((r * c(al)).diff(t) + r * al.diff(t) * s(al)))
# 97: KE = 1/2(M|odot|^2 + I Omega . Omega) written out
Ii_, Ir = sp.symbols('I_i I_r', positive=True)
x, y = sp.Function('x')(t), sp.Function('y')(t)
odisk = sp.Matrix([x.diff(t), y.diff(t), -r * al.diff(t) * s(al)])
Idisk = sp.diag(Ii_, Ir, Ii_)
KEd = sp.Rational(1, 2) * (Mm * (odisk.T * odisk)[0] + (Omd.T * Idisk * Omd)[0])
KEd_text = sp.Rational(1, 2) * (Mm * x.diff(t) ** 2 + Mm * y.diff(t) ** 2 + Ir * ph.diff(t) ** 2
                                + (Ii_ + Mm * r ** 2 * s(al) ** 2) * al.diff(t) ** 2
                                + (Ii_ * c(al) ** 2 + Ir * s(al) ** 2) * th.diff(t) ** 2
                                - 2 * Ir * ph.diff(t) * th.diff(t) * s(al))
check(97, z(KEd - KEd_text))
assert z(KEd - KEd_text - 2 * Ir * ph.diff(t) * th.diff(t) * s(al))   # +2 I_r phidot thetadot sin(alpha) repairs it
# --- gimbal, 3-1-3 angles
q1, q2, q3 = sp.symbols('theta_1 theta_2 theta_3', real=True)
Rg = R3(q1) * R1(q2) * R3(q3)
c1, c2, c3, s1, s2, s3 = c(q1), c(q2), c(q3), s(q1), s(q2), s(q3)
Rg_text = sp.Matrix([[c1 * c3 - c2 * s1 * s3, c2 * c3 * s1 + c1 * s3, s1 * s2],
                     [-c3 * s1 - c1 * c2 * s3, c1 * c2 * c3 - s1 * s3, c1 * s2],
                     [s2 * s3, -c3 * s2, c2]])
# 112: T^u = [T_1 T_2 T_3]^T names the components: not a claim
# 119: the 3-1-3 matrix as written
check(119, z(Rg_text - Rg))
assert z(Rg_text - Rg.subs({q1: -q1, q2: -q2, q3: -q3}, simultaneous=True))   # what it is: all angles negated
# 131, 138, 145: the moments on the gimbals and the disc, named in their frames: not claims
# 153: massless gimbals: each gimbal's moments balance (the modelling assumption): not a claim
u1, u2, u3 = sp.symbols('u_1 u_2 u_3')
T12, T22, T13 = sp.symbols('T^1_2 T^2_2 T^3_1')
T32 = sp.symbols('T^3_2')
# moments as vectors in e: e T^1, b T^2 = e R3(q1) T^2, c T^3 = e R3(q1) R1(q2) T^3, d T^u = e Rg T^u
Tu = sp.Matrix(sp.symbols('Tu1:4'))
T3v = R3(q3) * Tu                                   # c T^3 = d T^u  =>  T^3 = R3(q3) T^u
T2v = -R1(q2) * T3v                                 # b T^2 = -c T^3
T1v = -R3(q1) * T2v                                 # e T^1 = -b T^2
# 157: T^1 = -R3(q1) T^2, T^2 = -R1(q2) T^3, T^3 = R3(q3) T^u (the balances written in e)
check(157, z(R3(q1) * T2v + T1v) and z(R3(q1) * (R1(q2) * T3v + T2v)) and z(R3(q1) * R1(q2) * (R3(q3) * Tu - T3v)))
# 161: T^1 = R3 R1 R3 T^u = R T^u
check(161, z(T1v - Rg * Tu))
# 166: with T^2 = [u2, T^2_2, -u1] and T^3 = [-u2, T^3_2, u3]: [u2, T^2_2, -u1] = R1(q2)[u2, -T^3_2, -u3]
T2s = sp.Matrix([u2, T22, -u1]); T3s = sp.Matrix([-u2, T32, u3])
claim166 = T2s - R1(q2) * sp.Matrix([u2, -T32, -u3])
check(166, z(claim166 - (T2s + R1(q2) * T3s)))      # the same equation as the balance T^2 = -R1(q2) T^3
# 176: the last row solved for T^3_2
sol32 = sp.solve((T2s + R1(q2) * T3s)[2], T32)[0]
check(176, z(sol32 - (u1 - c2 * u3) / s2))
# 180, 202: T^u = R3^T T^3 written as a product, then multiplied out
T3full = sp.Matrix([-u2, sol32, u3])
Tu_sol = R3(q3).T * T3full
prod = sp.Matrix([[c3, s3, 0], [-s3, c3, 0], [0, 0, 1]]) * sp.Matrix([[0, -1, 0], [1 / s2, 0, -sp.cot(q2)], [0, 0, 1]])
uu = sp.Matrix([u1, u2, u3])
check(180, z(Tu_sol - prod * uu) and z(R3(q3).T * sp.Matrix([-u2, (u1 - c2 * u3) / s2, u3]) - Tu_sol))
final = sp.Matrix([[s3 / s2, -c3, -s3 * sp.cot(q2)], [c3 / s2, s3, -c3 * sp.cot(q2)], [0, 0, 1]])
check(202, z(final * uu - Tu_sol))
# negative controls
assert not z(Rg_text - Rg.T)
assert not z(Omd_text - vee(sp.simplify(Rd * Rd.diff(t).T)))

KEYS = [29, 34, 38, 44, 51, 77, 85, 92, 97, 112, 119, 131, 138, 145, 153, 157, 161, 166, 176, 180, 202]

def display_lines(path):
    """The notebook file's line of each display's first row (its Markdown cells, in order)."""
    text = pathlib.Path(path).read_text()
    lines, offset = [], 0
    for cell in json.loads(text)['cells']:
        if cell['cell_type'] != 'markdown':
            continue
        for piece in cell['source']:
            at = text.find(json.dumps(piece, ensure_ascii=False), offset)
            offset = at + 1
            if piece.startswith('\\begin{align'):
                lines.append(text.count('\n', 0, at) + 1)
    return lines

if __name__ == "__main__":
    here = pathlib.Path(__file__)
    assert display_lines(here.with_name('maithripala-rolling-disk-gimbal-312-313.ipynb')) == KEYS
    sys.exit(truth_table.compare(__file__, CHECKS, KEYS))
