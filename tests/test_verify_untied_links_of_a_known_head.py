"""The notes reader on a chain whose head it knows (dφ/dt) and whose later members are in names the
text never tied (m, r, θ_z, ω): no member can be compared with the head, but a link among them that is
an identity whatever the names stand for (the sin γ cancelled) holds; a link that is not stays unread."""
import kept_readings as kept

verdicts, line_of = kept.verdicts_by_line, kept.line_of
HEAD = "# A weight on a top\n\nThe axis turns about the vertical at the rate\n\n$$\n"


def test_a_link_that_cancels_a_common_factor_holds_though_the_head_is_not_compared():
    text = HEAD + ("\\Omega = \\frac{\\mathrm{d}\\varphi}{\\mathrm{d}t} = \\frac{m\\,g\\,r\\,\\sin\\gamma}{\\theta_{z}\\,"
                   "\\omega\\,\\sin\\gamma} = \\frac{m\\,g\\,r}{\\theta_{z}\\,\\omega}\n$$\n")
    assert verdicts(text)[line_of(text, "$$\n\\Omega")] == {"unchecked", "holds"}


def test_a_link_that_is_no_identity_is_neither_held_nor_flagged():
    text = HEAD + ("\\Omega = \\frac{\\mathrm{d}\\varphi}{\\mathrm{d}t} = \\frac{m\\,g\\,r\\,\\sin\\gamma}{\\theta_{z}\\,"
                   "\\omega\\,\\sin\\gamma} = \\frac{2\\,m\\,g\\,r}{\\theta_{z}\\,\\omega}\n$$\n")
    assert verdicts(text)[line_of(text, "$$\n\\Omega")] == {"unchecked"}


def test_a_link_is_kept_only_when_its_members_are_the_same_as_written_not_through_a_definition():
    from sympy import sin, symbols
    from derive.lecture.untied_links import identical_as_written
    m, g, r, th, w, gam, R, phi, t = symbols("m g r theta omega gamma R vartheta t")
    assert identical_as_written(m * g * r * sin(gam) / (th * w * sin(gam)), m * g * r / (th * w))
    assert not identical_as_written(R * phi / t, R * w)        # equal only if the text's ω is ϑ/t
