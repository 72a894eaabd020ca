"""Independent SymPy truth table for lusk-nonlinearquad-quadrotor-model-321-euler-kinematics-dynamics.ipynb.

The notebook's convention (Beard and McLain's): passive, right-handed rotations; 3-2-1 Euler angles,
yaw psi about k^v, then pitch theta about the new j^{v1}, then roll phi about the new i^{v2}. The
inertial frame's k^i points down (the notebook does not name its axes, but its weight in body axes,
F_g = mg (-sin theta, cos theta sin phi, cos theta cos phi), and its mg k^i say so), the thrust T = (0, 0, f) acts along -k^b
(hence "F_g - T"). R_b^i, body to inertial, is R_z(psi) R_y(theta) R_x(phi) in the active elementary
matrices; the passive turns it writes, R_{v2}^b(phi) and R_{v1}^{v2}(theta), are R_x(phi)^T and
R_y(theta)^T. The body rates (p, q, r) are read off R^T dR/dt; v^b are the body components of the
inertial velocity; u_1 is the total thrust f (the first row of its mixer). The translational law is
derived from m d(R v^b)/dt = R (F_g - T), the rotational one from d(R I omega)/dt = R M.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Ry, Rz, numeric_zero, zero

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


t = sp.Symbol('t')
phi, th, psi = (sp.Function(n)(t) for n in ('phi', 'theta', 'psi'))
R = Rz(psi) * Ry(th) * Rx(phi)                            # R_b^i for the 3-2-1 sequence
W = sp.simplify(R.T * R.diff(t))                          # [omega x] in body axes
assert zero(W + W.T)
omega = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])            # (p, q, r)
rates = sp.Matrix([phi.diff(t), th.diff(t), psi.diff(t)])

# 96: rdot^i = R_b^i v^b, with v^b := R^T rdot^i the body components of the inertial velocity
rpos = sp.Matrix([sp.Function(n)(t) for n in ('x', 'y', 'z')])
vb_of_r = R.T * rpos.diff(t)
check(96, zero(R * vb_of_r - rpos.diff(t)))

# 112: omega = (phidot,0,0) + R_{v2}^b (0,thetadot,0) + R_{v2}^b R_{v1}^{v2} (0,0,psidot), the same with
# the two passive matrices written out, and = Gamma^{-1} (phidot, thetadot, psidot)
Rv2b = Rx(phi).T
Rv1v2 = Ry(th).T
row1 = (sp.Matrix([phi.diff(t), 0, 0]) + Rv2b * sp.Matrix([0, th.diff(t), 0])
        + Rv2b * Rv1v2 * sp.Matrix([0, 0, psi.diff(t)]))
Xs = sp.Matrix([[1, 0, 0], [0, sp.cos(phi), sp.sin(phi)], [0, -sp.sin(phi), sp.cos(phi)]])
Ys = sp.Matrix([[sp.cos(th), 0, -sp.sin(th)], [0, 1, 0], [sp.sin(th), 0, sp.cos(th)]])
row2 = (sp.Matrix([phi.diff(t), 0, 0]) + Xs * sp.Matrix([0, th.diff(t), 0])
        + Xs * Ys * sp.Matrix([0, 0, psi.diff(t)]))
Ginv = sp.Matrix([[1, 0, -sp.sin(th)],
                  [0, sp.cos(phi), sp.sin(phi) * sp.cos(th)],
                  [0, -sp.sin(phi), sp.cos(phi) * sp.cos(th)]])
check(112, zero(row1 - omega) and zero(row2 - omega) and zero(Ginv * rates - omega)
      and zero(Xs - Rv2b) and zero(Ys - Rv1v2))
assert zero(Ginv.det() - sp.cos(th))                      # the prose's det Gamma^{-1} = cos theta

# 152: Phidot = Gamma(phi, theta) omega with the matrix written
Gam = sp.Matrix([[1, sp.sin(phi) * sp.tan(th), sp.cos(phi) * sp.tan(th)],
                 [0, sp.cos(phi), -sp.sin(phi)],
                 [0, sp.sin(phi) * sp.sec(th), sp.cos(phi) * sp.sec(th)]])
check(152, zero(Gam * omega - rates) and zero(Gam * Ginv - sp.eye(3)))

# 184, 190: the body-axes translational law. From m d(R v)/dt = R (F_g - T):
# F_g - T = m R^T d(R v)/dt = m (vdot + omega x v), so vdot = (F_g - T)/m - omega x v.
m, g, f = sp.symbols('m g f', positive=True)
v = sp.Matrix([sp.Function(n)(t) for n in ('u', 'v', 'w')])
Fg = m * g * sp.Matrix([-sp.sin(th), sp.cos(th) * sp.sin(phi), sp.cos(th) * sp.cos(phi)])
Tb = sp.Matrix([0, 0, f])
assert numeric_zero(Fg - R.T * sp.Matrix([0, 0, m * g]), t)   # the weight in body axes (k^i down)
# Newton's law in the inertial frame, m d(R v^b)/dt = R (F_g - T), read in body axes:
# F_g - T = m R^T d(R v^b)/dt, which is m (vdot^b + omega x v^b) (R^T Rdot = [omega x])
body_law = m * (v.diff(t) + omega.cross(v))
assert numeric_zero(m * R.T * (R * v).diff(t) - body_law, t)
# the display: F_g - T = m vdot + omega x v, with F_g - T the true net force m (vdot + omega x v)
check(184, zero(body_law - (m * v.diff(t) + omega.cross(v))))
# the display: vdot = (1/m)[F_g - T - omega x v], with F_g - T = m (vdot + omega x v)
check(190, zero(v.diff(t) - (body_law - omega.cross(v)) / m))

# 204: m rddot^i = m g k^i - R_b^i (0, 0, u_1), u_1 = f: R times the true body law
net_inertial = R * (Fg - Tb)
check(204, numeric_zero(net_inertial - (m * g * sp.Matrix([0, 0, 1]) - R * sp.Matrix([0, 0, f])), t))
# and m rddot^i is indeed R times the body-axes net force m (vdot + omega x v)
assert numeric_zero(m * (R * v).diff(t) - R * body_law, t)

# 234: I omegadot = -omega x I omega + M, from d(R I omega)/dt = R M with Rdot = R [omega x]
Ix, Iy, Iz, Ixy, Ixz, Iyz = sp.symbols('I_x I_y I_z I_xy I_xz I_yz')
Ifull = sp.Matrix([[Ix, Ixy, Ixz], [Ixy, Iy, Iyz], [Ixz, Iyz, Iz]])
wb = sp.Matrix([sp.Function(n)(t) for n in ('p', 'q', 'r')])
Rt = sp.Matrix(3, 3, lambda i, j: sp.Function(f'R{i}{j}')(t))
wsk = sp.Matrix([[0, -wb[2], wb[1]], [wb[2], 0, -wb[0]], [-wb[1], wb[0], 0]])
dH = (Rt * Ifull * wb).diff(t).subs({Rt[i, j].diff(t): (Rt * wsk)[i, j] for i in range(3) for j in range(3)})
# R^T dH/dt = M is Euler's law; its body form I omegadot = M - omega x I omega is the display
check(234, zero(dH - Rt * (Ifull * wb.diff(t) + wb.cross(Ifull * wb))))

LINES = [61, 96, 112, 152, 184, 190, 204, 218, 234, 239, 258, 270]

ROWS = {
    61: ("not a claim", "the ranges assumed for roll, pitch and yaw"),
    96: ("holds", "v^b are the body components of the inertial velocity, so R_b^i v^b = rdot^i (check 96)"),
    112: ("holds", "omega = (phidot,0,0) + R_x(phi)^T (0,thetadot,0) + R_x(phi)^T R_y(theta)^T (0,0,psidot), with the passive turns written out, equals Gamma^{-1} (phidot, thetadot, psidot) = (phidot - psidot s_theta, thetadot c_phi + psidot s_phi c_theta, -thetadot s_phi + psidot c_phi c_theta), the (p, q, r) of R^T Rdot for R = R_z(psi) R_y(theta) R_x(phi) (check 112)"),
    152: ("holds", "Gamma = [[1, s_phi t_theta, c_phi t_theta], [0, c_phi, -s_phi], [0, s_phi sec_theta, c_phi sec_theta]] is the inverse of Gamma^{-1}, and Gamma (p, q, r) gives the Euler rates (check 152)"),
    184: ("typo", "the mass is missing from the transport term: m d(R v^b)/dt = R (F_g - T) gives F_g - T = m (vdot^b + omega x v^b), while the display has m vdot^b + omega x v^b (check 184)",
          "\\mathbf{F}_g - \\mathbf{T} = m\\dot{\\mathbf{v}}^b + m\\,\\mathbf{\\omega} \\times \\mathbf{v}^b",
          "A steady turn with no acceleration in body axes (vdot^b = 0): m = 2 kg, v^b = (1, 0, 0) m/s, omega = (0, 0, 1) rad/s, a circle of radius 1 m at 1 m/s. The net force must be the centripetal m v^2 / radius = 2 N along +j^b: m omega x v^b = 2 (0, 1, 0) = (0, 2, 0) N; the display gives omega x v^b = (0, 1, 0), half of it (and the mass does not enter at all).",
          "Units: F_g - T and m vdot^b are forces (kg m/s^2), while omega x v^b has units (1/s)(m/s) = m/s^2, an acceleration, so the display adds a force to an acceleration; only m omega x v^b, the transport term of Beard and McLain's m (vdot + omega x v) = f, has the units of a force."),
    190: ("typo", "solved from the true law, vdot^b = (F_g - T)/m - omega x v^b; the display divides the transport term by m too, (1/m)[F_g - T - omega x v^b] (the rearrangement of the slipped 184, itself wrong) (check 190)",
          "\\dot{\\mathbf{v}}^b = \\frac{1}{m}[\\mathbf{F}_g - \\mathbf{T}] - \\mathbf{\\omega} \\times \\mathbf{v}^b",
          "No net force (F_g - T = 0): the inertial velocity is constant, and a body spinning at omega sees its constant inertial velocity turn backwards in body axes, vdot^b = -omega x v^b, whatever the mass. With m = 2 kg, v^b = (1, 0, 0) m/s, omega = (0, 0, 1) rad/s: vdot^b = (0, -1, 0) m/s^2; the display gives -(1/2)(0, 1, 0) = (0, -0.5, 0) m/s^2, and a different value for every mass.",
          "Units: vdot^b is an acceleration (m/s^2); (F_g - T)/m is one, but (1/m) omega x v^b has units (m/s^2)/kg, so the display's bracket mixes a force with an acceleration before dividing by the mass."),
    204: ("holds", "R_b^i times the true body law: R (F_g - T) = m g k^i - R_b^i (0, 0, f) (k^i down), with u_1 = f the total thrust, and R (m (vdot + omega x v)) = m rddot^i (check 204)"),
    218: ("not a claim", "the inertial law with a drag force -diag(mu, mu, 0) rdot^i added to the model (an assumed force, after Leishman et al.)"),
    234: ("holds", "Euler's law in body axes: from d(R I omega)/dt = R M with Rdot = R [omega x], I omegadot + omega x I omega = M, that is I omegadot = -omega x I omega + M (check 234)"),
    239: ("not a claim", "the diagonal inertia matrix assumed for a quadrotor symmetric about its axes"),
    258: ("not a claim", "the mixer that defines u_1 (total thrust) and the three moments from the rotor thrusts; its signs and arms follow a figure the notebook does not give"),
    270: ("not a claim", "the rotor model: thrust proportional to the square of the propeller speed"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
