"""The notes reader on unit vectors written with a prime (î′, ĵ′, k̂′): the axes of a frame of the
angle sequence, tried in turn (after the first two turns, the body's, space's); a statement is kept
under the frame in which it holds, and one that holds under none is read as written: a slip along
them is not flagged by a frame the reader chose."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n\n# Notes\n\n"
NODES = ("$$\\mathbf{\\omega} = \\dot{\\theta}\\hat{i}' + \\dot{\\phi}\\sin\\theta\\hat{j}' "
         "+ (\\dot{\\phi}\\cos\\theta + \\dot{\\psi})\\hat{k}'$$\n")
BODY = ("$$\\boldsymbol{\\omega} = (\\dot\\phi \\sin\\theta \\sin\\psi + \\dot\\theta \\cos\\psi) \\hat{\\mathbf{x}}^\\prime "
        "+ (\\dot\\phi \\sin\\theta \\cos\\psi - \\dot\\theta \\sin\\psi) \\hat{\\mathbf{y}}^\\prime "
        "+ (\\dot\\phi \\cos\\theta + \\dot\\psi) \\hat{\\mathbf{z}}^\\prime$$\n")


def _claims(text):
    return [c for c in kept.check_text(HEAD + text) if c.line == kept.line_of(HEAD + text, "$$")]


def test_the_angular_velocity_along_the_primed_axes_of_the_line_of_nodes_holds_naming_that_frame():
    claims = _claims(NODES)
    assert {c.verdict for c in claims} == {"holds"}
    assert all("after the first two turns" in c.why for c in claims)


def test_primed_axes_that_are_the_body_axes_hold_as_the_body_frame():
    claims = _claims(BODY)
    assert {c.verdict for c in claims} == {"holds"}
    assert all("the body frame" in c.why for c in claims)


def test_a_slip_along_primed_axes_is_left_unchecked_never_flagged():
    claims = _claims(NODES.replace("\\dot{\\phi}\\sin\\theta\\hat{j}'", "\\dot{\\phi}\\cos\\theta\\hat{j}'"))
    assert {c.verdict for c in claims} == {"unchecked"}
