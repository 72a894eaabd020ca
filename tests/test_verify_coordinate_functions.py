"""A one-coordinate system in the text's own names — its Lagrangian L(θ, θ̇), functions of θ it
defines (``f(\\theta)``, ``x_C = …``), primes for their derivatives, unknown functions, values at
θ₀ — read by `derive.lecture.coordinate_functions` (checks in `coordinate_statements`)."""
import kept_readings as kept

HEAD = "---\ntitle: a rolling body\n---\n# A body rolling through an angle\n\nA body of mass $m$ and radius $R$ rolls; its centre of mass is at distance $a$ from the centre.\n\n"


def _verdicts(*displays):
    text = HEAD + "".join(f"\n$$\n{d}\n$$\n" for d in displays)
    return [(c.line, c.verdict, c.why) for c in kept.check_text(text)]


def _last(*displays):
    return _verdicts(*displays)[-1][1]


LAGRANGIAN = r"L(\theta, \dot{\theta}) = mR(R-a\cos\theta)\dot{\theta}^2 + mga\cos\theta"


def test_the_texts_lagrangian_is_a_definition_and_its_equation_of_motion_is_checked():
    verdicts = _verdicts(LAGRANGIAN, r"2mR(R-a\cos\theta)\ddot{\theta} = -mRa\sin\theta\dot{\theta}^2 - mga\sin\theta")
    assert [v[1] for v in verdicts] == ["unchecked", "holds"]
    assert _last(LAGRANGIAN, r"2mR(R-a\cos\theta)\ddot{\theta} = mRa\sin\theta\dot{\theta}^2 - mga\sin\theta") == "fails"


def test_the_euler_lagrange_equation_written_with_partials_holds():
    el = r"\frac{\mathrm{d} }{\mathrm{d} t}\frac{\partial L}{\partial{\dot{\theta}}} = \frac{\partial L}{\partial{\theta}}"
    assert _last(LAGRANGIAN, el) == "holds"


def test_unknown_functions_of_the_angle_make_a_claim_that_must_hold_for_all_of_them():
    general = r"L(\theta, \dot{\theta}) = \frac{1}{2}I_{p}(\theta)\dot{\theta}^2 - V(\theta)"
    ok = r"I_{p}(\theta)\ddot{\theta} = - V'(\theta) - \frac{1}{2}I'_{p}(\theta)\dot{\theta}^2"
    bad = r"I_{p}(\theta)\ddot{\theta} = - V'(\theta) + \frac{1}{2}I'_{p}(\theta)\dot{\theta}^2"
    assert _last(LAGRANGIAN, general, ok) == "holds"
    assert _last(LAGRANGIAN, general, bad) == "fails"
    assert _last(general, r"p_\theta = L = \frac{\partial L}{\partial{\dot{\theta}}} = I_{p}(\theta)\dot{\theta}") == "holds"


def test_a_prime_written_as_a_superscript_is_the_derivative_as_an_apostrophe_is():
    general = r"L(\theta, \dot{\theta}) = \frac{1}{2}I_{p}(\theta)\dot{\theta}^2 - V(\theta)"
    ok = r"I_{p}(\theta)\ddot{\theta} = - V^{\prime}(\theta) - \frac{1}{2}I^\prime_{p}(\theta)\dot{\theta}^2"
    bad = r"I_{p}(\theta)\ddot{\theta} = - V^{\prime}(\theta) + \frac{1}{2}I^\prime_{p}(\theta)\dot{\theta}^2"
    assert _last(LAGRANGIAN, general, ok) == "holds"
    assert _last(LAGRANGIAN, general, bad) == "fails"


def test_a_function_defined_as_an_expression_in_the_angle_is_evaluated_and_differentiated_with_a_prime():
    x = r"x_{C} = a\sin\theta - \theta R"
    assert _last(LAGRANGIAN, x, r"x_{C}'(\theta_0) = a\cos\theta_0 - R") == "holds"
    assert _last(LAGRANGIAN, x, r"x_{C}'(\theta_0) = a\cos\theta_0 + R") == "fails"


def test_a_chain_after_a_two_argument_definition_is_checked_against_it():
    f = r"F(\theta, \theta_0) = m(\theta - \theta_0)^2"
    assert _last(LAGRANGIAN, f, r"= m\theta^2 - 2m\theta\theta_0 + m\theta_0^2") == "holds"
    assert _last(LAGRANGIAN, f, r"= m\theta^2 + m\theta_0^2") == "fails"


def test_a_derivative_evaluated_at_a_point_with_a_bar():
    f = r"F(\theta, \theta_0) = m(\theta - \theta_0)^2 + \theta"
    assert _last(LAGRANGIAN, f, r"\left.\frac{\partial F(\theta, \theta_0)}{\partial\theta}\right|_{\theta=\theta_0} = 1") == "holds"


def test_a_symbol_met_first_in_a_relation_is_defined_by_it():
    verdicts = _verdicts(LAGRANGIAN, r"I_{O} = mR^2 = I_{C} + ma^2", r"I_{C} = m(R^2 - a^2)")
    assert [v[1] for v in verdicts] == ["unchecked", "unchecked", "holds"]


def test_the_coordinate_set_to_a_value_is_no_claim_of_this_reading():
    verdicts = _verdicts(LAGRANGIAN, r"\theta = \theta_0")
    assert verdicts[-1][1] == "unchecked"


def test_a_text_without_its_own_lagrangian_is_read_as_before():
    claims = kept.check_text(HEAD + "\n$$\nx_{C} = a\\sin\\theta - \\theta R\n$$\n\n$$\nx_{C}'(\\theta) = 0\n$$\n")
    assert all(c.verdict == "unchecked" for c in claims)


def test_an_inline_formula_broken_across_a_line_is_read():
    text = HEAD + "The moment about the contact point is $I_{P}(\\theta) =\n2mR(R-a\\cos\\theta)$ here.\n\n" + \
        f"$$\n{LAGRANGIAN}\n$$\n\n$$\nI_{{P}}'(\\theta) = 2maR\\sin\\theta\n$$\n"
    assert kept.check_text(text)[-1].verdict == "holds"


def test_a_text_in_euler_angles_is_left_to_the_general_reader():
    head = "---\nconvention: z-x-z\nangles: [\\phi, \\theta, \\psi]\n---\n# Heavy top\n\n"
    claims = kept.check_text(head + f"$$\n{LAGRANGIAN}\n$$\n")
    assert not [c for c in claims if c.why.startswith("defines L (recorded")]


def test_a_bracketed_rate_after_a_symbol_is_a_product_not_a_call():
    lagrangian = r"L(\theta, \dot{\theta}) = \frac{1}{2} m R^2 \left(\dot\theta\right)^2 + mgR\cos\theta"
    assert _last(lagrangian, r"m R^2\ddot\theta = -mgR\sin\theta") == "holds"
    assert _last(lagrangian, r"m R^2\ddot\theta = mgR\sin\theta") == "fails"
