"""Texts in operator notation (D the time derivative, 𝒜 the cross-product matrix, the orientation
matrix, components on principal axes labelled after the moments A, B, C), read by
`derive.lecture.operator_notation` on the motions of `derive.lecture.motion_jets`."""
import random

import mpmath
import pytest

from derive.lecture import motion_jets as mj
import kept_readings as kept
from derive.lecture.statements import statements

HEAD = r"""---
convention: z-x-z
angles: [\phi, \theta, \psi]
---
# Rigid bodies in functional notation

Notation: $D$ is the time derivative, $A$, $B$, $C$ are the principal moments of inertia,
$\omega^a, \omega^b, \omega^c$ the components of the angular velocity on the principal axes,
primes mark principal-axis components, $\mathbf{M}$ is the orientation matrix and
$\mathscr{A}$ turns a vector into the antisymmetric matrix of the cross product.

"""


def _verdicts(body, head=HEAD):
    return [(c.verdict, c.why) for c in kept.check_text(head + body)]


def _display(latex, before=""):
    return before + "\n\n$$\n" + latex + "\n$$\n"


def test_the_orientation_matrix_rate_holds_and_its_sign_slip_is_a_typo_corrected_in_the_texts_notation():
    assert _verdicts(_display(r"D\mathbf{M} = \mathbf{M}\mathscr{A}(\boldsymbol{\omega}')"))[0][0] == "holds"
    claim = kept.check_text(HEAD + _display(r"D\mathbf{M} = -\mathbf{M}\mathscr{A}(\boldsymbol{\omega}')"))[0]
    assert claim.verdict == "typo" and "-" not in claim.correction
    assert _verdicts(_display(claim.correction))[0][0] == "holds"


def test_a_slip_that_no_sign_repairs_fails():
    assert _verdicts(_display(r"D\mathbf{M} = \mathscr{A}(\boldsymbol{\omega}')\mathbf{M}"))[0][0] == "fails"


def test_euler_equations_in_components_hold_for_the_free_body_the_section_states():
    text = _display(r"A D\omega^a = (B - C) \omega^b \omega^c", "For a free body the angular momentum is constant.")
    verdict, why = _verdicts(text)[0]
    assert verdict == "holds" and "free body" in why
    assert _verdicts(_display(r"A D\omega^a = (C - B) \omega^b \omega^c", "For a free body:"))[0][0] in ("typo", "fails")


def test_a_torque_makes_euler_equations_hold_on_any_motion():
    ok = _display(r"A D \omega^a - (B - C) \omega^b \omega^c = T_a", "The torque $\\mathbf{T}$ acts.")
    assert _verdicts(ok)[0][0] == "holds"


def test_without_a_free_body_stated_the_torque_free_equations_fail():
    assert _verdicts(_display(r"A D\omega^a = (B - C) \omega^b \omega^c", "The body is pushed."))[0][0] == "fails"


def test_the_potentials_slot_derivative_is_minus_the_generalised_force():
    v = r"\partial_{1,1} V(t; \theta(t), \phi(t), \psi(t))"
    assert _verdicts(_display(rf"D p_\phi = -{v}"))[0][0] == "holds"
    assert _verdicts(_display(rf"D p_\phi = {v}"))[0][0] == "typo"
    claim = kept.check_text(HEAD + _display(rf"D \partial_{{\dot\phi}} L = -D p_\phi = {v}"))[0]
    assert claim.verdict == "typo" and claim.correction == rf"-D \partial_{{\dot\phi}} L = -D p_\phi = {v}"


def test_an_identity_in_vectors_the_text_leaves_arbitrary_holds_and_a_wrong_one_is_not_judged():
    assert _verdicts(_display(r"\mathscr{A}(\mathbf{u})\mathbf{v} = \mathbf{u} \times \mathbf{v}"))[0][0] == "holds"
    verdict, why = _verdicts(_display(r"\mathscr{A}(\mathbf{u})\mathbf{v} = \mathbf{v} \times \mathbf{u}"))[0]
    assert verdict == "unchecked" and "arbitrary" in why


def test_a_capital_letter_the_prose_calls_a_rotation_is_any_rotation():
    text = _display(r"\mathscr{A}(\mathbf{u}) = \mathbf{R}^{T} \mathscr{A}(\mathbf{R} \mathbf{u}) \mathbf{R}",
                    "Rotating a cross product gives the cross product of the rotated vectors.")
    assert _verdicts(text)[0][0] == "holds"


def test_a_symbol_met_first_on_the_left_is_a_definition_not_a_claim():
    verdict, why = _verdicts(_display(r"\mathbf{L}' = \mathbf{I}'\boldsymbol{\omega}'"))[0]
    assert verdict == "unchecked" and "definition" in why


def test_the_rates_matrix_of_the_angles_holds():
    latex = r"""\begin{pmatrix} D\theta \\ D\phi \\ D\psi \end{pmatrix} = \frac{1}{\sin\theta}\begin{pmatrix}
\cos\psi\sin\theta & -\sin\psi\sin\theta & 0\\ \sin\psi & \cos\psi & 0 \\
-\sin\psi\cos\theta & -\cos\psi\cos\theta & \sin\theta\end{pmatrix} \begin{pmatrix}\omega^a\\ \omega^b\\ \omega^c \end{pmatrix}"""
    assert _verdicts(_display(latex))[0][0] == "holds"


def test_a_function_with_a_braced_argument_keeps_the_braces_of_the_fraction_around_it():
    # \frac{1}{\sin{\theta}}: the outer braces are the denominator, not braces around one decorated symbol
    latex = r"""\begin{pmatrix} D\theta \\ D\phi \\ D\psi \end{pmatrix} = \frac{1}{\sin{\theta}}\begin{pmatrix}
\cos{\psi}\sin{\theta} & -\sin{\psi}\sin{\theta} & 0\\ \sin{\psi} & \cos{\psi} & 0 \\
-\sin{\psi}\cos{\theta} & -\cos{\psi}\cos{\theta} & \sin{\theta}\end{pmatrix} \begin{pmatrix}\omega^a\\ \omega^b\\ \omega^c \end{pmatrix}"""
    assert _verdicts(_display(latex))[0][0] == "holds"
    assert _verdicts(_display(r"D\mathbf{M} = {\mathbf{M}}\mathscr{A}(\boldsymbol{\omega}')"))[0][0] == "holds"


def test_a_text_that_declares_no_operator_notation_is_read_as_before():
    head = "---\nconvention: z-x-z\n---\n# Top\n\n"
    claims = kept.check_text(head + _display(r"D\mathbf{M} = \mathbf{M}\mathscr{A}(\boldsymbol{\omega}')"))
    assert all(c.kind != "operator identity" for c in claims)


def test_a_semicolon_inside_a_functions_brackets_does_not_cut_the_statement():
    assert statements(r"T = V(t; \theta, \phi)") == [r"T = V(t; \theta, \phi)"]
    assert len(statements(r"a = 1; b = 2")) == 2


def test_a_jets_sine_has_the_derivatives_of_the_sine():
    x = mj.Jet([0.4, 1.0, 0.3, -0.2])
    s, _ = mj.sin_cos(x)
    want = mpmath.taylor(lambda t: mpmath.sin(0.4 + t + 0.3 * t ** 2 - 0.2 * t ** 3), 0, 3)
    assert all(abs(a - b) < 1e-12 for a, b in zip(s.a, want))


def test_jet_products_and_quotients_are_mpmaths_53_bit_values_bit_for_bit():
    a, b = mj.Jet([0.7, -1.3, 0.25, 2.1]), mj.Jet([1.9, 0.35, -0.6, 0.05])
    A, B = ([mpmath.mpf(x) for x in j.a] for j in (a, b))
    with mpmath.workprec(53):
        product = [sum((A[k] * B[n - k] for k in range(1, n + 1)), A[0] * B[n]) for n in range(mj.ORDER)]
        inverse = [1 / B[0]]
        for n in range(1, mj.ORDER):
            inverse.append(-sum(B[k] * inverse[n - k] for k in range(1, n + 1)) / B[0])
    assert (a * b).a == [float(x) for x in product]
    assert b.reciprocal().a == [float(x) for x in inverse]


@pytest.mark.parametrize("free", [True, False])
def test_a_free_instant_has_no_torque_and_a_forced_one_has_one(free):
    instant = mj.Instant(("z", "x", "z"), [1.0, 2.0, 3.5], "seed", free)
    size = max(abs(t.value) for t in instant.torque)
    assert (size < 1e-12) == free


@pytest.mark.slow
def test_every_planted_sign_slip_in_the_sicm_notes_is_flagged_on_its_display_only():
    """Each '-' of a correct display of the SICM study notes turned into '+', one at a time (up to
    three per display): flagged on that display, and on no other correct display."""
    import re
    import sys
    from pathlib import Path

    real = Path(__file__).resolve().parent / "notes" / "real"
    sys.path.insert(0, str(real))
    import measure

    slug = "sicm-workbook-euler-equations-forced"
    lines = (real / f"{slug}.md").read_text().split("\n")
    rows = {r["line"]: r["verdict"] for r in measure.truth(slug)}
    planted, missed, alarms = 0, [], []
    for ln in sorted(k for k, v in rows.items() if v == "holds"):
        end = ln
        while end < len(lines) and not (end > ln and lines[end - 1].strip().startswith("$$")):
            end += 1
        seg = "\n".join(lines[ln - 1:end])
        for m in list(re.finditer(r"(?<=[ =(])- ?", seg))[:3]:
            text = "\n".join(lines[:ln - 1] + [seg[:m.start()] + "+ " + seg[m.end():]] + lines[end:])
            flagged = {c.line for c in kept.check_text(text) if c.verdict in ("typo", "fails")}
            planted += 1
            if ln not in flagged:
                missed.append(ln)
            alarms += [x for x in flagged if rows.get(x) == "holds" and x != ln]
    assert planted >= 20 and not missed and not alarms, (planted, missed, alarms)


def test_a_matrix_of_jets_multiplies_row_by_column_left_to_right():
    rng = random.Random(7)
    A = mj.Array.of([[mj.Jet([rng.uniform(-1, 1) for _ in range(4)]) for _ in range(3)] for _ in range(3)])
    v = mj.Array.of([mj.Jet([rng.uniform(-1, 1) for _ in range(4)]) for _ in range(3)])
    by_hand = [A[i, 0] * v[0] + A[i, 1] * v[1] + A[i, 2] * v[2] for i in range(3)]
    assert [e.a for e in (A @ v).ravel()] == [e.a for e in by_hand]
    AT = A.T
    assert all(AT[i, j] is A[j, i] for i in range(3) for j in range(3))
    assert [e.a for e in (AT @ A)[:, 1].ravel()] == [(A[0, i] * A[0, 1] + A[1, i] * A[1, 1] + A[2, i] * A[2, 1]).a
                                                   for i in range(3)]
    assert [e.a for e in (v @ A).ravel()] == [(v[0] * A[0, j] + v[1] * A[1, j] + v[2] * A[2, j]).a for j in range(3)]
    s = mj.Jet([0.5, 1.0])
    assert [e.a for e in (s * v - v).ravel()] == [(s * v[i] - v[i]).a for i in range(3)]
    with pytest.raises(ValueError):
        v + mj.Array.of([s, s])
