"""Independent SymPy truth table for hikarimusic-physics-note-landau-rigid-body-symmetric-top-euler-equations-ja.md.

The note's convention is Landau's: Omega is the angular velocity (Omega_1, Omega_2, Omega_3 its components
on the principal axes of the body), M the angular momentum (M_1, M_2, M_3 on the body axes, M_z along the
fixed Z axis), N the torque, I_1, I_2, I_3 the principal moments, T the kinetic energy, E the energy. For a
frame that moves and turns, R, V, A are the position, velocity and acceleration of its origin, primed
quantities are seen in the turning frame and d'/dt is the rate seen there. The Euler angles phi, theta, psi
are Landau's: a turn phi about the fixed Z axis, theta about the line of nodes, psi about the body axis 3,
so the orientation is R_z(phi) R_x(theta) R_z(psi) (the note does not name the sequence; its formula for
Omega_1, Omega_2, Omega_3 is this one, and check 56 derives it). For the free symmetric top (I_1 = I_2) the
note writes M_3 = M_z cos(theta), which puts the fixed Z axis along the constant angular momentum, so M_z is
its size. For the heavy top, M is the mass, a the distance from the fixed point to the centre of mass on the
figure axis, I_1 and I_3 the moments about the centre of mass, g the gravity and Z points up. For the free
asymmetric top the bounds sqrt(2 E I_1) <= M <= sqrt(2 E I_3) order the moments I_1 < I_2 < I_3.

Everything is derived here from the orientation matrix, from point masses or from the Lagrangian built from
the parallel-axis theorem, never from the note's later lines. A quantity of time is a jet of symbols (its value and rates) stepped by the
chain rule; identities in them are tested at three generic points with 30 digits. Run as a program it compares its verdicts with the
table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import Rx, Rz, zero

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


c, s = sp.cos, sp.sin
NEXT = {}


def jet(name, order):
    """A quantity of time and its first ``order`` rates, as symbols name_0, name_1, ...; Dt steps along them."""
    syms = [sp.Symbol(f'{name}_{k}', real=True) for k in range(order + 1)]
    NEXT.update(zip(syms, syms[1:]))
    return syms


def Dt(e):
    """The rate in time of a scalar or matrix built from jets (the chain rule through every jet symbol)."""
    if hasattr(e, 'applyfunc'):
        return e.applyfunc(Dt)
    return sum((sp.diff(e, x) * NEXT[x] for x in e.free_symbols if x in NEXT), sp.Integer(0))


def num_zero(expr, samples=3):
    """``expr`` (scalar or matrix) vanishes, to 1e-20, with every symbol given a generic value (30 digits):
    an identity in the jets holds for every motion, so a slip shows."""
    m = expr if hasattr(expr, 'shape') else sp.Matrix([expr])
    syms = sorted(m.free_symbols, key=str)
    for shift in range(samples):
        vals = {x: sp.Float(sp.Rational(3 + 2 * i + shift, 7 + i + shift), 30) for i, x in enumerate(syms)}
        if max(abs(e) for e in m.xreplace(vals)) > sp.Float('1e-20', 30):
            return False
    return True


def vee(W):
    """The vector of a skew matrix W (W x = w cross x)."""
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


def cross(a, b):
    return a.cross(b)


def jets(names, order):
    return [jet(n, order) for n in names]


# ---- a frame that moves and turns (lines 24, 36) --------------------------------------------------
A_ = jets(('a1', 'a2', 'a3'), 3)                                     # the frame's orientation angles and rates
Rot = Rz(A_[0][0]) * Rx(A_[1][0]) * Rz(A_[2][0])
Om = vee(Dt(Rot) * Rot.T)                                            # angular velocity, fixed-frame components
Omd = Dt(Om)
Rv = sp.Matrix([j[0] for j in jets(('X', 'Y', 'Z'), 2)])              # the origin of the turning frame
xb = sp.Matrix([j[0] for j in jets(('x1', 'x2', 'x3'), 2)])           # the point's coordinates in that frame
rp = Rot * xb                                                        # r'
vp = Rot * Dt(xb)                                                    # v' = d'r'/dt
ap = Rot * Dt(Dt(xb))                                                # a' = d'v'/dt
r = Rv + rp
V, A = Dt(Rv), Dt(Dt(Rv))
vel, acc = Dt(r), Dt(Dt(r))
v_claim = V + vp + cross(Om, rp)
a_claim = A + ap + cross(Omd, rp) + cross(Om, cross(Om, rp)) + 2 * cross(Om, vp)
check(24, num_zero(vel - v_claim) and num_zero(acc - a_claim))

qb = sp.Matrix([j[0] for j in jets(('q1', 'q2', 'q3'), 1)])
Q = Rot * qb                                                         # any vector; d'Q/dt = Rot qb'
rule = num_zero(Dt(Q) - (Rot * Dt(qb) + cross(Om, Q)))
step_r = num_zero(vel - (V + Dt(rp))) and num_zero(Dt(rp) - (vp + cross(Om, rp)))
dv_1 = Dt(V) + Dt(vp) + cross(Omd, rp) + cross(Om, Dt(rp))
dv_2 = A + ap + cross(Om, vp) + cross(Omd, rp) + cross(Om, vp + cross(Om, rp))
step_v = (num_zero(Dt(v_claim) - dv_1) and num_zero(dv_1 - dv_2)
          and num_zero(dv_2 - a_claim) and num_zero(vel - v_claim))
check(36, rule and step_r and step_v)

# ---- Euler angles (line 56) -----------------------------------------------------------------------
ph, th, ps = sp.symbols('phi theta psi', real=True)
phd, thd, psd = sp.symbols('phidot thetadot psidot', real=True)
NEXT.update({ph: phd, th: thd, ps: psd})
E_ang = Rz(ph) * Rx(th) * Rz(ps)
Wbody = [sp.simplify(e) for e in vee(E_ang.T * Dt(E_ang))]           # body components of the angular velocity
W1 = phd * s(th) * s(ps) + thd * c(ps)
W2 = phd * s(th) * c(ps) - thd * s(ps)
W3 = phd * c(th) + psd
check(56, all(zero(x - y) for x, y in zip(Wbody, (W1, W2, W3))))

# ---- the inertia tensor (lines 69, 80) ------------------------------------------------------------
O = sp.Matrix(sp.symbols('Omega_1:4', real=True))
masses = sp.symbols('m_1:3', positive=True)
pts = [sp.Matrix(sp.symbols(f'x_{k} y_{k} z_{k}', real=True)) for k in (1, 2)]
Iten = sp.zeros(3, 3)
for m, p in zip(masses, pts):
    Iten += m * (p.dot(p) * sp.eye(3) - p * p.T)                     # I_ij = sum m (delta_ij r^2 - r_i r_j)
T_pts = sum(sp.Rational(1, 2) * m * cross(O, p).dot(cross(O, p)) for m, p in zip(masses, pts))
M_pts = sum((m * cross(p, cross(O, p)) for m, p in zip(masses, pts)), sp.zeros(3, 1))
check(69, zero(T_pts - sp.Rational(1, 2) * (O.T * Iten * O)[0]) and zero(M_pts - Iten * O))
T_mid = sum(sp.Rational(1, 2) * m * (O.dot(O) * p.dot(p) - O.dot(p)**2) for m, p in zip(masses, pts))
M_mid = sum((m * (O * p.dot(p) - p * p.dot(O)) for m, p in zip(masses, pts)), sp.zeros(3, 1))
check(80, zero(T_pts - T_mid) and zero(T_mid - sp.Rational(1, 2) * (O.T * Iten * O)[0])
      and zero(M_pts - M_mid) and zero(M_mid - Iten * O))

# ---- Euler's equations (lines 97, 107) ------------------------------------------------------------
I1, I2, I3 = sp.symbols('I_1 I_2 I_3', positive=True)
Ib = sp.diag(I1, I2, I3)
B_ = jets(('b1', 'b2', 'b3'), 2)                                     # a body's Euler angles and rates
E_rot = Rz(B_[0][0]) * Rx(B_[1][0]) * Rz(B_[2][0])
Wf = vee(E_rot.T * Dt(E_rot))                                         # body rates of a general turning
Mspace = E_rot * Ib * Wf                                              # angular momentum, fixed-frame components
Nbody = E_rot.T * Dt(Mspace)                                          # torque = dM/dt, on the body axes
Wd = Dt(Wf)
euler = [I1 * Wd[0] + (I3 - I2) * Wf[1] * Wf[2],
         I2 * Wd[1] + (I1 - I3) * Wf[2] * Wf[0],
         I3 * Wd[2] + (I2 - I1) * Wf[0] * Wf[1]]
check(97, num_zero(Nbody - sp.Matrix(euler)))
col = sp.Matrix([I1 * Wd[0], I2 * Wd[1], I3 * Wd[2]]) + cross(Wf, sp.Matrix([I1 * Wf[0], I2 * Wf[1], I3 * Wf[2]]))
Mb = Ib * Wf                                                          # dM/dt = d'M/dt + Omega x M, on body axes
check(107, num_zero(Nbody - (Dt(Mb) + cross(Wf, Mb))) and num_zero(Nbody - col))

# ---- the free symmetric top (lines 139, 151) ------------------------------------------------------
Mz = sp.Symbol('M_z', positive=True)
Ebod = E_ang
Mbody = Ebod.T * sp.Matrix([0, 0, Mz])                                # M along the fixed Z axis, on the body axes
rates = sp.solve([W1 - Mbody[0] / I1, W2 - Mbody[1] / I1, W3 - Mbody[2] / I3], [phd, thd, psd], dict=True)[0]
free = {phd: Mz / I1, thd: 0, psd: Mz * c(th) * (1 / I3 - 1 / I1)}
check(139, all(zero(rates[k] - free[k]) for k in (phd, thd, psd)))

Tsym = sp.Rational(1, 2) * (I1 * W1**2 + I1 * W2**2 + I3 * W3**2)
Lfree = sp.Rational(1, 2) * I1 * (phd**2 * s(th)**2 + thd**2) + sp.Rational(1, 2) * I3 * (phd * c(th) + psd)**2
on = {phd: Mz / I1, psd: Mz * c(th) * (1 / I3 - 1 / I1)}              # the motion of check 139 (thetadot kept)
ok151 = zero(Tsym - Lfree)
ok151 &= zero(sp.diff(Lfree, psd) - I3 * (phd * c(th) + psd)) and zero(sp.diff(Lfree, psd).subs(on) - Mz * c(th))
ok151 &= zero(Mbody[2] - Mz * c(th))                                  # M_3 = M_z cos(theta)
pphi = sp.diff(Lfree, phd)
ok151 &= zero(pphi - (I1 * phd * s(th)**2 + I3 * (phd * c(th) + psd) * c(th))) and zero(pphi.subs(on) - Mz)
sol = sp.solve([sp.Eq(pphi, Mz), sp.Eq(sp.diff(Lfree, psd), Mz * c(th))], [phd, psd], dict=True)[0]
ok151 &= zero(sol[phd] - (Mz - Mz * c(th)**2) / (I1 * s(th)**2)) and zero(sol[phd] - Mz / I1)
ok151 &= zero(sol[psd] - (Mz * c(th) / I3 - sol[phd] * c(th))) and zero(sol[psd] - on[psd])
dLdth = sp.diff(Lfree, th)
ok151 &= zero(dLdth - (I1 * phd**2 * s(th) * c(th) - I3 * (phd * c(th) + psd) * phd * s(th)))
ok151 &= zero(dLdth.subs(on)) and zero(sp.diff(Lfree, thd) - I1 * thd)
Efree = Lfree.subs(on)                                                # no potential: E = T on the motion
ok151 &= zero(Efree - (sp.Rational(1, 2) * I1 * (Mz**2 / I1**2 * s(th)**2 + thd**2)
                       + sp.Rational(1, 2) * I3 * Mz**2 / I3**2 * c(th)**2))
check(151, ok151)

# ---- the heavy symmetric top (lines 177, 189) -----------------------------------------------------
Mm, a, g = sp.symbols('M a g', positive=True)
M3, E, u, ud = sp.symbols('M_3 E u udot', real=True)
I1p = I1 + Mm * a**2                                                  # parallel axes: the moment about the fixed point
Theavy = sp.Rational(1, 2) * (I1p * W1**2 + I1p * W2**2 + I3 * W3**2)
cm = Ebod * sp.Matrix([0, 0, a])                                      # the centre of mass, fixed-frame components
Lheavy = Theavy - Mm * g * cm[2]
Lnote = (sp.Rational(1, 2) * I1p * (phd**2 * s(th)**2 + thd**2) + sp.Rational(1, 2) * I3 * (phd * c(th) + psd)**2
         - Mm * g * a * c(th))
hsol = sp.solve([sp.Eq(sp.diff(Lheavy, phd), Mz), sp.Eq(sp.diff(Lheavy, psd), M3)], [phd, psd], dict=True)[0]
phd_note = (Mz - M3 * c(th)) / (I1p * s(th)**2)
psd_note = M3 / I3 - (Mz - M3 * c(th)) * c(th) / (I1p * s(th)**2)
check(177, zero(hsol[phd] - phd_note) and zero(hsol[psd] - psd_note))

ok189 = zero(Lheavy - Lnote)
ok189 &= zero(sp.diff(Lnote, psd) - I3 * (phd * c(th) + psd))
ok189 &= zero(sp.diff(Lnote, phd) - (I1p * phd * s(th)**2 + I3 * (phd * c(th) + psd) * c(th)))
ok189 &= zero(hsol[phd] - phd_note) and zero(hsol[psd] - psd_note)
Eheavy = (Theavy + Mm * g * cm[2]).subs(hsol)                         # E = T + U with the momenta put in
E_note = (sp.Rational(1, 2) * I1p * thd**2 + sp.Rational(1, 2) * (Mz - M3 * c(th))**2 / (I1p * s(th)**2)
          + sp.Rational(1, 2) * M3**2 / I3 + Mm * g * a * c(th))
ok189 &= zero(Eheavy - E_note)
# u = cos(theta): udot = -sin(theta) thetadot, so thetadot^2 = udot^2/(1 - u^2)
ok189 &= zero(((-s(th) * thd)**2 / (1 - c(th)**2)) - thd**2)
E_u = (sp.Rational(1, 2) * I1p * ud**2 / (1 - u**2) + sp.Rational(1, 2) * (Mz - M3 * u)**2 / (I1p * (1 - u**2))
       + sp.Rational(1, 2) * M3**2 / I3 + Mm * g * a * u)
ok189 &= zero(E_note.subs(thd, -ud / s(th)).subs(c(th), u).subs(s(th)**2, 1 - u**2) - E_u)
# solve the energy for udot^2: (1 - u^2)(A - B u) - (M_z - M_3 u)^2/I1'^2 with A, B constants of the motion
udsq = sp.solve(sp.Eq(E_u, E), ud**2)[0]
A_, B_ = (2 * E - M3**2 / I3) / I1p, 2 * Mm * g * a / I1p
ok189 &= zero(udsq - ((1 - u**2) * (A_ - B_ * u) - (Mz - M3 * u)**2 / I1p**2))
check(189, ok189)

# ---- the free asymmetric top (lines 213, 221) -----------------------------------------------------
p_, q_ = sp.symbols('p q', positive=True)                             # I_2 = I_1 + p, I_3 = I_1 + p + q
Mc = sp.symbols('M_1:4', real=True)
order = {I2: I1 + p_, I3: I1 + p_ + q_}
E_M = sum(Mi**2 / (2 * Ii) for Mi, Ii in zip(Mc, (I1, I2, I3)))
Msq = sum(Mi**2 for Mi in Mc)


def nonneg_sum(expr):
    """expr is a sum of terms each a product of squares and positive symbols: it cannot be negative."""
    poly = sp.expand(sp.cancel(expr.subs(order) * I1 * (I1 + p_) * (I1 + p_ + q_)))
    return poly != 0 and all(bool(term.is_nonnegative) for term in sp.Add.make_args(poly))


bounds = nonneg_sum(Msq - 2 * E_M * I1) and nonneg_sum(2 * E_M * I3 - Msq)
# linear stability of the free Euler equations about each axis: lambda^2 from the Jacobian
Wd_free = sp.Matrix([(I2 - I3) * O[1] * O[2] / I1, (I3 - I1) * O[2] * O[0] / I2, (I1 - I2) * O[0] * O[1] / I3])
J = Wd_free.jacobian(O)
lam = sp.Symbol('lambda')
note_l2 = [-O[0]**2 * (I3 - I1) * (I2 - I1) / (I2 * I3),
           O[1]**2 * (I3 - I2) * (I2 - I1) / (I1 * I3),
           -O[2]**2 * (I3 - I2) * (I3 - I1) / (I1 * I2)]
lin_ok, signs_ok = True, True
for k in range(3):
    at = {O[j]: (O[k] if j == k else 0) for j in range(3)}
    cp = sp.factor((J.subs(at) - lam * sp.eye(3)).det())              # -lambda (lambda^2 - kappa)
    kappa = sp.solve(sp.cancel(cp / (-lam)), lam**2)
    lin_ok &= len(kappa) == 1 and zero(kappa[0] - note_l2[k])
    signed = sp.factor(note_l2[k].subs(order) / O[k]**2)
    signs_ok &= bool(signed.is_negative) if k != 1 else bool(signed.is_positive)
check(213, bounds and signs_ok)
check(221, zero(sp.expand(2 * E_M.subs({Mi: Ii * Oi for Mi, Ii, Oi in zip(Mc, (I1, I2, I3), O)}))
                - sum(Ii * Oi**2 for Ii, Oi in zip((I1, I2, I3), O))) and bounds and lin_ok and signs_ok)

# negative controls: a flipped sign, a swapped moment and a wrong rate are caught
assert not num_zero(Nbody - sp.Matrix([I1 * Wd[0] - (I3 - I2) * Wf[1] * Wf[2], euler[1], euler[2]]))
assert not num_zero(acc - (a_claim + cross(Om, vp)))
assert not zero(rates[psd] - Mz * c(th) * (1 / I1 - 1 / I3))
assert not zero(hsol[phd] - (Mz - M3 * c(th)) / (I1 * s(th)**2))
assert not zero(Wbody[0] - (phd * s(th) * c(ps) + thd * s(ps)))

LINES = [24, 36, 56, 69, 80, 97, 107, 139, 151, 177, 189, 213, 221]

ROWS = {
    24: ("holds", "r = R + r' places the point; with v' = d'r'/dt and a' = d'v'/dt the fixed-frame velocity and acceleration are V + v' + Omega x r' and A + a' + Omega' x r' + Omega x (Omega x r') + 2 Omega x v', derived from r = R + Rot x with Rot a general turning (check 24)"),
    36: ("holds", "the rule dQ/dt = d'Q/dt + Omega x Q for Q = Rot q, then each step of the two derivatives of r = R + r' and v = V + v' + Omega x r' (dOmega/dt is the same in both frames) down to the acceleration of line 24 (check 36)"),
    56: ("holds", "the body components of the angular velocity for R_z(phi) R_x(theta) R_z(psi), from Rot^T dRot/dt: Omega_1 = phi' sin(theta) sin(psi) + theta' cos(psi), Omega_2 = phi' sin(theta) cos(psi) - theta' sin(psi), Omega_3 = phi' cos(theta) + psi' (Landau 35.1) (check 56)"),
    69: ("holds", "with the definition I_ij = sum m (delta_ij r^2 - r_i r_j), T = (1/2) sum m |Omega x r|^2 = (1/2) I_ij Omega_i Omega_j and M = sum m r x (Omega x r) = I Omega, shown for two point masses in general position (check 69)"),
    80: ("holds", "each step: |Omega x r|^2 = Omega^2 r^2 - (Omega.r)^2, which is (delta_ij r^2 - r_i r_j) Omega_i Omega_j, and r x (Omega x r) = Omega r^2 - r (r.Omega), whose components are the same sum with Omega_j (check 80)"),
    97: ("holds", "N = dM/dt with M = Rot I Omega put on the body axes gives I_1 Omega_1' + (I_3 - I_2) Omega_2 Omega_3 = N_1 and its cyclic shifts, derived with the body rates of a general turning (check 97)"),
    107: ("holds", "dM/dt = d'M/dt + Omega x M = N on the body axes, the column form I Omega' + Omega x I Omega = N (check 107)"),
    139: ("holds", "with the fixed Z axis along the constant M (the note's M_3 = M_z cos(theta)), M on the body axes is M_z (sin(theta) sin(psi), sin(theta) cos(psi), cos(theta)); Omega_i = M_i/I_i with I_2 = I_1 solved for the rates gives theta' = 0, phi' = M_z/I_1, psi' = M_z cos(theta)(1/I_3 - 1/I_1) (Landau section 33) (check 139)"),
    151: ("holds", "the Lagrangian is the kinetic energy in the Euler angles; its momenta are I_3 (phi' cos(theta) + psi') = M_3 = M_z cos(theta) and I_1 phi' sin^2(theta) + I_3 (...) cos(theta) = M_z; solving them gives the rates of line 139; dL/dtheta vanishes on that motion and dL/dtheta' = I_1 theta'; the energy is T with the rates put in (check 151); checked twice more by hand against a flag: a numerical integration of a free top (I_1 = 2, I_3 = 1, Omega(0) = (0.7, -0.4, 1.3)) read in Euler angles about Z along M gives theta constant, phi' = M/I_1 and psi' = M cos(theta)(1/I_3 - 1/I_1) to 1e-12 and E to 1e-14; and in the limit I_3 = I_1 the rates are psi' = 0, phi' = M/I, the body turning as a whole about M at M/I"),
    177: ("holds", "the heavy top about its fixed point: moments I_1 + M a^2 and I_3 (parallel axes), potential M g a cos(theta); the momenta p_phi = M_z and p_psi = M_3 solved for the rates give phi' = (M_z - M_3 cos(theta))/((I_1 + M a^2) sin^2(theta)) and psi' = M_3/I_3 - (M_z - M_3 cos(theta)) cos(theta)/((I_1 + M a^2) sin^2(theta)) (Landau section 35); the tilt is confined between the roots of line 189 (check 177)"),
    189: ("holds", "the Lagrangian built from the parallel-axis moments, its two momenta, the rates, the energy T + U in the momenta, theta'^2 = u'^2/(1 - u^2) for u = cos(theta), the energy in u, and u'^2 = (1 - u^2)(A - B u) - (M_z - M_3 u)^2/(I_1 + M a^2)^2 with A = (2E - M_3^2/I_3)/(I_1 + M a^2), B = 2 M g a/(I_1 + M a^2) (the note leaves A, B and f unnamed) (check 189)"),
    213: ("holds", "for I_1 < I_2 < I_3, M^2 - 2 E I_1 and 2 E I_3 - M^2 are sums of non-negative terms, and the rates of line 221 make the rotations about axes 1 and 3 stable and about axis 2 unstable (check 213)"),
    221: ("holds", "M^2 is the sum of squares, E = sum M_i^2/(2 I_i) is (1/2) sum I_i Omega_i^2, the bounds as in line 213, and the free Euler equations linearised about each axis give lambda^2 = -Omega_1^2 (I_3 - I_1)(I_2 - I_1)/(I_2 I_3), Omega_2^2 (I_3 - I_2)(I_2 - I_1)/(I_1 I_3), -Omega_3^2 (I_3 - I_2)(I_3 - I_1)/(I_1 I_2), of the stated signs (check 221)"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
