"""`derive verify NOTES.md` on vectors, tensors, sums over particles and frame derivatives.

Each kind the vector reader (`derive.lecture.vectors`) adds holds on its correct form and is flagged
on a planted error, with the correction where the single-edit search finds one:

* sums over particles (T, 𝐋, I_ij, Ï as the particle sums), read for two generic particles;
* the principal axes' eigen-equation Ï·ê_i = I_i ê_i (Ï diagonal in body axes);
* frame derivatives: (d𝐫/dt)_inertial = ω × 𝐫 and the transport theorem, with R(t) of the
  z-y-z angles;
* d𝐋/dt = 0 with τ = 0 stated: each component is Euler's torque-free equation;
* continuation lines starting with ``=``.

The planted-error set of tests/notes/rigid-body-vectors.md is made of the new kinds of edit: a
sign (in a cross product: its operands swapped; or a + / − flipped), an index (r_pj → r_pi,
i ↔ j), a missing ½ and a power. The lecture's notes (read through the repository's parent) are
skipped with a reason when absent (the ``lecture_claims`` fixture).
"""
import re
from pathlib import Path

import pytest

import kept_readings as kept
from derive.lecture import vectors as vc

HERE = Path(__file__).parent
VECTORS = HERE / "notes" / "rigid-body-vectors.md"
FLAGGED = ("typo", "fails")


def verdicts(text):
    return [(c.kind, c.verdict) for c in kept.check_text(text)]


def one(text):
    claims = kept.check_text(text)
    assert len(claims) == 1, [(c.latex, c.verdict, c.why) for c in claims]
    return claims[0]


# ---- each kind: holds, and flagged on a planted error ------------------------------------------
PARTICLES = "# Particles\n\n$$%s$$\n"


def test_sum_over_particles_holds_and_a_cross_product_sign_is_corrected():
    right = one(PARTICLES % r"\mathbf{L} = \sum_{p} m_p \mathbf{r}_p \times \left( \boldsymbol{\omega} \times \mathbf{r}_p \right)")
    assert (right.kind, right.verdict) == ("definition", "holds")
    assert "two generic particles" in right.why and "v_p = ω × r_p" in right.why
    wrong = one(PARTICLES % r"\mathbf{L} = \sum_{p} m_p \mathbf{r}_p \times \left( \mathbf{r}_p \times \boldsymbol{\omega} \right)")
    assert wrong.verdict == "typo"
    # the correction reads back as a formula that holds
    assert one(PARTICLES % wrong.correction).verdict == "holds"


def test_inertia_components_index_slip_is_corrected():
    right = one(PARTICLES % r"I_{ij} \equiv \sum_{p} m_p \left( \delta_{ij} r_p^2 - r_{pi} r_{pj} \right)")
    assert (right.verdict, "for i, j = 1, 2, 3" in right.why) == ("holds", True)
    wrong = one(PARTICLES % r"I_{ij} \equiv \sum_{p} m_p \left( \delta_{ij} r_p^2 - r_{pi} r_{pi} \right)")
    assert wrong.verdict == "typo" and "at i = 1, j = 2" in wrong.why
    assert "r_{pj}" in wrong.correction and one(PARTICLES % wrong.correction).verdict == "holds"


def test_missing_half_is_corrected():
    right = one(PARTICLES % r"T = \frac{1}{2} \sum_{ij} I_{ij} \omega_i \omega_j")
    assert right.verdict == "holds"
    wrong = one(PARTICLES % r"T = \sum_{ij} I_{ij} \omega_i \omega_j")
    assert wrong.verdict == "typo" and wrong.correction.startswith(r"T = \frac{1}{2}")


def test_dyadic_and_unit_tensor():
    right = one(PARTICLES % r"\ddot{\mathbf{I}} \equiv \sum_{p} m_p \left( \mathbf{1} r_p^2 - \mathbf{r}_p \mathbf{r}_p \right)")
    assert right.verdict == "holds"
    wrong = one(PARTICLES % r"\ddot{\mathbf{I}} \equiv \sum_{p} m_p \left( \mathbf{1} r_p^2 + \mathbf{r}_p \mathbf{r}_p \right)")
    assert wrong.verdict == "typo" and r"\mathbf{1}" in wrong.correction and "- " in wrong.correction


def test_a_square_of_a_sum_is_not_a_sum():
    # one generic particle cannot tell these apart; two can
    c = one(PARTICLES % r"T = \frac{1}{2} \left( \sum_{p} m_p \mathbf{v}_p \right) \cdot \left( \sum_{p} \mathbf{v}_p \right)")
    assert c.verdict in FLAGGED


def test_principal_axes_eigen_equation():
    text = "# Principal axes\n\n$$\\ddot{\\mathbf{I}} \\cdot \\hat{\\mathbf{e}}_i = %s$$\n"
    right = one(text % r"I_i \hat{\mathbf{e}}_i")
    assert (right.kind, right.verdict) == ("identity", "holds") and "for i = 1, 2, 3" in right.why
    wrong = one(text % r"I_j \hat{\mathbf{e}}_i")
    assert wrong.verdict in FLAGGED


FRAME = "# Frames\n\n$$%s$$\n"


def test_frame_derivative_of_a_body_point():
    right = one(FRAME % r"\left(\frac{d\mathbf{r}}{dt}\right)_{inertial} = \boldsymbol{\omega} \times \mathbf{r}")
    assert (right.kind, right.verdict) == ("kinematics", "holds") and "R(t)" in right.why
    wrong = one(FRAME % r"\left(\frac{d\mathbf{r}}{dt}\right)_{inertial} = \mathbf{r} \times \boldsymbol{\omega}")
    assert wrong.verdict == "typo"
    assert re.sub(r"\s", "", wrong.correction).endswith(r"=\boldsymbol{\omega}\times\mathbf{r}") or \
        re.sub(r"\s", "", wrong.correction).endswith(r"=-\mathbf{r}\times\boldsymbol{\omega}")
    # in the body frame a body-fixed point does not move
    body = one(FRAME % r"\left(\frac{d\mathbf{r}}{dt}\right)_{body} = \boldsymbol{\omega} \times \mathbf{r}")
    assert body.verdict in FLAGGED


def test_transport_theorem():
    right = one(FRAME % r"\frac{d\mathbf{L}}{dt} = \left(\frac{d\mathbf{L}}{dt}\right)_{body} + \boldsymbol{\omega} \times \mathbf{L}")
    assert (right.kind, right.verdict) == ("kinematics", "holds")
    wrong = one(FRAME % r"\frac{d\mathbf{L}}{dt} = \left(\frac{d\mathbf{L}}{dt}\right)_{body} - \boldsymbol{\omega} \times \mathbf{L}")
    assert wrong.verdict == "typo" and r"\left(\frac{d\mathbf{L}}{dt}\right)_{body}" in wrong.correction
    assert one(FRAME % wrong.correction).verdict == "holds"
    law = kept.check_text(FRAME % r"\frac{d\mathbf{L}}{dt} = \left(\frac{d\mathbf{L}}{dt}\right)_{body} + \boldsymbol{\omega} \times \mathbf{L} = \boldsymbol{\tau}")
    assert [(c.kind, c.verdict) for c in law] == [("kinematics", "holds"), ("law", "unchecked")]


EULER = ("# Torque-free\n\nFor $\\tau = 0$ we solve\n\n$$\\frac{d\\mathbf{L}}{dt} = 0 = I_1 \\dot{\\tilde{\\omega}}_1 "
         "\\hat{\\mathbf{e}}_1 + I_2 \\dot{\\tilde{\\omega}}_2 \\hat{\\mathbf{e}}_2 + I_3 \\dot{\\tilde{\\omega}}_3 \\hat{\\mathbf{e}}_3 "
         "+ \\tilde{\\omega}_2 \\tilde{\\omega}_3 (I_3 - I_2) \\hat{\\mathbf{e}}_1 + \\tilde{\\omega}_3 \\tilde{\\omega}_1 "
         "(I_1 - I_3) \\hat{\\mathbf{e}}_2 + \\tilde{\\omega}_1 \\tilde{\\omega}_2 (%s) \\hat{\\mathbf{e}}_3$$\n")


def test_torque_free_vector_equation_component_wise():
    right = kept.check_text(EULER % "I_2 - I_1")
    assert right[0].kind == "equation of motion" and right[0].verdict == "holds" and "Euler's equation" in right[0].why
    assert all(c.verdict == "holds" for c in right)
    wrong = kept.check_text(EULER % "I_1 - I_2")
    assert wrong[0].verdict == "fails" and "component 3" in wrong[0].why
    unstated = kept.check_text((EULER % "I_2 - I_1").replace("For $\\tau = 0$ we solve", "We solve"))
    assert unstated[0].verdict == "unchecked" and "τ = 0" in unstated[0].why


def test_continuation_lines_take_the_left_side():
    text = ("# T\n\n$$T = \\sum_{p} \\frac{1}{2} m_p \\mathbf{v}_p \\cdot \\mathbf{v}_p$$\n\n"
            "$$= \\frac{1}{2} \\boldsymbol{\\omega} \\cdot \\ddot{\\mathbf{I}} \\cdot \\boldsymbol{\\omega}$$\n\n"
            "$$= \\boldsymbol{\\omega} \\cdot \\ddot{\\mathbf{I}} \\cdot \\boldsymbol{\\omega}$$\n")
    claims = kept.check_text(text)
    assert [(c.line, c.verdict) for c in claims] == [(3, "holds"), (5, "holds"), (7, "typo")]
    assert claims[2].correction.startswith(r"T = \frac{1}{2}")


def test_user_text_is_never_evaluated():
    # a command outside the whitelist is refused by name, never run
    c = one(PARTICLES % r"\mathbf{L} = \sum_{p} m_p \mathbf{r}_p \times \input{/etc/passwd}")
    assert c.verdict == "unchecked" and "input" in c.why


# ---- our own notes in vectors: all hold, planted errors caught ------------------------------------
def test_vector_notes_every_display_holds():
    claims = kept.check_notes(VECTORS)
    lines = VECTORS.read_text(encoding="utf-8").split("\n")
    displays = {k + 1 for k, line in enumerate(lines) if line.startswith("$$")}
    assert [c for c in claims if c.verdict != "holds"] == []
    assert displays == {c.line for c in claims}
    assert {"definition", "identity", "kinematics"} <= {c.kind for c in claims}


def vector_plants():
    """(line, kind, edited text) for every single planted edit of the vector notes' displays."""
    text = VECTORS.read_text(encoding="utf-8")
    lines = text.split("\n")
    for k, line in enumerate(lines):
        if not (line.startswith("$$") and line.endswith("$$")):
            continue
        latex = line[2:-2]
        m = re.search(r"\\equiv|=", latex)
        head, body = latex[:m.end()], latex[m.end():]
        edits = []
        for s in re.finditer(r"(?<=\s)[+\-](?=\s)", body):
            edits.append(("sign", body[:s.start()] + ("+" if s.group() == "-" else "-") + body[s.end():]))
        edits += [("cross order", e) for e in vc._cross_swaps(body)]
        for s in re.finditer(r"r_\{?p([ij])\}?", body):
            edits.append(("index", body[:s.start(1)] + ("i" if s.group(1) == "j" else "j") + body[s.end(1):]))
        for s in re.finditer(r"\\frac\{1\}\{2\}", body):
            edits.append(("missing 1/2", body[:s.start()] + body[s.end():]))
        for s in re.finditer(r"\^2", body):
            edits.append(("power", body[:s.start()] + "^3" + body[s.end():]))
        for kind, edited in edits:
            yield k + 1, kind, "\n".join(lines[:k] + [f"$${head}{edited}$$"] + lines[k + 1:])


def _caught(plants):
    caught, spilled = 0, []
    for line, kind, text in plants:
        claims = kept.check_text(text, path="planted.md")
        caught += any(c.verdict in FLAGGED for c in claims if c.line == line)
        spilled += [(line, kind, c.line) for c in claims if c.verdict in FLAGGED and c.line != line]
    return caught / len(plants), spilled


def test_vector_planted_errors_caught():
    """One plant of each kind (every plant: the slow test below)."""
    plants = list(vector_plants())
    kinds = {"sign", "cross order", "index", "missing 1/2", "power"}
    assert len(plants) >= 15 and {p[1] for p in plants} == kinds
    sample = [next(p for p in plants if p[1] == kind) for kind in sorted(kinds)]
    rate, spilled = _caught(sample)
    assert rate >= 0.95, rate
    assert spilled == []


@pytest.mark.slow
def test_every_vector_planted_error_caught():
    rate, spilled = _caught(list(vector_plants()))
    assert rate >= 0.95, rate
    assert spilled == []


# ---- the lecture -----------------------------------------------------------------------------------
NOT_CLAIMS = {"text", "assumption", "expression", "law"}


def test_lecture_vector_displays_are_checked(lecture_claims):
    by_line = {}
    for c in lecture_claims:
        by_line.setdefault(c.line, []).append(c)
    for line in (63, 66, 68, 70, 72, 74, 76, 83, 85, 87, 95, 98, 100, 102, 104, 112, 116, 124):
        assert by_line[line] and all(c.verdict == "holds" for c in by_line[line] if c.kind != "law"), line
    torque_free = [c for c in by_line[130] if "τ = 0" in c.why]
    assert [c.verdict for c in torque_free] == ["holds"]


def test_lecture_unchecked_only_where_not_a_claim(lecture_claims):
    left = [(c.line, c.kind, c.why) for c in lecture_claims if c.verdict == "unchecked" and c.kind not in NOT_CLAIMS
            and not c.why.startswith("repeats")]
    assert left == []


LAW_CHAIN = ("# Notes\n\nThe torque $\\mathbf{N}$ on the body:\n\n"
             "$$\\mathbf{N} = \\left( \\frac{d\\mathbf{L}}{dt}\\right)_{space} = \\left( \\frac{d\\mathbf{L}}{dt}\\right)_{body} "
             "+ \\boldsymbol{\\omega} \\times \\mathbf{L}$$\n")


def test_a_chain_headed_by_the_torque_is_checked_past_the_law_in_its_first_link():
    got = [(c.kind, c.verdict) for c in kept.check_text(LAW_CHAIN) if c.line == 5]
    assert ("law", "unchecked") in got and any(v == "holds" for _, v in got)
    slip = LAW_CHAIN.replace("+ \\boldsymbol{\\omega}", "- \\boldsymbol{\\omega}")
    assert "holds" not in {c.verdict for c in kept.check_text(slip) if c.line == 5}


def test_the_rotational_kinetic_energy_named_t_rot_is_the_kinetic_energy_of_the_turning_body():
    # T_rot, T_{\text{rot}}: the kinetic energy's rotational part, all of it for a body turning about a point
    for name in ("T_{rot}", r"T_{\text{rot}}", r"T_{\mathrm{rot}}"):
        right = one(PARTICLES % (name + r" = \frac{1}{2} \sum_{i,j} I_{ij} \omega_i \omega_j"))
        assert (right.kind, right.verdict) == ("definition", "holds"), (name, right.why)
    wrong = one(PARTICLES % r"T_{rot} = \sum_{i,j} I_{ij} \omega_i \omega_j")
    assert wrong.verdict == "typo" and one(PARTICLES % wrong.correction).verdict == "holds"
    # a subscript that names some other part is not read as the whole
    other = one(PARTICLES % r"T_{trans} = \frac{1}{2} \sum_{i,j} I_{ij} \omega_i \omega_j")
    assert other.verdict not in FLAGGED


def test_particle_coordinates_written_x_with_the_particle_and_an_axis_are_read_in_the_texts_own_index():
    # Σ_α m_α with x_{α,k}, the α-th particle's k-th coordinate: the inertia tensor and T in components
    tensor = r"I_{ij} = \sum_{\alpha}^{N} m_{\alpha}\left[\delta_{i j}\left(\sum_{k}^{3} x_{\alpha, k}^2 \right) - x_{\alpha, i}x_{\alpha, j} \right]"
    right = one(PARTICLES % tensor)
    assert (right.kind, right.verdict) == ("definition", "holds") and "two generic particles" in right.why
    wrong = one(PARTICLES % tensor.replace(r"x_{\alpha, i}x_{\alpha, j}", r"x_{\alpha, i}x_{\alpha, i}"))
    assert wrong.verdict in FLAGGED
    energy = (r"T = \frac{1}{2} \sum_{\alpha}^{N} m_{\alpha}\left[\left(\sum_{i} \omega_{i}^{2}\right) \left(\sum_{k} "
              r"x_{\alpha, k}^{2}\right)-\left(\sum_{i} \omega_{i} x_{\alpha, i}\right)\left(\sum_{j} \omega_{j} x_{\alpha, j}\right)\right]")
    assert one(PARTICLES % energy).verdict == "holds"
    assert one(PARTICLES % energy.replace(r"\frac{1}{2} ", "")).verdict in FLAGGED


def test_a_bold_t_set_to_a_scalar_is_the_kinetic_energy_as_the_scalar_reader_reads_it():
    right = one(PARTICLES % r"\mathbf{T} = \frac{1}{2} \boldsymbol{\omega} \cdot \{\mathbf{I}\} \cdot \boldsymbol{\omega}")
    assert right.verdict == "holds", right.why
    assert one(PARTICLES % r"\mathbf{T} = \boldsymbol{\omega} \cdot \{\mathbf{I}\} \cdot \boldsymbol{\omega}").verdict in FLAGGED
