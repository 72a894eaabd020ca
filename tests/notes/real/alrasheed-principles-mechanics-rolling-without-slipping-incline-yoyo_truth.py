"""Independent SymPy truth table for alrasheed-principles-mechanics-rolling-without-slipping-incline-yoyo.md
(Alrasheed, Principles of Mechanics, ch. 8, section 8.2 with Examples 8.3, 8.4 and 8.6, MyST edition).

The text's setting: plane motion of homogeneous bodies that roll without slipping. Everything is
built from first principles: the rolling condition as a point of contact at rest (v_cm + omega x
r_P = 0), the kinetic energy summed over particles, the moments of inertia of a solid sphere and a
solid cylinder by integration, Newton's law for the centre of mass and Euler's law about it with
the forces written as vectors, and for the block-and-sphere system a Lagrangian in one coordinate;
no formula of the text is assumed. The text's letters: R, M, m, g, h, theta (the wheel's angle in
section 8.2, the slope's angle in Example 8.3), omega, alpha, v_cm, a_cm, f_s, n, mu_s, T.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import zero

t = sp.Symbol('t', real=True)
M, m, R, g, h = sp.symbols('M m R g h', positive=True)
CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def cross(a, b):
    return sp.Matrix(a).cross(sp.Matrix(b))


# ---- moments of inertia by integration -------------------------------------------------------
r, th_, ph_, z_ = sp.symbols('r theta_ phi_ z_', nonnegative=True)
rho_s = M / (sp.Rational(4, 3) * sp.pi * R**3)
I_sphere = sp.integrate(rho_s * (r * sp.sin(th_))**2 * r**2 * sp.sin(th_), (r, 0, R), (th_, 0, sp.pi), (ph_, 0, 2 * sp.pi))
Hc = sp.Symbol('H', positive=True)
rho_c = M / (sp.pi * R**2 * Hc)
I_cyl = sp.integrate(rho_c * r**2 * r, (r, 0, R), (ph_, 0, 2 * sp.pi), (z_, 0, Hc))
assert zero(I_sphere - sp.Rational(2, 5) * M * R**2) and zero(I_cyl - M * R**2 / 2)

# ---- section 8.2: a wheel rolling to +x on the floor y = 0 ---------------------------------
theta = sp.Function('theta')(t)
x = sp.Function('x')(t)
omega_vec = sp.Matrix([0, 0, -sp.diff(theta, t)])     # turning clockwise as it rolls to +x
rP = sp.Matrix([0, -R, 0])                            # the point of contact from the centre
vP = sp.Matrix([sp.diff(x, t), 0, 0]) + cross(omega_vec, rP)
xdot = sp.solve(vP[0], sp.diff(x, t))[0]              # rolling: the contact point is at rest
s = sp.integrate(xdot, (t, 0, t)).doit()              # distance moved, theta(0) = 0
s = s.subs(theta.subs(t, 0), 0)
omega = sp.diff(theta, t)                             # the angular speed
vcm = sp.diff(s, t)
acm = sp.diff(vcm, t)
# line 23: s = R theta
check(23, zero(s - R * theta))
# line 29: v_cm = ds/dt = R dtheta/dt = R omega
check(29, zero(vcm - R * sp.diff(theta, t)) and zero(vcm - R * omega))
# line 35: a_cm = dv_cm/dt = R domega/dt = R alpha
alpha = sp.diff(omega, t)
check(35, zero(acm - R * sp.diff(omega, t)) and zero(acm - R * alpha))
# line 44: a rim particle's speed in the pure rotation about the centre is R omega, which rolling
# makes equal to v_cm
a_ = sp.Symbol('a_', real=True)
rim = sp.Matrix([R * sp.cos(a_), R * sp.sin(a_), 0])
speed2 = cross(omega_vec, rim).dot(cross(omega_vec, rim))
check(44, zero(speed2 - (R * omega)**2) and zero(vcm - R * omega))
# line 54: K of a rigid body in plane motion, summed over particles (three masses about the centre)
m1, m2, m3 = sp.symbols('m_1 m_2 m_3', positive=True)
x1, y1, x2, y2 = sp.symbols('x_1 y_1 x_2 y_2', real=True)
V, W = sp.symbols('V W', real=True)                   # centre's velocity (V, 0), angular velocity W
p1, p2 = sp.Matrix([x1, y1, 0]), sp.Matrix([x2, y2, 0])
p3 = -(m1 * p1 + m2 * p2) / m3                        # positions about the centre of mass
K_sum = sum(mi * (sp.Matrix([V, 0, 0]) + cross([0, 0, W], pi)).dot(sp.Matrix([V, 0, 0]) + cross([0, 0, W], pi)) / 2
            for mi, pi in ((m1, p1), (m2, p2), (m3, p3)))
Icm = sum(mi * (pi[0]**2 + pi[1]**2) for mi, pi in ((m1, p1), (m2, p2), (m3, p3)))
Mtot = m1 + m2 + m3
check(54, zero(K_sum - (Icm * W**2 / 2 + Mtot * V**2 / 2)))
# line 58: with v_cm = R omega
check(58, zero((Icm * W**2 / 2 + Mtot * V**2 / 2).subs(V, R * W) - (Icm * W**2 / 2 + Mtot * R**2 * W**2 / 2)))

# ---- Example 8.3: a solid sphere rolling down an incline of angle th ------------------------
th = sp.Symbol('theta', positive=True)
f, n, a, mu = sp.symbols('f_s n a_cm mu_s', real=True)
# slope frame: x down the slope, y along the outward normal, z = x X y
weight = M * g * sp.Matrix([sp.sin(th), -sp.cos(th), 0])
normal = sp.Matrix([0, n, 0])
fric = sp.Matrix([-f, 0, 0])                          # static friction up the slope, at the contact
Fnet = weight + normal + fric
tau = cross(rP, fric) + cross(rP, normal) + cross([0, 0, 0], weight)
# rolling down the slope: v x + w_z z X (0, -R, 0) = 0 gives w_z = -v/R, so alpha_z = -a/R
alpha_z = -a / R
eqs = [Fnet[0] - M * a, Fnet[1], tau[2] - I_sphere * alpha_z]
sol = sp.solve(eqs, [a, f, n], dict=True)[0]
a_s, f_s_, n_s = sol[a], sol[f], sol[n]
# line 90: (8.3) sum F_x = M g sin(theta) - f_s = M a_cm
check(90, zero(Fnet[0] - (M * g * sp.sin(th) - f)) and zero((M * g * sp.sin(th) - f - M * a).subs(sol)))
# line 95: sum F_y = n - M g cos(theta) = 0
check(95, zero(Fnet[1] - (n - M * g * sp.cos(th))) and zero((n - M * g * sp.cos(th)).subs(sol)))
# line 102: sum tau = f_s R = I_cm alpha = (2/5 M R^2)(a_cm/R), alpha the magnitude a/R
check(102, zero(-tau[2] - f * R) and zero(I_sphere - sp.Rational(2, 5) * M * R**2)
      and zero((f * R - I_sphere * a / R).subs(sol)))
# line 108: (8.4) f_s = 2/5 M a_cm
check(108, zero(f_s_ - sp.Rational(2, 5) * M * a_s))
# line 115: M g sin(theta) - 2/5 M a_cm = M a_cm
check(115, zero(M * g * sp.sin(th) - sp.Rational(2, 5) * M * a_s - M * a_s))
# line 121: a_cm = 5/7 g sin(theta)
check(121, zero(a_s - sp.Rational(5, 7) * g * sp.sin(th)))
# line 127: f_s = 2/7 M g sin(theta) (printed with a doubled = sign)
check(127, zero(f_s_ - sp.Rational(2, 7) * M * g * sp.sin(th)))
# line 134: about to slip: mu_s n, with the least mu_s that holds the ball, is the friction needed
mu_min = sp.simplify(f_s_ / n_s)
assert zero(mu_min - sp.Rational(2, 7) * sp.tan(th))
check(134, zero(mu_min * n_s - sp.Rational(2, 7) * M * g * sp.sin(th)) and zero(mu_min * n_s - f_s_))

# ---- Example 8.4: a solid cylinder unwinding from a fixed vertical string ---------------------
T = sp.Symbol('T', real=True)
# y upward; the string leaves the cylinder at (R, 0) from the centre and is fixed above
yacc = -a                                            # the centre accelerates downward with a_cm
Fy = T - M * g
wz_rate = sp.Symbol('wz_rate', real=True)           # angular acceleration about z
# the string's point (R, 0) is at rest: v_cm + w x (R, 0) = (0, y' + R w_z) = 0, so w_z' = -y''/R = a/R
wz_rate_val = -yacc / R
tau_c = cross([R, 0, 0], [0, T, 0])[2]
eqs_c = [Fy - M * yacc, tau_c - I_cyl * wz_rate_val]
sol_c = sp.solve(eqs_c, [a, T], dict=True)[0]
a_c, T_c = sol_c[a], sol_c[T]
# line 160: (8.5) sum F_y = T - M g = -M a_cm
check(160, zero(Fy - (T - M * g)) and zero((T - M * g + M * a).subs(sol_c)))
# line 165: sum tau = T R = I_cm alpha = 1/2 M R^2 (a_cm/R)
check(165, zero(tau_c - T * R) and zero(I_cyl - M * R**2 / 2) and zero((T * R - I_cyl * a / R).subs(sol_c)))
# line 172: (8.6) T = 1/2 M a_cm
check(172, zero(T_c - M * a_c / 2))
# line 179: printed -M_9 + 1/2 M a_cm = -M a_cm; M_9 is a letter defined nowhere
M9 = sp.Symbol('M_9')
check(179, zero((-M9 + M * a / 2 + M * a).subs(sol_c)))
assert zero((-M * g + M * a / 2 + M * a).subs(sol_c))      # with M g the line holds
# line 185: a_cm = 2/3 g
check(185, zero(a_c - sp.Rational(2, 3) * g))
# line 192: the mechanical energy is conserved along the motion (the string's point does no work)
y = sp.Function('y')(t)
E = M * sp.diff(y, t)**2 / 2 + I_cyl * (sp.diff(y, t) / R)**2 / 2 + M * g * y
dE = sp.diff(E, t).subs(sp.diff(y, t, 2), -a_c)
check(192, zero(dE))
# lines 196, 200: from rest, after a fall h: v_cm^2 = 2 a_cm h, omega = v_cm/R
vc = sp.sqrt(2 * a_c * h)
Ktrue = M * vc**2 / 2 + I_cyl * (vc / R)**2 / 2
vs, Is_, ws = sp.symbols('v_cm I_cm omega', positive=True)
check(196, zero(Ktrue - M * g * h) and zero((M * vs**2 / 2 + Is_ * ws**2 / 2).subs({vs: vc, Is_: I_cyl, ws: vc / R}) - M * g * h))
check(200, zero((M * vs**2 / 2 + (M * R**2 / 2) * (vs / R)**2 / 2) - (M * vs**2 / 2 + I_cyl * (vs / R)**2 / 2))
      and zero((M * vs**2 / 2 + (M * R**2 / 2) * (vs / R)**2 / 2).subs(vs, vc) - M * g * h))
# line 206: v_cm = sqrt(4/3 g h)
check(206, zero(vc - sp.sqrt(sp.Rational(4, 3) * g * h)))
# line 213: a_cm = v_cm^2/(2h) = 4 g h/(3 (2h)) = 2/3 g
check(213, zero(a_c - vc**2 / (2 * h)) and zero(vc**2 / (2 * h) - 4 * g * h / (3 * (2 * h)))
      and zero(4 * g * h / (3 * (2 * h)) - sp.Rational(2, 3) * g))
# line 219: T = 1/2 M a_cm = 1/2 M (2/3 g) = 1/3 M g
check(219, zero(T_c - M * a_c / 2) and zero(M * a_c / 2 - M * sp.Rational(2, 3) * g / 2)
      and zero(M * sp.Rational(2, 3) * g / 2 - M * g / 3))

# ---- Example 8.6: a hanging block m pulling a solid sphere M that rolls on a table ----------
q = sp.Function('q')(t)                              # the block's drop = the sphere centre's travel
Lag = m * sp.diff(q, t)**2 / 2 + M * sp.diff(q, t)**2 / 2 + I_sphere * (sp.diff(q, t) / R)**2 / 2 + m * g * q
eom = sp.diff(sp.diff(Lag, sp.diff(q, t)), t) - sp.diff(Lag, q)
a6 = sp.solve(eom, sp.diff(q, t, 2))[0]
v6 = sp.sqrt(2 * a6 * h)                              # from rest, uniform acceleration, after the drop h
v, v0, aa = sp.symbols('v v_0 a', real=True)
Ktrue6 = M * v**2 / 2 + I_sphere * (v / R)**2 / 2 + m * v**2 / 2
# line 241: m g h = 1/2 M v_cm^2 + 1/2 I_cm omega^2 + 1/2 m v^2, v_cm = v, omega = v/R
text241 = (M * vs**2 / 2 + Is_ * ws**2 / 2 + m * v**2 / 2).subs({vs: v, ws: v / R, Is_: I_sphere})
check(241, zero(text241 - Ktrue6) and zero(text241.subs(v, v6) - m * g * h))
# line 248: printed with (v^2/R)^2 for the rate of turning squared
text248 = M * v**2 / 2 + (sp.Rational(2, 5) * M * R**2) * (v**2 / R)**2 / 2 + m * v**2 / 2
check(248, zero(text248 - Ktrue6))
fixed248 = M * v**2 / 2 + (sp.Rational(2, 5) * M * R**2) * (v / R)**2 / 2 + m * v**2 / 2
assert zero(fixed248 - Ktrue6)
# line 254: v = sqrt(2 g h/(1 + 7M/5m)), 7M/5m read as 7M/(5m) as the next displays write it
check(254, zero(v6 - sp.sqrt(2 * g * h / (1 + 7 * M / (5 * m)))))
# line 260: v^2 - v_0^2 = 2 a h for uniform acceleration over the distance h
tt = sp.Symbol('tt', positive=True)
vv = v0 + aa * tt
xx = v0 * tt + aa * tt**2 / 2
check(260, zero(vv**2 - v0**2 - 2 * aa * xx))
# line 266: a = v^2/(2h) = 2 g h/(2h(1 + 7/5 (M/m)))
check(266, zero(a6 - v6**2 / (2 * h)) and zero(v6**2 / (2 * h) - 2 * g * h / (2 * h * (1 + sp.Rational(7, 5) * (M / m)))))
# line 272: a = g/(1 + 7/5 (M/m))
check(272, zero(a6 - g / (1 + sp.Rational(7, 5) * (M / m))))

LINES = [23, 29, 35, 44, 54, 58, 90, 95, 102, 108, 115, 121, 127, 134, 160, 165, 172, 179, 185, 192, 196,
         200, 206, 213, 219, 241, 248, 254, 260, 266, 272]

ROWS = {
    23: ("holds", "rolling without slipping: the contact point r_P = (0, -R) is at rest, v_cm + omega x r_P = 0 with omega = -theta' z gives x' = R theta', so the centre advances s = R theta (check 23)"),
    29: ("holds", "differentiating s = R theta: v_cm = R theta' = R omega (check 29)"),
    35: ("holds", "differentiating again: a_cm = R omega' = R alpha (check 35)"),
    44: ("holds", "in the pure rotation about the centre a rim particle at distance R moves with |omega x r| = R omega, which rolling makes equal to v_cm (check 44)"),
    54: ("holds", "kinetic energy summed over particles v_i = v_cm + omega x r_i' with sum m_i r_i' = 0: K = 1/2 I_cm omega^2 + 1/2 M v_cm^2 (check 54)"),
    58: ("holds", "the previous K with v_cm = R omega (check 58)"),
    90: ("holds", "slope frame, x down the slope: weight M g (sin theta, -cos theta), normal (0, n), static friction (-f_s, 0); the x component of the net force is M g sin theta - f_s = M a_cm (check 90)"),
    95: ("holds", "the y component of the net force, n - M g cos theta, vanishes: no acceleration along the normal (check 95)"),
    102: ("holds", "only friction has a torque about the centre, of size f_s R; rolling gives alpha = a_cm/R and a solid sphere has I_cm = 2/5 M R^2 by integration (check 102)"),
    108: ("holds", "f_s R = (2/5 M R^2)(a_cm/R) gives f_s = 2/5 M a_cm (check 108)"),
    115: ("holds", "(8.4) put into (8.3) (check 115)"),
    121: ("holds", "solving: (1 + 2/5) M a_cm = M g sin theta, a_cm = 5/7 g sin theta (check 121)"),
    127: ("holds", "f_s = 2/5 M a_cm = 2/7 M g sin theta; the doubled = sign is a typesetting slip that states nothing else (check 127)"),
    134: ("holds", "the least mu_s that holds the ball is f_s/n = (2/7 M g sin theta)/(M g cos theta) = 2/7 tan theta; at it mu_s n equals the friction needed, 2/7 M g sin theta (check 134)"),
    160: ("holds", "y upward, the centre accelerating down with a_cm: the net force T - M g equals M (-a_cm) (check 160)"),
    165: ("holds", "the tension acts at R from the centre, torque T R; the string's point of the cylinder is at rest, so alpha = a_cm/R; a solid cylinder has I_cm = 1/2 M R^2 by integration (check 165)"),
    172: ("holds", "T R = (1/2 M R^2)(a_cm/R) gives T = 1/2 M a_cm (check 172)"),
    179: ("typo", "(8.6) put into (8.5) gives -M g + 1/2 M a_cm = -M a_cm; the printed line has -M_{9}, a letter defined nowhere, in place of -M g (check 179)", "-Mg+\\frac{1}{2}Ma_{cm}=-Ma_{cm}", "M = 2 kg, g = 9.8 m/s^2, a_cm = 2/3 g = 6.533 m/s^2: -M g + 1/2 M a_cm = -19.6 + 6.533 = -13.07 = -M a_cm, as it must. The printed -M_9 + 6.533 = -13.07 holds only if M_9 = 19.6 N = M g: the subscript 9 stands where the g belongs.", "From the two equations before it: (8.5) T - M g = -M a_cm and (8.6) T = 1/2 M a_cm, so T - M g = 1/2 M a_cm - M g. The next line, a_cm = 2/3 g, follows only from -M g + 1/2 M a_cm = -M a_cm; with a mass M_9 in its place it would give a_cm = 2/3 M_9/M, not a multiple of g."),
    185: ("holds", "solving: 3/2 M a_cm = M g, a_cm = 2/3 g (check 185)"),
    192: ("holds", "the string's point of the cylinder is at rest, so the tension does no work: d/dt (1/2 M v^2 + 1/2 I_cm omega^2 + M g y) = 0 along the motion (check 192)"),
    196: ("holds", "from rest, after a fall h: K_f = M g h with v_cm^2 = 2 a_cm h and omega = v_cm/R (check 196)"),
    200: ("holds", "the same with I_cm = 1/2 M R^2 and omega = v_cm/R (check 200)"),
    206: ("holds", "M g h = 3/4 M v_cm^2 gives v_cm = sqrt(4/3 g h) (check 206)"),
    213: ("holds", "uniform acceleration from rest over h: a_cm = v_cm^2/(2h) = (4/3 g h)/(2h) = 2/3 g (check 213)"),
    219: ("holds", "T = 1/2 M a_cm = 1/2 M (2/3 g) = 1/3 M g (check 219)"),
    241: ("holds", "the block falls h; the sphere rolls on a level table, its centre moving with the block's speed v and turning with omega = v/R: m g h = 1/2 M v^2 + 1/2 I_cm omega^2 + 1/2 m v^2 (check 241)"),
    248: ("typo", "rolling makes the sphere turn with omega = v/R, so its rotational energy is 1/2 (2/5 M R^2)(v/R)^2 = 1/5 M v^2; the printed (v^2/R)^2 squares v twice (check 248)", "mgh=\\frac{1}{2}Mv^{2}+\\frac{1}{2}\\bigg (\\frac{2}{5}MR^{2}\\bigg )\\bigg (\\frac{v}{R}\\bigg )^{2}+\\frac{1}{2}mv^{2}", "M = m = 1 kg, R = 0.5 m, v = 2 m/s: the true energy is 1/2*1*4 + 1/2*(2/5*1*0.25)*(2/0.5)^2 + 1/2*1*4 = 2 + 0.8 + 2 = 4.8 J; the printed rotational term 1/2*(0.1)*(4/0.5)^2 = 3.2 J gives 7.2 J.", "Units: (v^2/R)^2 is m^2/s^4, times M R^2 it gives kg m^4/s^4, not an energy; and only with (v/R)^2 does the next display follow: (1/2 M + 1/5 M + 1/2 m) v^2 = m g h gives v^2 = 2 g h/(1 + 7M/(5m)), while (v^2/R)^2 would leave a v^4 term."),
    254: ("holds", "(7/10 M + 1/2 m) v^2 = m g h: v = sqrt(2 g h/(1 + 7M/(5m))), 7M/5m read as 7M/(5m) as the next displays write 7/5 (M/m) (check 254)"),
    260: ("holds", "uniform acceleration: v = v_0 + a t and h = v_0 t + 1/2 a t^2 give v^2 - v_0^2 = 2 a h (check 260)"),
    266: ("holds", "with v_0 = 0 and v^2 from the energy: a = v^2/(2h) = 2 g h/(2h (1 + 7/5 (M/m))) (check 266)"),
    272: ("holds", "Lagrange's equation for the drop q: (m + M + I_cm/R^2) q'' = m g, so a = m g/(m + 7/5 M) = g/(1 + 7/5 (M/m)) (check 272)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
