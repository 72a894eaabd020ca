"""Independent SymPy truth table for cline-principal-axes-orthogonality-dynamic-balancing.md
(Cline, Variational Principles in Classical Mechanics, ch. 13, sections 13.10 and 13.25, MyST edition).

The text's names: omega_{im} is the i-th body component of an angular velocity directed along the
m-th principal axis, I_m (written also I_{mm}) that axis's principal moment, I_{ik} the inertia
tensor in arbitrary body axes. Here the tensor is built as a general symmetric tensor
I = Q diag(I_1, I_2, I_3) Q^T, Q a rotation by three free angles; omega_m = s_m Q e_m with free
lengths s_m; every sum of the text is then evaluated for all m, n (and a free k) and compared. The
orthogonality of (13.54) is also checked on a symmetric matrix diagonalized numerically, with no use
of Q. For 13.25 the thin uniform disk's tensor is integrated, the angular velocity built by turning
e_3 through alpha about e_2, the torque found as dL/dt in the inertial frame (no Euler equations
used), and the bearing forces from the couple of two opposite forces at +-d along the axle.
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import mpmath
import sympy as sp

import truth_table
from truth_table import Rx, Ry, Rz, zero

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# ---- 13.10: a general symmetric tensor and its principal axes ----
a, b, c = sp.symbols('a b c', real=True)
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
s = sp.symbols('s1:4', positive=True)
Q = Rz(a) * Rx(b) * Rz(c)
Imom = [I1, I2, I3]
T = Q * sp.diag(*Imom) * Q.T                     # I_{ik}, symmetric
assert zero(T - T.T)
W = [s[m] * Q[:, m] for m in range(3)]           # omega_m, W[m][i] = omega_{im}
R3 = range(3)


def L(i, m):                                     # L_{im} = sum_k I_{ik} omega_{km}
    return sum(T[i, k] * W[m][k] for k in R3)


# line 52: L_{im} = I_m omega_{im}; line 58: (13.47); line 64: (13.48), the same for axis n
ok52 = all(zero(L(i, m) - Imom[m] * W[m][i]) for i in R3 for m in R3)
check(52, ok52)
check(58, ok52)
check(64, all(zero(sum(T[k, i] * W[n][i] for i in R3) - Imom[n] * W[n][k]) for k in R3 for n in R3))
# line 70: sum_{i,k} I_ik omega_km omega_in = sum_i I_m omega_im omega_in, all m, n
lhs = lambda m, n: sum(T[i, k] * W[m][k] * W[n][i] for i in R3 for k in R3)  # noqa: E731
lhs2 = lambda m, n: sum(T[k, i] * W[m][k] * W[n][i] for i in R3 for k in R3)  # noqa: E731
check(70, all(zero(lhs(m, n) - sum(Imom[m] * W[m][i] * W[n][i] for i in R3)) for m in R3 for n in R3))
# line 76: as printed the right side sums over i a term in a free k: 3 I_n omega_km omega_kn
printed76 = all(zero(lhs2(m, n) - 3 * Imom[n] * W[m][k] * W[n][k]) for m in R3 for n in R3 for k in R3)
fixed76 = all(zero(lhs2(m, n) - sum(Imom[n] * W[m][k] * W[n][k] for k in R3)) for m in R3 for n in R3)
assert fixed76 and not printed76
check(76, printed76)
# line 83: the difference of the two right sides
d83 = lambda m, n: (sum(Imom[m] * W[m][i] * W[n][i] for i in R3)  # noqa: E731
                    - sum(Imom[n] * W[m][k] * W[n][k] for k in R3))
check(83, all(zero(d83(m, n)) for m in R3 for n in R3))
# line 89 and 95 (13.53): (I_m - I_n) sum_k omega_km omega_kn = (I_m - I_n) omega_m . omega_n = 0
check(89, all(zero((Imom[m] - Imom[n]) * sum(W[m][k] * W[n][k] for k in R3)) for m in R3 for n in R3))
check(95, all(zero((Imom[m] - Imom[n]) * W[m].dot(W[n])) for m in R3 for n in R3))
# line 101 (13.54): distinct moments -> perpendicular axes; here from Q, and on a symmetric matrix
# diagonalized numerically (eigenvectors found by mpmath, no Q)
with mpmath.workdps(30):
    A = mpmath.matrix([[5, -2, 1], [-2, 3, mpmath.mpf(1) / 2], [1, mpmath.mpf(1) / 2, 7]])
    ev, V = mpmath.eigsy(A)
    distinct = min(abs(ev[i] - ev[j]) for i in R3 for j in R3 if i < j) > 0.1
    eig_ok = max(abs(mpmath.norm(A * V[:, j] - ev[j] * V[:, j])) for j in R3) < mpmath.mpf(10) ** -20
    ortho = max(abs(sum(V[k, i] * V[k, j] for k in R3)) for i in R3 for j in R3 if i < j) < mpmath.mpf(10) ** -20
check(101, distinct and eig_ok and ortho and all(zero(W[m].dot(W[n])) for m in R3 for n in R3 if m != n))

# ---- 13.25: the tilted disk ----
M, Rr, w, d, t = sp.symbols('M R omega d t', positive=True)
al = sp.Symbol('alpha', positive=True)
r, ph = sp.symbols('r varphi', positive=True)
sig = M / (sp.pi * Rr**2)
pos = sp.Matrix([r * sp.cos(ph), r * sp.sin(ph), 0])   # the disk in its 1-2 plane
Idisk = sp.zeros(3, 3)
for i in R3:
    for j in R3:
        f = (pos.dot(pos) * (1 if i == j else 0) - pos[i] * pos[j]) * sig * r
        Idisk[i, j] = sp.integrate(sp.integrate(f, (ph, 0, 2 * sp.pi)), (r, 0, Rr))
# line 134: I = M R^2/4 diag(1, 1, 2)
check(134, zero(Idisk - M * Rr**2 / 4 * sp.diag(1, 1, 2)))
# line 141: the axle: e_3 turned by alpha about e_2 stays in the e_1-e_3 plane; omega along it.
# The text's '\ cos' is a markup glitch (a backslash space before cos) rendering as 'cos'; read as cos.
u = Ry(al) * sp.Matrix([0, 0, 1])
wb = w * u
check(141, zero(wb - sp.Matrix([w * sp.sin(al), 0, w * sp.cos(al)])) and zero(u.dot(u) - 1)
      and zero(u[2] - sp.cos(al)))
# line 147: the torque from dL/dt in an inertial frame with the axle along z: the body's orientation
# B(t) = Rz(omega t) B0, B0 taking body components to space ones with B0 u = z
B0 = Ry(-al)
assert zero(B0 * u - sp.Matrix([0, 0, 1]))
B = Rz(w * t) * B0
w_space = sp.Matrix([0, 0, w])
assert zero(B.T * w_space - wb)                 # the body components of omega stay fixed: omega' = 0
Lsp = B * Idisk * B.T * w_space
Nbody = sp.simplify(B.T * sp.diff(Lsp, t))
check(147, zero(Nbody - sp.Matrix([0, -w**2 * sp.sin(al) * sp.cos(al) * M * Rr**2 / 4, 0])))
# line 154: bearings at +-d u from the centre, forces F and -F normal to the axle (in the plane of
# e_1 and e_3, where the couple must lie across e_2): the couple is d u x F + (-d u) x (-F) = 2 d u x F
F1, F3 = sp.symbols('F1 F3', real=True)
Fv = sp.Matrix([F1, 0, F3])
sol = sp.solve(list(2 * d * u.cross(Fv) - Nbody) + [Fv.dot(u)], [F1, F3], dict=True)
Fs = Fv.subs(sol[0])
N2 = Nbody[1]                                   # negative for 0 < alpha < pi/2: |N_2| = -N_2
ok154 = zero(Fs.dot(Fs) - (N2 / (2 * d))**2) \
    and zero(-N2 / (2 * d) - M * Rr**2 * w**2 * sp.sin(2 * al) / (16 * d))
check(154, ok154)

LINES = [52, 58, 64, 70, 76, 83, 89, 95, 101, 134, 141, 147, 154]

ROWS = {
    52: ("holds", "along a principal axis the tensor acts as its moment: for I = Q diag(I_1, I_2, I_3) Q^T and omega_m = s_m Q e_m, sum_k I_ik omega_km = I_m omega_im for every i, m (check 52)"),
    58: ("holds", "the same eigen-relation with the sum over k written out (check 52)"),
    64: ("holds", "the same relation for the n-th axis, with the symmetric tensor's indices as printed, I_ki (check 64)"),
    70: ("holds", "(13.47) times omega_in summed over i: sum_{i,k} I_ik omega_km omega_in = I_m sum_i omega_im omega_in, I_mm standing for the principal moment I_m as in the text (check 70)"),
    76: ("typo", "(13.48) times omega_km summed over k gives I_n sum_k omega_km omega_kn; the display sums over i a term that carries only k, which leaves k free on the right while the left has no free index (read literally, 3 I_n omega_km omega_kn); the next display sums it over k (check 76)", "\\sum_{i,k} I_{ki} \\omega_{km}\\omega_{in} = \\sum_k I_{nn}\\omega_{km}\\omega_{kn}", "Principal axes along the body axes (Q = 1), unit omega_m = e_m, m = n = 1, I_1 = 2: left side sum_{i,k} I_ki omega_k1 omega_i1 = I_11 = 2. Right side as printed, sum_i I_11 omega_k1 omega_k1 for k = 1: 3 * 2 * 1 = 6 (and 0 for k = 2); with the sum over k: 2 * (1 + 0 + 0) = 2, equal to the left.", "Index count: on the left i and k are both summed, so only m and n remain; on the right the summation index i does not occur in I_nn omega_km omega_kn, and k is free, so the two sides are not even the same kind of object; the following display, the difference of the two right sides, writes this term as sum_k I_nn omega_km omega_kn, the corrected form."),
    83: ("holds", "the two left sides are equal because I_ik = I_ki, so the right sides of (13.47) x omega_in and (13.48) x omega_km differ by zero; true for every m, n (check 83)"),
    89: ("holds", "both sums run over the same components, so the difference is (I_m - I_n) sum_k omega_km omega_kn, zero for every m, n (check 89)"),
    95: ("holds", "sum_k omega_km omega_kn is the dot product omega_m . omega_n (check 95)"),
    101: ("holds", "for I_m != I_n the factor can be divided out: omega_m . omega_n = 0; also checked on a symmetric matrix with distinct eigenvalues diagonalized numerically, its eigenvectors mutually perpendicular (check 101)"),
    134: ("holds", "thin uniform disk of mass M, radius R in its 1-2 plane: I_11 = I_22 = M R^2/4, I_33 = M R^2/2, products zero, by integration over the disk (check 134)"),
    141: ("holds", "the axle is e_3 turned by alpha about e_2, in the plane of e_1 and e_3: omega = omega (sin alpha, 0, cos alpha); the '\\ cos' is a markup glitch (backslash-space before cos, rendering as italic cos), read as cos alpha (check 141)"),
    147: ("holds", "dL/dt in the inertial frame, the body turning at omega about the fixed axle, carried to body axes: N = (0, -omega^2 sin alpha cos alpha M R^2/4, 0), the same as Euler's equations with omega' = 0 and I_3 - I_1 = M R^2/4 (check 147)"),
    154: ("holds", "with the bearings at +-d along the axle from the centre, as the formula takes them, opposite forces F, -F across the axle give the couple 2 d u x F, so |F| = |N_2|/(2 d) = (M R^2/4) omega^2 sin alpha cos alpha/(2 d) = M R^2 omega^2 sin 2alpha/(16 d) (check 154)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
