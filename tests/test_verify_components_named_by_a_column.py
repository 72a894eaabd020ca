"""A written column of one letter's components after a sentence that says whose components they are
("the body components of the angular velocity:" then [ω_x; ω_y; ω_z] = …) names the letter; once
that column holds read so, a later formula in those names that does not hold is flagged."""
import kept_readings as kept

HEAD = "---\nconvention: x-y-z\n---\n# Rates of the 1-2-3 sequence\n\n"
SAID = "The three turns give the body components of the angular velocity as columns:\n\n"
COLUMN = (r"$\left[{\begin{matrix}\omega _{x}\\\omega _{y}\\\omega _{z}\end{matrix}}\right]="
          r"\left[{\begin{matrix}c_{\theta }c_{\psi }{\dot {\phi }}\\-c_{\theta }s_{\psi }{\dot {\phi }}\\"
          r"s_{\theta }{\dot {\phi }}\end{matrix}}\right]+\left[{\begin{matrix}s_{\psi }{\dot {\theta }}\\"
          r"c_{\psi }{\dot {\theta }}\\0\end{matrix}}\right]+\left[{\begin{matrix}0\\0\\{\dot {\psi }}\end{matrix}}\right]$"
          "\n\n")
RATES = ("With the shorthand $cos(\\theta) = c_{\\theta}$, $sin(\\theta) = s_{\\theta}$ the rates are\n\n"
         "$ \\dot{\\theta} = \\omega_x s_{\\psi} + \\omega_y c_{\\psi} $\n\n"
         "$ \\dot{\\psi} = (-\\omega_x c_{\\psi} + \\omega_y %s) s_{\\theta} / c_{\\theta} + \\omega_z $\n")


def _verdicts(body):
    return {c.latex.strip()[:12]: c.verdict for c in kept.check_text(HEAD + body)
            if c.latex.strip().startswith(("\\left[", "\\dot{\\theta}", "\\dot{\\psi}"))}


def test_the_column_holds_and_names_the_components_so_a_rate_in_them_is_judged():
    good = _verdicts(SAID + COLUMN + RATES % "s_{\\psi}")
    assert set(good.values()) == {"holds"} and len(good) == 3
    # a cosine for the sine on omega_y: flagged, the column having shown what the names are
    slip = _verdicts(SAID + COLUMN + RATES % "c_{\\psi}")
    assert slip["\\dot{\\psi} ="] in ("typo", "fails") and slip["\\dot{\\theta}"] == "holds"


def test_without_the_sentence_the_letters_stay_unnamed():
    unsaid = _verdicts("The turns give three columns:\n\n" + COLUMN + RATES % "c_{\\psi}")
    assert set(unsaid.values()) == {"unchecked"}


def test_a_sentence_naming_another_quantity_names_nothing():
    other = _verdicts("The three turns give the components of the angular momentum as columns:\n\n"
                      + COLUMN + RATES % "c_{\\psi}")
    assert "typo" not in other.values() and "fails" not in other.values()


def test_a_column_in_plain_brackets_names_the_components_as_a_sized_one_does():
    plain = COLUMN.replace("\\left[", "[").replace("\\right]", "]")
    verdicts = {c.latex.strip()[:12]: c.verdict for c in kept.check_text(HEAD + SAID + plain + RATES % "c_{\\psi}")
                if c.latex.strip().startswith(("[", "\\dot{\\theta}", "\\dot{\\psi}"))}
    assert verdicts["\\dot{\\psi} ="] in ("typo", "fails") and verdicts["\\dot{\\theta}"] == "holds"
    assert "holds" in {v for k, v in verdicts.items() if k.startswith("[")}
