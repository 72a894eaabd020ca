"""The notes reader on the notation of flight-dynamics texts: plain TeX fractions, derivatives
written as a simulation names them (``d\\varphi = …``), the 3-2-1 sequence named by its order and
its turns written axis first, the aircraft's body rates listed rate by rate, the two glyphs of φ,
the usual yaw-pitch-roll names, the shorthand cθ the text defines, and one name R used for each
rotation matrix in turn."""
from kept_readings import verdicts_by_line
from derive.lecture import source

PLAIN = "# Notes\n\n"


verdicts = verdicts_by_line


def test_a_plain_tex_fraction_is_a_fraction_and_a_word_starting_with_over_is_untouched():
    assert source.normalize(r"F = {d \over dt}") == r"F = {\frac{d}{dt}}"
    # and the rate of a bracket is d/dt of what it holds
    assert source.normalize(r"F = {d(m \cdot v) \over dt}") == r"F = {\frac{d}{dt}(m \cdot v)}"
    assert source.normalize(r"\theta = 30 \cdot {\pi \over 180}") == r"\theta = 30 \cdot {\frac{\pi}{180}}"
    assert r"\frac" not in source.normalize(r"\overline{x} = {a}")


def test_a_derivative_named_as_code_names_it_is_a_rate_and_a_differential_stays_one():
    assert source.normalize(r"dv_x = {F[0] \over m}").startswith(r"\dot{v}_x =")
    assert source.normalize(r"d\varphi = p").startswith(r"\dot{\varphi} =")
    for kept in (r"dm = \rho dV", r"dW = F \, dx", r"dL = \tau dt", r"d = 2r"):
        assert not source.normalize(kept).startswith(r"\dot")


KINEMATICS = (PLAIN + "The attitude follows three successive rotations in the order 3-2-1: a turn about $z_b$ "
              "through the heading $\\psi$, then about $y_b$ through the pitch $\\theta$, then about $x_b$ "
              "through the roll $\\varphi$.\n\n"
              "$$\nd\\varphi = p + (q \\cdot sin(\\varphi) + r \\cdot cos(\\varphi)) \\cdot tan(\\theta)\n$$\n\n"
              "$$\nd\\theta = q \\cdot cos(\\varphi) - r \\cdot sin(\\varphi)\n$$\n\n"
              "$$\nd\\psi = {q \\cdot sin(\\varphi) + r \\cdot cos(\\phi) \\over cos(\\theta)}\n$$\n\n"
              "Here:\n\n- $dp, dq, dr$ are the changes of the body roll rate, pitch rate and yaw rate;\n"
              "- $p, q, r$ are the body roll rate, pitch rate, and yaw rate.\n")


def test_the_321_rates_from_the_body_rates_hold_written_as_a_simulation_writes_them():
    got = verdicts(KINEMATICS)
    rows = [k - 1 for k, row in enumerate(KINEMATICS.split("\n"), start=1) if row.startswith("d")]
    assert [got.get(k) for k in rows] == [{"holds"}] * 3


def test_a_wrong_sign_in_the_pitch_rate_is_not_passed():
    wrong = KINEMATICS.replace(r"d\theta = q \cdot cos(\varphi) - r", r"d\theta = q \cdot cos(\varphi) + r")
    row = next(k - 1 for k, r in enumerate(wrong.split("\n"), start=1) if r.startswith(r"d\theta"))
    assert "holds" not in verdicts(wrong).get(row, set())


def test_a_list_of_code_rates_before_the_phrase_binds_no_body_rate():
    # only "$dp, dq, dr$" names the rates: its items are no single symbols, so p, q, r stay unbound
    text = KINEMATICS.replace("- $p, q, r$ are the body roll rate, pitch rate, and yaw rate.\n", "")
    row = next(k - 1 for k, r in enumerate(text.split("\n"), start=1) if r.startswith(r"d\theta"))
    assert verdicts(text).get(row) != {"fails"}


ROTATIONS = (PLAIN + "The angles turn in a 3-2-1 sequence. Each matrix turns components onto the rotated axes.\n\n"
             "$$\nR = \\begin{bmatrix} 1 & 0 & 0 \\\\ 0 & cos(\\varphi) & sin(\\varphi) \\\\ 0 & -sin(\\varphi) & cos(\\varphi) \\end{bmatrix}\n$$\n\n"
             "$$\nR = \\begin{bmatrix} cos(\\theta) & 0 & -sin(\\theta) \\\\ 0 & 1 & 0 \\\\ sin(\\theta) & 0 & cos(\\theta) \\end{bmatrix}\n$$\n\n"
             "$$\nR = \\begin{bmatrix} c\\theta \\cdot c\\psi & c\\theta \\cdot s\\psi & -s\\theta \\\\ "
             "s\\varphi \\cdot s\\theta \\cdot c\\psi - c\\varphi \\cdot s\\psi & s\\varphi \\cdot s\\theta \\cdot s\\psi + c\\varphi \\cdot c\\psi & s\\varphi \\cdot c\\theta \\\\ "
             "c\\varphi \\cdot s\\theta \\cdot c\\psi + s\\varphi \\cdot s\\psi & c\\varphi \\cdot s\\theta \\cdot s\\psi - s\\varphi \\cdot c\\psi & c\\varphi \\cdot c\\theta \\end{bmatrix}\n$$\n\n"
             "where $c\\varphi \\equiv cos(\\varphi)$, $s\\varphi \\equiv sin(\\varphi)$, $c\\theta \\equiv cos(\\theta)$, "
             "$s\\theta \\equiv sin(\\theta)$, $c\\psi \\equiv cos(\\psi)$ and $s\\psi \\equiv sin(\\psi)$.\n")


def _displays(text):
    return [k - 1 for k, row in enumerate(text.split("\n"), start=1) if row.startswith("R =")]


def test_one_name_for_each_rotation_in_turn_is_each_checked_as_its_own_rotation():
    got = verdicts(ROTATIONS)
    assert [got.get(k) for k in _displays(ROTATIONS)] == [{"holds"}] * 3


def test_the_321_matrix_written_again_with_a_wrong_entry_is_flagged_and_right_passes():
    matrix = ROTATIONS[ROTATIONS.index("$$\nR = \\begin{bmatrix} c\\theta"):ROTATIONS.index("where $c")]
    wrong = matrix.replace(r"s\varphi \cdot s\theta \cdot s\psi + c\varphi \cdot c\psi",
                           r"s\varphi \cdot s\theta \cdot s\psi - c\varphi \cdot c\psi")
    for again, flagged in ((matrix, False), (wrong, True)):
        text = ROTATIONS + "\nThe same matrix again:\n\n" + again
        got = verdicts(text).get(_displays(text)[3], set())
        assert bool(got & {"typo", "fails"}) == flagged and ("holds" in got) != flagged


def test_without_the_texts_definition_c_theta_is_no_cosine():
    text = ROTATIONS[:ROTATIONS.index("where $c")]
    third = _displays(text)[2]
    assert verdicts(text).get(third) == {"unchecked"}


def test_newtons_law_as_the_rate_of_the_momentum_gives_m_times_the_rate_of_v():
    text = (PLAIN + "The force is the rate of the momentum, $m$ the mass and $v$ the velocity:\n\n"
            "$$\nF = {d(m \\cdot v) \\over dt}\n$$\n\nWith the acceleration:\n\n$$\nF = m \\cdot \\dot{v}\n$$\n")
    assert verdicts(text).get(11) == {"holds"}
    wrong = text.replace(r"F = m \cdot \dot{v}", r"F = 2 m \cdot \dot{v}")
    assert "holds" not in verdicts(wrong).get(11, set())
