"""Independent SymPy truth table for math-se-cuboid-inertia-tensor-half-edges-triple-integral.md.

The question's convention and names (it has no Euler angles): a uniform cuboid of mass m whose half
edges are a (the width, along x), b (the height, along y) and c (the depth, along z); I_c is its
inertia tensor about its centre, axes along the edges, I_xx = int (y^2 + z^2) dm and the products
I_xy = -int x y dm and so on; d is the distance of a point (x, y, z) from the x axis and r its
distance from the origin. The tensor is integrated here over the block [-a, a] x [-b, b] x [-c, c]
with the density m / (8 a b c); the asker's own integrals over [0, a] x [0, b] x [0, c] are worked
out too, to say what each bare step of the chain is (those steps state no relation and are no claim).
Run as a program it compares its verdicts with the table; ``--write`` writes the table.
"""
import sys

import sympy as sp

import truth_table
from truth_table import zero

a, b, c, m = sp.symbols('a b c m', positive=True)
x, y, z = sp.symbols('x y z', real=True)

CHECKS = {}


def check(key, ok):
    CHECKS[key] = bool(ok)


# the cuboid with half edges a, b, c about its centre: density m / (8abc)
rho = m / (8 * a * b * c)
box = ((x, -a, a), (y, -b, b), (z, -c, c))
pos = sp.Matrix([x, y, z])
I_c = sp.Matrix(3, 3, lambda i, j: rho * sp.integrate(
    ((pos.T * pos)[0] if i == j else 0) - pos[i] * pos[j], *box))
assert zero(sp.integrate(rho, *box) - m)                   # the density gives the mass m
assert zero(I_c - sp.diag(m * (b**2 + c**2) / 3, m * (a**2 + c**2) / 3, m * (a**2 + b**2) / 3))


def diag_with(k):
    """The tensor the question writes: k m (b^2 + c^2), k m (a^2 + c^2), k m (a^2 + b^2) on the diagonal."""
    return sp.diag(k * m * (b**2 + c**2), k * m * (a**2 + c**2), k * m * (a**2 + b**2))


# line 16: the encyclopaedia's tensor with 1/12, read with a, b, c the half edges as the question says
check(16, zero(I_c - diag_with(sp.Rational(1, 12))))

# line 23: the squared distance of (x, y, z) from the x axis: |r - (r . e_x) e_x|^2
e_x = sp.Matrix([1, 0, 0])
perp = pos - (pos.T * e_x)[0] * e_x
check(23, zero((perp.T * perp)[0] - (y**2 + z**2)))

# line 27 defines r (the distance from the origin); line 31 takes x^2 away from it
r2 = x**2 + y**2 + z**2
check(31, zero(r2 - x**2 - (y**2 + z**2)))

# lines 36-56: the asker's chain over [0, a] x [0, b] x [0, c], bare expressions (no claim); the
# steps are worked here to say in the table what they are
corner = ((x, 0, a), (y, 0, b), (z, 0, c))
steps = [
    sp.integrate(y**2 + z**2, *corner),                                    # line 36
    sp.integrate((y**2 + z**2) * a, (y, 0, b), (z, 0, c)),                 # line 38
    sp.integrate(a * b**3 / 3 + a * b * z**2, (z, 0, c)),                  # line 40
    a * b * sp.integrate(b**2 / 3 + z**2, (z, 0, c)),                      # line 42
    a * b * (sp.integrate(b**2 / 3, (z, 0, c)) + sp.integrate(z**2, (z, 0, c))),  # line 44
    a * b**3 * c / 3 + a * b * c**3 / 3,                                   # line 46
    a * b * c * (b**2 + c**2) / 3,                                         # line 48
]
assert all(zero(s - steps[0]) for s in steps)
assert zero(sp.integrate(x**2 + z**2, *corner) - a * b * c * (a**2 + c**2) / 3)   # line 52
assert zero(sp.integrate(x**2 + y**2, *corner) - a * b * c * (a**2 + b**2) / 3)   # line 56

# line 61: the asker's tensor with 1/3, for the cuboid with half edges a, b, c about its centre
check(61, zero(I_c - diag_with(sp.Rational(1, 3))))

LINES = [16, 23, 27, 31, 36, 38, 40, 42, 44, 46, 48, 52, 56, 61]

BARE = "a bare expression, no relation stated (the asker's chain sets each step as an equation environment of its own)"
ROWS = {
    16: ("fails",
         "for a uniform cuboid of mass m with half edges a, b, c the tensor about its centre is "
         "diag(m(b^2 + c^2)/3, m(a^2 + c^2)/3, m(a^2 + b^2)/3) (density m/(8abc) over [-a,a]x[-b,b]x[-c,c]); "
         "the display's 1/12 belongs to the encyclopaedia's formula in the full edge lengths 2a, 2b, 2c, so read "
         "with a, b, c the half edges, as the question sets them, every entry is a quarter of the true one (check 16)",
         "\\dfrac{1}{3}m(b^2 + c^2), \\dfrac{1}{3}m(a^2 + c^2), \\dfrac{1}{3}m(a^2 + b^2) on the diagonal",
         "A cube with a = b = c = 1 (edges 2) and m = 1: the density is 1/8, int_{-1}^{1} y^2 dy = 2/3, so "
         "int (y^2 + z^2) dV = 2 * (2 * 2/3 * 2) = 16/3 and I_xx = 16/3 / 8 = 2/3 = m(b^2 + c^2)/3; the display "
         "gives m(b^2 + c^2)/12 = 1/6, a quarter of it.",
         "Limiting case: let b, c -> 0, a thin rod of length 2a along x. Its moment about the z axis through its "
         "centre is m (2a)^2 / 12 = m a^2 / 3, which is the 1/3 form's m(a^2 + b^2)/3 at b = 0; the display's "
         "m(a^2 + b^2)/12 -> m a^2/12 is the moment of a rod of length a, not 2a."),
    23: ("holds", "the squared distance of (x, y, z) from the x axis, |r - (r . e_x) e_x|^2, is y^2 + z^2 (check 23)"),
    27: ("not a claim", "defines r, the distance of the point from the origin"),
    31: ("holds", "r^2 - x^2 = y^2 + z^2 with the r^2 = x^2 + y^2 + z^2 of the display before (check 31)"),
    36: ("not a claim", BARE + "; the integral of the squared distance from the x axis over [0,a]x[0,b]x[0,c], abc(b^2 + c^2)/3"),
    38: ("not a claim", BARE + "; the x integral done, equal to the step before"),
    40: ("not a claim", BARE + "; the y integral done, a b^3/3 + a b z^2, equal to the step before"),
    42: ("not a claim", BARE + "; ab taken out, equal to the step before"),
    44: ("not a claim", BARE + "; the integral split in two, equal to the step before"),
    46: ("not a claim", BARE + "; the z integral done, ab^3c/3 + abc^3/3, equal to the step before"),
    48: ("not a claim", BARE + "; factored, abc(b^2 + c^2)/3, equal to the step before"),
    52: ("not a claim", BARE + "; the same integral for the y axis, int (x^2 + z^2) = abc(a^2 + c^2)/3"),
    56: ("not a claim", BARE + "; the same integral for the z axis, int (x^2 + y^2) = abc(a^2 + b^2)/3"),
    61: ("holds",
         "the tensor of the cuboid with half edges a, b, c about its centre is diag(m(b^2 + c^2)/3, m(a^2 + c^2)/3, "
         "m(a^2 + b^2)/3) with no products of inertia (check 61); the prose's 'multiply each by m' would give "
         "m abc(b^2 + c^2)/3, but the display's entries are the integrals times the density m/(abc) of the block "
         "[0,a]x[0,b]x[0,c], which equal the centred half-edge cuboid's"),
}

if __name__ == "__main__":
    if "--write" in sys.argv:
        truth_table.write_table(__file__, ROWS, CHECKS, LINES)
    sys.exit(truth_table.compare(__file__, CHECKS, LINES))
