"""A heavy top's names given in its formulas, its units typed as plain letters, and the fast top's
precession rate (derive/lecture/formula_names.py, derive/lecture/units.py, derive/lecture/fast_top.py).

The notes below are written for these tests in the way course notebooks write a spinning top: the
mass only in the weight m g, the symmetry axis only through "assuming I_x = I_y", units after a tie
(``0.1~kg``, ``~\\frac{rad}{s}``), and the gyroscopic approximation stated as an equality.
"""
import kept_readings as kept

from derive.lecture import formula_names
from derive.lecture import names as nm
from derive.lecture.units import plain_numbers

HEAD = """---
convention: z-x-z
angles: [\\phi, \\theta, \\psi]
---

A top spins about a fixed point; its centre of mass sits at a distance $d$ from the fixed point.
Its moments about the centre of mass are $I_x$, $I_y$, $I_z$, and we assume $I_x=I_y$.

For a fast spin, $\\dot{\\psi}>>\\dot{\\phi}$, the precession rate is

"""


def verdicts(display: str) -> list:
    return [(c.verdict, c.why) for c in kept.check_text(HEAD + display + "\n") if c.line >= 11]


def test_a_unit_typed_after_a_tie_is_dropped_and_a_tied_product_of_symbols_stays():
    assert plain_numbers("m=0.1~kg").strip() == "m=0.1"
    assert plain_numbers(r"d = 2r = 0.2~m").strip() == "d = 2r = 0.2"
    assert plain_numbers(r"\dot{\phi} = \frac{mgd}{I_z\dot{\psi}}~\frac{rad}{s}").strip() == \
        r"\dot{\phi} = \frac{mgd}{I_z\dot{\psi}}"
    assert plain_numbers(r"T = \frac{2\pi}{\dot{\phi}}~s").strip() == r"T = \frac{2\pi}{\dot{\phi}}"
    assert plain_numbers("a~s = c") == "a~s = c"            # after a letter: a product, kept
    assert plain_numbers("x = 2~m_1") == "x = 2~m_1"        # an indexed symbol is no unit


def test_a_tied_unit_written_as_a_display_fraction_or_before_a_tag_is_dropped():
    assert plain_numbers(r"\dot{\phi} = \dfrac{mgd}{I_z\dot{\psi}}~\dfrac{rad}{s}").strip() == \
        r"\dot{\phi} = \dfrac{mgd}{I_z\dot{\psi}}"
    assert plain_numbers(r"\omega = \frac{a}{b}~\tfrac{rad}{s}").strip() == r"\omega = \frac{a}{b}"
    assert plain_numbers(r"d = 2r = 0.2~m \tag{13.89}") == r"d = 2r = 0.2 \tag{13.89}"
    assert plain_numbers(r"x = 2~m \label{eq:x}") == r"x = 2 \label{eq:x}"
    assert plain_numbers(r"d = 0.2~m \, .") == r"d = 0.2 ."


def test_the_weight_names_the_mass_and_the_equal_pair_names_the_axial_moment():
    names = nm.Names()
    formula_names.learn(names, "$V = mgd\\cos\\theta$ and $I_x=I_y$, with $T = \\frac12 I_z \\omega_3^2$")
    assert names.symbols[("m", "")] == "mass"
    assert names.symbols[("I", "z")] == "axial moment"
    assert ("I", "x") not in names.symbols          # the transverse moment depends on the point


def test_a_moment_the_text_defines_or_a_pair_that_disagrees_names_nothing():
    names = nm.Names()
    formula_names.learn(names, "$I_x=I_y$ and $I_z = \\frac{1}{2} m R^2 = 0.0405$")
    assert ("I", "z") not in names.symbols
    names = nm.Names()
    formula_names.learn(names, "$I_x=I_y$, later $J_x = J_y$, and $I_z$, $J_z$")
    assert ("I", "z") not in names.symbols and ("J", "z") not in names.symbols
    names = nm.Names()
    formula_names.learn(names, "$\\lim g = 0$, $x_{mg}$ and $\\mathrm{kg}$")
    assert ("m", "") not in names.symbols


def test_the_fast_tops_precession_rate_holds_to_leading_order():
    got = verdicts("$$\\dot{\\phi} = \\frac{mgd}{I_z\\dot{\\psi}}~\\frac{rad}{s}$$")
    assert [v for v, _ in got] == ["holds"], got
    assert "fast" in got[0][1]


def test_a_wrong_moment_or_factor_in_the_fast_tops_rate_is_never_called_right():
    for wrong in ("\\frac{mgd}{I_x\\dot{\\psi}}", "\\frac{2mgd}{I_z\\dot{\\psi}}", "\\frac{mgd}{I_z\\dot{\\psi}^2}",
                  "\\frac{I_z\\dot{\\psi}}{mgd}"):
        got = verdicts(f"$$\\dot{{\\phi}} = {wrong}$$")
        assert "holds" not in [v for v, _ in got], (wrong, got)


def test_a_moment_shifted_by_m_d_squared_is_the_transverse_moment_about_the_pivot():
    names = nm.Names()
    names.symbols[("d", "")] = "centre-of-mass distance"
    formula_names.learn(names, "$V = mgd\\cos\\theta$, and the pivot's moment $I_O = I_x +md^2$")
    assert names.symbols[("I", "O")] == "transverse moment"
    assert ("I", "x") not in names.symbols          # the moment about the centre of mass stays the text's
    valued = nm.Names()
    valued.symbols[("d", "")] = "centre-of-mass distance"
    formula_names.learn(valued, "$V = mgd$, $I_O = I_x + md^2$ and $I_O = 0.1765$")
    assert ("I", "O") not in valued.symbols         # a moment worked out in numbers is the text's own


def test_the_tilt_equation_in_the_pivots_moment_holds_and_a_slip_in_it_is_never_called_right():
    text = HEAD.replace("For a fast spin", "The moment about the pivot is $I_O = I_x +md^2$.\n\nFor a fast spin")
    eq = ("$$I_O\\ddot{\\theta} - \\dot{\\phi}^2\\sin\\theta\\cos\\theta(I_O-I_z)"
          "+\\dot{\\phi}\\dot{\\psi}I_z\\sin\\theta-mgd\\sin\\theta = 0$$")
    good = [c.verdict for c in kept.check_text(text + eq + "\n") if c.line >= 13]
    assert good == ["holds"], good
    bad = [c.verdict for c in kept.check_text(text + eq.replace("-mgd", "+mgd") + "\n") if c.line >= 13]
    assert "holds" not in bad, bad


def test_the_fast_tops_lead_is_the_root_solve_gives_in_every_euler_sequence():
    import sympy as sp

    from derive.lecture.derivation import Derivation
    from derive.lecture.fast_top import _C, _S, slow_precession_lead
    from derive.symbolic import rotations as rot

    for seq in ("z-x-z", "z-y-z", "x-y-x", "x-z-x", "y-x-y", "y-z-y", "z-y-x", "x-y-z", "y-z-x"):
        force = Derivation(seq).steady_force
        at = sp.expand(force.xreplace({rot.gamma_d: _S, rot.alpha_d: _C / _S}))
        roots = sp.solve(sp.limit(at, _S, sp.oo), _C)
        lead = slow_precession_lead(force, rot.alpha_d, rot.gamma_d)
        assert len(roots) == 1 and lead is not None, seq
        assert lead == roots[0], (seq, lead, roots)     # the same tree, so the same message
