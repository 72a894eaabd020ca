"""Independent SymPy truth table for physics-se-cone-rolling-on-table-angular-velocity-contact-line.md.

The question's convention: the laboratory's z axis vertical and its y axis horizontal in the plane
of the page, the vertex O of the cone at the origin, the cone touching the table along +y; the cone's
axis x_3 = cos(alpha) y + sin(alpha) z (half-angle alpha, axis length h, the base's centre
P = h x_3) and x_2 = y x z = x out of the page, P moving at v along +x_2. The cone turns at omega_z
about the vertical (in the sense that carries P along +x_2, so its vector is -omega_z z) and at omega_3
about its own axis (vector omega_3 x_3). Rolling without slipping: every point of the contact line
is at rest, in particular the rim's contact point A = (h / cos(alpha)) y. The rates are solved from
these conditions and every display is compared with them; velocities are omega x r (O at rest).
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import zero

al = sp.symbols('alpha', positive=True)       # 0 < alpha < pi/2
h, v = sp.symbols('h v', positive=True)
wz, w3 = sp.symbols('omega_z omega_3', real=True)

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


X, Y, Z = sp.Matrix([1, 0, 0]), sp.Matrix([0, 1, 0]), sp.Matrix([0, 0, 1])
x3 = sp.cos(al) * Y + sp.sin(al) * Z
x2 = Y.cross(Z)                                # out of the page
assert x2 == X
P = h * x3
A = h / sp.cos(al) * Y                         # the rim's contact point: |OA| = h / cos(alpha)
assert zero((A - P).dot(x3))                   # A lies on the base's plane
assert zero((A - P).dot(A - P) - (h * sp.tan(al))**2)   # at the base's radius h tan(alpha)

# the angular velocity as the sum of the two turns (the vector addition of the answer's first line)
omega = -wz * Z + w3 * x3
vel = lambda r: omega.cross(r)

# the true rates: P moves at v along +x_2, A is at rest
sol = sp.solve(list(vel(P) - v * x2) + list(vel(A)), [wz, w3], dict=True)
assert len(sol) == 1
sol = sol[0]
WZ, W3 = sp.simplify(sol[wz]), sp.simplify(sol[w3])
assert zero(WZ - v / (h * sp.cos(al)))
assert zero(W3 - v / (h * sp.sin(al) * sp.cos(al)))
OMEGA = omega.subs(sol)
assert zero(OMEGA - v / (h * sp.sin(al)) * Y)  # along the contact line, of size v / (h sin alpha)
# every point of the contact line is at rest (instantaneous axis)
s = sp.symbols('s', real=True)
assert zero(OMEGA.cross(s * Y))

# line 31: omega_3 (h tan alpha) = v
check(31, zero(W3 * h * sp.tan(al) - v))
# line 36: omega_z (h cos alpha) = v
check(36, zero(WZ * h * sp.cos(al) - v))
# line 40: omega = -omega_z z + omega_3 x_3 with the rates' senses of the set-up (P carried along +x_2
# by the turn about the vertical alone, the spin leaving the axis' points in place)
check(40, zero((-wz * Z).cross(P) - wz * h * sp.cos(al) * x2) and zero((w3 * x3).cross(P)))
# line 45: the angular velocity as printed against the true one
w45 = -v / (h * sp.cos(al)) * Z + v / (h * sp.tan(al)) * (sp.cos(al) * Y + sp.sin(al) * Z)
check(45, zero(w45 - OMEGA))
# line 49: the final angular velocity as printed (the en dash read as the minus sign it stands for)
w49 = v / h * ((sp.cos(al) - 1 / sp.cos(al)) * Z + sp.cos(al)**2 / sp.sin(al) * Y)
check(49, zero(w49 - OMEGA))
# the printed steps follow from each other: 45 is 40 with the rates of 31 and 36, 49 is 45 simplified
assert zero(w45 - (-wz * Z + w3 * x3).subs({wz: v / (h * sp.cos(al)), w3: v / (h * sp.tan(al))}))
assert zero(w45 - w49)
# hand check 1 in numbers: alpha = pi/4, h = 1, v = 1
num = {al: sp.pi / 4, h: 1, v: 1}
assert zero(W3.subs(num) - 2) and zero(WZ.subs(num) - sp.sqrt(2))
assert zero(OMEGA.subs(num) - sp.Matrix([0, sp.sqrt(2), 0]))
# hand check 2: with the printed rates the rim's contact point A would move at v (1/cos^2 - 1) = v tan^2
bad = (-v / (h * sp.cos(al)) * Z + v / (h * sp.tan(al)) * x3).cross(A)
assert zero(bad - v * sp.tan(al)**2 * X)

LINES = [27, 31, 36, 40, 45, 49]

HC1_31 = ("Numbers: alpha = 45 deg, h = 1, v = 1. P is h cos(alpha) = 0.707 from the vertical through the vertex, so "
          "omega_z = 1/0.707 = 1.414; the rim's contact point A is h / cos(alpha) = 1.414 from that vertical, so the turn "
          "about it carries A at 1.414 * 1.414 = 2, and the spin must cancel that with omega_3 * (h tan alpha) = omega_3 * 1 "
          "= 2, not v = 1. Then omega = -1.414 z + 2 (0.707 y + 0.707 z) = 1.414 y, horizontal, of size v/(h sin alpha) = 1.414.")
HC2_31 = ("Instantaneous axis: the vertex and A are both at rest, so omega lies along the contact line OA, horizontal, and "
          "the distance of P from that line is h sin(alpha), so |omega| = v/(h sin alpha) and its z part is 0; the spin part "
          "omega_3 sin(alpha) must cancel omega_z = v/(h cos alpha), giving omega_3 = v/(h sin alpha cos alpha), i.e. "
          "omega_3 h tan(alpha) = v/cos^2(alpha). With omega_3 h tan(alpha) = v, A would slide at v tan^2(alpha).")

ROWS = {
    27: ("not a claim", "the rolling condition imposed: the rim's contact point A is at rest"),
    31: ("fails", "A is h/cos(alpha) from the vertical through the vertex (P only h cos(alpha)), so the turn about the "
                  "vertical carries A at omega_z h/cos(alpha) = v/cos^2(alpha), and A at rest needs omega_3 (h tan alpha) "
                  "= v/cos^2(alpha): omega_3 = v/(h sin alpha cos alpha), not v/(h tan alpha) (check 31)",
         r"\omega_3\cdot(h\cdot\tan\alpha) = \frac{v}{\cos^2\alpha}", HC1_31, HC2_31),
    36: ("holds", "P is h cos(alpha) from the vertical through the vertex and only the turn about the vertical moves "
                  "it (check 36)"),
    40: ("holds", "angular velocities of the two turns add; with x_2 = y x z out of the page and P carried along +x_2, "
                  "the turn about the vertical is -omega_z z (check 40)"),
    45: ("fails", "the sum with omega_3 = v/(h tan alpha) from the slip at line 31 carried in; the spin is "
                  "v/(h sin alpha cos alpha), and the true omega is v/(h sin alpha) y (check 45)",
         r"\vec{\omega} = \frac{-v}{h \cos\alpha}\hat{z} + \frac{v}{h \sin\alpha\cos\alpha} \left[ \cos{\left(\alpha \right)} \, \hat{y}+ \sin{\left( \alpha \right)} \, \hat{z} \right]",
         "Numbers, alpha = 45 deg, h = 1, v = 1: the printed sum is -1.414 z + 1 (0.707 y + 0.707 z) = 0.707 y - 0.707 z; "
         "the true omega is -1.414 z + 2 (0.707 y + 0.707 z) = 1.414 y.",
         "The printed omega has a vertical part; then the rim's contact point A = (h/cos alpha) y, on the table, moves "
         "at omega x A = v tan^2(alpha) along x_2 (0 only when alpha = 0), so the cone would slide at A."),
    49: ("fails", "the printed sum simplified (its steps are right; the en dash stands for a minus): it carries the "
                  "slip of line 31; the cone's angular velocity is v/(h sin alpha) y, along the contact line (check 49)",
         r"\vec{\omega} = \frac{v}{h \sin\alpha}\hat{y}",
         "Numbers, alpha = 45 deg, h = 1, v = 1: the printed (cos - 1/cos) = 0.707 - 1.414 = -0.707 gives a z part -0.707 "
         "and a y part 0.5/0.707 = 0.707; the true omega is 1.414 y with no z part.",
         "Small alpha (a thin cone rolling about its vertex): the true |omega| = v/(h sin alpha) grows like v/(h alpha), "
         "the spin of a thin needle; the printed y part cos^2(alpha)/sin(alpha) v/h matches it to leading order, but the "
         "printed z part -v sin^2(alpha)/(h cos alpha) is not 0, and for alpha = 45 deg the printed size is v/h, not 1.414 v/h."),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
