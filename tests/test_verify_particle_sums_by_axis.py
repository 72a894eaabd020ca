"""The vector-algebra reader on a body written as particles a with coordinates indexed by axis:
x_{ai} (particle a's i-th coordinate), a component J_i or ω_i at a free index beside the sum over
a, and a sum over the axes (Σ_j) inside the sum over the particles; and a matrix with an entry in
a symbol no model knows, its other entries read one by one."""
from kept_readings import by_line

BODY = ("# Particles\n\nA rigid body is a set of particles with positions $\\mathbf{r}_a$ and masses $m_a$, "
        "turning with angular velocity $\\boldsymbol{\\omega}$ about its centre of mass, and its angular "
        "momentum $\\mathbf{J}$ is\n\n$$\n\\mathbf{J} = \\sum_a m_a \\mathbf{r}_a \\times (\\boldsymbol{\\omega} "
        "\\times \\mathbf{r}_a)\n$$\n\nIn components:\n\n$$\nSTATEMENT\n$$\n")
AT = 11


def _verdicts(statement):
    return [c.verdict for c in by_line(BODY.replace("STATEMENT", statement))[AT]]


def test_a_component_at_a_free_index_with_coordinates_indexed_by_particle_and_axis():
    assert _verdicts(r"J_i = \sum_a m_a r_a^2 \omega_i - \sum_a m_a x_{ai} \sum_j x_{aj}\omega_j") == ["holds"]
    assert _verdicts(r"I_{ij} = \sum_a m_a (r_a^2 \delta_{ij} - x_{ai} x_{aj})") == ["holds"]
    assert _verdicts(r"I_{ij} = \sum_a m_a (r_a^2 \delta_{ij} - x_{a,i} x_{a,j})") == ["holds"]


def test_a_sum_over_the_axes_with_the_axis_index_slipped_is_flagged():
    slipped = by_line(BODY.replace("STATEMENT", r"J_i = \sum_a m_a r_a^2 \omega_i - \sum_a m_a x_{ai} "
                                                r"\sum_j x_{ai}\omega_j"))[AT]
    assert [c.verdict for c in slipped] == ["typo"]
    assert "x_{aj}" in slipped[0].correction
    assert _verdicts(r"I_{ij} = \sum_a m_a (r_a^2 \delta_{ij} + x_{ai} x_{aj})") in (["typo"], ["fails"])
    assert _verdicts(r"I_{ij} = \sum_a m_a (r_a^2 \delta_{ij} - x_{a,i} x_{a,i})") in (["typo"], ["fails"])


def test_a_sum_whose_index_writes_a_particle_is_not_read_as_over_the_axes():
    # m_b under Σ_b: a second sum over the particles, never a sum over the axes
    assert _verdicts(r"J_i = \sum_a \sum_b m_b r_a^2 \omega_i") == ["unchecked"]


MATRIX = (r"I = \sum_a m_a \begin{pmatrix} y_a^2 + z_a^2 & -x_ay_a & -x_az_a\\ -x_ay_a & x_a^2 + z_a^2 & -y_az_a\\ "
          r"ROW & x_a^2 + y_q^2 \end{pmatrix}")


def test_a_matrix_entry_in_an_unknown_symbol_leaves_the_other_entries_judged():
    slipped = by_line(BODY.replace("STATEMENT", MATRIX.replace("ROW", r"-x_ay_a & -y_az_a")))[AT]
    assert [c.verdict for c in slipped] == ["fails"]
    assert "entry 3,1" in slipped[0].why and "y_q" in slipped[0].why
    # the entries read agree: the entry with y_q is not judged either way
    assert _verdicts(MATRIX.replace("ROW", r"-x_az_a & -y_az_a")) == ["unchecked"]


def test_a_matrix_with_many_unknown_entries_or_zeros_beside_them_is_not_judged():
    many = r"I = \sum_a m_a \begin{pmatrix} p & q & -x_az_a\\ s & x_a^2 + z_a^2 & -y_az_a\\ -x_az_a & -y_az_a & u \end{pmatrix}"
    assert _verdicts(many) == ["unchecked"]
    zeros = r"I = \sum_a m_a \begin{pmatrix} p & 0 & 0\\ 0 & q & 0\\ 0 & 0 & x_a^2 + y_a^2 \end{pmatrix}"
    assert _verdicts(zeros) == ["unchecked"]
