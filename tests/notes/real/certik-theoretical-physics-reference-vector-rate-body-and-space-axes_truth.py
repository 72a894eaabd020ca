"""Independent SymPy truth table for certik-theoretical-physics-reference-vector-rate-body-and-space-axes.md.

The reference follows Goldstein: G_i are a vector's components on the space axes, G'_j on the body
axes, G_i = a_ji G'_j with a the rotation matrix from space to body axes, and dOmega the
infinitesimal rotation of the body in the time dt, omega = dOmega/dt its angular velocity. The
checks build the body axes as a rotation R(t) = exp(t [w]x) about a fixed axis through a constant
angular velocity w, so that a = R^T, and compare the rates at t = 0, where the axes coincide.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero
t = sp.Symbol('t', real=True)
w = sp.Matrix(sp.symbols('w1:4', real=True))             # the angular velocity, constant here
W = sp.Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])    # [w]x
# the body axes' matrix to second order in t (enough for first derivatives at t = 0)
Rt = sp.eye(3) + t * W + t ** 2 * W * W / 2
a = Rt.T                                                 # a_ij: body component i from space component j
Gb = sp.Matrix([sp.Function(f'Gb{k}')(t) for k in range(1, 4)])          # body components G'_j(t)
Gs = Rt * Gb                                             # space components: G_i = a_ji G'_j = (R G')_i

# line 27: a vector fixed in the body (G' constant) changes on the space axes by dOmega x G
g0 = sp.Matrix(sp.symbols('g1:4', real=True))
fixed = Rt * g0
check(27, zero(sp.diff(fixed, t).subs(t, 0) - w.cross(g0)))
# line 33: for any vector, d G_space = d G_body + dOmega x G (rates at the instant the axes coincide)
rate_space = sp.diff(Gs, t).subs(t, 0)
rate_body = sp.diff(Gb, t).subs(t, 0)
check(33, zero(rate_space - rate_body - w.cross(Gb.subs(t, 0))))
# line 40: with the body components G' = a G (a orthogonal, Goldstein's x'_i = a_ij x_j), the space
# components are G_i = a_ji G'_j: checked with an exact rotation matrix of two angles
th, ph = sp.symbols('theta phi', real=True)
Rz = sp.Matrix([[sp.cos(th), -sp.sin(th), 0], [sp.sin(th), sp.cos(th), 0], [0, 0, 1]])
Rx = sp.Matrix([[1, 0, 0], [0, sp.cos(ph), -sp.sin(ph)], [0, sp.sin(ph), sp.cos(ph)]])
aa = (Rz * Rx).T
Gsp = sp.Matrix(sp.symbols('G1:4', real=True))
Gbd = aa * Gsp
check(40, zero(Gsp - sp.Matrix([sum(aa[j, i] * Gbd[j] for j in range(3)) for i in range(3)])))
# line 44: the product rule
dGs = sp.diff(Gs, t)
check(44, zero(dGs - sp.Matrix([sum(a[j, i] * sp.diff(Gb[j], t) + sp.diff(a[j, i], t) * Gb[j] for j in range(3))
                               for i in range(3)])))
# line 52: at coincidence (a = delta), dG_i = dG'_i + eps_ikj dOmega_k G'_j
eps = sp.LeviCivita
alt = sp.Matrix([rate_body[i] + sum(eps(i, k, j) * w[k] * Gb[j].subs(t, 0) for k in range(3) for j in range(3))
                 for i in range(3)])
check(52, zero(rate_space - alt))
# line 64: (dG/dt)_space = (dG/dt)_body + omega x G
check(64, zero(rate_space - (rate_body + w.cross(Gb.subs(t, 0)))))

LINES = [20, 27, 33, 40, 44, 52, 58, 64]

NC = "not a claim"
H = "holds"
ROWS = {
    20: (NC, "names the parts of the change of G: the space change as the body change plus a change due to the rotation, (dG)_rot"),
    27: (H, "a vector fixed in the body turns with it, so its change on the space axes is dOmega x G, which is (dG)_rot since (dG)_body = 0 (check 27)"),
    33: (H, "at the instant the axes coincide, the space rate of G is its body rate plus omega x G, i.e. dG_space = dG_body + dOmega x G (check 33)"),
    40: (H, "the space components from the body components with the rotation matrix's transpose, G_i = a_ji G'_j (check 40)"),
    44: (H, "the product rule on G_i = a_ji G'_j (check 44)"),
    52: (H, "with a = delta and da_ji = eps_ikj dOmega_k: dG_i = dG'_i + eps_ikj dOmega_k G'_j, the i-th component of dOmega x G (check 52)"),
    58: (NC, "defines the angular velocity omega as the rate of the infinitesimal rotation"),
    64: (H, "the rates: (dG/dt)_space = (dG/dt)_body + omega x G (check 64)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
