"""Independent SymPy truth table for game-physics-notes-collision-impulse-relative-velocity-zh.md.

The page's convention: bodies A and B meet at the contact point P; n is the unit normal from B to A;
r_a = P - C_a, r_b = P - C_b; A receives the impulse j n and B receives -j n (Newton's third law); a
body's velocity changes by its impulse over its mass and its angular velocity by its inverse inertia
tensor times the impulse's moment about its centre of mass, r x J (the inertia tensor does not change
during the instant of the collision). The inverse inertia tensors are general symmetric matrices.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


def nzero(expr):
    return truth_table.numeric_zero(expr, t)


def vec(name):
    return sp.Matrix(sp.symbols(f'{name}_1:4', real=True))


def sym(name):
    return sp.Matrix(3, 3, lambda i, j: sp.Symbol(f'{name}{min(i, j)}{max(i, j)}', real=True))


def dot(a, b):
    return (a.T * b)[0]


# 34, 35: the velocity of the contact point as a point of a rigid body: P = C + R s, dP/dt = v + omega x (P - C)
t = sp.Symbol('t')
phi, th, psi = (sp.Function(n)(t) for n in ('phi', 'theta', 'psi'))


R = Rz(phi) * Rx(th) * Rz(psi)
W = R.diff(t) * R.T
om = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
C = sp.Matrix([sp.Function(f'C{k}')(t) for k in 'xyz'])
s = vec('s')
P = C + R * s
check(34, nzero(P.diff(t) - (C.diff(t) + om.cross(P - C))))
check(35, CHECKS[34])   # the same statement for body B

# the collision
ma, mb, j, e = sp.symbols('m_a m_b j e', positive=True)
va, vb, wa, wb, ra, rb = (vec(n) for n in ('va', 'vb', 'wa', 'wb', 'ra', 'rb'))
Ka, Kb = sym('Ka'), sym('Kb')            # I_a^-1, I_b^-1
n1, n2 = sp.symbols('nu1 nu2', real=True)
n = sp.Matrix([sp.sin(n1) * sp.cos(n2), sp.sin(n1) * sp.sin(n2), sp.cos(n1)])   # a unit normal
Ja, Jb = j * n, -j * n
dva, dvb = Ja / ma, Jb / mb
dwa, dwb = Ka * ra.cross(Ja), Kb * rb.cross(Jb)
# 31: the definition of the relative velocity; 45: Newton's law of restitution, a model: not claims
# 54, 55, 58, 59: the impulse's effect, as the page writes each
check(54, zero(dva - j * n / ma))
check(55, zero(dwa - Ka * ra.cross(j * n)))
check(58, zero(dvb - (-(j * n) / mb)))
check(59, zero(dwb - Kb * rb.cross(-j * n)))
vrel_m = (va + wa.cross(ra)) - (vb + wb.cross(rb))
vap, vbp, wap, wbp = va + dva, vb + dvb, wa + dwa, wb + dwb
vrel_p = (vap + wap.cross(ra)) - (vbp + wbp.cross(rb))
# 64: the relative velocity after the collision, the definition applied to the new velocities
check(64, nzero(vrel_p - ((vap + wap.cross(ra)) - (vbp + wbp.cross(rb)))))
# 67: substituting v+ = v- + dv
check(67, nzero(vrel_p - (vrel_m + (j * n / ma + (Ka * ra.cross(j * n)).cross(ra))
                         - (-(j * n) / mb + (Kb * rb.cross(-j * n)).cross(rb)))))
# 70: the bracket adds the numbers 1/m_a + 1/m_b to vectors; read as adding them to each component
ones = sp.ones(3, 1)
text70 = vrel_m + j * ((1 / ma + 1 / mb) * ones + (Ka * ra.cross(n)).cross(ra) + (Kb * rb.cross(n)).cross(rb))
check(70, nzero(vrel_p - text70))
right70 = vrel_m + j * ((1 / ma + 1 / mb) * n + (Ka * ra.cross(n)).cross(ra) + (Kb * rb.cross(n)).cross(rb))
assert nzero(vrel_p - right70)
# 73: dotting with the unit n and using the restitution law v+ . n = -e v- . n
dn = dot(vrel_m, n) + j * (1 / ma + 1 / mb + dot((Ka * ra.cross(n)).cross(ra), n)
                           + dot((Kb * rb.cross(n)).cross(rb), n))
check(73, nzero(dot(vrel_p, n) - dn))
# 79: solving the restitution law for j
jsol = sp.solve(sp.Eq(sp.expand(dot(vrel_p, n)), sp.expand(-e * dot(vrel_m, n))), j)
text79 = -(1 + e) * dot(vrel_m, n) / (1 / ma + 1 / mb + dot((Ka * ra.cross(n)).cross(ra), n)
                                        + dot((Kb * rb.cross(n)).cross(rb), n))
check(79, len(jsol) == 1 and nzero(jsol[0] - text79))

LINES = [31, 34, 35, 45, 54, 55, 58, 59, 64, 67, 70, 73, 79]
NC, H_ = "not a claim", "holds"
ROWS = {
    31: (NC, "defines the relative velocity at the contact point"),
    34: (H_, "the velocity of a point of a rigid body: v + omega x r, r from the centre of mass (check 34)"),
    35: (H_, "the same for body B (check 35)"),
    45: (NC, "Newton's law of restitution, the model of the collision"),
    54: (H_, "the impulse j n over A's mass (check 54)"),
    55: (H_, "A's angular momentum changes by r_a x j n, and I_a does not change in the instant (check 55)"),
    58: (H_, "B receives -j n (check 58)"),
    59: (H_, "B's angular momentum changes by r_b x (-j n) (check 59)"),
    64: (H_, "the relative velocity's definition applied to the velocities after the collision (check 64)"),
    67: (H_, "substituting v+ = v- + dv and omega+ = omega- + d omega (check 67)"),
    70: ("typo",
         "taking j out of j n/m_a + j n/m_b leaves (1/m_a + 1/m_b) n, a vector along the normal; the bracket writes the "
         "number 1/m_a + 1/m_b added to the two vectors of the angular terms, the n after it dropped (the next display, "
         "dotted with n, writes 1/m_a + 1/m_b because n . n = 1) (check 70)",
         "\\mathbf{v}_{rel}^+ = \\mathbf{v}_{rel}^- + j \\left[ \\left(\\frac{1}{m_a} + \\frac{1}{m_b}\\right)\\mathbf{n} + (\\mathbf{I}_a^{-1}(\\mathbf{r}_a \\times \\mathbf{n})) \\times \\mathbf{r}_a + (\\mathbf{I}_b^{-1}(\\mathbf{r}_b \\times \\mathbf{n})) \\times \\mathbf{r}_b \\right]",
         "By hand: the display before has j n/m_a - (-j n/m_b) = j (1/m_a + 1/m_b) n; every other term in the bracket "
         "is a vector (a cross product), so the mass term must be the vector (1/m_a + 1/m_b) n; the number "
         "1/m_a + 1/m_b alone cannot be added to them.",
         "Numbers: an impulse through both centres (r_a = r_b = 0), m_a = m_b = 1, j = 1, n = (0, 0, 1), v_rel- = 0: "
         "v_rel+ = (0, 0, 2); the display gives 0 + 1 [2], the number 2 (read on each component, (2, 2, 2)), not "
         "(0, 0, 2)."),
    73: (H_, "the previous relation with (1/m_a + 1/m_b) n, dotted with the unit normal, and the law of restitution "
              "(check 73)"),
    79: (H_, "solving the last relation for j (check 79)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
