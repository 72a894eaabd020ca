"""An equation of motion that ends in the value its sides take in the case the prose considers
(``I_3\\dot{\\omega}_3 = (I_1 - I_2)\\omega_1\\omega_2 = 0`` for a spin about one principal axis): the
equation it begins with is judged as if written alone, the trailing 0 is read only when the settings
make it hold (derive/lecture/eom_case_value.py)."""
import kept_readings as kept

_HEAD = ("A rigid body with principal moments $I_1$, $I_2$, $I_3$ turns freely. We look for a rotation at a "
         "constant angular velocity about the third principal axis, with $\\omega_3$ the only non-zero "
         "component. Euler's equations give\n\n")


def _block(third):
    return _HEAD + ("\\begin{align}\n"
                    "I_1\\dot{\\omega}_1 &= (I_2 - I_3)\\omega_2\\omega_3 = 0,\\\\\n"
                    "I_2\\dot{\\omega}_2 &= (I_3 - I_1)\\omega_3\\omega_1 = 0,\\\\\n"
                    f"I_3\\dot{{\\omega}}_3 &= {third} = 0.\n"
                    "\\end{align}\n")


def _eoms(claims):
    return [c for c in claims if c.kind == "equation of motion"]


def test_each_equation_ending_in_zero_is_judged_by_the_equation_it_begins_with():
    eoms = _eoms(kept.check_text(_block("(I_1 - I_2)\\omega_1\\omega_2")))
    assert [c.verdict for c in eoms] == ["holds"] * 3
    assert all("last member 0" in c.why and "not read" in c.why for c in eoms)


def test_a_slip_in_the_factors_before_the_zero_is_flagged_with_its_one_edit():
    eoms = _eoms(kept.check_text(_block("(I_1 - I_2)\\omega_1\\omega_3")))
    assert [c.verdict for c in eoms] == ["holds", "holds", "typo"]
    assert "\\omega_1\\omega_2" in eoms[2].correction


def test_the_zero_is_checked_when_the_settings_make_the_sides_vanish():
    text = ("A rigid body with principal moments $I_1$, $I_2$, $I_3$ turns freely, with $I_1 = I_2$. Then\n\n"
            "$$\nI_3\\dot{\\omega}_3 = (I_1 - I_2)\\omega_1\\omega_2 = 0\n$$\n")
    eoms = _eoms(kept.check_text(text))
    assert [c.verdict for c in eoms] == ["holds"] and "under the section's settings" in eoms[0].why
