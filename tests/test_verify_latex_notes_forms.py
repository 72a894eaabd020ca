"""The notes reader on forms lecture notes set in LaTeX use: a system of equations in a brace opened
with ``\\left\\{`` and closed by ``\\right.`` (aligned rows or a one-column array), a component's rate
written with a bold letter, inline math in ``\\( … \\)``, ``\\section`` headings, a symbol the prose
says is "being the …", and a name defined value-first ("let … = α₂")."""
from kept_readings import by_line

from derive.lecture.statements import statements

SYSTEM = (r"\left\{ \begin{aligned} I_1 \dot\omega_1 + (I_3 - I_2) \omega_2 \omega_3 & = M_1; \\ "
          r"I_2 \dot\omega_2 + (I_1 - I_3) \omega_1 \omega_3 & = M_2. \end{aligned} \right.")


def test_a_system_brace_around_aligned_rows_is_cut_into_its_rows():
    rows = statements(SYSTEM.replace(r"\right.", ""))         # the source drops \right.
    assert [r.split("=")[1].strip() for r in rows] == ["M_1", "M_2"]


def test_a_system_brace_around_a_one_column_array_is_cut_into_its_rows():
    rows = statements(r"\left\{ \begin{array}{l} a = b, \\ c = d \end{array} \quad \text{and} \quad "
                      r"\left\{ \begin{array}{l} e = f \end{array}")
    assert [r.replace(" ", "").rstrip(",") for r in rows] == ["a=b", "c=d", "e=f"]


def test_a_brace_closed_by_a_right_brace_is_a_set_not_a_system():
    assert len(statements(r"S = \left\{ x, y \right\}")) == 1


EULER = ("# Euler's equations\n\nIn principal axes, with $M_i$ the torque's components:\n\n$$\n"
         r"\left\{ \begin{aligned} \mathrm I_{11} \dfrac{\mathrm d \boldsymbol \omega_1}{\mathrm dt} + "
         r"(\mathrm I_{33} - \mathrm I_{22}) \omega_2 \omega_3 & = M_1; \\ \mathrm I_{22} \dfrac{\mathrm d "
         r"\boldsymbol \omega_2}{\mathrm dt} + (\mathrm I_{11} - \mathrm I_{33}) \omega_1 \omega_3 & = M_2; \\ "
         r"\mathrm I_{33} \dfrac{\mathrm d \boldsymbol \omega_3}{\mathrm dt} + SLIP \omega_1 \omega_2 & = M_3. "
         r"\end{aligned} \right." "\n$$\n")


def test_a_bold_component_in_a_rate_is_the_component_and_a_slip_in_the_system_is_flagged():
    held = [c.verdict for c in by_line(EULER.replace("SLIP", r"(\mathrm I_{22} - \mathrm I_{11})"))[5]]
    slipped = [c.verdict for c in by_line(EULER.replace("SLIP", r"(\mathrm I_{11} - \mathrm I_{22})"))[5]]
    assert held == ["holds", "holds", "holds"]
    assert slipped[:2] == ["holds", "holds"] and slipped[2] in ("typo", "fails")


# LaTeX sources: \( … \) is inline math, \section is a heading
from derive.lecture import tex_structure  # noqa: E402


def test_inline_parentheses_math_in_a_latex_source_is_read_as_inline_math_on_its_line():
    text = "Here we assume \\(\\omega_1 = \\Omega\\) and\nmore.\n"
    out = tex_structure.as_notes(text)
    assert out.split("\n")[0].strip() == "Here we assume  $\\omega_1 = \\Omega$  and"
    assert len(out) == len(text)


def test_sectioning_commands_of_a_latex_source_are_headings_of_their_level():
    out = tex_structure.as_notes("\\section{Euler's equations}\\label{s}\ntext\n\\subsection*{Case \\(1\\)}\n")
    assert out.split("\n")[0] == "## Euler's equations"
    assert out.split("\n")[2] == "### Case  $1$"


# the prose's names and definitions
from derive.lecture import names as nm  # noqa: E402
from derive.lecture.vocabulary import Atom  # noqa: E402


def test_a_symbol_the_prose_says_is_being_the_torque_is_the_torque():
    learned = nm.learn("By the angular momentum theorem, $\\boldsymbol M$ being the external torque, we have\n")
    assert learned.meaning(Atom("M", bold=True)) == "torque"


AXIS = ("# Intermediate axis\n\nHere we assume $\\omega_1 = \\Omega$ and $\\omega_2, \\omega_3 \\ll \\Omega$; to "
        "first order:\n\n$$\n\\ddot{\\omega}_2 + \\dfrac{(I_1 - I_3)(I_1 - I_2)}{I_2 I_3} \\Omega^2 \\omega_2 = 0\n$$\n\n"
        "Let $\\dfrac{(I_1 - I_3)(I_1 - I_2)}{I_2 I_3} \\Omega^2 = \\alpha_2$; then\n\n$$\nSOLUTION\n$$\n")


def test_a_name_defined_value_first_is_used_by_the_solution_that_follows():
    good = by_line(AXIS.replace("SOLUTION", r"\omega_2 = C_1 \sin(\sqrt{\alpha_2} t) + C_2 \cos(\sqrt{\alpha_2} t)"))
    bad = by_line(AXIS.replace("SOLUTION", r"\omega_2 = C_1 \sin(\alpha_2 t) + C_2 \cos(\alpha_2 t)"))
    assert [c.verdict for c in good[11]] == ["holds"]
    assert [c.verdict for c in bad[11]] in (["fails"], ["typo"])
    assert [c.verdict for c in good[5]] == ["holds"]


ZXZ = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# The angular velocity in the body frame\n\n"


def _column(first_row):
    rows = [first_row, r"\dot\phi\sin\theta\cos\psi - \dot\theta\sin\psi", r"\dot\phi\cos\theta + \dot\psi"]
    return ZXZ + "$$\n\\boldsymbol\\omega = \\left[\\begin{array}{c} " + r" \\ ".join(rows) + \
        " \\end{array}\\right]\n$$\n"


def test_a_bracketed_factor_opening_an_array_row_is_kept_in_the_row():
    assert [c.verdict for c in by_line(_column(r"(\dot\phi)\sin\theta\sin\psi + \dot\theta\cos\psi"))[7]] == ["holds"]
    assert [c.verdict for c in by_line(_column(r"(\dot\phi)\sin\theta\cos\psi + \dot\theta\cos\psi"))[7]] == ["typo"]
