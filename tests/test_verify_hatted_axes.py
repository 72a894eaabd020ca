"""The notes reader on unit vectors written with a hat and no prime (x̂, ŷ, ẑ, î, ĵ, k̂) that the
text has not defined: tried as the space frame's axes, then the body's; a statement is kept under
the frame in which it holds, flagged only where it fails alike as no vector in both (a product of
two unit vectors), and a slip that fails differently in each is left unchecked."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n\n# Notes\n\n"
OMEGA = ("$$\\boldsymbol{\\omega} = \\dot{\\phi}\\hat{\\mathbf{z}} + \\dot{\\theta}\\hat{\\mathbf{e}}_1' "
         "+ \\dot{\\psi}\\hat{\\mathbf{e}}_3'$$\n")
VERTICAL = "$$\\bm{\\hat{z}} = \\cos\\theta\\,\\hat{\\mathbf{e}}_3' + \\sin\\theta\\,\\hat{\\mathbf{e}}_2'$$\n"


def _claims(text):
    return [c for c in kept.check_text(HEAD + text) if c.line == kept.line_of(HEAD + text, "$$")]


def test_the_vertical_written_z_hat_in_the_angular_velocity_holds_as_the_space_frame_axis():
    claims = _claims(OMEGA)
    assert {c.verdict for c in claims} == {"holds"}
    assert all("the space frame" in c.why for c in claims)


def test_the_vertical_on_the_primed_axes_holds():
    assert {c.verdict for c in _claims(VERTICAL)} == {"holds"}


def test_two_unit_vectors_side_by_side_in_the_decomposition_are_flagged_in_every_frame():
    slip = VERTICAL.replace("\\,\\hat{\\mathbf{e}}_3' +", "\\,\\hat{\\mathbf{e}}_3'\\hat{\\mathbf{e}}_1' +")
    claims = _claims(slip)
    assert {c.verdict for c in claims} == {"fails"}
    assert all("not a vector" in c.why and "fails alike" in c.why for c in claims)


def test_a_sign_slip_along_hatted_axes_is_left_unchecked_never_flagged():
    slip = VERTICAL.replace("+ \\sin\\theta", "- \\sin\\theta")
    assert {c.verdict for c in _claims(slip)} == {"unchecked"}
