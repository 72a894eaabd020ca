"""Independent SymPy truth table for kit-p1-gyroscope-nutation-gimbal-precession-de.md.

The hints' convention: a symmetric top with figure axis z-hat, principal moments theta_z along it and
theta_perp across it (the letter theta names moments of inertia); omega is the angular velocity, L = Theta
omega the angular momentum. For nutation the top is free of torque: omega is split into a part omega_N along
L and a part along z-hat; alpha is the angle between omega and z-hat, beta the angle between L and z-hat.
For precession the figure axis makes the angle gamma with the vertical Z, the spin is omega about the figure
axis so that L = theta_z omega z-hat, and a weight m g hangs at r = r z-hat.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}
zero = truth_table.zero


def check(key, ok):
    CHECKS[key] = bool(ok)


wp, wz, tp, tz = sp.symbols('omega_perp omega_z theta_perp theta_z', positive=True)
# the vectors in the plane of z-hat and L (x across the figure axis, z along it)
w = sp.Matrix([wp, 0, wz])
L = sp.Matrix([tp * wp, 0, tz * wz])
zhat = sp.Matrix([0, 0, 1])
Lhat = L / sp.sqrt(L.dot(L))
# omega = omega_N Lhat + b zhat: solve for omega_N, the part along L
wN, bz = sp.symbols('w_N b_z')
sol = sp.solve(list(w - (wN * Lhat + bz * zhat)), [wN, bz], dict=True)[0]
omegaN = sp.simplify(sol[wN])
alpha = sp.atan(wp / wz)
beta = sp.atan(L[0] / L[2])
om = sp.sqrt(w.dot(w))
tan_a, tan_b = sp.tan(alpha), sp.tan(beta)
# 45: the relations between alpha, beta, the moments and omega_N
links = [
    tan_b - L[0] / L[2],
    L[0] / L[2] - tp * wp / (tz * wz),
    tp * wp / (tz * wz) - tp / tz * tan_a,
    sp.sin(alpha) - wp / om,
    sp.sin(beta) - wp / omegaN,
    omegaN - wp / sp.sin(beta),
    wp / sp.sin(beta) - om / sp.sin(beta) * sp.sin(alpha),
    om / sp.sin(beta) * sp.sin(alpha) - om / sp.sin(beta) * sp.sqrt(tan_a**2 / (1 + tan_a**2)),
    tan_a - tz / tp * tan_b,
    om / sp.sin(beta) * sp.sqrt(tan_a**2 / (1 + tan_a**2)) - om / sp.sin(beta) * sp.sqrt(1 / (1 / tan_a**2 + 1)),
    om / sp.sin(beta) * sp.sqrt(1 / (1 / tan_a**2 + 1))
    - om * sp.sqrt(tz**2 / (tp**2 * sp.cos(beta)**2 + tz**2 * sp.sin(beta)**2)),
]
check(45, all(zero(sp.simplify(e)) for e in links))
# 63: the exact form and its small-beta limit omega theta_z / theta_perp (beta -> 0 as omega_perp -> 0)
b = sp.Symbol('beta', positive=True)
exact = om * sp.sqrt(tz**2 / (tp**2 * sp.cos(beta)**2 + tz**2 * sp.sin(beta)**2))
check(63, zero(exact - omegaN)
      and zero(sp.limit((om * sp.sqrt(tz**2 / (tp**2 * sp.cos(b)**2 + tz**2 * sp.sin(b)**2))).subs(wp, 0), b, 0)
               - wz * tz / tp))
# 88: with the frames' moments the small-beta nutation rate is omega theta_z' / sqrt(theta_x' theta_y');
# with massless frames (theta_x' = theta_y' = theta_perp) it must reduce to line 63's omega theta_z / theta_perp
txp, typ, tzp, spin = sp.symbols("theta_xp theta_yp theta_zp omega", positive=True)
shown = tzp / sp.sqrt(txp * typ)
check(88, zero(shown.subs({txp: tp, typ: tp, tzp: tz}) - spin * tz / tp))
# 98, 112, 118, 124: precession under the weight
m, g, r, gam, dt = sp.symbols('m g r gamma dt', positive=True)
zfig = sp.Matrix([sp.sin(gam), 0, sp.cos(gam)])      # the figure axis, gamma from the vertical Z
rvec = r * zfig
Fg = sp.Matrix([0, 0, -m * g])
M = rvec.cross(Fg)
Mmag = m * g * r * sp.sin(gam)                      # the size the display states; 0 < gamma < pi
check(98, zero(M.dot(M) - Mmag**2))
Lvec = tz * spin * zfig
Lmag = tz * spin
Lperp = Lmag * sp.sin(gam)                          # the horizontal part of L, the radius it turns on
dL = M * dt
dLmag = Mmag * dt
assert zero(dL.dot(dL) - dLmag**2)
dphi = dLmag / Lperp
check(112, zero(dphi - Mmag * dt / (Lmag * sp.sin(gam))))
Om = sp.simplify(dphi / dt)
check(118, zero(Om - Mmag / (Lmag * sp.sin(gam)))
      and zero(Mmag / (Lmag * sp.sin(gam)) - m * g * r * sp.sin(gam) / (tz * spin * sp.sin(gam)))
      and zero(m * g * r * sp.sin(gam) / (tz * spin * sp.sin(gam)) - m * g * r / (tz * spin)))
# 124: the vertical precession vector turns L at the rate the torque demands, dL/dt = Omega x L = M
Omvec = sp.Matrix([0, 0, m * g * r / (tz * spin)])
check(124, zero(Omvec.cross(Lvec) - M))

LINES = [37, 45, 63, 77, 88, 98, 105, 112, 118, 124]
NC, H_ = "not a claim", "holds"
ROWS = {
    37: (NC, "splits omega into a part along L and a part along the figure axis (a definition)"),
    45: (H_, "tan(beta) = L_perp/L_z = theta_perp omega_perp/(theta_z omega_z) = (theta_perp/theta_z) tan(alpha), the "
              "sines of the two half-angles, omega_N = omega_perp/sin(beta) and its rewritings down to "
              "omega sqrt(theta_z^2/(theta_perp^2 cos^2 beta + theta_z^2 sin^2 beta)) all hold (check 45)"),
    63: (H_, "the exact form tends to omega theta_z/theta_perp as beta -> 0 (check 63)"),
    77: (NC, "the effective moments of the gimbal: the rotor's plus the frames' that turn with it (definitions)"),
    88: ("typo",
         "the nutation rate of the gimbal-mounted top is omega theta_z'/sqrt(theta_x' theta_y'); the display drops "
         "the spin omega and equates a rate with a pure number (check 88)",
         "\\omega_{N} = \\omega\\,\\frac{\\theta_{z}^{\\prime}}{\\sqrt{\\theta_{x}^{\\prime}\\,\\theta_{y}^{\\prime}}}",
         "By hand: with massless frames theta_x' = theta_y' = theta_perp and theta_z' = theta_z, the display gives "
         "theta_z/theta_perp, a number without units, where the page's own small-beta result (line 63) is "
         "omega theta_z/theta_perp, a rate; the factor omega is missing.",
         "Numbers: theta_z = 2, theta_perp = 1 (massless frames), spin omega = 50 rad/s: line 63 gives "
         "omega_N = 100 rad/s, the display gives 2; doubling the spin doubles the true rate but leaves the "
         "display at 2."),
    98: (H_, "the torque of the weight m g at r = r z-hat has size m g r sin(gamma), gamma the tilt from the "
              "vertical (check 98)"),
    105: (NC, "the law dL = M dt (the rate of the angular momentum is the torque), stated"),
    112: (H_, "dL = M dt turns the horizontal part L sin(gamma) of L through dL/L_perp (check 112)"),
    118: (H_, "Omega = M/(L sin gamma) = m g r sin(gamma)/(theta_z omega sin gamma) = m g r/(theta_z omega) "
               "(check 118)"),
    124: (H_, "a vertical Omega of that size turns L at the rate Omega x L, which is the torque (check 124)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
