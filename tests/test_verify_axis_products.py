"""The notes reader on a product of matrices named only by their axes (R_z R_x R_z) written out
factor by factor: each factor is held to the turn about its name's axis, all in one sense, and the
name set equal to the product is that matrix, also when written again at a setting of an angle."""
import sympy as sp

import kept_readings as kept

HEAD = "---\nangles: [\\alpha, \\beta, \\gamma]\n---\n# Notes\n\n"


def z(q, s=""):
    return (f"\\begin{{bmatrix}} \\cos\\{q} & {s}\\sin\\{q} & 0 \\\\ -\\sin\\{q} & \\cos\\{q} & 0 \\\\ "
            "0 & 0 & 1 \\end{bmatrix}")


def x(q, s=""):
    return (f"\\begin{{bmatrix}} 1 & 0 & 0 \\\\ 0 & \\cos\\{q} & {s}\\sin\\{q} \\\\ "
            f"0 & -\\sin\\{q} & \\cos\\{q} \\end{{bmatrix}}")


IDENTITY = "\\begin{bmatrix} 1 & 0 & 0 \\\\ 0 & 1 & 0 \\\\ 0 & 0 & 1 \\end{bmatrix}"


def chain(first, middle, last):
    return ("$$\n\\begin{array}{ll}\n\\mathbf{R}_{zxz} & = \\mathbf{R_{z}} \\mathbf{R_{x}} \\mathbf{R_{z}} \\\\\n"
            f"& = {first}\n{middle}\n{last}\n\\end{{array}}\n$$\n\n")


def line_of(text, marker):
    """The line of the display that holds ``marker`` (where its ``$$`` opens)."""
    return text[:text.rindex("$$", 0, text.index(marker))].count("\n") + 1


verdicts = kept.verdicts_by_line


def test_written_factors_that_are_the_turns_about_their_names_axes_hold():
    got = verdicts(HEAD + chain(z("gamma"), x("beta"), z("alpha")))
    assert got[6] == {"holds"}


def test_a_factor_turned_the_other_way_from_the_rest_is_left_unchecked():
    # the middle factor is the active turn, the others passive: R_x would be two matrices
    got = verdicts(HEAD + chain(z("gamma"), x("beta", "-"), z("alpha")))
    assert "holds" not in got[6] and not got[6] & {"fails", "typo"}


def test_a_factor_about_another_axis_than_its_name_is_not_held():
    got = verdicts(HEAD + chain(z("gamma"), z("beta"), z("alpha")))
    assert "holds" not in got[6] and not got[6] & {"fails", "typo"}


def test_the_named_product_at_a_set_angle_is_that_matrix_with_the_setting():
    at = ("$$\n\\mathbf{R}_{zxz}(\\alpha, \\beta=0, \\gamma) = " + z("gamma") + "\n" + IDENTITY + "\n"
          + z("alpha") + "\n$$\n")
    text = HEAD + chain(z("gamma"), x("beta"), z("alpha")) + at
    got = verdicts(text)
    line = line_of(text, "(\\alpha, \\beta=0")
    assert got[line] == {"holds"}


def test_the_named_product_at_a_set_angle_written_wrong_fails():
    at = ("$$\n\\mathbf{R}_{zxz}(\\alpha, \\beta=0, \\gamma) = " + z("gamma") + "\n" + IDENTITY + "\n"
          + z("alpha", "-") + "\n$$\n")
    text = HEAD + chain(z("gamma"), x("beta"), z("alpha")) + at
    line = line_of(text, "(\\alpha, \\beta=0")
    assert verdicts(text)[line] == {"fails"}


def test_a_setting_in_the_arguments_of_a_name_the_text_has_not_bound_is_not_read_as_one():
    text = HEAD + ("$$\n\\mathbf{Q}(\\alpha, \\beta=0, \\gamma) = " + z("gamma") + "\n" + IDENTITY + "\n"
                   + z("alpha") + "\n$$\n")
    assert not verdicts(text)[6] & {"holds", "fails", "typo"}


def test_a_chain_that_also_writes_the_product_out_binds_the_name_to_its_written_factors():
    a, b, g = sp.symbols("alpha beta gamma")
    turn_z = lambda q: sp.Matrix([[sp.cos(q), sp.sin(q), 0], [-sp.sin(q), sp.cos(q), 0], [0, 0, 1]])  # noqa: E731
    turn_x = lambda q: sp.Matrix([[1, 0, 0], [0, sp.cos(q), sp.sin(q)], [0, -sp.sin(q), sp.cos(q)]])  # noqa: E731
    product = turn_z(g) * turn_x(b) * turn_z(a)
    out = " \\\\ ".join(" & ".join(sp.latex(e) for e in product.row(i)) for i in range(3))
    four = chain(z("gamma"), x("beta"), z("alpha")).replace(
        "\n\\end{array}", " \\\\\n& = \\begin{bmatrix} " + out + " \\end{bmatrix}\n\\end{array}")
    at = ("$$\n\\mathbf{R}_{zxz}(\\alpha, \\beta=0, \\gamma) = " + z("gamma") + "\n" + IDENTITY + "\n"
          + z("alpha") + "\n$$\n")
    text = HEAD + four + at
    got = verdicts(text)
    assert got[6] & {"holds"} and not got[6] & {"fails", "typo"}
    assert got[line_of(text, "(\\alpha, \\beta=0")] == {"holds"}
