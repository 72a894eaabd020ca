"""Independent SymPy truth table for rigid-body-inertia-tensor-blog-nrsyed.md.
Names follow the text: r_i = (x, y, z) of particle i, omega = (w_x, w_y, w_z),
L angular momentum, T torque (bold T), I inertia matrix with I_xy = -int xy dm, alpha = omega-dot."""
import sys, os, tomllib
import sympy as sp

HERE = os.path.dirname(os.path.abspath(__file__))
SLUG = "rigid-body-inertia-tensor-blog-nrsyed"
TOML = tomllib.load(open(os.path.join(HERE, SLUG + ".truth.toml"), "rb"))["display"]

VERD = []  # computed verdicts in display order
def check(ok, kind="claim"):
    """kind: 'claim' -> holds if ok else fails; 'nac' -> not a claim"""
    if kind == "nac":
        VERD.append("not a claim")
    else:
        VERD.append("holds" if ok else "fails")

def zero(e):
    e = sp.Matrix(e) if isinstance(e, (list, tuple)) else e
    if isinstance(e, sp.MatrixBase):
        return all(sp.simplify(c) == 0 for c in e)
    return sp.simplify(e) == 0

t = sp.symbols("t", real=True)
m, wx, wy, wz = sp.symbols("m omega_x omega_y omega_z", real=True)
x, y, z = sp.symbols("x y z", real=True)
w = sp.Matrix([wx, wy, wz])
r = sp.Matrix([x, y, z])

# three particles with independent coordinates, used for sums
P = [(sp.Symbol(f"m{i}", positive=True), sp.Matrix(sp.symbols(f"x{i} y{i} z{i}", real=True))) for i in range(3)]

def Imat(rv):  # text's matrix in Equation 3b
    X, Y, Z = rv
    return sp.Matrix([[Y**2 + Z**2, -X*Y, -X*Z], [-X*Y, X**2 + Z**2, -Y*Z], [-X*Z, -Y*Z, X**2 + Y**2]])

# d1: F = m dv/dt = d/dt(m v), constant m
v = sp.Matrix([sp.Function(f"v{k}")(t) for k in range(3)])
check(zero(m*v.diff(t) - (m*v).diff(t)))
# d2: F = p-dot : law
check(True, "nac")
# d3: sum d/dt(m_i v_i) = sum p_i-dot, p_i = m_i v_i
vs = [sp.Matrix([sp.Function(f"v{i}{k}")(t) for k in range(3)]) for i in range(3)]
lhs = sum(((mi*vi).diff(t) for (mi, _), vi in zip(P, vs)), sp.zeros(3, 1))
rhs = sum(((mi*vi).diff(t) for (mi, _), vi in zip(P, vs)), sp.zeros(3, 1))
check(zero(lhs - rhs))
# d4: T = sum r_i x p_i-dot = sum r_i x d/dt(m_i v_i)
rs = [sp.Matrix([sp.Function(f"r{i}{k}")(t) for k in range(3)]) for i in range(3)]
a = sum((ri.cross((mi*ri.diff(t)).diff(t)) for (mi, _), ri in zip(P, rs)), sp.zeros(3, 1))
b = sum((ri.cross(mi*ri.diff(t).diff(t)) for (mi, _), ri in zip(P, rs)), sp.zeros(3, 1))
check(zero(a - b))
# d5: L-dot = sum r_i x d/dt(m_i v_i), L = sum r_i x m_i v_i
L = sum((ri.cross(mi*ri.diff(t)) for (mi, _), ri in zip(P, rs)), sp.zeros(3, 1))
check(zero(L.diff(t) - a))
# d6: T = L-dot : law ; d7: definition of L
check(True, "nac"); check(True, "nac")
# d8: Equation 2, v_i = omega x r_i
L_def = sum((ri.cross(mi*w.cross(ri)) for mi, ri in P), sp.zeros(3, 1))
L_eq2 = sum((mi*ri.cross(w.cross(ri)) for mi, ri in P), sp.zeros(3, 1))
check(zero(L_def - L_eq2))
# d9: determinant form of omega x r
ii, jj, kk = sp.Matrix([1, 0, 0]), sp.Matrix([0, 1, 0]), sp.Matrix([0, 0, 1])
def det_vec(row2, row3):
    return (ii*(row2[1]*row3[2] - row2[2]*row3[1]) - jj*(row2[0]*row3[2] - row2[2]*row3[0])
            + kk*(row2[0]*row3[1] - row2[1]*row3[0]))
check(zero(det_vec(w, r) - w.cross(r)))
# d10: components as typed (the &#8211; entity read as minus)
wxr_text = sp.Matrix([wy*z - wz*y, -wx*z + wz*x, wx*y - wy*x])
check(zero(wxr_text - w.cross(r)))
# d11: determinant with rows (x,y,z) and text's components
check(zero(det_vec(r, wxr_text) - r.cross(w.cross(r))))
# d12: Equation 3a as typed
eq3a = sp.Matrix([wx*(y**2 + z**2) - wy*x*y - wz*x*z,
                  -wx*x*y + wy*(x**2 + z**2) - wz*y*z,
                  -wx*x*z - wy*y*z + wz*(x**2 + y**2)])
check(zero(eq3a - r.cross(w.cross(r))))
# d13: Equation 3b
check(zero(Imat(r)*w - r.cross(w.cross(r))))
# d14: Equation 4 with 3 particles
check(zero(L_eq2 - sum((mi*Imat(ri)*w for mi, ri in P), sp.zeros(3, 1))))
# d15: sum taken entrywise inside the matrix
Msum = sp.Matrix(3, 3, lambda p, q: sum(Imat(ri)[p, q]*mi for mi, ri in P))
check(zero(L_eq2 - Msum*w))
# d16: Equation 5 (continuum limit: integrand entries identical to the sum's entries)
eq5_integrand = sp.Matrix([[y**2 + z**2, -x*y, -x*z], [-x*y, x**2 + z**2, -y*z], [-x*z, -y*z, x**2 + y**2]])
check(zero(eq5_integrand - Imat(r)))
# d17-d22: abbreviations equal to entries of Equation 5 (integrands)
Ixx, Iyy, Izz = y**2 + z**2, x**2 + z**2, x**2 + y**2
Ixy = Iyx = -(x*y); Ixz = Izx = -(x*z); Iyz = Izy = -(y*z)
check(zero(Ixx - eq5_integrand[0, 0])); check(zero(Iyy - eq5_integrand[1, 1])); check(zero(Izz - eq5_integrand[2, 2]))
check(zero(Ixy - eq5_integrand[0, 1]) and zero(Iyx - eq5_integrand[1, 0]))
check(zero(Ixz - eq5_integrand[0, 2]) and zero(Izx - eq5_integrand[2, 0]))
check(zero(Iyz - eq5_integrand[1, 2]) and zero(Izy - eq5_integrand[2, 1]))
# d23: Equation 6
eq6 = sp.Matrix([[Ixx, Ixy, Ixz], [Iyx, Iyy, Iyz], [Izx, Izy, Izz]])
check(zero(eq6 - eq5_integrand))
# d24: Equation 7  L = I omega
check(zero(eq6*w - r.cross(w.cross(r))))

# Rotating body for the dynamics claims: dumbbell, two masses m at +-a(sin th cos wt, sin th sin wt, cos th),
# omega = W z-hat constant, and a general body with time-dependent omega for d(I omega)/dt.
aa, th, W = sp.symbols("a theta W", positive=True)
rd = aa*sp.Matrix([sp.sin(th)*sp.cos(W*t), sp.sin(th)*sp.sin(W*t), sp.cos(th)])
wd = sp.Matrix([0, 0, W])
parts = [(m, rd), (m, -rd)]
Ld = sum((mi*ri.cross(ri.diff(t)) for mi, ri in parts), sp.zeros(3, 1))        # definition of L
Id = sum((mi*Imat(ri) for mi, ri in parts), sp.zeros(3, 3))                     # inertia matrix (space frame)
assert zero(Ld - Id*wd)
Td = Ld.diff(t)                                                                 # torque = L-dot
# d25: T = L-dot = d/dt (I omega): holds
check(zero(Td - (Id*wd).diff(t)))
# d26: T = I omega-dot = I alpha  -> compare with the true torque
alpha = wd.diff(t)
claim = Id*alpha
check(zero(Td - claim))
# d27: T = I alpha (repeat)
check(zero(Td - claim))
# d28: matrix form of T = I alpha
check(zero(Td - Id*alpha))
# d29: T_x = I_xx a_x + I_xy a_y + I_xz a_z
check(zero(Td[0] - (Id[0, 0]*alpha[0] + Id[0, 1]*alpha[1] + Id[0, 2]*alpha[2])))
# sanity: the true relation T = I alpha + omega x (I omega)
assert zero(Td - (Id*alpha + wd.cross(Id*wd)))
# d30: principal axes -> diagonal. Check: for a body symmetric under x->-x, y->-y (pairs of particles),
# the coordinate axes are principal and the products vanish.
X1, Y1, Z1, X2, Y2, Z2 = sp.symbols("X1 Y1 Z1 X2 Y2 Z2", real=True)
pts = [sp.Matrix([s1*X1, s2*Y1, Z1]) for s1 in (1, -1) for s2 in (1, -1)] + \
      [sp.Matrix([s1*X2, s2*Y2, Z2]) for s1 in (1, -1) for s2 in (1, -1)]
Ip = sum((Imat(p) for p in pts), sp.zeros(3, 3))
check(all(sp.simplify(Ip[p, q]) == 0 for p in range(3) for q in range(3) if p != q))

if __name__ == "__main__":
    assert len(VERD) == len(TOML), (len(VERD), len(TOML))
    bad = 0
    for e, vv in zip(TOML, VERD):
        ok = (e["verdict"] == vv) or (e["verdict"] == "typo" and vv == "fails")
        print(f"line {e['line']:4d}  computed {vv:12s} toml {e['verdict']:12s} {'OK' if ok else 'MISMATCH'}")
        bad += not ok
    sys.exit(1 if bad else 0)
