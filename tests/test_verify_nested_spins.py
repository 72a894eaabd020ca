"""The notes reader on the angular velocity written as spins about the successive axes, each carried
by the turns before it (ȧ û + R_u(a)(ḃ v̂ + R_v(b)(ċ ŵ))): the rotation beside a spin must be the
turn about that spin's axis by that spin's angle in every convention, so another one fails; a
nesting that pairs each spin with its own turn holds, unless the text writes its turns in another
order."""
import kept_readings as kept

HEAD = "# Spins\n\nThe angles are $a$, $b$, $c$; $R_y$, $R_z$ turn about the y and z axes.\n\n"


def _verdicts(display, head=HEAD):
    text = head + "$$" + display + "$$\n"
    return kept.verdicts_by_line(text)[kept.line_of(text, "$$" + display)]


def test_a_rotation_about_another_axis_beside_a_spin_fails():
    assert _verdicts("\\vec{\\omega} = \\dot{a} \\hat{y} + R_z(b) \\left( \\dot{b} \\hat{z} + R_y(c) \\left( \\dot{c} \\hat{y} \\right) \\right)") == {"fails"}


def test_each_spin_beside_its_own_turn_holds():
    assert _verdicts("\\vec{\\omega} = \\dot{a} \\hat{y} + R_y(a) \\left( \\dot{b} \\hat{z} + R_z(b) \\left( \\dot{c} \\hat{y} \\right) \\right)") == {"holds"}
    assert _verdicts("\\vec{\\omega} = \\dot{c} \\hat{j} + \\mathrm{rot}(\\hat{j}, c) \\left( \\hat{k} \\dot{b} + \\mathrm{rot}(\\hat{k}, b) \\hat{j} \\dot{a} \\right)") == {"holds"}


def test_a_turn_by_another_angle_about_the_spins_axis_fails():
    assert _verdicts("\\vec{\\omega} = \\dot{a} \\hat{z} + R_z(b) \\left( \\dot{b} \\hat{y} \\right)") == {"fails"}


def test_a_bracket_left_open_at_the_end_is_closed_there():
    assert _verdicts("\\vec{\\omega} = \\dot{a} \\hat{y} + R_z(b)( \\left( \\dot{b} \\hat{z} + R_y(c) \\left( \\dot{c} \\hat{y} \\right) \\right)") == {"fails"}


def test_nested_spins_against_a_product_written_in_another_order_are_left_unchecked():
    head = HEAD + "The rotation is $R_y(c) R_z(b) R_y(a)$.\n\n"
    assert _verdicts("\\vec{\\omega} = \\dot{a} \\hat{y} + R_y(a) \\left( \\dot{b} \\hat{z} + R_z(b) \\left( \\dot{c} \\hat{y} \\right) \\right)", head) == {"unchecked"}


def test_a_matrix_the_prose_names_a_turn_is_that_turn_beside_its_spin():
    head = "# Spins\n\nTake $T_1$ turning by $\\phi$ about z and $T_2$ by $\\theta$ about x.\n\n"
    assert _verdicts("\\vec{\\omega} = \\dot{\\phi} \\hat{z} + T_1 \\left( \\dot{\\theta} \\hat{x} + T_2 \\left( \\dot{\\psi} \\hat{z} \\right) \\right)", head) == {"holds"}
    assert _verdicts("\\vec{\\omega} = \\dot{\\psi} \\hat{z} + T_1 (\\dot{\\theta} \\hat{x})", head) == {"fails"}
    assert _verdicts("\\vec{\\omega} = \\dot{\\psi} \\hat{z} + T_3 (\\dot{\\theta} \\hat{x})", head) == {"unchecked"}


def test_spins_each_carried_by_the_products_of_the_turns_before_it_hold():
    display = ("\\begin{aligned} \\mathrm{E}_a & = \\mathrm{rot}(\\hat{j}, a) & \\vec{\\omega}_b & = \\dot{a} \\left( \\hat{j} \\right) "
               "+ \\dot{b} \\left( \\mathrm{E}_a \\hat{k} \\right) \\end{aligned}")
    assert "holds" in _verdicts(display)
    assert _verdicts("\\vec{\\omega} = \\dot{a} \\hat{z} + \\dot{b} R_z(a) \\hat{x} + \\dot{c} R_z(a) R_x(b) \\hat{z}") == {"holds"}


def test_spins_in_a_bracket_crossed_with_the_matrix_beside_omega_are_judged_as_omega():
    head = "# Spins\n\nTake $T_1$ turning by $\\phi$ about z and $T_2$ by $\\theta$ about x, and $T = T_1 T_2$.\n\n"
    crossed = "\\frac{dT}{dt} = \\left(\\dot{%s} \\hat{z} + T_1 (\\dot{\\theta} \\hat{x}) \\right) \\times T = \\vec{\\omega} \\times T"
    assert "fails" in _verdicts(crossed % "\\psi", head)
    assert "fails" not in _verdicts(crossed % "\\phi", head)
    assert "fails" not in _verdicts("\\frac{dT}{dt} = \\left(\\dot{\\psi} \\hat{z} + T_1 (\\dot{\\theta} \\hat{x}) \\right) \\times T", head)


def test_spins_at_rates_written_d_dt_are_read_as_dotted_ones():
    assert _verdicts("\\vec{\\omega} = \\frac{d a}{d t} \\hat{y} + R_y(a) \\left( \\frac{\\mathrm{d} b}{\\mathrm{d} t} \\hat{z} "
                     "+ R_z(b) \\left( \\frac{dc}{dt} \\hat{y} \\right) \\right)") == {"holds"}
    assert _verdicts("\\vec{\\omega} = \\frac{d a}{d t} \\hat{z} + R_z(b) \\left( \\frac{d b}{d t} \\hat{y} \\right)") == {"fails"}
    assert _verdicts("\\vec{\\omega} = \\frac{d a}{d t} \\hat{z} + \\frac{d b}{d t} R_z(a) \\hat{x}") == {"holds"}


def test_spins_about_another_axis_than_the_stated_sequence_turns_that_angle_are_never_held():
    head = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n" + HEAD
    spins = "\\vec{\\omega} = \\dot{\\phi} \\hat{z} + R_z(\\phi) \\left( \\dot{\\theta} \\hat{x} + R_x(\\theta) \\left( \\dot{\\psi} \\hat{%s} \\right) \\right)"
    assert _verdicts(spins % "z", head) == {"holds"}
    assert _verdicts(spins % "x", head) == {"unchecked"}
