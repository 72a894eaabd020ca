"""The notes reader on Schaub's inertia tensor in brackets with the frame it is written in, ``^B[\\mathbf{I}_C]``
(its components in the body frame B, about the centre of mass C): the frame's label before the bracket
goes as before a vector, the tensor is the body's, constant in body axes, so its rate seen from B,
``^B\\frac{\\text{d}\\,^B[\\mathbf{I}_C]}{\\text{d}t}``, is zero; the rate seen from B written as an operator on a
bracket, ``^B\\frac{\\text{d}}{\\text{d}t}\\left(\\ldots\\right)``, is read, and the product rule with them is
checked (its sign slip flagged)."""
from kept_readings import by_line, line_of

TEXT = "# About the centre of mass\n\nIn the body frame B:\n\n$$\nROW\n$$\n"
H = r"^B\vec{\mathbf{H}}_C = ^B[\mathbf{I}_C] \vec{\boldsymbol{\omega}}_{B/N}"
STILL = r"^B\frac{\text{d}\,^B[\mathbf{I}_C]}{\text{d}t} = 0"
OPERATOR = (r"^B\frac{\text{d}\vec{\mathbf{H}}_C}{\text{d}t} = ^B\frac{\text{d}}{\text{d}t}\left(^B[\mathbf{I}_C] "
            r"\vec{\boldsymbol{\omega}}_{B/N}\right)")
PRODUCT = (r"^B\frac{\text{d}}{\text{d}t}\left(^B[\mathbf{I}_C] \vec{\boldsymbol{\omega}}_{B/N}\right) = \left(^B\frac{\text{d}\,"
           r"^B[\mathbf{I}_C]}{\text{d}t}\right)\vec{\boldsymbol{\omega}}_{B/N} SIGN ^B[\mathbf{I}_C] "
           r"^B\frac{\text{d}\vec{\boldsymbol{\omega}}_{B/N}}{\text{d}t}")


def _verdicts(row: str) -> list[str]:
    text = TEXT.replace("ROW", row)
    return [c.verdict for c in by_line(text)[line_of(text, "$$\n" + row)]]


def test_the_momentum_about_c_as_the_bracketed_tensor_in_b_times_omega_holds():
    assert _verdicts(H) == ["holds"]


def test_the_rate_of_the_bracketed_tensor_seen_from_the_body_is_zero():
    assert _verdicts(STILL) == ["holds"]


def test_the_rate_seen_from_the_body_as_an_operator_on_a_bracket_is_read():
    assert _verdicts(OPERATOR) == ["holds"]


def test_the_product_rule_with_frame_labelled_rates_holds_and_its_sign_slip_is_flagged():
    assert _verdicts(PRODUCT.replace("SIGN", "+")) == ["holds"]
    assert _verdicts(PRODUCT.replace("SIGN", "-")) in (["fails"], ["typo"])


def test_the_rate_of_the_tensor_seen_from_the_inertial_frame_is_not_read():
    assert _verdicts(STILL.replace("^B\\frac", "^N\\frac")) == ["unchecked"]
