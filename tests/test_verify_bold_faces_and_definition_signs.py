"""A bold letter is the same symbol whichever command sets it (``\\mathbf``, ``\\boldsymbol``, ``\\bm``,
``\\pmb``, …), and a definition is one sign however it is written (``\\equiv``, ``\\coloneqq``,
``\\triangleq``, ``:=``): the reader knows each spelling from one place, `derive.lecture.latex_spellings`,
so a form it reads in one spelling it reads in every other."""
import re

import kept_readings as kept
import pytest
from kept_readings import verdicts_by_line
from test_verify_density_at_a_point import L
from test_verify_primed_axes import BODY
from test_verify_primed_axes import HEAD as PRIMED_HEAD

from derive.lecture import latex_spellings as ls
from derive.lecture import source, vocabulary

FACES = ("\\mathbf{C}", "\\boldsymbol{C}", "\\bm{C}", "\\bm C", "\\pmb{C}")

FRAMES = ("Frames $E$ and $D$ with right-handed unit vectors.\n\n"
          "$$\n{}^D\\mathbf{C}^E = \\begin{bmatrix} 1 & 0 & 0 \\\\ 0 & \\cos\\phi & \\sin\\phi \\\\ "
          "0 & -\\sin\\phi & \\cos\\phi \\end{bmatrix}\n$$\n\n")


@pytest.mark.parametrize("face", FACES)
def test_a_direction_cosine_matrix_in_any_bold_face_is_read_as_the_matrix(face):
    def dcm(f, g):
        return "{}^" + f + face + "^" + g
    held = FRAMES + "$$\n" + dcm("E", "D") + " = \\left(" + dcm("D", "E") + "\\right)^T\n$$\n"
    slip = FRAMES + "$$\n" + dcm("E", "D") + " = " + dcm("D", "E") + "\n$$\n"
    assert verdicts_by_line(held)[7] == {"holds"}
    assert verdicts_by_line(slip)[7] == {"fails"}


def bracket_text(sign: str, bold: str = "\\mathbf") -> str:
    def b(x):
        return bold + "{" + x + "}"
    return ("The particles sit at $" + b("r") + "_i$; $" + b("S") + "$ is a point and $" + b("y") + "$ any vector. "
            "The cross product is a matrix product:\n\n"
            "$$" + b("b") + " \\times " + b("y") + " " + sign + " \\left[" + b("b") + "\\right] " + b("y") + "$$\n\n"
            "so that\n\n$$[r_i -S]" + b("y") + " = (" + b("r") + "_i - " + b("S") + ")\\times " + b("y") + "$$\n")


@pytest.mark.parametrize("sign", ["\\equiv", "\\coloneqq", "\\triangleq", ":=", "\\defeq"])
def test_a_bracket_defined_as_the_cross_product_with_any_definition_sign_is_that_matrix(sign):
    text = bracket_text(sign)
    assert verdicts_by_line(text)[3] == {"holds"}
    assert verdicts_by_line(text)[7] == {"holds"}
    # the same bracket acting with the wrong sign of the difference is a slip, whichever sign defined it
    assert verdicts_by_line(text.replace("(\\mathbf{r}_i - \\mathbf{S})", "(\\mathbf{S} - \\mathbf{r}_i)"))[7] & {"typo", "fails"}


@pytest.mark.parametrize("bold", ["\\boldsymbol", "\\bm"])
def test_a_bracket_defined_on_vectors_in_another_bold_face_is_the_same_matrix(bold):
    assert verdicts_by_line(bracket_text("\\coloneqq", bold))[7] == {"holds"}


def test_every_bold_command_is_one_fragment_the_scanner_and_the_normaliser_share():
    bold = re.compile(ls.BOLD)
    for name in ls.BOLD_NAMES + tuple(ls.REWRITTEN_BOLD_NAMES):
        assert bold.fullmatch("\\" + name), name
        assert not bold.match("\\" + name + "x")         # another command's name, not a bold one
    assert all(vocabulary.DECORATIONS[name] == "bold" for name in ls.BOLD_NAMES)
    for name in ls.REWRITTEN_BOLD_NAMES:                 # written as a bold every reader knows
        assert source.normalize("\\" + name + "{x} = 1").startswith("\\boldsymbol{x}")


def test_every_definition_sign_is_one_fragment_and_normalised_to_equiv():
    defines = re.compile(ls.DEFINES)
    for sign in ["\\equiv", ":=", ": ="] + ["\\" + n for n in sorted(ls.DEFINITION_NAMES)]:
        assert defines.search("a " + sign + " b"), sign
        assert "\\equiv" in source.normalize("a " + sign + " b"), sign
    assert not defines.search("a = b") and not defines.search("a \\equivalent b") and not defines.search("a =: b")


def test_the_density_at_a_point_written_in_another_bold_face_is_the_mass_element():
    for face in ("\\bm", "\\boldsymbol"):
        text = L.replace("\\rho(\\mathbf{r})", "\\rho(" + face + "{r})")
        assert text != L and verdicts_by_line(text)[5] == {"holds"}, face
        assert "typo" in verdicts_by_line(text.replace("r^2 - \\mathbf{r}", "r^2 + \\mathbf{r}"))[5], face


def test_primed_unit_vectors_in_another_bold_face_are_the_same_axes():
    from_bold = BODY.replace("\\mathbf", "\\bm")
    claims = [c for c in kept.check_text(PRIMED_HEAD + from_bold) if c.line == kept.line_of(PRIMED_HEAD + from_bold, "$$")]
    assert from_bold != BODY and {c.verdict for c in claims} == {"holds"}
    assert all("the body frame" in c.why for c in claims)
