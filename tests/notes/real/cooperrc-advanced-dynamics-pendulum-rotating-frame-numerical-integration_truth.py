"""Independent SymPy truth table for cooperrc-advanced-dynamics-pendulum-rotating-frame-numerical-integration.md.

A point mass m on a massless rod of length l hangs from a pivot carried by an arm that turns at the
constant rate Omega about the vertical k axis; the pivot sits at (a cos Omega t, a sin Omega t, a).
The pendulum swings in the vertical plane that holds the arm; theta is measured from the downward
vertical, positive outward (the geometry of the notebook's code cell, x1 = cos(w t)(a + l sin theta),
z1 = a - l cos theta). Gravity g acts along -k. The equation of motion is derived by Lagrange's
equation from these positions; the Euler-method lines are checked by exact arithmetic.

Run as a program it compares its verdicts with the .truth.toml (with --write it first writes the table).
"""
import sys

import sympy as sp

import truth_table

t = sp.symbols('t')
th = sp.Function('theta')(t)
thd, thdd = th.diff(t), th.diff(t, 2)
m, g, l, a, Om = sp.symbols('m g l a Omega', positive=True)
R = sp.Rational

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def zero(e):
    return sp.simplify(sp.expand_trig(sp.expand(e))) == 0


def eom(r):
    """theta-double-dot from Lagrange's equation for a point mass at r(t) under gravity along -k."""
    v = r.diff(t)
    L = m * v.dot(v) / 2 - m * g * r[2]
    EL = sp.expand(L.diff(thd).diff(t) - L.diff(th))
    return sp.solve(EL, thdd)[0]


# --- line 20: the equation of motion in the rotating frame -------------------------------------
radial = a + l * sp.sin(th)
r_true = sp.Matrix([radial * sp.cos(Om * t), radial * sp.sin(Om * t), a - l * sp.cos(th)])
thdd_true = eom(r_true)
printed20 = (Om ** 2 * sp.cos(th) - g / l) * sp.sin(th) + a * Om ** 2 / l * sp.cos(th)
check(20, zero(thdd_true - printed20))

# --- Euler's method (lines 46, 50, 54) ----------------------------------------------------------
yi, yn, dt = sp.symbols('y_i y_ip1 Delta_t')
# line 50: line 46 solved for y_{i+1}
check(50, zero(sp.solve(sp.Eq((yn - yi) / dt, -2 * yi), yn)[0] - (yi - 2 * yi * dt)))
# line 54: one step from y(0) = 2 with Delta t = 0.1 (the page's values)
step = (yi - 2 * yi * dt).subs({yi: 2, dt: R(1, 10)})
check(54, step == R(18, 10))
assert step == R(16, 10)                       # the correction: 2 - 2(2)(0.1) = 1.6
assert 2 - 2 * R(1, 10) == R(18, 10)           # the printed arithmetic itself is right; the y_0 is missing
# the page's exact value beside it: y(0.1) = 2 e^{-0.2} = 1.637
assert abs(sp.N(2 * sp.exp(-R(2, 10))) - 1.6375) < 1e-4

# --- line 67: the rate of the state [theta, theta-dot] --------------------------------------------
ybar = sp.Matrix([th, thd])
check(67, ybar.diff(t) == sp.Matrix([thd, thdd]))

# --- line 85: the frame at rest, small angles, released from rest at pi/6 (the code's start) ------
Om0 = sp.expand(printed20.subs(Om, 0))
lin = Om0.subs(sp.sin(th), th)                 # sin theta ~ theta
x = sp.Function('x')
sol = sp.dsolve(sp.Eq(x(t).diff(t, 2), lin.subs(th, x(t))), x(t),
                ics={x(0): sp.pi / 6, x(t).diff(t).subs(t, 0): 0}).rhs
check(85, zero(sol - sp.pi / 6 * sp.cos(sp.sqrt(g / l) * t)))

# --- line 91: the 3D position of the pendulum's end, with x_2 = l sin theta, y_2 = l cos theta -----
x2, y2 = l * sp.sin(th), l * sp.cos(th)
r_printed = sp.Matrix([(a + y2) * sp.cos(Om * t), (a + y2) * sp.sin(Om * t), a - x2])
check(91, zero((r_printed - r_true).norm() ** 2) or zero(eom(r_printed) - printed20))
# the correction, x_2 and y_2 in each other's places, is the code cell's position and gives line 20
r_corr = sp.Matrix([(a + x2) * sp.cos(Om * t), (a + x2) * sp.sin(Om * t), a - y2])
assert zero((r_corr - r_true).norm() ** 2) and zero(eom(r_corr) - printed20)
# what the printed kinematics give instead (the why of line 91)
assert zero(l * eom(r_printed) - (g * sp.cos(th) - Om ** 2 * (a + l * sp.cos(th)) * sp.sin(th)))
# hand checks: at theta = 0 the printed point is level with the pivot, l further out, not below it
assert r_printed.subs(th, 0) == sp.Matrix([(a + l) * sp.cos(Om * t), (a + l) * sp.sin(Om * t), a])
# with the frame at rest the printed kinematics give theta-double-dot = g/l at theta = 0, not 0
assert sp.simplify(eom(r_printed).subs(Om, 0).subs(th, 0)) == g / l
assert sp.simplify(printed20.subs(Om, 0).subs(th, 0)) == 0

LINES = [20, 38, 42, 46, 50, 54, 63, 67, 71, 85, 91, 93, 94]

ROWS = {
    20: ("holds", "Lagrange's equation for a point mass at radius a + l sin(theta) from the axis and height "
                  "a - l cos(theta), T = m/2 (l^2 thetadot^2 + Omega^2 (a + l sin theta)^2), V = m g (a - l cos theta), "
                  "gives l thetadot-dot = Omega^2 (a + l sin theta) cos theta - g sin theta, the printed form (check 20)"),
    38: ("not a claim", "the model equation the Euler method is shown on"),
    42: ("not a claim", "the approximation made: the derivative replaced by a ratio of finite steps"),
    46: ("not a claim", "the forward Euler scheme, the right side taken at step i (a definition)"),
    50: ("holds", "line 46 solved for y_{i+1} (check 50)"),
    54: ("typo", "one Euler step from y(0) = 2 with Delta t = 0.1 is y_0 - 2 y_0 Delta t = 2 - 2(2)(0.1) = 1.6; "
                 "the printed step drops the factor y_0 = 2 in the decrement (its arithmetic 2 - 0.2 = 1.8 is right, "
                 "the substitution is not); the exact y(0.1) = 2 e^{-0.2} = 1.637 the page quotes lies between (check 54)",
         "y(\\Delta t) = 2 - 2(2)(0.1) = 1.6",
         "Line 49 with y_i = y_0 = 2 and Delta t = 0.1: 2 y_i Delta t = 2 x 2 x 0.1 = 0.4, so y_1 = 2 - 0.4 = 1.6, not 1.8.",
         "Slope at the start: dy/dt(0) = -2 y(0) = -4, so one step of 0.1 along it drops y by 0.4 to 1.6; the printed "
         "drop of 0.2 is the slope -2 = -2y of y = 1, not of y = 2. (The exact 2 e^{-0.2} = 1.637 lies 0.037 above "
         "1.6, the O(Delta t^2) error 2 x (2 x 0.1)^2 / 2 = 0.04 of one step.)"),
    63: ("not a claim", "defines the state vector"),
    67: ("holds", "the time derivative of [theta, thetadot] component by component (check 67)"),
    71: ("not a claim", "schematic: the second-order equation recast as the integrator's first-order form"),
    85: ("holds", "with the frame at rest (Omega = 0) and sin theta ~ theta, line 20 is thetadot-dot = -(g/l) theta; "
                  "released from rest at pi/6, the angle the notebook's code starts from, theta = pi/6 cos(sqrt(g/l) t) "
                  "(check 85). The notebook's sentence before it says theta(0) = pi/12, which disagrees with its code "
                  "and with this curve; that slip is in the prose, not in the display"),
    91: ("typo", "with x_2 = l sin(theta) and y_2 = l cos(theta) (lines 93, 94) the printed point lies a + l cos(theta) "
                 "from the axis at height a - l sin(theta): x_2 and y_2 are in each other's places. The pendulum of "
                 "line 20, and the notebook's code (x1 = cos(w t)(a + l sin theta), z1 = a - l cos theta), have radius "
                 "a + x_2 and height a - y_2; the printed kinematics give l thetadot-dot = g cos theta - Omega^2 "
                 "(a + l cos theta) sin theta, not line 20 (check 91)",
         "r_{P/O} = (a+x_2)\\cos(\\Omega t) \\hat{i} +(a+x_2)\\sin\\Omega t \\hat{j} +(a-y_2)\\hat{k} = x_1\\hat{i} +y_1\\hat{j}+z_1 \\hat{k}",
         "Hanging straight down, theta = 0: the bob should be directly below the pivot (a cos Omega t, a sin Omega t, a), at "
         "(a cos Omega t, a sin Omega t, a - l). The printed r with x_2 = 0, y_2 = l gives ((a + l) cos Omega t, "
         "(a + l) sin Omega t, a): level with the pivot and l further out, the rod horizontal.",
         "Frame at rest, Omega = 0, at theta = 0: line 20 gives thetadot-dot = 0 (the hanging equilibrium). The printed "
         "kinematics give height a - l sin(theta), V = m g (a - l sin theta), so m l^2 thetadot-dot = -dV/dtheta = "
         "m g l cos(theta) = m g l at theta = 0: thetadot-dot = g/l, not 0, and the equilibrium sits at theta = pi/2."),
    93: ("not a claim", "defines x_2, the pendulum's horizontal offset from the pivot"),
    94: ("not a claim", "defines y_2, the pendulum's drop below the pivot"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
