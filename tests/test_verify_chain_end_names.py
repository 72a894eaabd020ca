"""The notes reader on a name the text defines at the end of a chain (``L_z = \\omega \\sum_i m_i r_i^2
= J_z \\omega``): the new name times a factor of the member before it is that member over the
factor, and the displays after it use the name so defined."""
import kept_readings as kept

from derive.lecture.chain_end_names import put_in

CHAIN = "# Notes\n\n$$L_z = \\omega \\sum_i m_i r_i^2 = J_z \\omega$$\n\n"
RADIUS = "The radius of gyration, $\\rho_z^2 = \\sum_i m_i r_i^2 / m$:\n\n"


verdicts, line_of = kept.verdicts_by_line, kept.line_of


def test_a_name_met_at_a_chains_end_is_defined_by_the_member_before_it():
    text = CHAIN + RADIUS + "$$\\rho_z = \\sqrt{\\frac{J_z}{m}}$$\n"
    assert verdicts(text)[line_of(text, "$$\\rho_z =")] == {"holds"}


def test_the_name_so_defined_does_not_make_a_wrong_relation_hold():
    text = CHAIN + RADIUS + "$$\\rho_z = \\sqrt{\\frac{m}{J_z}}$$\n"
    assert "holds" not in verdicts(text)[line_of(text, "$$\\rho_z =")]


def test_a_name_at_a_chains_end_without_a_shared_factor_is_not_defined():
    text = ("# Notes\n\n$$L_z = \\omega \\sum_i m_i r_i^2 = J_z$$\n\n" + RADIUS +
            "$$\\rho_z = \\sqrt{\\frac{J_z \\omega}{m}}$$\n")
    assert "holds" not in verdicts(text)[line_of(text, "$$\\rho_z =")]


def test_a_name_defined_at_a_chains_end_is_put_in_with_its_index_braced_or_not():
    for defined, later in (("J_{z}", "J_z"), ("J_z", "J_{ z }"), ("J_z", "J_z")):
        got = put_in("\\sum_i m_i x_i^2 = " + later + " + J_{zz}", {defined: (1, "S")}, 5)
        assert got == "\\sum_i m_i x_i^2 = \\left(S\\right) + J_{zz}", (defined, later, got)
