"""A definite integral written out, its bounds and its differential given: worked out by SymPy and
compared with the value the text gives it; a name set to an integral is never a setting."""
import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n# A solid of revolution\n\nA cylinder of radius $a$ and height $b$.\n\n"


def _claims(body):
    return [c for c in kept.check_text(HEAD + body) if "\\int" in c.latex]


def test_a_volume_integral_written_with_its_jacobian_holds():
    body = r"$$\int_0^b \mathrm{d} z \int_0^{a} \mathrm{d} r \int_0^{2\pi} \mathrm{d} \phi \, r = \pi a^2 b$$"
    assert [c.verdict for c in _claims(body)] == ["holds"]


def test_a_volume_integral_without_its_jacobian_fails_with_its_value():
    body = r"$$\int_0^b \mathrm{d} z \int_0^{a} \mathrm{d} r \int_0^{2\pi} \mathrm{d} \phi = \pi a^2 b$$"
    (claim,) = _claims(body)
    assert claim.verdict == "fails" and "2 a b \\pi as written" in claim.why


def test_an_inner_bound_in_the_outer_variable_and_the_differential_last():
    body = (r"$$\int_0^b \mathrm{d} z \int_0^{az/b} \mathrm{d} r \, r = \frac{a^2 b}{6}$$" "\n\n"
            r"$$\int_0^1 (1 - s^2) \, \mathrm{d}s = \frac{2}{3}$$" "\n\n"
            r"$$\int_0^1 (1 - s^2) \, \mathrm{d}s = \frac{1}{3}$$")
    assert [c.verdict for c in _claims(body)] == ["holds", "holds", "fails"]


def test_two_integrals_equal_only_numerically_hold():
    body = (r"$$\int_0^1 \frac{\mathrm{d}s}{\sqrt{(1-s^2)(1-k^2s^2)}} = "
            r"\int_0^{\frac{\pi}{2}} \frac{\mathrm{d}\phi}{\sqrt{1-k^2\sin^2\phi}}$$")
    assert [c.verdict for c in _claims(body)] == ["holds"]


def test_the_variable_is_bound_an_euler_angle_of_the_same_letter_untouched():
    body = r"$$\int_0^{2\pi} \cos^2\phi \, \mathrm{d}\phi = \pi$$"
    assert [c.verdict for c in _claims(body)] == ["holds"]


def test_a_name_set_to_an_integral_is_no_setting_and_a_condition_is_not_judged():
    body = (r"$$I_3 = \int_0^b \mathrm{d} z \int_0^{a} \mathrm{d} r \int_0^{2\pi} \mathrm{d} \phi \, r^3$$" "\n\n"
            r"$$\int_0^b \mathrm{d} z \int_0^{a} \mathrm{d} r \int_0^{2\pi} \mathrm{d} \phi \, \rho r = M$$" "\n\n"
            r"$$I_3 = \frac{1}{2} M a^2$$")
    claims = kept.check_text(HEAD + body)
    assert [(c.kind, c.verdict) for c in claims if "\\int" in c.latex] == [("unknown", "unchecked")] * 2
    alone = kept.check_text(HEAD + "\n\n\n\n" + body.rsplit("\n\n", 1)[1])
    assert [(c.kind, c.verdict, c.why) for c in claims if "\\int" not in c.latex] == \
        [(c.kind, c.verdict, c.why) for c in alone]


def test_an_integral_over_the_time_is_not_read():
    body = r"$$\int_0^T \dot\theta \, \mathrm{d}t = 0$$"
    assert [c.verdict for c in _claims(body)] == ["unchecked"]


def test_a_row_going_on_with_equals_after_an_integral_gives_the_value_it_works_out_to():
    # the integral ends one row of an aligned block, its value opens the next: that link is judged
    row = (r"$$\begin{align*} I_{11} & = \rho \int^{b/2}_{-b/2} \int^{b/2}_{-b/2} (x^2 + y^2) dy dx \\[4pt] "
           r"& = %s \end{align*}$$")
    claims = kept.check_text(HEAD + row % r"\frac{1}{6} \rho b^4")
    assert [c.verdict for c in claims if c.latex.lstrip().startswith("=")] == ["holds"]
    claims = kept.check_text(HEAD + row % r"\frac{1}{3} \rho b^4")
    assert [c.verdict for c in claims if c.latex.lstrip().startswith("=")] == ["fails"]
    # the same value in a display of its own after the integral is not that row's continuation
    apart = row.split(r"\\[4pt]")[0] + r"\end{align*}$$" + "\n\nso that\n\n$$I_{11} = \\frac{1}{3} \\rho b^4$$"
    assert all(c.verdict not in ("holds", "fails") for c in kept.check_text(HEAD + apart) if "frac{1}{3}" in c.latex)


def test_a_named_chain_whose_value_keeps_a_name_the_integral_dropped_fails():
    # the cylinder's volume worked in rings: the height b, a name of the text's, left out of the integral
    body = (r"$$V = b \int_0^a 2\pi r \, \mathrm{d} r = \pi a^2 b$$" "\n\n"
            r"$$V = \int_0^a 2\pi r \, \mathrm{d} r = \pi a^2 b$$")
    assert [c.verdict for c in _claims(body)] == ["holds", "fails"]


def test_a_value_in_a_name_the_text_has_not_used_is_not_compared():
    # ∫ … = σ π a²: σ first met here may be what the equation sets, not a value of the integral
    body = r"$$m = \int_0^a 2\pi r \, \mathrm{d} r = \sigma \pi a^2$$"
    assert [c.verdict for c in _claims(body)] == ["unchecked"]


def _across(integral, value):
    """A chain set over two displays: the first ends with ``=`` after an integral, the next goes on with ``=``."""
    return (r"$$I = \int \rho \, r^2 \, \mathrm{d}^3 r = \frac{M}{V} %s =$$" "\n\n"
            r"$$= %s = \frac{1}{2} M a^2 \, \frac{\pi a^2 b}{V}$$" % (integral, value))


def test_a_chain_carried_into_the_next_display_judges_its_integral_against_the_value_there():
    good = r"\int_0^{2\pi} \mathrm{d}\phi \int_0^a \mathrm{d} r \int_0^b \mathrm{d} z \, r^2 r"
    slip = r"\int_0^{2\pi} \mathrm{d}\phi \int_0^a \mathrm{d} a \int_0^b \mathrm{d} z \, r^2 r"   # d a for d r
    value = r"\frac{M}{V} 2\pi \frac{a^4}{4} b"
    first = HEAD.count("\n") + 1            # the line of the display that writes the integral
    held = [c for c in kept.check_text(HEAD + _across(good, value)) if c.line == first and c.verdict != "unchecked"]
    assert [c.verdict for c in held] == ["holds"]
    (flag,) = [c for c in kept.check_text(HEAD + _across(slip, value)) if c.verdict in ("typo", "fails")]
    # the display that writes the integral is the one flagged, its value as written given
    assert flag.line == first and "as written" in flag.why and "next display" in flag.why


def _through(integral, again, value):
    """A chain set over three displays: an integral, the same integral rewritten, then its value."""
    return (r"$$I = \int \rho \, r^2 \, \mathrm{d}^3 r = \frac{M}{V} %s =$$" "\n\n"
            r"$$= \frac{M}{V} %s =$$" "\n\n"
            r"$$= %s = \frac{1}{2} M a^2 \, \frac{\pi a^2 b}{V}$$" % (integral, again, value))


def test_an_integral_carried_through_a_second_integral_is_judged_against_the_value_the_chain_reaches():
    good = r"\int_0^{2\pi} \mathrm{d}\phi \int_0^a \mathrm{d} r \int_0^b \mathrm{d} z \, r^2 r"
    again = r"\int_0^{2\pi} \mathrm{d}\phi \int_0^b \mathrm{d} z \int_0^a \mathrm{d} r \, r^3"
    slip = r"\int_0^{2\pi} \mathrm{d}\phi \int_0^a \mathrm{d} a \int_0^b \mathrm{d} z \, r^2 r"   # d a for d r
    value = r"\frac{M}{V} 2\pi \frac{a^4}{4} b"
    first = HEAD.count("\n") + 1
    second = first + 2

    def judged(body):
        return {c.line: c for c in kept.check_text(HEAD + body) if c.line in (first, second)
                and c.verdict != "unchecked"}
    held = judged(_through(good, again, value))
    assert {line: c.verdict for line, c in held.items()} == {first: "holds", second: "holds"}
    # the slip written in the first display only: that display is flagged, through the second's integral
    flagged = judged(_through(slip, again, value))
    assert flagged[first].verdict == "fails" and f"through the integral of line {second}" in flagged[first].why
    assert flagged[second].verdict == "holds"
    # the slip written in both: both flagged, each with its value as written
    both = judged(_through(slip, slip.replace(r"\mathrm{d} a", r"\mathrm{d} a \,"), value))
    assert {c.verdict for c in both.values()} == {"fails"} and len(both) == 2


def test_a_display_that_does_not_go_on_with_equals_is_no_continuation():
    slip = r"\int_0^{2\pi} \mathrm{d}\phi \int_0^a \mathrm{d} a \int_0^b \mathrm{d} z \, r^2 r"
    apart = _across(slip, r"\frac{M}{V} 2\pi \frac{a^4}{4} b").replace("$$= ", "$$I = ")
    assert all(c.verdict not in ("typo", "fails") for c in kept.check_text(HEAD + apart))


def test_two_integrals_across_displays_judge_neither_display_by_their_link():
    # unequal, either display may hold the slip; equal, both may share one (a slip written twice)
    first = HEAD.count("\n") + 1
    for power in ("r^4", "r^3"):
        body = (r"$$I = \int \rho \, r^2 \, \mathrm{d}^3 r = \int_0^a \mathrm{d} r \, r^3 =$$" "\n\n"
                r"$$= \int_0^a \mathrm{d} r \, %s = \frac{a^5}{5}$$" % power)
        claims = kept.check_text(HEAD + body)
        assert {c.verdict for c in claims if c.line == first} == {"unchecked"}
