"""Independent SymPy truth table for derphysicsjagger-blog-euler-disk-steady-precession-bump-loss-worked-problem.md.

The post's convention: a thin disk of mass m and radius a at angle alpha to the horizontal on a
frictionless table, turning about the vertical at Omega; x-hat along the disk's axis, z-hat in its plane
(pointing up the disk, so that the contact point is at -a z-hat from the centre) and y-hat = z-hat x
x-hat; the vertical is sin(alpha) z-hat + cos(alpha) x-hat; the moment of inertia about a diameter is
m a^2 / 4. Vectors are columns of (x, y, z) components. The later parts are the post's own model (an
energy loss m g h per bump, bumps delta apart, small alpha), checked here step by step with the
approximations it states (sin alpha ~ alpha, cos alpha ~ 1, a alpha'' ~ g as it takes the falling
acceleration). Run as a program it compares its verdicts with the table; ``--write`` writes it.
"""
import sys

import sympy as sp

import truth_table
from truth_table import zero

m, a, g, al, W0, h, de, t, t0, f0 = sp.symbols('m a g alpha Omega_0 h delta t t_0 f_0', positive=True)
wx, ad, add = sp.symbols('omega_x alphadot alphaddot', real=True)
x, y, z = sp.eye(3)[:, 0], sp.eye(3)[:, 1], sp.eye(3)[:, 2]
vert = sp.sin(al) * z + sp.cos(al) * x
Wst = 2 * sp.sqrt(g / (a * sp.sin(al)))          # the steady rate of part (a)

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def leading(expr, approx):
    """expr / approx -> 1 as alpha -> 0: the two agree to leading order in small alpha."""
    return sp.limit(sp.simplify(expr / approx), al, 0) == 1


# line 31: rolling: Omega_0 a cos(alpha) = -omega_x a, so omega_x = -Omega_0 cos(alpha)
check(31, zero(sp.solve(sp.Eq(W0 * a * sp.cos(al), -wx * a), wx)[0] + W0 * sp.cos(al)))

# line 39: omega_tot = Omega_0 (vertical) + omega_x x-hat = Omega_0 sin(alpha) z-hat
rows = [W0 * vert + (-W0 * sp.cos(al)) * x, W0 * (sp.sin(al) * z + sp.cos(al) * x) - W0 * sp.cos(al) * x,
        W0 * sp.sin(al) * z]
check(39, all(zero(rows[i] - rows[i + 1]) for i in range(2)))

# line 51: L' = Omega_0 x L with L = m a^2/4 Omega_0 sin(alpha) z-hat equals the torque of the normal
# force m g (vertical) at the contact point -a z-hat: m g a cos(alpha) = m a^2/4 Omega_0^2 sin cos,
# whence Omega_0 = 2 sqrt(g/(a sin alpha))
L = m * a**2 / 4 * W0 * sp.sin(al) * z
dL = (W0 * vert).cross(L)
torque = (-a * z).cross(m * g * vert)
ok51 = zero(dL.dot(y) + m * a**2 / 4 * W0**2 * sp.sin(al) * sp.cos(al))
ok51 &= zero(torque.dot(y) + m * g * a * sp.cos(al)) and zero(torque.dot(x)) and zero(torque.dot(z))
sol = [s for s in sp.solve(sp.Eq(m * g * a * sp.cos(al), m * a**2 / 4 * W0**2 * sp.sin(al) * sp.cos(al)), W0)]
# the equation's roots are +-Wst; the rate about the vertical is the positive one
check(51, ok51 and any(zero(r - Wst) for r in sol) and all(zero(r**2 - Wst**2) for r in sol))

# line 62: E = m g a sin + 1/2 (m a^2/4) omega_tot^2 = m g a sin + m a^2 Omega_0^2 sin^2 / 8 = 3/2 m g a sin
E1 = m * g * a * sp.sin(al) + sp.Rational(1, 2) * sp.Rational(1, 4) * m * a**2 * (W0 * sp.sin(al))**2
E2 = m * g * a * sp.sin(al) + sp.Rational(1, 8) * m * a**2 * W0**2 * sp.sin(al)**2
check(62, zero(E1 - E2) and zero(E2.subs(W0, Wst) - sp.Rational(3, 2) * m * g * a * sp.sin(al)))

# line 74: Omega' = Omega (1 - cos alpha) = 2 (1 - cos alpha) sqrt(g/(a sin alpha)) at the steady Omega
check(74, zero(Wst * (1 - sp.cos(al)) - 2 * (1 - sp.cos(al)) * sp.sqrt(g / (a * sp.sin(al)))))

# line 84: v_COM = d/dt (a sin alpha) = a cos(alpha) alpha' ~ a alpha' for small alpha
alf = sp.Function('alpha')(t)
ok84 = zero((a * sp.sin(alf)).diff(t) - a * sp.cos(alf) * alf.diff(t))
check(84, ok84 and leading(a * sp.cos(al) * ad, a * ad))

# line 92: E = 1/2 m v^2 + 3/2 m g a sin(alpha) ~ 1/2 m a^2 alpha'^2 + 3/2 m g a alpha
exact = sp.Rational(1, 2) * m * (a * sp.cos(al) * ad)**2 + sp.Rational(3, 2) * m * g * a * sp.sin(al)
approx = sp.Rational(1, 2) * m * a**2 * ad**2 + sp.Rational(3, 2) * m * g * a * al
check(92, zero(sp.series(exact - approx, al, 0, 2).removeO()))

# line 101: dE/dt = m a^2 alpha' alpha'' + 3/2 m g a alpha' = -m g h / (delta/(Omega a cos alpha))
W = sp.symbols('Omega', positive=True)
Et = sp.Rational(1, 2) * m * a**2 * alf.diff(t)**2 + sp.Rational(3, 2) * m * g * a * alf
ok101 = zero(Et.diff(t) - (sp.Rational(3, 2) * m * g * a * alf.diff(t) + m * a**2 * alf.diff(t) * alf.diff(t, 2)))
ok101 &= zero(-m * g * h / (de / (W * a * sp.cos(al))) + m * g * h / de * W * a * sp.cos(al))
check(101, ok101)

# line 111: with a alpha'' = g: (3/2 + 1) m g a alpha' = -(m g h/delta) Omega a cos(alpha), Omega the
# steady rate: alpha' = -(4/5)(h/delta) cos(alpha) sqrt(g/(a sin alpha)); to first order (cos ~ 1,
# sin ~ alpha) this is the display's -(4/5)(h/delta) sqrt(g/(a sin)) ~ -(4h/(5 delta)) sqrt(g/a) alpha^(-1/2)
exact111 = sp.solve(sp.Eq(sp.Rational(3, 2) * m * g * a * ad + m * a * ad * g,
                          -m * g * h / de * Wst * a * sp.cos(al)), ad)[0]
mid111 = -sp.Rational(4, 5) * h / de * sp.sqrt(g / (a * sp.sin(al)))
last111 = -4 * h / (5 * de) * sp.sqrt(g / a) * al**sp.Rational(-1, 2)
check(111, leading(exact111, mid111) and leading(mid111, last111))

# line 122: the integral of alpha^(1/2), and alpha(t) solving 2/3 (alpha^(3/2) - alpha_0^(3/2)) = -K (t - t0)
s, a0 = sp.symbols('s alpha_0', positive=True)
K = 4 * h / (5 * de) * sp.sqrt(g / a)
ok122 = zero(sp.integrate(sp.sqrt(s), (s, a0, al)) - sp.Rational(2, 3) * (al**sp.Rational(3, 2) - a0**sp.Rational(3, 2)))
B = 1 - 6 * h / (5 * de * a0**sp.Rational(3, 2)) * sp.sqrt(g / a) * (t - t0)
Bp = sp.symbols('B', positive=True)        # the bracket, positive while the disk still stands
alpha_t = a0 * Bp**sp.Rational(2, 3)
res = sp.Rational(2, 3) * (alpha_t**sp.Rational(3, 2) - a0**sp.Rational(3, 2)) + K * (t - t0)
check(122, ok122 and zero(sp.expand(res.subs(Bp, B))))

# line 132: Omega(t) = 2 sqrt(g/(a sin alpha(t))) ~ 2 sqrt(g/(a alpha_0)) B^(-1/3) = Omega_0 B^(-1/3)
ok132 = zero(sp.simplify(2 * sp.sqrt(g / (a * alpha_t)) - 2 * sp.sqrt(g / (a * a0)) * Bp**sp.Rational(-1, 3)))
check(132, ok132 and leading(2 * sp.sqrt(g / (a * sp.sin(al))), 2 * sp.sqrt(g / (a * al))))

# line 144: f = Omega a cos(alpha)/delta ~ Omega a/delta = (2/delta) sqrt(g a/alpha_0) B^(-1/3)
f_t = 2 * sp.sqrt(g / (a * a0)) * Bp**sp.Rational(-1, 3) * a / de
check(144, zero(sp.simplify(f_t - 2 / de * sp.sqrt(g * a / a0) * Bp**sp.Rational(-1, 3)))
      and leading(W * a * sp.cos(al) / de, W * a / de))

# line 152: the time tau_0 = t - t0 at which f = f_0
tau = 5 * de * a0**sp.Rational(3, 2) / (6 * h) * sp.sqrt(a / g) * (1 - (2 / (de * f0) * sp.sqrt(g * a / a0))**3)
Bt = B.subs(t, t0 + tau)
check(152, zero(sp.simplify(Bt - (2 / (de * f0) * sp.sqrt(g * a / a0))**3)))

LINES = [31, 39, 51, 62, 74, 84, 92, 101, 111, 122, 132, 144, 152]

ROWS = {
    31: ("holds", "Omega_0 a cos(alpha_0) = -omega_x a gives omega_x = -Omega_0 cos(alpha_0) (check 31)"),
    39: ("holds", "the vertical is sin(alpha_0) z-hat + cos(alpha_0) x-hat, and adding -Omega_0 cos(alpha_0) x-hat leaves Omega_0 sin(alpha_0) z-hat (check 39)"),
    51: ("holds", "Omega_0 x L has size m a^2/4 Omega_0^2 sin cos (the vertical makes the angle pi/2 - alpha_0 with z-hat) and the direction of the torque of the normal force m g at the contact point, of size m g a cos(alpha_0); solving gives Omega_0 = 2 sqrt(g/(a sin alpha_0)) (check 51)"),
    62: ("holds", "omega_tot = Omega_0 sin(alpha_0), and with Omega_0^2 = 4 g/(a sin alpha_0) the kinetic term is m g a sin(alpha_0)/2, so E = 3/2 m g a sin(alpha_0) (check 62)"),
    74: ("holds", "Omega (1 - cos alpha) with the steady Omega = 2 sqrt(g/(a sin alpha)) (check 74)"),
    84: ("holds", "d/dt (a sin alpha) = a cos(alpha) alpha', which is a alpha' to first order in small alpha (check 84)"),
    92: ("holds", "1/2 m (a cos(alpha) alpha')^2 + 3/2 m g a sin(alpha) agrees with 1/2 m a^2 alpha'^2 + 3/2 m g a alpha to first order in alpha (check 92)"),
    101: ("holds", "the derivative of 1/2 m a^2 alpha'^2 + 3/2 m g a alpha is m a^2 alpha' alpha'' + 3/2 m g a alpha', and m g h over delta/(Omega a cos alpha) is (m g h/delta) Omega a cos(alpha) (check 101)"),
    111: ("holds", "with a alpha'' ~ g the left side is 5/2 m g a alpha', so alpha' = -(2h/(5 delta)) Omega cos(alpha) = -(4/5)(h/delta) cos(alpha) sqrt(g/(a sin alpha)) at the steady Omega: the display to first order in alpha (cos alpha ~ 1), and ~ -(4h/(5 delta)) sqrt(g/a) alpha^(-1/2) with sin alpha ~ alpha (check 111)"),
    122: ("holds", "the integral of alpha^(1/2) is 2/3 alpha^(3/2), and alpha(t) = alpha_0 [1 - 6h/(5 delta alpha_0^(3/2)) sqrt(g/a)(t - t_0)]^(2/3) solves 2/3 (alpha^(3/2) - alpha_0^(3/2)) = -(4h/(5 delta)) sqrt(g/a)(t - t_0) (check 122)"),
    132: ("holds", "with sin alpha ~ alpha, 2 sqrt(g/(a alpha(t))) = 2 sqrt(g/(a alpha_0)) [..]^(-1/3) for the alpha(t) of line 122, and 2 sqrt(g/(a alpha_0)) is Omega_0 of part (a) for small alpha_0 (check 132)"),
    144: ("holds", "Omega a/delta with the Omega(t) of line 132: (2/delta) sqrt(g a/alpha_0) [..]^(-1/3); cos alpha ~ 1 for small alpha (check 144)"),
    152: ("holds", "f = f_0 when [..]^(-1/3) = delta f_0/(2 sqrt(g a/alpha_0)), that is [..] = (2 sqrt(g a/alpha_0)/(delta f_0))^3, so t - t_0 = 5 delta alpha_0^(3/2)/(6h) sqrt(a/g) (1 - (2 sqrt(g a/alpha_0)/(delta f_0))^3) (check 152)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
