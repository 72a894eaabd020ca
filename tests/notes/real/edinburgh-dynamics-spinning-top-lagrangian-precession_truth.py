"""Independent SymPy truth table for edinburgh-dynamics-spinning-top-lagrangian-precession.tex.

The text's own setting: a symmetric top with one point on the table, its symmetry axis a-hat at
the angle vartheta from the vertical k-hat, spinning at rate omega about a-hat while a-hat goes round
k-hat at rate Omega; I_parallel is the moment about a-hat, I_perp the one about any axis at right
angles to it, h the distance from the contact point to the centre of mass along a-hat. Here the
top is built from an explicit rotation R = Rz(phi) Ry(vartheta) Rz(psi), Omega = phi', omega = psi'
(z-y-z angles): the angular velocity from R' R^T, the angular momentum R diag(I_perp, I_perp,
I_parallel) R^T omega, the kinetic energy 1/2 omega . L, the height of the centre of mass, the
Lagrangian and its Euler-Lagrange equations; never from the text's later displays. Steady
precession is vartheta' = 0. Run with --write to regenerate the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Ry, Rz

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
t = sp.symbols("t", real=True)
M, g, h, Ip, Ia = sp.symbols("M g h I_perp I_parallel", positive=True)
th, w, W, thd, thdd, eps = sp.symbols("vartheta omega Omega thetadot thetaddot epsilon", real=True)
La = sp.symbols("L_a", positive=True)                  # the spin momentum, taken positive (a fast top)
phi = sp.Function("phi")(t)
psi = sp.Function("psi")(t)
tht = sp.Function("theta")(t)

R = Rz(phi) * Ry(tht) * Rz(psi)
S = sp.simplify(R.diff(t) * R.T)                       # skew matrix of the space angular velocity
wS = sp.Matrix([S[2, 1], S[0, 2], S[1, 0]])
Ib = sp.diag(Ip, Ip, Ia)
Lvec = R * Ib * R.T * wS
T_full = sp.simplify(wS.dot(Lvec) / 2)
a_hat = R * sp.Matrix([0, 0, 1])
a_perp = Rz(phi) * Ry(tht) * sp.Matrix([1, 0, 0])     # at right angles to a-hat, in the plane of a-hat and k-hat
k_hat = sp.Matrix([0, 0, 1])

# the text's names: Omega = phi', omega = psi', vartheta = theta, steady: theta' = theta'' = 0
def named(e):
    e = e.subs({tht.diff(t, 2): thdd}).subs({tht.diff(t): thd, phi.diff(t): W, psi.diff(t): w})
    return e.subs(tht, th)

steady = {thd: 0, thdd: 0}

# 31: the angular velocity of the precessing, spinning top (vartheta fixed) is omega a-hat + Omega k-hat
check(31, zero(named(wS - (psi.diff(t) * a_hat + phi.diff(t) * k_hat)).subs(steady)))

# 33: k-hat = cos(vartheta) a-hat - sin(vartheta) a-hat_perp, a-hat_perp a unit vector at right angles to a-hat
check(33, zero(named(k_hat - (sp.cos(tht) * a_hat - sp.sin(tht) * a_perp)))
      and zero(named(a_perp.dot(a_hat))) and zero(named(a_perp.dot(a_perp) - 1)))

# 35: L = -I_perp Omega sin(vartheta) a_perp + I_parallel (omega + Omega cos(vartheta)) a-hat
L35 = -Ip * W * sp.sin(th) * named(a_perp) + Ia * (w + W * sp.cos(th)) * named(a_hat)
check(35, zero(named(Lvec).subs(steady) - L35))

# Lagrangian (full, theta' kept), V = M g h (a-hat . k-hat)
V = M * g * h * a_hat.dot(k_hat)
Lag = T_full - V
# 37: L . a-hat = I_parallel (omega + Omega cos(vartheta)) = dLag/dpsi', and psi is cyclic (so it is constant)
pa = sp.simplify(Lag.diff(psi.diff(t)))
check(37, zero(named(Lvec.dot(a_hat)).subs(steady) - Ia * (w + W * sp.cos(th)))
      and zero(named(pa) - Ia * (w + W * sp.cos(th))) and zero(Lag.diff(psi)))

# 39: the kinetic energy in steady precession
T_st = sp.simplify(named(T_full).subs(steady))
T39 = Ip * W**2 * sp.sin(th)**2 / 2 + (w**2 + 2 * w * W * sp.cos(th) + W * sp.cos(th)**2) / 2
check(39, zero(T_st - T39))
T_right = Ip * W**2 * sp.sin(th)**2 / 2 + Ia * (w**2 + 2 * w * W * sp.cos(th) + W**2 * sp.cos(th)**2) / 2
assert zero(T_st - T_right)

# 41: V = M g h cos(vartheta)
check(41, zero(named(V) - M * g * h * sp.cos(th)))

# 43: the Lagrangian T - V in steady precession
L43 = T39 - M * g * h * sp.cos(th)
check(43, zero(named(Lag).subs(steady) - L43))

# 45: the Euler-Lagrange equation in theta, steady precession (theta' = theta'' = 0)
EL = Lag.diff(tht) - Lag.diff(tht.diff(t)).diff(t)      # = 0 on a motion
EL_st = sp.simplify(named(EL).subs(steady))
d45 = Ip * W**2 * sp.sin(th) * sp.cos(th) - Ia * (w * W * sp.sin(th) + W**2 * sp.cos(th) * sp.sin(th)) + M * g * h * sp.sin(th)
check(45, zero(EL_st - d45))

# 47: divided by sin(vartheta), with L_a = I_parallel (omega + Omega cos(vartheta))
q47 = Ip * W**2 * sp.cos(th) - La * W + M * g * h
check(47, zero((EL_st / sp.sin(th)) - q47.subs(La, Ia * (w + W * sp.cos(th)))))

# 49: the two roots of I_perp cos(vartheta) Omega^2 - L_a Omega + M g h = 0
q = Ip * sp.cos(th) * W**2 - La * W + M * g * h
roots49 = [(La + sg * sp.sqrt(La**2 - 4 * M * g * h * Ip * sp.cos(th))) / (2 * Ip * sp.cos(th)) for sg in (1, -1)]
check(49, all(zero(q.subs(W, r)) for r in roots49)
      and zero(sum(roots49) - La / (Ip * sp.cos(th))) and zero(roots49[0] * roots49[1] - M * g * h / (Ip * sp.cos(th))))

# 51, 54: fast top: M g h small against L_a^2 / (I_perp cos); put M g h -> eps M g h, expand to first order
small = roots49[1].subs(M, eps * M)
large = roots49[0].subs(M, eps * M)
ser_small = sp.series(small, eps, 0, 2).removeO().subs(eps, 1)
ser_large = sp.series(large, eps, 0, 1).removeO().subs(eps, 1)
mid51 = (La - La + 2 * M * g * h * Ip * sp.cos(th) / La) / (2 * Ip * sp.cos(th))
# the middle member is the minus root with sqrt(L_a^2 - x) ~ L_a - x/(2 L_a)
x = 4 * M * g * h * Ip * sp.cos(th)
check(51, zero(ser_small - M * g * h / La) and zero(mid51 - M * g * h / La)
      and zero(mid51 - (La - (La - x / (2 * La))) / (2 * Ip * sp.cos(th))))
check(54, zero(ser_large - La / (Ip * sp.cos(th))))

# 58: T = T_steady + 1/2 I_perp theta'^2 (T_steady the kinetic energy at theta' = 0)
check(58, zero(named(T_full) - (T_right + Ip * thd**2 / 2)))

# 60: the Euler-Lagrange equation in theta with theta' kept: I_perp theta'' = (...) sin(vartheta)
d60 = Ip * thdd - (Ip * W**2 * sp.cos(th) - La * W + M * g * h) * sp.sin(th)
check(60, zero(sp.expand(-named(EL) - d60.subs(La, Ia * (w + W * sp.cos(th))))))

T39_FIX = (r"T = \frac{1}{2}I_\perp\Omega^2\sin^2\vartheta + \frac{1}{2}I_\parallel(\omega^2 + 2\omega\Omega\cos\vartheta"
           r" + \Omega^2\cos^2\vartheta)")
ROWS = {
    31: ("holds", "the top turned by R = Rz(phi) Ry(vartheta) Rz(psi) with vartheta fixed has angular velocity "
                  "psi' a-hat + phi' k-hat: omega a-hat + Omega k-hat (check 31)"),
    33: ("holds", "with a-hat_perp the unit vector at right angles to a-hat in the plane of a-hat and k-hat, on the side "
                  "away from k-hat (a-hat_perp . k-hat = -sin(vartheta)): k-hat = cos(vartheta) a-hat - sin(vartheta) a-hat_perp (check 33)"),
    35: ("holds", "omega = (omega + Omega cos(vartheta)) a-hat - Omega sin(vartheta) a-hat_perp, each part times its "
                  "principal moment (check 35)"),
    37: ("holds", "L . a-hat = I_parallel (omega + Omega cos(vartheta)), the momentum of the cyclic spin angle psi, "
                  "so constant (check 37)"),
    39: ("typo", "T = 1/2 omega . L = 1/2 I_perp Omega^2 sin^2(vartheta) + 1/2 I_parallel (omega + Omega cos(vartheta))^2; "
                 "the second term has lost its I_parallel and the last Omega its square (check 39)",
         T39_FIX,
         "From the display before: T = 1/2 omega . L with omega = (omega + Omega cos) a-hat - Omega sin a-hat_perp and "
         "L = I_parallel (omega + Omega cos) a-hat - I_perp Omega sin a-hat_perp gives 1/2 I_perp Omega^2 sin^2 + "
         "1/2 I_parallel (omega^2 + 2 omega Omega cos + Omega^2 cos^2). In numbers: I_perp = 2, I_parallel = 3, omega = 1, "
         "Omega = 2, vartheta = 0: T = 0 + 1/2 * 3 * (1 + 2)^2 = 13.5, while the display gives 1/2 (1 + 4 + 2) = 3.5.",
         "Limiting case omega = 0, vartheta = 0: the top turns about its own axis, which is vertical, at rate Omega, so "
         "T = 1/2 I_parallel Omega^2; the display gives 1/2 Omega, which is not even an energy (units s^-1 beside the "
         "first term's kg m^2 s^-2, and omega^2 beside Omega cos^2 mixes s^-2 with s^-1)."),
    41: ("holds", "the centre of mass at h a-hat above the contact point: height h cos(vartheta) (check 41)"),
    43: ("typo", "L = T - V carries the kinetic energy's slips: the second term needs I_parallel and Omega^2 cos^2(vartheta) "
                 "(check 43)",
         r"\LL = \frac{1}{2}I_\perp\Omega^2\sin^2\vartheta + \frac{1}{2}I_\parallel(\omega^2 + 2\omega\Omega\cos\vartheta"
         r" + \Omega^2\cos^2\vartheta) - Mgh\cos\vartheta",
         "T - V from the corrected T (1/2 I_perp Omega^2 sin^2 + 1/2 I_parallel (omega + Omega cos)^2) and V = M g h cos. "
         "In numbers: I_perp = 2, I_parallel = 3, omega = 1, Omega = 2, vartheta = 0, M g h = 1: L = 13.5 - 1 = 12.5, "
         "while the display gives 3.5 - 1 = 2.5.",
         "The next display, the Euler-Lagrange equation, has the term -I_parallel (omega Omega sin + Omega^2 cos sin), "
         "which is d/dvartheta of 1/2 I_parallel (omega^2 + 2 omega Omega cos + Omega^2 cos^2); from the display's "
         "1/2 (omega^2 + 2 omega Omega cos + Omega cos^2) it would be -(omega Omega sin + Omega cos sin), with no I_parallel "
         "and Omega unsquared."),
    45: ("holds", "dL/dvartheta = 0 (no vartheta' in steady precession) from the correct Lagrangian: "
                  "I_perp Omega^2 sin cos - I_parallel (omega Omega sin + Omega^2 cos sin) + M g h sin = 0 (check 45)"),
    47: ("holds", "divided by sin(vartheta), with I_parallel (omega + Omega cos(vartheta)) = L_a (check 47)"),
    49: ("holds", "the roots of I_perp cos(vartheta) Omega^2 - L_a Omega + M g h = 0 (check 49)"),
    51: ("holds", "the minus root with sqrt(L_a^2 - x) ~ L_a - x/(2 L_a), x = 4 M g h I_perp cos: M g h / L_a to first "
                  "order in M g h (check 51)"),
    54: ("holds", "the plus root at leading order for a fast top: 2 L_a / (2 I_perp cos(vartheta)) (check 54)"),
    58: ("holds", "1/2 omega . L with vartheta' kept adds 1/2 I_perp vartheta'^2 to the steady kinetic energy (check 58)"),
    60: ("holds", "the Euler-Lagrange equation in vartheta: I_perp vartheta'' = (I_perp Omega^2 cos - L_a Omega + M g h) "
                  "sin(vartheta) (check 60)"),
}

LINES = sorted(ROWS)


if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
