"""The notes reader on index notation and on a flat body: an index the first member does not write,
written twice in a later member (``\\omega_j\\omega_j``), is summed there by the summation convention,
not a free index; and a bare ``$z = 0$`` in the prose puts the body's points in that plane for the
rest of its section, so that a lamina's theorem (I_zz = I_xx + I_yy) holds where it fails of a body
in general."""
import kept_readings as kept

verdicts, line_of = kept.verdicts_by_line, kept.line_of
SQUARE = ("# Notes\n\nThe square of the angular velocity, with the Kronecker delta:\n\n"
          "$$\\begin{align*} \\omega^2 &= \\vec\\omega \\cdot \\vec\\omega \\\\ &= ")
SUM = "\\sum_{k=1}^3 \\omega_k \\delta_{jk} \\sum_{k=1}^3 \\omega_k \\delta_{jk}"
END = " \\end{align*}$$\n"


def test_an_index_written_twice_and_absent_from_the_first_member_is_summed():
    text = SQUARE + SUM + END
    assert verdicts(text)[line_of(text, "$$")] == {"holds", "unchecked"}


def test_the_summed_index_does_not_make_a_wrong_member_hold():
    text = SQUARE + "2 " + SUM + END
    assert verdicts(text)[line_of(text, "$$")] & {"fails", "typo"}


def test_an_index_written_once_stays_free_and_is_read_at_each_value():
    text = SQUARE.replace("\\omega^2 &= \\vec\\omega \\cdot \\vec\\omega", "\\omega_j &= \\omega_j") + \
        "\\sum_{k=1}^3 \\omega_k \\delta_{jk}" + END
    assert "fails" not in verdicts(text)[line_of(text, "$$")]


PLATE = ("# Notes\n\nThe moments of inertia of a body are sums over its particles:\n\n"
         "$$I_{xx} = \\sum_i m_i (y_i^2 + z_i^2)$$\n\n"
         "## Perpendicular axes\n\nThe theorem applies to a flat body, lying in the plane $z = 0$:\n\n")


def test_a_bare_z_equal_zero_in_the_prose_puts_the_body_in_that_plane():
    text = PLATE + "$$I_{zz} = I_{xx} + I_{yy}$$\n"
    assert verdicts(text)[line_of(text, "$$I_{zz}")] == {"holds"}


def test_the_plane_does_not_make_a_wrong_relation_hold():
    text = PLATE + "$$I_{zz} = I_{xx} - I_{yy}$$\n"
    assert "holds" not in verdicts(text)[line_of(text, "$$I_{zz}")]


def test_without_the_plane_the_lamina_theorem_is_not_taken_to_hold():
    text = PLATE.replace(", lying in the plane $z = 0$", "") + "$$I_{zz} = I_{xx} + I_{yy}$$\n"
    assert "holds" not in verdicts(text)[line_of(text, "$$I_{zz}")]


def test_the_plane_holds_only_in_the_section_that_sets_it():
    text = PLATE + "## Another body\n\nA solid body.\n\n$$I_{zz} = I_{xx} + I_{yy}$$\n"
    assert "holds" not in verdicts(text)[line_of(text, "$$I_{zz}")]
