"""A name the prose gives in one section holds there (derive/lecture/names.py): Landau's M is the
top's mass in one section and the angular momentum's magnitude in the next; with the moments
ordered, the bounds on it at a given energy follow (derive/lecture/motion.py)."""
from derive.lecture import names as nm
import kept_readings as kept
from derive.lecture.vocabulary import scan

TWO_SECTIONS = (
    "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n"
    "## Heavy top\n\nHere $M$ is the top's mass and $a$ is the distance from the fixed point to the centre of mass.\n\n"
    "$$V = Mga \\cos\\theta$$\n\n"
    "## Free asymmetric top\n\nWith $I_1 < I_2 < I_3$: bounds on the magnitude $M$ of the angular momentum at "
    "given energy $E$.\n\n"
)


def test_a_name_means_what_the_prose_of_its_own_section_says():
    names = nm.learn(TWO_SECTIONS)
    m = next(t.value for t in scan("M") if t.kind == "atom")
    names.here = 8
    assert names.meaning(m) == "mass"
    names.here = 15
    assert names.meaning(m) == "angular momentum"
    names.here = None                   # no position: the first binding, as before
    assert names.meaning(m) == "mass"


def test_the_front_matter_wins_over_a_sections_prose():
    names = nm.learn(TWO_SECTIONS, {"M": "mass"})
    m = next(t.value for t in scan("M") if t.kind == "atom")
    names.here = 15
    assert names.meaning(m) == "mass"


def test_bounds_on_the_angular_momentum_at_given_energy_follow_from_the_ordered_moments():
    claims = kept.check_text(TWO_SECTIONS + "$$\\sqrt{2EI_1} \\leq M \\leq \\sqrt{2EI_3}$$\n")
    assert [c.verdict for c in claims if c.latex.startswith("\\sqrt")] == ["holds"]


def test_bounds_with_the_moments_swapped_are_not_taken_as_holding():
    claims = kept.check_text(TWO_SECTIONS + "$$\\sqrt{2EI_3} \\leq M \\leq \\sqrt{2EI_1}$$\n")
    assert [c.verdict for c in claims if c.latex.startswith("\\sqrt")] != ["holds"]
