"""Independent SymPy truth table for bryanwweber-orbital-notes-time-derivatives-rotating-frame.md.

The notes' convention: capital unit vectors I, J, K are fixed in the inertial frame, lower-case
i, j, k are carried by the moving frame (or body), which turns with absolute angular velocity
Omega (omega for the body of the single-frame section). The moving frame is modelled by a rotation
R(t) = R_z(phi) R_x(theta) R_z(psi) with the three angles arbitrary functions of time; its unit
vectors are R's columns and its angular velocity is read off the skew matrix dR/dt R^T. Components
of vectors are arbitrary functions of time; the derivative "relative to the moving frame" differentiates
the moving components only.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


t = sp.Symbol('t')
phi, th, psi = (sp.Function(n)(t) for n in ('phi', 'theta', 'psi'))


R = Rz(phi) * Rx(th) * Rz(psi)
W = sp.simplify(R.diff(t) * R.T)
Om = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])          # the frame's angular velocity, inertial components
i_, j_, k_ = R[:, 0], R[:, 1], R[:, 2]
I_, J_, K_ = sp.eye(3)[:, 0], sp.eye(3)[:, 1], sp.eye(3)[:, 2]
assert zero(W + W.T)


def comps(name):
    return [sp.Function(f'{name}{c}')(t) for c in 'xyz']


# 32: a = dv/dt = sum d(v_x i)/dt over fixed unit vectors (linearity of the derivative)
vx, vy, vz = comps('v')
v = vx * I_ + vy * J_ + vz * K_
check(32, zero(v.diff(t) - ((vx * I_).diff(t) + (vy * J_).diff(t) + (vz * K_).diff(t))))
# 38: with fixed unit vectors a = (dv_x/dt) i + ...; the last member writes imath (no backslash) for the unit vector
imath = sp.Matrix(sp.symbols('imath_1:4', real=True))   # the symbol the source's \uvec{imath} renders
ax, ay, az = (c.diff(t) for c in (vx, vy, vz))
check(38, zero(v.diff(t) - (ax * I_ + ay * J_ + az * K_)) and zero(v.diff(t) - (ax * imath + ay * J_ + az * K_)))
# 48: a vector of fixed length carried by the body: A = R A0, dA/dt = omega x A
A0 = sp.Matrix(sp.symbols('A_1:4', real=True))
A = R * A0
check(48, zero(A.diff(t) - Om.cross(A)))
# 60: d^2A/dt^2 = alpha x A + omega x (omega x A), alpha = d omega/dt
alpha = Om.diff(t)
check(60, zero(A.diff(t, 2) - (alpha.cross(A) + Om.cross(Om.cross(A)))))
# 74: dB/dt in inertial components; the source writes B_Y/dt and B_Z/dt without the d of the numerator
BX, BY, BZ = comps('B')
dt = sp.Symbol('dt', positive=True)
Bin = BX * I_ + BY * J_ + BZ * K_
check(74, zero(Bin.diff(t) - (BX.diff(t) * I_ + BY / dt * J_ + BZ / dt * K_)))
# 86: the product rule for B = B_x i + B_y j + B_z k with moving unit vectors
Bx, By, Bz = comps('b')
B = Bx * i_ + By * j_ + Bz * k_
check(86, zero(B.diff(t) - (Bx.diff(t) * i_ + Bx * i_.diff(t) + By.diff(t) * j_ + By * j_.diff(t)
                            + Bz.diff(t) * k_ + Bz * k_.diff(t))))
# 92: di/dt = Omega x i and likewise
check(92, all(zero(e.diff(t) - Om.cross(e)) for e in (i_, j_, k_)))
# 98: dB/dt = (dB/dt)_rel + Omega x B
rel = lambda comp: sum((c.diff(t) * e for c, e in zip(comp, (i_, j_, k_))), sp.zeros(3, 1))  # noqa: E731
check(98, zero(B.diff(t) - (rel((Bx, By, Bz)) + Om.cross(B))))
# 104: d^2B/dt^2 = (d^2B/dt^2)_rel + Omega-dot x B + Omega x (Omega x B) + 2 Omega x (dB/dt)_rel
rel2 = sum((c.diff(t, 2) * e for c, e in zip((Bx, By, Bz), (i_, j_, k_))), sp.zeros(3, 1))
check(104, zero(B.diff(t, 2) - (rel2 + Om.diff(t).cross(B) + Om.cross(Om.cross(B))
                                  + 2 * Om.cross(rel((Bx, By, Bz))))))
# 118, 124: r = r_O + r_rel with r_rel resolved in the moving frame
rO = sp.Matrix(comps('O'))
xr, yr, zr = comps('x')
rrel = xr * i_ + yr * j_ + zr * k_
r = rO + rrel
vrel = rel((xr, yr, zr))
arel = sum((c.diff(t, 2) * e for c, e in zip((xr, yr, zr), (i_, j_, k_))), sp.zeros(3, 1))
check(118, zero(r.diff(t) - (rO.diff(t) + Om.cross(rrel) + vrel)))
# 124: the display as written, without the acceleration relative to the moving frame
assert zero(r.diff(t, 2) - (rO.diff(t, 2) + Om.diff(t).cross(rrel) + Om.cross(Om.cross(rrel)) + 2 * Om.cross(vrel) + arel))
check(124, zero(r.diff(t, 2) - (rO.diff(t, 2) + Om.diff(t).cross(rrel) + Om.cross(Om.cross(rrel)) + 2 * Om.cross(vrel))))

LINES = [14, 26, 32, 38, 48, 54, 60, 68, 74, 80, 86, 92, 98, 104, 112, 118, 124]
NC, H_ = "not a claim", "holds"
ROWS = {
    14: (NC, "the book's macro definitions (\\vector, \\uvec, \\cross) copied from its _config.yml, used by the displays"),
    26: (NC, "the velocity written in components along fixed unit vectors (recalled)"),
    32: (H_, "the derivative of a sum is the sum of the derivatives (check 32)"),
    38: ("typo",
         "with fixed unit vectors a = (dv_x/dt) i + (dv_y/dt) j + (dv_z/dt) k holds, but the last member writes "
         "\\uvec{imath} (no backslash), which sets the letters imath under the hat in place of the unit vector i (check 38)",
         "a_x \\uvec{\\imath} + a_y \\uvec{\\jmath} + a_z \\uvec{k}",
         "By hand: \\uvec{#1} is \\boldsymbol{\\hat{#1}}, so \\uvec{imath} typesets bold hat-i-m-a-t-h, a product of "
         "letters, where the other two terms have the unit vectors \\uvec{\\jmath} and \\uvec{k}; the first term's unit "
         "vector is \\uvec{\\imath} in the member before.",
         "Numbers: v = (t, 0, 0) along the fixed x axis, so a = (1, 0, 0) = 1 i-hat; the last member gives 1 times "
         "the product imath, not the unit vector i, so it is not the same vector."),
    48: (H_, "a vector carried by the rotating body, A = R A0, has dA/dt = omega x A (check 48)"),
    54: (NC, "defines the angular acceleration"),
    60: (H_, "differentiating omega x A with dA/dt = omega x A (check 60)"),
    68: (NC, "B written in inertial components"),
    74: ("typo",
         "the first term is dB_X/dt, but the second and third write B_Y/dt and B_Z/dt, each without the d of its "
         "numerator (check 74)",
         "\\frac{d\\vector{B}}{dt} = \\frac{dB_X}{dt}\\uvec{I} + \\frac{dB_Y}{dt}\\uvec{J} + \\frac{dB_Z}{dt}\\uvec{K}",
         "By hand: with I, J, K fixed, dB/dt = (dB_X/dt) I + (dB_Y/dt) J + (dB_Z/dt) K; B_Y/dt is the component "
         "divided by the differential dt, which is not its rate.",
         "Numbers: B = (0, 2 + t, 0): dB/dt = (0, 1, 0); the display's J term is B_Y/dt = (2 + t)/dt, which depends on "
         "B_Y's value (it is 2/dt at t = 0, not 1)."),
    80: (NC, "the same vector resolved along the moving frame's unit vectors"),
    86: (H_, "the product rule on each term (check 86)"),
    92: (H_, "the moving unit vectors are vectors of fixed length carried by the frame (check 92)"),
    98: (H_, "the transport theorem: the absolute rate is the relative rate plus Omega x B (check 98)"),
    104: (H_, "the second derivative: relative second rate, Omega-dot x B, the centripetal Omega x (Omega x B) and "
               "twice Omega x the relative rate (check 104)"),
    112: (NC, "the position as the moving origin's position plus the position relative to it"),
    118: (H_, "v = v_O + Omega x r_rel + v_rel, v_rel the rate relative to the moving frame (check 118)"),
    124: ("typo",
          "differentiating v = v_O + Omega x r_rel + v_rel gives a = a_O + Omega-dot x r_rel + Omega x (Omega x r_rel) "
          "+ 2 Omega x v_rel + a_rel; the display leaves out a_rel, the acceleration relative to the moving frame "
          "(check 124)",
          "\\vector{a} = \\vector{a}_O + \\dot{\\vector{\\Omega}}\\cross\\vector{r}_{\\text{rel}} + \\vector{\\Omega}\\cross\\left(\\vector{\\Omega}\\cross\\vector{r}_{\\text{rel}}\\right) + 2\\vector{\\Omega}\\cross\\vector{v}_{\\text{rel}} + \\vector{a}_{\\text{rel}}",
          "By hand: apply the page's own second-derivative formula (line 104) to B = r_rel: d^2 r_rel/dt^2 = "
          "(d^2 r_rel/dt^2)_rel + Omega-dot x r_rel + Omega x (Omega x r_rel) + 2 Omega x v_rel, and its first term "
          "is a_rel; adding a_O gives the display plus a_rel.",
          "Numbers: a frame that does not turn (Omega = 0) and does not move (a_O = 0), with P moving along its x axis "
          "as x = t^2: a = (2, 0, 0), while the display gives a_O + 0 + 0 + 0 = 0."),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
