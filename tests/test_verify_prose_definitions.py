"""A symbol a text names in running prose, in inline math ("the rates are named $\\dot\\phi =
\\omega_\\phi$"), is the text's name for that value in later sections; an inline relation between
symbols the text already has binds nothing, and what is not rendered (a code span, an HTML
comment) names nothing."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Angles\n\n"
LATER = "\n\n# Integrating\n\nThe axial rate is\n\n$$\\omega_3 = \\omega_\\phi \\cos\\theta + \\omega_\\psi$$\n"


def _at_display(sentence, display=LATER):
    text = HEAD + sentence + display
    line = text.split("\n").index("$$" + display.split("$$")[1] + "$$") + 1
    return [c.verdict for c in kept.check_text(text) if c.line == line]


NAMED = "The text names the rates: $\\dot\\phi = \\omega_\\phi$, $\\dot\\theta = \\omega_\\theta$, $\\dot\\psi = \\omega_\\psi$."


def test_a_rate_named_in_prose_makes_a_display_of_a_later_section_checkable():
    assert _at_display(NAMED) == ["holds"]


def test_a_name_in_a_chinese_sentence_is_read_the_same_way():
    assert _at_display("其中 $\\dot\\phi = \\omega_\\phi$ 为进动角速度, $\\dot\\psi = \\omega_\\psi$ 为自转角速度。") == ["holds"]


def test_a_slip_in_a_display_that_rests_on_a_prose_name_is_left_unchecked_never_called_correct():
    assert _at_display(NAMED, LATER.replace("+ \\omega_\\psi", "- \\omega_\\psi")) == ["unchecked"]


def test_without_the_prose_name_the_display_stays_unchecked():
    assert _at_display("The text turns the body by three angles.") == ["unchecked"]


def test_an_inline_relation_between_symbols_the_text_already_has_binds_nothing():
    text = ("The rates appear in $\\omega_\\phi \\sin\\theta$ and $\\omega_\\psi$ before any equation; "
            "the text notes $\\dot\\phi = \\omega_\\phi$ and $\\dot\\psi = \\omega_\\psi$.")
    assert _at_display(text) == ["unchecked"]


def test_a_name_inside_a_code_span_or_an_html_comment_names_nothing():
    spans = "The notebook's code writes `$\\dot\\phi = \\omega_\\phi$` and `$\\dot\\psi = \\omega_\\psi$`."
    comments = "The rates are <!-- $\\dot\\phi = \\omega_\\phi$, $\\dot\\psi = \\omega_\\psi$ --> left unnamed."
    assert _at_display(spans) == ["unchecked"]
    assert _at_display(comments) == ["unchecked"]


def test_a_name_given_before_the_first_heading_holds_after_it():
    text = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n" + NAMED + LATER
    claims = kept.check_text(text)
    assert [c.verdict for c in claims if c.latex.startswith("\\omega_3")] == ["holds"]


def test_an_angle_held_at_a_value_in_prose_is_a_case_and_names_nothing_after_its_section():
    text = HEAD + "The nutation angle stays $\\theta = \\theta_0$ here." + \
        "\n\n# Nutation\n\nThe nutation is\n\n$$\\theta = \\theta_0 + \\epsilon$$\n"
    assert not [c for c in kept.check_text(text) if c.kind == "new symbol"]
