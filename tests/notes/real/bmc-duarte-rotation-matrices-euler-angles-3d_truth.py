"""Independent SymPy truth table for bmc-duarte-rotation-matrices-euler-angles-3d.ipynb.

The notebook's own convention. A local system xyz turned relative to the Global system XYZ: the
local-to-Global matrix R_Gl has the local axes' unit vectors, in Global coordinates, as its columns
(so R_Gl P_l = P_G), and the Global-to-local matrix R_lG is its transpose. An elemental rotation of the
local system by an angle about a Global axis turns the local axes by the right-hand rule about that
axis: R_Gl,axis(angle) = exp(angle [e]_x). A sequence about the fixed Global axes X, then Y, then Z is
R_Gl,XYZ = R_Z R_Y R_X; a sequence about the turning local axes x, then y, then z has the Global-to-local
matrix R_lG,xyz = R_lG,z R_lG,y R_lG,x; the zxz sequence is R_lG,z(gamma) R_lG,x(beta) R_lG,z(alpha).
Every check is built from these definitions (matrix exponentials of the axes' cross-product
matrices), never from the notebook's later displays.
"""
import sys

import sympy as sp

import truth_table

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


zero = truth_table.zero


al, be, ga = sp.symbols("alpha beta gamma", real=True)
E = [sp.Matrix([1, 0, 0]), sp.Matrix([0, 1, 0]), sp.Matrix([0, 0, 1])]


def hat(v):
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def turn(axis, q):
    """Rodrigues: the right-hand rotation by q about the unit vector axis (local to Global)."""
    K = hat(axis)
    return sp.simplify(sp.eye(3) + sp.sin(q) * K + (1 - sp.cos(q)) * K * K)


GX, GY, GZ = turn(E[0], al), turn(E[1], be), turn(E[2], ga)       # R_Gl about X, Y, Z
lx, ly, lz = GX.T, GY.T, GZ.T                                       # R_lG about x, y, z
c, s = sp.cos, sp.sin

# 31, 39, 51: a pure translation: P_G = L_G + P_l, componentwise and as columns
L = sp.Matrix(sp.symbols("L_X L_Y L_Z"))
Pl = sp.Matrix(sp.symbols("P_x P_y P_z"))
PG = L + sp.eye(3) * Pl                 # R_Gl = identity for a translation
check(31, zero(PG - (L + Pl)))
check(39, all(sp.simplify(PG[i] - (L[i] + Pl[i])) == 0 for i in range(3)))
check(51, zero(PG - (L + Pl)))
# 99: the entries of R_Gl are the cosines between the Global axis (row) and the local axis (column)
R = GZ * GY * GX
local_axes = [R * e for e in E]
check(99, all(sp.simplify(R[i, j] - E[i].dot(local_axes[j])) == 0 for i in range(3) for j in range(3)))
# 131, 142, 153: the elemental local-to-Global matrices about X, Y, Z
check(131, zero(GX - sp.Matrix([[1, 0, 0], [0, c(al), -s(al)], [0, s(al), c(al)]])))
check(142, zero(GY - sp.Matrix([[c(be), 0, s(be)], [0, 1, 0], [-s(be), 0, c(be)]])))
check(153, zero(GZ - sp.Matrix([[c(ga), -s(ga), 0], [s(ga), c(ga), 0], [0, 0, 1]])))
# 176, 187, 198: the Global-to-local matrices are the transposes
check(176, zero(lx - sp.Matrix([[1, 0, 0], [0, c(al), s(al)], [0, -s(al), c(al)]])))
check(187, zero(ly - sp.Matrix([[c(be), 0, -s(be)], [0, 1, 0], [s(be), 0, c(be)]])))
check(198, zero(lz - sp.Matrix([[c(ga), s(ga), 0], [-s(ga), c(ga), 0], [0, 0, 1]])))
# 219: R_Gl,XYZ = R_Z R_Y R_X, written out
RXYZ_text = sp.Matrix([
    [c(be) * c(ga), s(al) * s(be) * c(ga) - c(al) * s(ga), c(al) * s(be) * c(ga) + s(al) * s(ga)],
    [c(be) * s(ga), s(al) * s(be) * s(ga) + c(al) * c(ga), c(al) * s(be) * s(ga) - s(al) * c(ga)],
    [-s(be), s(al) * c(be), c(al) * c(be)]])
check(219, zero(GZ * GY * GX - RXYZ_text))
# 264: R_lG,xyz = R_z R_y R_x, written out; the notebook's (0, 2) entry has the opposite sign
Rxyz = lz * ly * lx
Rxyz_text = sp.Matrix([
    [c(be) * c(ga), s(al) * s(be) * c(ga) + c(al) * s(ga), c(al) * s(be) * c(ga) - s(al) * s(ga)],
    [-c(be) * s(ga), -s(al) * s(be) * s(ga) + c(al) * c(ga), c(al) * s(be) * s(ga) + s(al) * c(ga)],
    [s(be), -s(al) * c(be), c(al) * c(be)]])
check(264, zero(Rxyz - Rxyz_text))
fixed = Rxyz_text.copy()
fixed[0, 2] = s(al) * s(ga) - c(al) * s(be) * c(ga)
assert zero(Rxyz - fixed)                                             # the correction
# 311: R_Gl,XYZ(a, b, g) = R_Gl,Z(g) R_Gl,Y(b) R_Gl,X(a) = R_lG,z(-g) R_lG,y(-b) R_lG,x(-a) = R_lG,xyz(-a, -b, -g)
neg = {al: -al, be: -be, ga: -ga}
check(311, zero(GZ * GY * GX - lz.subs(neg) * ly.subs(neg) * lx.subs(neg))
      and zero(lz.subs(neg) * ly.subs(neg) * lx.subs(neg) - Rxyz.subs(neg, simultaneous=True)))
# 331: R_lG,xyz = R_Gl,Z^-1 R_Gl,Y^-1 R_Gl,X^-1 = R_Gl,Z^T R_Gl,Y^T R_Gl,X^T = (R_Gl,X R_Gl,Y R_Gl,Z)^T = R_Gl,ZYX^T
# (R_Gl,ZYX: about Z by gamma first, then Y by beta, then X by alpha: R_X R_Y R_Z)
RZYX = GX * GY * GZ
check(331, zero(Rxyz - GZ.inv() * GY.inv() * GX.inv()) and zero(Rxyz - GZ.T * GY.T * GX.T)
      and zero(Rxyz - (GX * GY * GZ).T) and zero(Rxyz - RZYX.T))
# 374: the Cardan angles of R_lG,xyz (0-based entries), for |beta| < 90 degrees
num = {al: sp.Rational(3, 10), be: sp.Rational(-7, 10), ga: sp.Rational(11, 10)}
Rn = Rxyz.subs(num)
check(374, abs(float(sp.atan2(-Rn[2, 1], Rn[2, 2])) - 0.3) < 1e-12
      and abs(float(sp.atan2(Rn[2, 0], sp.sqrt(Rn[0, 0]**2 + Rn[1, 0]**2))) + 0.7) < 1e-12
      and abs(float(sp.atan2(-Rn[1, 0], Rn[0, 0])) - 1.1) < 1e-12)
# 398: R_zxz = R_z(gamma) R_x(beta) R_z(alpha), Global-to-local elemental matrices
lz_a = turn(E[2], al).T
Rzxz = lz * turn(E[0], be).T * lz_a
Rzxz_text = (sp.Matrix([[c(ga), s(ga), 0], [-s(ga), c(ga), 0], [0, 0, 1]])
             * sp.Matrix([[1, 0, 0], [0, c(be), s(be)], [0, -s(be), c(be)]])
             * sp.Matrix([[c(al), s(al), 0], [-s(al), c(al), 0], [0, 0, 1]]))
check(398, zero(Rzxz - Rzxz_text))
# 425: beta = 0: the middle factor is the identity (the product is a turn about z by alpha + gamma)
Rz0 = Rzxz.subs(be, 0)
check(425, zero(Rz0 - lz * sp.eye(3) * lz_a) and zero(Rz0 - turn(E[2], al + ga).T))

# negative control: the checks above can fail
assert not zero(GZ * GY * GX - GX * GY * GZ)

LINES = [31, 39, 51, 99, 131, 142, 153, 176, 187, 198, 219, 264, 311, 331, 353, 374, 398, 425]

if __name__ == "__main__":
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
