"""A precession vector the prose ties to the precession ("makes it precess, at the angular
velocity"), judged by solving Ω × L = τ for Ω across L (derive/lecture/precession_vector.py).
"""
from derive.lecture.notes_check import check_text

HEAD = """# Precession

A torque across the angular momentum makes it precess, at the angular velocity

"""


def precession(display: str, head: str = HEAD) -> list:
    return [(c.verdict, c.why, c.correction) for c in check_text(head + "$$" + display + "$$\n")
            if c.kind == "precession vector"]


def test_the_precession_vector_l_cross_tau_over_l_squared_holds():
    (verdict, _, _), = precession("\\boldsymbol{\\Omega}_{p} = \\frac{\\mathbf{L} \\times \\boldsymbol{\\tau}}{L^{2}}")
    assert verdict == "holds"


def test_the_reversed_cross_product_is_a_typo_with_its_correction():
    (verdict, why, fix), = precession("\\boldsymbol{\\Omega}_{p} = \\frac{\\boldsymbol{\\tau} \\times \\mathbf{L}}{L^{2}}")
    assert verdict == "typo" and "negative" in why
    assert fix == "\\boldsymbol{\\Omega}_{p} = \\frac{\\mathbf{L} \\times \\boldsymbol{\\tau}}{L^{2}}"


def test_a_wrong_power_of_l_is_flagged():
    (verdict, _, _), = precession("\\boldsymbol{\\Omega}_{p} = \\frac{\\mathbf{L} \\times \\boldsymbol{\\tau}}{L}")
    assert verdict in ("typo", "fails")


def test_without_the_precession_in_the_prose_it_stays_a_definition():
    head = "# Vectors\n\nA vector of the text's own:\n\n"
    assert precession("\\boldsymbol{\\Omega}_{p} = \\frac{\\boldsymbol{\\tau} \\times \\mathbf{L}}{L^{2}}", head) == []
