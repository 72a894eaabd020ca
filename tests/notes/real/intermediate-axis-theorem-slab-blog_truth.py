"""Independent SymPy truth table for intermediate-axis-theorem-slab-blog.md.
Text's names: slab sides a (x), b (y), c (z), mass M; principal moments I_x, I_y, I_z;
body angular velocity (omega_x, omega_y, omega_z); k1 = I_z - I_y, k2 = I_z - I_x, k3 = I_y - I_x;
k4^2 = k2 k3 w_x^2/(I_y I_z), k5^2 = k1 k3 w_y^2/(I_x I_z)."""
import sys, os, tomllib
import sympy as sp

HERE = os.path.dirname(os.path.abspath(__file__))
SLUG = "intermediate-axis-theorem-slab-blog"
TOML = tomllib.load(open(os.path.join(HERE, SLUG + ".truth.toml"), "rb"))["display"]
VERD = []
def check(ok, kind="claim", fixed_ok=None):
    if kind == "nac":
        VERD.append("not a claim"); return
    if ok:
        VERD.append("holds")
    else:
        VERD.append("typo" if fixed_ok else "fails")

def zero(e):
    if isinstance(e, sp.MatrixBase):
        return all(sp.simplify(c) == 0 for c in e)
    return sp.simplify(e) == 0

t = sp.symbols("t", real=True)
a, b, c, M = sp.symbols("a b c M", positive=True)
X, Y, Z = sp.symbols("X Y Z", real=True)
rho = M/(a*b*c)
def slab(f):
    return sp.integrate(rho*f, (X, -a/2, a/2), (Y, -b/2, b/2), (Z, -c/2, c/2))
Ixx, Iyy, Izz = slab(Y**2 + Z**2), slab(X**2 + Z**2), slab(X**2 + Y**2)
Ixy, Ixz, Iyz = slab(-X*Y), slab(-X*Z), slab(-Y*Z)

# d0 macros, d1 dot notation
check(True, "nac"); check(True, "nac")
# d2: I_x = M(b^2+c^2)/12, I_x = M(c^2+a^2)/12, I_z = M(a^2+b^2)/12
r1 = zero(Ixx - M*(b**2 + c**2)/12); r2 = zero(Ixx - M*(c**2 + a**2)/12); r3 = zero(Izz - M*(a**2 + b**2)/12)
fixed = r1 and zero(Iyy - M*(c**2 + a**2)/12) and r3
check(r1 and r2 and r3, fixed_ok=fixed)
# d3: diagonal tensor for the slab about its centre
check(zero(sp.Matrix([Ixy, Ixz, Iyz])))
# d4: a>b>c => b^2+c^2 < c^2+a^2 < a^2+b^2 => I_x<I_y<I_z  (check with a = c+p+q, b = c+p, p,q>0)
p, q = sp.symbols("p q", positive=True)
sub = {a: c + p + q, b: c + p}
d1_ = sp.expand(((c**2 + a**2) - (b**2 + c**2)).subs(sub)); d2_ = sp.expand(((a**2 + b**2) - (c**2 + a**2)).subs(sub))
ok4 = all(co > 0 for co in sp.Poly(d1_, c, p, q).coeffs()) and all(co > 0 for co in sp.Poly(d2_, c, p, q).coeffs())
ok4 = ok4 and sp.simplify((Iyy - Ixx) - M*((c**2 + a**2) - (b**2 + c**2))/12) == 0 \
      and sp.simplify((Izz - Iyy) - M*((a**2 + b**2) - (c**2 + a**2))/12) == 0
check(ok4)
# d5: tau = dL/dt : law
check(True, "nac")
# d6: Euler's equation in body frame. Space-frame L = R I_b w_b with R' = R [w_b]x.
Ix, Iy, Iz = sp.symbols("I_x I_y I_z", positive=True)
wx, wy, wz = [sp.Function(n)(t) for n in ("omega_x", "omega_y", "omega_z")]
w = sp.Matrix([wx, wy, wz])
Ib = sp.diag(Ix, Iy, Iz)
R = sp.Matrix(3, 3, lambda i, j: sp.Function(f"R{i}{j}")(t))
def hat(v): return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
Rdot = R*hat(w)
Lspace_dot = Rdot*Ib*w + R*Ib*w.diff(t)           # d/dt (R I_b w)
tau_body_claim = Ib*w.diff(t) + w.cross(Ib*w)
check(zero(Lspace_dot - R*tau_body_claim))
# d7: components
comp = sp.Matrix([Ix*wx.diff(t) + (Iz - Iy)*wy*wz, Iy*wy.diff(t) + (Ix - Iz)*wz*wx, Iz*wz.diff(t) + (Iy - Ix)*wx*wy])
check(zero(comp - tau_body_claim))
# d8: k's positive for the slab
k1, k2, k3 = Izz - Iyy, Izz - Ixx, Iyy - Ixx
okk = all(sp.simplify(k - M*(e)/12) == 0 for k, e in [(k1, b**2 - c**2), (k2, a**2 - c**2), (k3, a**2 - b**2)])
# with a > b > c each of b^2-c^2, a^2-c^2, a^2-b^2 > 0 (shown with the p,q substitution)
okk = okk and all(all(co > 0 for co in sp.Poly(sp.expand(e.subs(sub)), c, p, q).coeffs())
                  for e in (b**2 - c**2, a**2 - c**2, a**2 - b**2))
check(okk)
# d9: torque-free rearranged
K1, K2, K3 = Iz - Iy, Iz - Ix, Iy - Ix
sol = sp.solve(list(comp), [wx.diff(t), wy.diff(t), wz.diff(t)], dict=True)[0]
ok9 = zero(Ix*sol[wx.diff(t)] - (-K1*wy*wz)) and zero(Iy*sol[wy.diff(t)] - K2*wz*wx) and zero(Iz*sol[wz.diff(t)] - (-K3*wx*wy))
check(ok9)
# d10: "I_x ~ 0 => I_x w_x' ~ 0 => w_x const". First statement: I_x is not small for the slab.
num = {a: 2, b: 1, c: sp.Rational(1, 10), M: 12}
Ix_num, Iy_num, Iz_num = [float(v.subs(num)) for v in (Ixx, Iyy, Izz)]
first_true = Ix_num < 1e-3*Iz_num
eps = sp.symbols("epsilon", positive=True)
u, v_, W0 = sp.symbols("u v W0", real=True)
# corrected first statement: w_y w_z = O(eps^2) when w_y, w_z = O(eps) -> I_x w_x' = -k1 w_y w_z = O(eps^2)
rhs_x = (-K1*(eps*u)*(eps*v_))
fixed10 = sp.limit(rhs_x/eps, eps, 0) == 0
check(first_true, fixed_ok=fixed10)
# d11: differentiate with w_x constant
wxc = sp.symbols("omega_x0", real=True)
wyf, wzf = sp.Function("wy")(t), sp.Function("wz")(t)
e_y = Iy*wyf.diff(t) - K2*wzf*wxc; e_z = Iz*wzf.diff(t) + K3*wxc*wyf
ok11 = zero(e_y.diff(t) - (Iy*wyf.diff(t, 2) - (K2*wxc)*wzf.diff(t))) and zero(e_z.diff(t) - (Iz*wzf.diff(t, 2) + (K3*wxc)*wyf.diff(t)))
check(ok11)
# d12: substitute first derivatives
wy1 = K2*wzf*wxc/Iy; wz1 = -K3*wxc*wyf/Iz
wy2 = (K2*wxc)*wz1/Iy; wz2 = -(K3*wxc)*wy1/Iz
coef = K2*K3*wxc**2/(Iy*Iz)
check(zero(wy2 - (-coef*wyf)) and zero(wz2 - (-coef*wzf)))
# d13: oscillator solutions
k4 = sp.symbols("k_4", positive=True); y0, yd0 = sp.symbols("y0 yd0", real=True)
ys = y0*sp.cos(k4*t) + yd0/k4*sp.sin(k4*t)
check(zero(ys.diff(t, 2) + k4**2*ys) and zero(ys.subs(t, 0) - y0) and zero(ys.diff(t).subs(t, 0) - yd0))
# d14: "I_y ~ 0 => ..."  (I_y = 4.01 with the sample numbers)
first_true = Iy_num < 1e-3*Iz_num
rhs_y = K2*(eps*u)*(eps*v_)
check(first_true, fixed_ok=sp.limit(rhs_y/eps, eps, 0) == 0)
# d15: differentiate with w_y constant
wyc = sp.symbols("omega_y0", real=True)
wxf = sp.Function("wx")(t)
e_x = Ix*wxf.diff(t) + K1*wyc*wzf; e_z2 = Iz*wzf.diff(t) + K3*wxf*wyc
check(zero(e_x.diff(t) - (Ix*wxf.diff(t, 2) + (K1*wyc)*wzf.diff(t))) and zero(e_z2.diff(t) - (Iz*wzf.diff(t, 2) + (K3*wyc)*wxf.diff(t))))
# d16: substitution
wx1 = -K1*wyc*wzf/Ix; wz1b = -K3*wxf*wyc/Iz
wx2 = -(K1*wyc)*wz1b/Ix; wz2b = -(K3*wyc)*wx1/Iz
coef5 = K1*K3*wyc**2/(Ix*Iz)
check(zero(wx2 - coef5*wxf) and zero(wz2b - coef5*wzf))
# d17: row1 x'' = k5^2 x with solution; row2 z'' = k5 z (as typed) with solution in e^{+-k5 t}
k5 = sp.symbols("k_5", positive=True); x0, xd0 = sp.symbols("x0 xd0", real=True)
def hsol(f0, fd0):
    return sp.Rational(1, 2)*(f0 + fd0/k5)*sp.exp(k5*t) + sp.Rational(1, 2)*(f0 - fd0/k5)*sp.exp(-k5*t)
xs = hsol(x0, xd0); zs = hsol(*sp.symbols("z0 zd0", real=True))
row1 = zero(xs.diff(t, 2) - k5**2*xs) and zero(xs.subs(t, 0) - x0) and zero(xs.diff(t).subs(t, 0) - xd0)
row2_as_typed = zero(zs.diff(t, 2) - k5*zs)                 # ODE z'' = k5 z with the stated solution
row2_eq_prev = zero(k5 - coef5.subs(wyc, 1))                 # also not what the previous display gives
row2_fixed = zero(zs.diff(t, 2) - k5**2*zs)
check(row1 and row2_as_typed, fixed_ok=row1 and row2_fixed)
# d18: late-time approximation with w'(0) = 0 (text's assumption)
xs0 = xs.subs(xd0, 0)
check(sp.limit(xs0/(sp.Rational(1, 2)*x0*sp.exp(k5*t)), t, sp.oo) == 1)
# d19: reflection: each row's equalities
ok19 = zero(-(Iz - Iy) - (-K1)) and zero((Iz - Ix) - K2) and zero(-(Iy - Ix) - (-K3)) and ok9
check(ok19)
# d20: bare cross product
check(True, "nac")

if __name__ == "__main__":
    assert len(VERD) == len(TOML), (len(VERD), len(TOML))
    bad = 0
    for e, vv in zip(TOML, VERD):
        ok = e["verdict"] == vv
        print(f"line {e['line']:4d}  computed {vv:12s} toml {e['verdict']:12s} {'OK' if ok else 'MISMATCH'}")
        bad += not ok
    sys.exit(1 if bad else 0)
