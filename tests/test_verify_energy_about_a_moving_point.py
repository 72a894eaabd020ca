"""The notes reader on the kinetic energy written about a moving point B of the body,
T = ½ m v_B² + m 𝐯_B·(𝛚 × 𝐫_{G/B}) + ½ 𝛚·𝐇_B: compared at random states with ½ m v_G² + ½ 𝛚·𝐈_G𝛚,
𝐇_B read from the velocities relative to B and from the absolute ones. It holds under either
reading, naming it; a form that holds under neither (the centre's own velocity where its velocity
relative to B belongs) is flagged; a list item that is one formula is judged like a display."""
import kept_readings as kept

HEAD = "# Energy\n\nThe kinetic energy about a point $B$ of the body, $G$ its centre of mass:\n\n"
RELATIVE = "T=\\frac{1}{2}m\\mathbf{v}_B^2+m\\mathbf{v}_B\\cdot(\\boldsymbol\\omega\\times\\mathbf{r}_{G/B})+\\frac{1}{2}\\boldsymbol\\omega\\cdot\\mathbf{H}_B"


def _kinds(display):
    return [(c.verdict, c.kind, c.why) for cs in kept.by_line(HEAD + "$$" + display + "$$\n").values() for c in cs]


def test_the_energy_about_a_moving_point_holds_with_either_reading_of_its_angular_momentum():
    absolute = RELATIVE.replace("+m\\mathbf{v}_B", "+\\frac{1}{2}m\\mathbf{v}_B")
    for display, reading in ((RELATIVE, "relative to B"), (absolute, "absolute velocities"),
                             ("T=\\frac{1}{2}m\\mathbf{v}_B^2+m\\mathbf{v}_B\\cdot\\mathbf{v}_{G/B}+\\frac{1}{2}\\mathbf{\\omega H_B}",
                              "relative to B")):
        [(verdict, kind, why)] = _kinds(display)
        assert (verdict, kind) == ("holds", "moving point") and reading in why, display


def test_the_centres_velocity_for_its_velocity_relative_to_the_point_is_flagged():
    slip = "T=\\frac{1}{2}m\\mathbf{v}_B^2+\\frac{1}{2}m\\mathbf{v}_B\\cdot\\mathbf{v}_G+\\frac{1}{2}\\mathbf{\\omega H_B}"
    [(verdict, kind, why)] = _kinds(slip)
    assert (verdict, kind) == ("fails", "moving point") and "either reading" in why


def test_the_cross_term_left_out_is_flagged_and_the_fixed_points_form_is_not():
    assert [v for v, _, _ in _kinds("T=\\frac{1}{2}m\\mathbf{v}_B^2+\\frac{1}{2}\\mathbf{\\omega H_B}")] == ["fails"]
    assert [v for v, _, _ in _kinds("T=\\frac{1}{2}\\mathbf{\\omega H_B}")] == ["holds"]


def test_a_list_item_that_is_one_formula_is_judged_like_a_display():
    slip = "T=\\frac{1}{2}m\\mathbf{v}_B^2+\\frac{1}{2}m\\mathbf{v}_B\\cdot\\mathbf{v}_G+\\frac{1}{2}\\mathbf{\\omega H_B}"
    for item in ("1. ", "- ", "* "):
        claims = [c for cs in kept.by_line(HEAD + item + "$" + slip + "$\n").values() for c in cs]
        assert [c.verdict for c in claims] == ["fails"], item
    in_a_sentence = [c for cs in kept.by_line(HEAD + "1. Written $" + slip + "$ here.\n").values() for c in cs]
    assert "fails" not in {c.verdict for c in in_a_sentence}
