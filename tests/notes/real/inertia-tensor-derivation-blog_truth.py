"""Independent SymPy truth table for inertia-tensor-derivation-blog.md.
Text's names: point mass m at r = (x, y, z), omega = (omega_x, omega_y, omega_z), L angular momentum,
[I] inertia tensor (includes the mass), particles m_i at r_i, body G, unit vectors x-hat etc."""
import sys, os, tomllib
import sympy as sp

HERE = os.path.dirname(os.path.abspath(__file__))
SLUG = "inertia-tensor-derivation-blog"
TOML = tomllib.load(open(os.path.join(HERE, SLUG + ".truth.toml"), "rb"))["display"]
VERD = []
def check(ok, kind="claim", fixed_ok=None):
    if kind == "nac":
        VERD.append("not a claim"); return
    VERD.append("holds" if ok else ("typo" if fixed_ok else "fails"))
def zero(e):
    if isinstance(e, sp.MatrixBase):
        return all(sp.simplify(c) == 0 for c in e)
    return sp.simplify(e) == 0

m = sp.symbols("m", positive=True)
x, y, z = sp.symbols("x y z", real=True)
wx, wy, wz = sp.symbols("omega_x omega_y omega_z", real=True)
r = sp.Matrix([x, y, z]); w = sp.Matrix([wx, wy, wz])
r2 = x**2 + y**2 + z**2
def M3(X, Y, Z):  # the text's matrix (as typed, with -yx, -zx, -zy entries)
    return sp.Matrix([[Y**2 + Z**2, -X*Y, -X*Z], [-Y*X, Z**2 + X**2, -Y*Z], [-Z*X, -Z*Y, X**2 + Y**2]])
Ltrue = m*r.cross(w.cross(r))
ex, ey, ez = sp.eye(3).col(0), sp.eye(3).col(1), sp.eye(3).col(2)

check(True, "nac")                                              # macros
# d1: L = r x p = r x (m v) = m [r x (omega x r)]
v = w.cross(r)
check(zero(r.cross(m*v) - Ltrue))
# d2: cross product determinant
ux, uy, uz, vx, vy, vz = sp.symbols("u_x u_y u_z v_x v_y v_z", real=True)
u_ = sp.Matrix([ux, uy, uz]); v_ = sp.Matrix([vx, vy, vz])
det = ex*(uy*vz - uz*vy) - ey*(ux*vz - uz*vx) + ez*(ux*vy - uy*vx)
comp = (uy*vz - uz*vy)*ex + (uz*vx - ux*vz)*ey + (ux*vy - uy*vx)*ez
check(zero(u_.cross(v_) - det) and zero(det - comp))
# d3: triple product
A = sp.Matrix(sp.symbols("a1:4", real=True)); B = sp.Matrix(sp.symbols("b1:4", real=True)); C = sp.Matrix(sp.symbols("c1:4", real=True))
check(zero(A.cross(B.cross(C)) - (A.dot(C)*B - A.dot(B)*C)))
# d4: L = m[r^2 omega - (r.omega) r]
check(zero(m*(r2*w - r.dot(w)*r) - Ltrue))
# d5: x-component rows
rows = [m*(r2*wx - r.dot(w)*x), m*(r2*wx - (x*wx + y*wy + z*wz)*x),
        m*((r2 - x**2)*wx - x*y*wy - x*z*wz), m*((y**2 + z**2)*wx - x*y*wy - x*z*wz)]
check(all(zero(rw - Ltrue[0]) for rw in rows))
# d6: full components
Lfull = m*sp.Matrix([(y**2 + z**2)*wx - x*y*wy - x*z*wz, -y*x*wx + (z**2 + x**2)*wy - y*z*wz, -z*x*wx - z*y*wy + (x**2 + y**2)*wz])
check(zero(Lfull - Ltrue))
# d7: matrix form
check(zero(m*M3(x, y, z)*w - Ltrue))
# d8, d9: collection of particles
P = [(sp.Symbol(f"m{i}", positive=True), sp.Matrix(sp.symbols(f"x{i} y{i} z{i}", real=True))) for i in range(3)]
Lsys = sum((mi*ri.cross(w.cross(ri)) for mi, ri in P), sp.zeros(3, 1))
rhs8 = sum((mi*M3(*ri)*w for mi, ri in P), sp.zeros(3, 1))
check(zero(Lsys - rhs8))
Isys = sum((mi*M3(*ri) for mi, ri in P), sp.zeros(3, 3))
check(zero(Lsys - Isys*w))
# d10: integral version: the integrand (per unit mass) times omega equals the point-mass L per unit mass,
# and omega (constant) factors out of the integral: linearity of the integrand in omega.
integrand = M3(x, y, z)*w
check(zero(integrand - r.cross(w.cross(r))) and zero(integrand.jacobian(w) - M3(x, y, z)))
# d11: I_G = integral of the same matrix: consistent with d10 (same matrix)
check(zero(M3(x, y, z) - M3(x, y, z).T) and zero(M3(x, y, z)*w - r.cross(w.cross(r))))
# d12: Kronecker delta definition
check(True, "nac")
# d13: I_ij = int (r^2 delta_ij - x_i x_j) dm
xs = [x, y, z]
Iij = sp.Matrix(3, 3, lambda i, j: r2*sp.KroneckerDelta(i, j) - xs[i]*xs[j])
check(zero(Iij - M3(x, y, z)))
# d14, d15: definitions
check(True, "nac"); check(True, "nac")
# d16: r^2 Id - r (x) r
check(zero(r2*sp.eye(3) - r*r.T - M3(x, y, z)))
# d17: L_omega = L . omega-hat = omega-hat^T L
n1, n2, n3 = sp.symbols("n1 n2 n3", real=True)
nhat = sp.Matrix([n1, n2, n3])
Lv = sp.Matrix(sp.symbols("L1:4", real=True))
check(zero(Lv.dot(nhat) - (nhat.T*Lv)[0]))
# d18: omega-hat^T (I omega) = (omega-hat^T I omega-hat) omega, with omega = Omega * n-hat
Om = sp.symbols("Omega", positive=True)
Ibody = Isys
lhs = (nhat.T*(Ibody*(Om*nhat)))[0]; rhs = (nhat.T*Ibody*nhat)[0]*Om
check(zero(lhs - rhs))
# d19: I_omega = n^T I n equals sum m (r^2 - (r.n)^2) for a unit vector n (moment about the axis)
th, ph = sp.symbols("theta phi", real=True)
nunit = sp.Matrix([sp.sin(th)*sp.cos(ph), sp.sin(th)*sp.sin(ph), sp.cos(th)])
quad = (nunit.T*Isys*nunit)[0]
perp = sum(mi*(ri.dot(ri) - ri.dot(nunit)**2) for mi, ri in P)
check(zero(sp.trigsimp(sp.expand(quad - perp))))
# d20: x-hat_i^T I x-hat_j = I_ij
E3 = sp.eye(3)
check(all(zero((E3.col(i).T*Isys*E3.col(j))[0] - Isys[i, j]) for i in range(3) for j in range(3)))
# d21: bare expression
check(True, "nac")

if __name__ == "__main__":
    assert len(VERD) == len(TOML), (len(VERD), len(TOML))
    bad = 0
    for e, vv in zip(TOML, VERD):
        ok = e["verdict"] == vv
        print(f"line {e['line']:4d}  computed {vv:12s} toml {e['verdict']:12s} {'OK' if ok else 'MISMATCH'}")
        bad += not ok
    sys.exit(1 if bad else 0)
