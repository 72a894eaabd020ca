"""Independent SymPy truth table for edinburgh-dynamics-foucault-pendulum-coriolis.tex.

The text's own setting: the Earth's frame S' (axes x', y' horizontal, z' up, right-handed) turns
with a constant angular velocity omega_E, whose vertical component at latitude phi is
omega_E sin(phi); a pendulum of length L, bob mass m, tension T ~ m g for small swings, with
omega_0^2 = g/L. Every check is built here from these definitions: Newton's law in S' from an
explicit turning frame (the position in the fixed frame differentiated twice), the cross product
from SymPy's, the swing's equations from their horizontal components, the trial solution
substituted and the quadratic solved; never from the text's later displays. Run with --write to
regenerate the table.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
t = sp.symbols("t", real=True)
m, g, L, wE, w0, al = sp.symbols("m g L omega_E omega_0 alpha", positive=True)
phi = sp.symbols("varphi", real=True)
wx, wy, wz, vx, vy, vz = sp.symbols("omega_x omega_y omega_z v_x v_y v_z", real=True)

# 30: the fixed-frame position is Q(t) r'(t), Q a turn at constant rate W about a fixed unit axis n;
# Q^T d^2(Q r')/dt^2 = a' + 2 W x v' + W x (W x r'); the display keeps the Coriolis term and leaves
# out the centrifugal one (the notes say so), so m (a' + 2 W x v') = F - m W x (W x r') ~ F.
W = sp.symbols("W", positive=True)
n = sp.Matrix([1, 2, 2]) / 3                              # a unit axis, not along any frame axis
K = sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
Q = sp.eye(3) + sp.sin(W * t) * K + (1 - sp.cos(W * t)) * K * K      # Rodrigues
rp = sp.Matrix([sp.Function(f"x{i}")(t) for i in range(3)])
aS = sp.simplify(Q.T * (Q * rp).diff(t, 2))
Wv = W * n
rhs = rp.diff(t, 2) + 2 * Wv.cross(rp.diff(t)) + Wv.cross(Wv.cross(rp))
check(30, zero(sp.simplify(aS - rhs)))

# 33: the components of omega x v
wv = sp.Matrix([wx, wy, wz])
vv = sp.Matrix([vx, vy, vz])
c = wv.cross(vv)
check(33, zero(c - sp.Matrix([wy * vz - wz * vy, wz * vx - wx * vz, wx * vy - wy * vx])))

# 36: with v_z = 0, and the k' component dropped
c0 = c.subs(vz, 0)
check(36, sp.expand(c0[0] + wz * vy) == 0 and sp.expand(c0[1] - wz * vx) == 0)

# 38: omega_z = omega_E sin(phi), v = (x', y'); the i' component is -omega_E sin(phi) dy'/dt
x = sp.Function("x")(t)
y = sp.Function("y")(t)
cc = c0.subs({wz: wE * sp.sin(phi), vx: x.diff(t), vy: y.diff(t)})
check(38, sp.simplify(cc[0] - wE * sp.sin(phi) * y.diff(t)) == 0
      and sp.simplify(cc[1] - wE * sp.sin(phi) * x.diff(t)) == 0)
assert sp.simplify(cc[0] + wE * sp.sin(phi) * y.diff(t)) == 0    # the right sign

# 40, 41: horizontal parts of m (a' + 2 omega x v') = -m g z - T r', T = m g, r' horizontal = (x, y)/L
Tn = m * g
eqx = sp.expand((m * (x.diff(t, 2) + 2 * cc[0]) + Tn * x / L) / m).subs(g, w0**2 * L)
eqy = sp.expand((m * (y.diff(t, 2) + 2 * cc[1]) + Tn * y / L) / m).subs(g, w0**2 * L)
dx = x.diff(t, 2) - 2 * wE * sp.sin(phi) * y.diff(t) + w0**2 * x
dy = y.diff(t, 2) + 2 * wE * sp.sin(phi) * x.diff(t) + w0**2 * y
check(40, sp.simplify(eqx - dx) == 0)
check(41, sp.simplify(eqy - dy) == 0)

# 44: x' = cos(alpha t), y' = sin(alpha t) in the x' equation
ans = {x: sp.cos(al * t), y: sp.sin(al * t)}
sx = sp.simplify(eqx.subs(ans).doit())
sy = sp.simplify(eqy.subs(ans).doit())
d44 = -al**2 * sp.cos(al * t) - 2 * wE * al * sp.sin(phi) * sp.cos(al * t) + w0**2 * sp.cos(al * t)
check(44, sp.simplify(sx - d44) == 0)

# 46: divided by cos(alpha t): -alpha^2 - 2 omega_E alpha sin(phi) + omega_0^2 = 0
quad = sp.simplify(sx / sp.cos(al * t))
assert sp.simplify(sy / sp.sin(al * t) - quad) == 0        # the y' equation gives the same
d46 = -al**2 - 2 * wE * sp.sin(phi) + w0
check(46, sp.simplify(quad - d46) == 0)

# 48, 50: the roots of the quadratic
a = sp.symbols("a", real=True)
q = quad.subs(al, a)
s = wE * sp.sin(phi)
r48 = [(2 * s + sg * sp.sqrt((2 * s)**2 + 4 * w0**2)) / (-2) for sg in (1, -1)]
r50 = [-s + sg * sp.sqrt(s**2 + w0**2) for sg in (1, -1)]
check(48, all(sp.simplify(q.subs(a, r)) == 0 for r in r48))
check(50, all(sp.simplify(q.subs(a, r)) == 0 for r in r50)
      and sp.simplify(sum(r48) - sum(r50)) == 0 and sp.simplify(r48[0] * r48[1] - r50[0] * r50[1]) == 0)

ROWS = {
    30: ("holds", "Newton's law in the turning frame, Q^T d^2(Q r')/dt^2 = a' + 2 omega x v' + omega x (omega x r'), with "
                  "the centrifugal term left out as the notes say (check 30)"),
    33: ("holds", "the components of omega x v in a right-handed frame (check 33)"),
    36: ("holds", "with v_z' = 0 and the k' component dropped: -omega_z' v_y' i' + omega_z' v_x' j' (check 36)"),
    38: ("typo", "with omega_z' = omega_E sin(phi) the display before gives -omega_E sin(phi) dy'/dt for the i' component; "
                 "its minus sign is lost (check 38)",
         r"\vv\omega_E\times\vv v' =-\omega_E\sin(\varphi)\dv{y'}{t}\vi' + \omega_E\sin(\varphi)\dv{x'}{t}\vj'",
         "The display before has i' component -omega_z' v_y'; putting omega_z' = omega_E sin(phi), v_y' = dy'/dt gives "
         "-omega_E sin(phi) dy'/dt. In numbers: omega = (0, 0, 1), v = (0, 2, 0) give omega x v = (0*0 - 1*2, 1*0 - 0*0, 0) "
         "= (-2, 0, 0), while the display gives +2 i'.",
         "The cross product is perpendicular to v: (-s y', s x') . (x', y') = 0 with s = omega_E sin(phi), but the display's "
         "(s y', s x') . (x', y') = 2 s x' y', not zero (x' = y' = 1: 2s). And the x' equation that follows, "
         "x'' - 2 omega_E sin(phi) y' + omega_0^2 x' = 0, needs -omega_E sin(phi) dy'/dt here (with the display's + it "
         "would read x'' + 2 omega_E sin(phi) y' + ...)."),
    40: ("holds", "x' component: x'' + 2(-omega_E sin(phi) y') + (g/L) x' = 0 with T ~ m g (check 40)"),
    41: ("holds", "y' component: y'' + 2 omega_E sin(phi) x' + (g/L) y' = 0 (check 41)"),
    44: ("holds", "x' = cos(alpha t), y' = sin(alpha t) in the x' equation: y' derivative alpha cos(alpha t) (check 44)"),
    46: ("typo", "dividing the display before by cos(alpha t) gives -alpha^2 - 2 omega_E alpha sin(phi) + omega_0^2 = 0; "
                 "the middle term has lost its alpha and omega_0 its square (check 46)",
         r"-\alpha^2 - 2\omega_E\alpha\sin(\varphi) + \omega_0^2 = 0",
         "Dividing -alpha^2 cos - 2 omega_E alpha sin(phi) cos + omega_0^2 cos = 0 by cos(alpha t) term by term keeps the alpha "
         "of the middle term and the square of omega_0. In numbers: s = omega_E sin(phi) = 0.1, omega_0 = 2, the root "
         "alpha = -0.1 + sqrt(0.01 + 4) = 1.9025 gives -3.6196 - 0.3805 + 4 = 0 in the corrected equation, but "
         "-3.6196 - 0.2 + 2 = -1.82 in the display.",
         "Units: alpha^2 is in s^-2 but 2 omega_E sin(phi) and omega_0 are in s^-1, so the display adds unlike terms. And "
         "the next display, alpha = [2s +- sqrt((2s)^2 + 4 omega_0^2)]/(-2), is the quadratic formula with a = -1, b = -2s, "
         "c = omega_0^2: the roots of the corrected equation (sum -2s, product -omega_0^2), not of the display's."),
    48: ("holds", "the quadratic formula for -alpha^2 - 2 omega_E sin(phi) alpha + omega_0^2 = 0 (check 48)"),
    50: ("holds", "the same two roots: -omega_E sin(phi) +- sqrt((omega_E sin(phi))^2 + omega_0^2) (check 50)"),
}

LINES = sorted(ROWS)


if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
