"""Independent SymPy truth table for planetphysics-euler-angle-velocity-123-sequence-encyclopaedia.md.

Names as the entries': R_1, R_2, R_3 turn a frame (passive rotations, R_3(psi) = [[c, s, 0],
[-s, c, 0], [0, 0, 1]], R_2(theta) = [[c, 0, -s], [0, 1, 0], [s, 0, c]], R_1(phi) = [[1, 0, 0],
[0, c, s], [0, -s, c]]), so C = R_3(psi) R_2(theta) R_1(phi) takes reference components to body
components; c_x, s_x are cos x, sin x. The body components of the angular velocity are read off
C' C^T = -[omega]_x (the skew matrix of omega), never from the entries' own columns.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


def zero(e):
    return truth_table.zero(e)


t = sp.symbols('t', real=True)
phi, th, psi = (f(t) for f in sp.symbols('phi theta psi', cls=sp.Function))
c, s = sp.cos, sp.sin


def R1(a):
    return sp.Matrix([[1, 0, 0], [0, c(a), s(a)], [0, -s(a), c(a)]])


def R2(a):
    return sp.Matrix([[c(a), 0, -s(a)], [0, 1, 0], [s(a), 0, c(a)]])


def R3(a):
    return sp.Matrix([[c(a), s(a), 0], [-s(a), c(a), 0], [0, 0, 1]])


C = R3(psi) * R2(th) * R1(phi)
W = -C.diff(t) * C.T                                 # [omega]_x in body components
assert zero(W + W.T)
dphi, dth, dpsi = sp.symbols('phidot thetadot psidot')
P, T, S = sp.symbols('phi theta psi')
plain = {phi.diff(t): dphi, th.diff(t): dth, psi.diff(t): dpsi}
back = {phi: P, th: T, psi: S}
W = W.subs(plain).subs(back)
w = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]]).applyfunc(sp.trigsimp)
phi, th, psi = P, T, S

# line 19: the sum of the three rates, each carried through the rotations after it
printed19 = (R3(psi) * R2(th) * R1(phi) * sp.Matrix([dphi, 0, 0])
             + R3(psi) * R2(th) * sp.Matrix([0, dth, 0]) + R3(psi) * sp.Matrix([0, 0, dpsi]))
check(19, zero(printed19 - w))

# line 24: the product R_3(psi) R_2(theta)
cps, sps, cth, sth = c(psi), s(psi), c(th), s(th)
printed24 = sp.Matrix([[cps * cth, sps, -cps * sth], [-sps * cth, cps, sth * sps], [sth, 0, cth]])
check(24, zero(printed24 - R3(psi) * R2(th)))

# line 28: R_3(psi) itself
check(28, zero(sp.Matrix([[cps, sps, 0], [-sps, cps, 0], [0, 0, 1]]) - R3(psi)))

# line 32: the body components as three columns
printed32 = (sp.Matrix([cth * cps * dphi, -cth * sps * dphi, sth * dphi])
             + sp.Matrix([sps * dth, cps * dth, 0]) + sp.Matrix([0, 0, dpsi]))
check(32, zero(printed32 - w))

# line 44: the shorthand c_theta, s_theta (a definition, no check)

# lines 49, 51, 53: the rates in terms of omega_x, omega_y, omega_z, solved from w here
wx, wy, wz = sp.symbols('omega_x omega_y omega_z')
sol = sp.solve(list(w - sp.Matrix([wx, wy, wz])), [dphi, dth, dpsi], dict=True)[0]
check(49, zero(sol[dphi] - (wx * cps - wy * sps) / cth))
check(51, zero(sol[dth] - (wx * sps + wy * cps)))
check(53, zero(sol[dpsi] - ((-wx * cps + wy * cps) * sth / cth + wz)))
# the rate as it should read, with the sine on omega_y
assert zero(sol[dpsi] - ((-wx * cps + wy * sps) * sth / cth + wz))

LINES = [19, 24, 28, 32, 44, 49, 51, 53]

ROWS = {
    19: ("holds", "with C = R_3(psi) R_2(theta) R_1(phi) taking reference to body components, -C' C^T is the skew matrix of the body angular velocity, and it equals the sum of the three rates carried through the rotations after each (check 19)"),
    24: ("holds", "the product of R_3(psi) = [[c, s, 0], [-s, c, 0], [0, 0, 1]] and R_2(theta) = [[c, 0, -s], [0, 1, 0], [s, 0, c]], entry by entry (check 24)"),
    28: ("holds", "the frame rotation about axis 3 by psi (check 28)"),
    32: ("holds", "the three columns are R_3 R_2 (phi', 0, 0), R_3 (0, theta', 0) and (0, 0, psi'), and their sum is the body angular velocity read off -C' C^T (check 32)"),
    44: ("not a claim", "the shorthand the entry fixes: c and s with an angle below for its cosine and sine"),
    49: ("holds", "solving omega_x = c_theta c_psi phi' + s_psi theta', omega_y = -c_theta s_psi phi' + c_psi theta' for phi': omega_x c_psi - omega_y s_psi = c_theta phi' (check 49)"),
    51: ("holds", "omega_x s_psi + omega_y c_psi = theta' from the same two equations (check 51)"),
    53: ("typo", "psi' = omega_z - s_theta phi' = (-omega_x c_psi + omega_y s_psi) s_theta / c_theta + omega_z: the printed cosine on omega_y should be a sine (check 53)",
         "\\dot{\\psi} = (-\\omega_x c_{\\psi} + \\omega_y s_{\\psi}) s_{\\theta} / c_{\\theta} + \\omega_z",
         "by hand: omega_z = s_theta phi' + psi' and phi' = (omega_x c_psi - omega_y s_psi)/c_theta, so psi' = omega_z - (omega_x c_psi - omega_y s_psi) s_theta / c_theta, whose omega_y term is + omega_y s_psi s_theta / c_theta, not omega_y c_psi s_theta / c_theta",
         "by hand at a point: psi = 0, theta = pi/4, omega = (0, 1, 0): then phi' = 0, theta' = 1, psi' = 0 (the rate about axis 2 only), but the printed formula gives psi' = (0 + 1 * 1) * 1 + 0 = 1"),
}

if __name__ == "__main__":
    if sys.argv[1:] == ["--write"]:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
