"""Names the prose gives in its own words: a moment by the axis it is taken about ("$C$ the moment of
inertia about the axis of symmetry", "$A$ the moment of inertia about either of the two other principal
axes"), a list or table of symbols, and "let $X$ be" or "denote" the quantity."""
import kept_readings as kept

TEXT = r"""---
convention: z-y-z
---
# Heavy top

The top has mass $M$, with PROSE, so

$$
\mathcal{L} = \frac{1}{2}A(\dot\beta^2 + \dot\alpha^2\sin^2\beta) + \frac{1}{2}C(\dot\gamma + \dot\alpha\cos\beta)^2 - Mgl\cos\beta
$$
"""


def _verdicts(prose):
    return {c.verdict for c in kept.check_text(TEXT.replace("PROSE", prose))}


def test_the_moments_about_the_axis_of_symmetry_and_about_the_other_axes():
    prose = ("$C$ the moment of inertia about the axis of symmetry and $A$ the moment of inertia about "
             "either of the two other principal axes")
    assert _verdicts(prose) == {"holds"}


def test_a_moment_about_its_symmetry_axis_and_one_about_any_of_the_transverse_axes():
    prose = ("$C$ the moment of inertia around its symmetry axis and $A$ the moment of inertia around any "
             "of the transverse axes")
    assert _verdicts(prose) == {"holds"}


def test_a_moment_about_an_axis_the_prose_does_not_name_binds_nothing():
    prose = "$C$ the moment of inertia about the pivot and $A$ the moment of inertia about the rim"
    assert _verdicts(prose) == {"unchecked"}


LIST = r"""---
convention: z-y-z
---
# Heavy top

The symbols:

ROWS

The Lagrangian is

$$
\mathcal{L} = \frac{1}{2}A(\dot\beta^2 + \dot\alpha^2\sin^2\beta) + \frac{1}{2}C(\dot\gamma + \dot\alpha\cos\beta)^2 - Mgl\cos\beta
$$
"""
SYMBOLS = (("M", "the mass of the top"), ("C", "the moment of inertia about the axis of symmetry"),
           ("A", "the moment of inertia about either of the two other principal axes"))


def _listed(row):
    return {c.verdict for c in kept.check_text(LIST.replace("ROWS", "\n".join(row(s, w) for s, w in SYMBOLS)))}


def test_a_list_of_symbols_each_with_a_colon_names_them():
    assert _listed(lambda s, w: f"- ${s}$: {w}") == {"holds"}


def test_a_table_of_symbols_names_them():
    assert _listed(lambda s, w: f"| ${s}$ | {w} |") == {"holds"}


def test_a_list_of_symbols_whose_words_name_nothing_binds_nothing():
    assert _listed(lambda s, w: f"- ${s}$: {w.replace('axis of symmetry', 'rim').replace('principal axes', 'points')}") \
        == {"unchecked"}


FREE = r"""---
convention: z-y-z
---
# Free body

PROSE Its kinetic energy is

$$
T = \frac{1}{2}(I_1\Omega_1^2 + I_2\Omega_2^2 + I_3\Omega_3^2)
$$
"""


def test_let_a_letter_be_or_denote_the_angular_velocity():
    for prose in (r"Let $\boldsymbol\Omega$ denote the angular velocity of the body.",
                  r"Let $\boldsymbol\Omega$ be the angular velocity of the body."):
        assert {c.verdict for c in kept.check_text(FREE.replace("PROSE", prose))} == {"holds"}, prose


def test_let_a_letter_be_something_else_binds_nothing():
    prose = r"Let $\boldsymbol\Omega$ be the vector of the three rates a gyroscope measures."
    assert {c.verdict for c in kept.check_text(FREE.replace("PROSE", prose))} == {"unchecked"}
