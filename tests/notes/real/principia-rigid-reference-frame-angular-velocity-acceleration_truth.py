"""Independent SymPy truth table for principia-rigid-reference-frame-angular-velocity-acceleration.tex.

The text's convention: vectors of R^3, the wedge \\wedge is the cross product and \\scal{.}{.} the
scalar product; r = q_2 - q_1, the frame F = r, B = r x r', N = B x F and its unit vectors f, n,
b; the angular velocity w is the vector with w x f = f', w x n = n', w x b = b'. The derivations
use a real motion: r(t) a cubic in t with random rational coefficients (and V(t) likewise for the
formulae on V/|V|), everything differentiated exactly and compared at a few times. The angular
velocity is computed independently of the text's formula, from the rotation matrix R = [f n b]
(R' R^T = [w]x). The jerk field is checked for two attracting bodies with the Jacobians SymPy
takes of the field itself, and the body-surface frame with explicit unit vectors x, y, z.
"""
import random
import sys

import sympy as sp

import truth_table

t = sp.Symbol('t', real=True)
rng = random.Random(17)
CHECKS = {}
TIMES = [sp.Rational(1, 3), sp.Rational(-4, 5), sp.Rational(7, 4)]


def check(line, ok):
    CHECKS[line] = bool(ok)


def vanishes(e):
    """True when the scalar or vector expression in t vanishes at the sample times."""
    items = list(e) if isinstance(e, sp.MatrixBase) else [e]
    return all(abs(sp.N(sp.sympify(x).subs(t, tt), 40)) < 1e-25 for x in items for tt in TIMES)


def cubic():
    return sp.Matrix([sum(sp.Rational(rng.randint(-9, 9), rng.randint(1, 4)) * t**k for k in range(4))
                      for _ in range(3)])


dot = lambda u, v: (u.T * v)[0]                                   # noqa: E731
norm = lambda u: sp.sqrt(dot(u, u))                               # noqa: E731
D = lambda u, k=1: u.diff(t, k)                                   # noqa: E731

# ---- 40, 48: derivatives of V/|V|
V = cubic()
u = V / norm(V)
sVV = dot(V, D(V))
first = [(norm(V) * D(V) - D(norm(V)) * V) / norm(V)**2,
         (norm(V) * D(V) - sVV / norm(V) * V) / norm(V)**2,
         D(V) / norm(V) - V * sVV / norm(V)**3]
check(40, all(vanishes(D(u) - x) for x in first))
X = norm(V)**2 * D(V) - sVV * V
second = [D(X / norm(V)**3),
          (norm(V)**3 * D(X) - 3 * norm(V) * sVV * X) / norm(V)**6,
          (2 * sVV * D(V) + norm(V)**2 * D(V, 2) - (dot(D(V), D(V)) + dot(V, D(V, 2))) * V - sVV * D(V)) / norm(V)**3
          - 3 * (norm(V)**3 * sVV * D(V) - norm(V) * sVV**2 * V) / norm(V)**6,
          D(V, 2) / norm(V) - 2 * D(V) * sVV / norm(V)**3 - V * (dot(D(V), D(V)) + dot(V, D(V, 2))) / norm(V)**3
          + 3 * V * sVV**2 / norm(V)**5]
check(48, all(vanishes(D(u, 2) - x) for x in second))

# ---- the trihedron of a moving r
r = cubic()
F = r
B = r.cross(D(r))
N = B.cross(F)
f, n, b = F / norm(F), N / norm(N), B / norm(B)
# 66: F' = r', B' = r x r'', N' = B' x F + B x F'
check(66, vanishes(D(F) - D(r)) and vanishes(D(B) - r.cross(D(r, 2)))
      and vanishes(D(N) - (D(B).cross(F) + B.cross(D(F)))))
R = sp.Matrix.hstack(f, n, b)
assert vanishes(R.T * R - sp.eye(3)) and all(abs(sp.N(R.det().subs(t, tt)) - 1) < 1e-20 for tt in TIMES)
Om = D(R) * R.T                                                   # [w]x in the fixed axes
w = sp.Matrix([Om[2, 1], Om[0, 2], Om[1, 0]])
assert vanishes(w.cross(f) - D(f)) and vanishes(w.cross(n) - D(n)) and vanishes(w.cross(b) - D(b))
al, be, ga = dot(w, f), dot(w, n), dot(w, b)
# 83: f' = be n x f + ga b x f, n' = al f x n + ga b x n, b' = al f x b + be n x b
check(83, vanishes(D(f) - (be * n.cross(f) + ga * b.cross(f))) and vanishes(D(n) - (al * f.cross(n) + ga * b.cross(n)))
      and vanishes(D(b) - (al * f.cross(b) + be * n.cross(b))))
# 91: <f', n> = ga, <n', b> = al, <b', f> = be
check(91, vanishes(dot(D(f), n) - ga) and vanishes(dot(D(n), b) - al) and vanishes(dot(D(b), f) - be))
# 99: w = <n', b> f + <b', f> n + <f', n> b
w_text = dot(D(n), b) * f + dot(D(b), f) * n + dot(D(f), n) * b
check(99, vanishes(w - w_text))
# 105: F'' = r'', B'' = r' x r'' + r x r''', N'' = B'' x F + 2 B' x F' + B x F''
check(105, vanishes(D(F, 2) - D(r, 2)) and vanishes(D(B, 2) - (D(r).cross(D(r, 2)) + r.cross(D(r, 3))))
      and vanishes(D(N, 2) - (D(B, 2).cross(F) + 2 * D(B).cross(D(F)) + B.cross(D(F, 2)))))
# 114: w' by the product rule on 99
wd_text = (dot(D(n, 2), b) * f + dot(D(n), D(b)) * f + dot(D(n), b) * D(f)
           + dot(D(b, 2), f) * n + dot(D(b), D(f)) * n + dot(D(b), f) * D(n)
           + dot(D(f, 2), n) * b + dot(D(f), D(n)) * b + dot(D(f), n) * D(b))
check(114, vanishes(D(w) - wd_text))

# ---- jerk of the field of two bodies
q = sp.Matrix(sp.symbols('q_x q_y q_z', real=True))
qk = [sp.Matrix(sp.symbols(f'p{k}_x p{k}_y p{k}_z', real=True)) for k in range(2)]
mu = sp.symbols('mu0 mu1', positive=True)
dk = [qk[k] - q for k in range(2)]
G = sum((mu[k] * dk[k] / norm(dk[k])**3 for k in range(2)), sp.zeros(3, 1))
I3 = sp.eye(3)
num = {s: sp.Rational(rng.randint(-9, 9), rng.randint(1, 3)) for s in list(q) + list(qk[0]) + list(qk[1])}
num.update({mu[0]: sp.Rational(3, 2), mu[1]: sp.Rational(5, 7)})


def same(e):
    items = list(e) if isinstance(e, sp.MatrixBase) else [e]
    return all(abs(sp.N(sp.sympify(x).xreplace(num), 40)) < 1e-25 for x in items)


dGk = [G.jacobian(qk[k]) for k in range(2)]
dGq = G.jacobian(q)
# 126: dG/dt = dG/dq q' + sum dG/dq_k q_k' (the chain rule, on paths q(t), q_k(t) linear in t)
vq = sp.Matrix(sp.symbols('v_x v_y v_z', real=True))
vk = [sp.Matrix(sp.symbols(f'u{k}_x u{k}_y u{k}_z', real=True)) for k in range(2)]
num.update({s: sp.Rational(rng.randint(-9, 9), 2) for s in list(vq) + list(vk[0]) + list(vk[1])})
path = {**{q[i]: q[i] + vq[i] * t for i in range(3)},
        **{qk[k][i]: qk[k][i] + vk[k][i] * t for k in range(2) for i in range(3)}}
dGdt = G.xreplace(path).diff(t).subs(t, 0)
check(126, same(dGdt - (dGq * vq + sum((dGk[k] * vk[k] for k in range(2)), sp.zeros(3, 1)))))
# 134: dG/dq_k, step by step
k = 0
nd = norm(dk[k])
steps = [mu[k] * (dk[k] / nd**3).jacobian(qk[k]),
         mu[k] * (dk[k].jacobian(qk[k]) / nd**3 - 3 * dk[k] * sp.Matrix([nd]).jacobian(qk[k]) / nd**4),
         mu[k] * (I3 / nd**3 - 3 * dk[k] * (dk[k].T / nd) / nd**4),
         mu[k] * (I3 / nd**3 - 3 * dk[k] * dk[k].T / nd**5)]
check(134, all(same(dGk[k] - s) for s in steps))
# 141: dG/dq = sum mu_k (-I/|d|^3 + 3 d d^T/|d|^5)
check(141, same(dGq - sum((mu[j] * (-I3 / norm(dk[j])**3 + 3 * dk[j] * dk[j].T / norm(dk[j])**5)
                           for j in range(2)), sp.zeros(3))))
# 147: dG/dt = sum mu_k (I/|d|^3 - 3 d d^T/|d|^5)(q_k' - q')
check(147, same(dGdt - sum((mu[j] * (I3 / norm(dk[j])**3 - 3 * dk[j] * dk[j].T / norm(dk[j])**5) * (vk[j] - vq)
                            for j in range(2)), sp.zeros(3, 1))))

# ---- the body-surface frame
om, ph = sp.symbols('omega varphi', positive=True)
x, y, z = I3[:, 0], I3[:, 1], I3[:, 2]
th = om * t + ph
rs = x * sp.cos(th) + y * sp.sin(th)
zs = lambda e: all(sp.simplify(c) == 0 for c in e)                 # noqa: E731
# 162: r', r'' = -w^2 r, r''' = -w^2 r'
check(162, zs(D(rs) - (-x * om * sp.sin(th) + y * om * sp.cos(th)))
      and zs(D(rs, 2) - (-x * om**2 * sp.cos(th) - y * om**2 * sp.sin(th))) and zs(D(rs, 2) + om**2 * rs)
      and zs(D(rs, 3) - (x * om**3 * sp.sin(th) - y * om**3 * sp.cos(th))) and zs(D(rs, 3) + om**2 * D(rs)))
Fs, Bs = rs, rs.cross(D(rs))
Ns = Bs.cross(Fs)
# 170: F = r, B = w z, N = r'
check(170, zs(Bs - om * z) and zs(Ns - D(rs)))
fs, bs, ns = Fs / sp.sqrt(sp.simplify(dot(Fs, Fs))), Bs / sp.sqrt(sp.simplify(dot(Bs, Bs))), Ns / sp.sqrt(sp.simplify(dot(Ns, Ns)))
# 178: f = r, b = z, n = r'/w (w > 0)
check(178, zs(fs - rs) and zs(bs - z) and zs(ns - D(rs) / om))
# 186: f' = r', b' = 0, n' = r''/w = -w r
check(186, zs(D(fs) - D(rs)) and zs(D(bs)) and zs(D(ns) - D(rs, 2) / om) and zs(D(ns) + om * rs))
# 194: f'' = r'' = -r (r'' is -w^2 r); b' = 0; n' = -w r' (n' is -w r; n'' is -w r')
line194 = zs(D(fs, 2) - D(rs, 2)) and zs(D(rs, 2) + rs) and zs(D(bs)) and zs(D(ns) + om * D(rs))
fixed194 = zs(D(fs, 2) + om**2 * rs) and zs(D(bs, 2)) and zs(D(ns, 2) + om * D(rs))
assert fixed194 and not line194
check(194, line194)

# negative controls: a sign slip in the first derivative of V/|V| and in the angular velocity
assert not vanishes(D(u) - (D(V) / norm(V) + V * sVV / norm(V)**3))
assert not vanishes(w - (-dot(D(n), b) * f + dot(D(b), f) * n + dot(D(f), n) * b))

LINES = [19, 28, 40, 48, 66, 75, 83, 91, 99, 105, 114, 122, 126, 134, 141, 147, 158, 162, 170, 178, 186, 194]

ROWS = {
    19: ('not a claim', 'defines the fore, binormal and normal vectors of the frame from r = q_2 - q_1'),
    28: ('not a claim', 'defines the orthonormal basis as the three vectors normalized'),
    40: ('holds', 'the derivative of V/|V|, each of its three members (check 40)'),
    48: ('holds', 'the second derivative of V/|V|, each of its four members (check 48)'),
    66: ('holds', "the derivatives of F = r, B = r x r' (r' x r' = 0) and N = B x F (check 66)"),
    75: ('not a claim', 'defines the angular velocity by its action on the three unit vectors'),
    83: ('holds', "w = al f + be n + ga b substituted in w x f = f' and its two companions (check 83)"),
    91: ('holds', "the scalar products of the three lines with n, b and f leave ga, al and be (check 91)"),
    99: ('holds', "the angular velocity from the scalar products, equal to the one R' R^T gives (check 99)"),
    105: ('holds', "the second derivatives of F, B and N (check 105)"),
    114: ('holds', 'the product rule on the expression of the angular velocity (check 114)'),
    122: ('not a claim', 'defines the gravitational acceleration field of the n bodies'),
    126: ('holds', 'the chain rule for the total derivative of the field (check 126)'),
    134: ('holds', 'the Jacobian of the field with respect to q_k, each step (check 134)'),
    141: ('holds', 'the Jacobian with respect to q, the opposite of the sum of those with respect to the q_k (check 141)'),
    147: ('holds', 'the jerk: the two Jacobians applied to the velocities (check 147)'),
    158: ('not a claim', 'chooses the unit vector r turning with the surface'),
    162: ('holds', "the derivatives of r, with r'' = -w^2 r and r''' = -w^2 r' (check 162)"),
    170: ('holds', "F = r, B = r x r' = w z and N = B x F = r' (check 170)"),
    178: ('holds', "the unit vectors, |r| = 1, |B| = w and |r'| = w for w > 0 (check 178)"),
    186: ('holds', "f' = r', b' = 0 and n' = r''/w = -w r (check 186)"),
    194: ('typo', "meant as the second derivatives: f'' = r'' is -w^2 r, not -r, and its last line, n'' = -w r', is printed as n' (which is -w r, by the display before); its middle line b' = 0 is true (check 194)",
          r"\ddot{\vf} &= \ddot{\vr} = -\gw^2 \vr \\ \ddot{\vb} &= 0 \\ \ddot{\vn} &= -\gw \dot{\vr}",
          "r = x cos(w t + j) + y sin(w t + j) gives r'' = -w^2 (x cos + y sin) = -w^2 r, as the text's own display of the derivatives of r says; so f'' = r'' = -w^2 r and the printed -r drops the factor w^2 (wrong for w different from 1). The text's previous display gives n' = r''/w = -w r; differentiating again, n'' = -w r'. The printed last line says n' = -w r', which contradicts n' = -w r (r and r' are orthogonal, both nonzero).",
          "Special case w = 2, j = 0, t = 0: r = x, r' = 2 y, r'' = -4 x. Then f'' = r'' = -4 x while the printed -r is -x. n = r'/w = (-sin 2t, cos 2t, 0), so n' = (-2 cos 2t, -2 sin 2t, 0) = -2 x at t = 0, while the printed -w r' = -4 y; n'' = (4 sin 2t, -4 cos 2t, 0) = -4 y at t = 0, which is -w r' as the corrected line says."),
}

if __name__ == "__main__":
    if sys.argv[1:] == ['--write']:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
