"""Linearised equations of motion, their second-order forms and their solutions, checked against
the text's own earlier equations (`derive.lecture.motion`)."""
import pytest

import kept_readings as kept

HEAD = "---\nconvention: z-x-z\n---\n# Stability of rotation about an axis\n\n"

LINEARISED = HEAD + r"""The torque-free Euler equations:

$$I_1\dot{\omega}_1-(I_2-I_3)\omega_2\omega_3 = 0$$

$$I_2\dot{\omega}_2-(I_3-I_1)\omega_1\omega_3 = 0$$

$$I_3\dot{\omega}_3-(I_1-I_2)\omega_1\omega_2 = 0$$

Near rotation about the first axis,

$$\omega_1 = \Omega$$

and the other two equations become

$$\dot{\omega}_2 = \frac{I_3-I_1}{I_2}\Omega\omega_3$$

$$\dot{\omega}_3 = \frac{I_1-I_2}{I_3}\Omega\omega_2$$

Eliminating one of them,

$$\ddot{\omega}_2 + \frac{(I_3-I_1)(I_2-I_1)}{I_2 I_3}\Omega^2\omega_2 = 0$$

whose solution is

$$\omega_2 = a \sqrt{I_3(I_3-I_1)} \sin(\omega_0 t + \phi_0)$$

$$\omega_3 = a \sqrt{I_2(I_2-I_1)} \cos(\omega_0 t + \phi_0)$$

where $a$ is a small constant and $\omega_0 = \sqrt{\frac{(I_3-I_1)(I_2-I_1)}{I_2 I_3}}\Omega$. The angular momentum's components:

$$L_2 = a I_2 \sqrt{I_3(I_3-I_1)} \sin(\omega_0 t + \phi_0)$$

$$L_3 = a I_3 \sqrt{I_2(I_2-I_1)} \cos(\omega_0 t + \phi_0)$$

For rotation near the second axis ($\omega_2 = \Omega$ to first order) the equations are

$$\dot{\omega}_1 = \frac{I_2-I_3}{I_1}\Omega\omega_3$$

$$\dot{\omega}_3 = \frac{I_1-I_2}{I_3}\Omega\omega_1$$

$$\ddot{\omega}_1 - \frac{(I_2-I_1)(I_3-I_2)}{I_1I_3}\Omega^2\omega_1 = 0$$
"""


def _verdicts(text):
    claims = kept.check_text(text)
    out = {}
    for c in claims:
        out.setdefault(c.line, []).append(c.verdict)
    return claims, out


def _line(text, start):
    return next(k for k, row in enumerate(text.split("\n"), start=1) if row.startswith(start))


def test_linearised_equations_their_second_order_form_and_solution_hold():
    claims, by_line = _verdicts(LINEARISED)
    assert not [c for c in claims if c.verdict in ("typo", "fails")], [(c.line, c.latex, c.why) for c in claims]
    for start in (r"$$\dot{\omega}_2 =", r"$$\ddot{\omega}_2", r"$$\omega_2 = a", r"$$\omega_3 = a", r"$$L_2",
                  r"$$L_3", r"$$\dot{\omega}_1 =", r"$$\ddot{\omega}_1"):
        assert by_line[_line(LINEARISED, start)] == ["holds"], start


@pytest.mark.parametrize("old, new", [
    (r"$$\omega_3 = a \sqrt{I_2(I_2-I_1)} \cos", r"$$\omega_3 = a \sqrt{I_2(I_2-I_1)} \sin"),      # sin for cos
    pytest.param(r"$$\omega_2 = a \sqrt{I_3(I_3-I_1)}", r"$$\omega_2 = a \sqrt{I_2(I_3-I_1)}",      # an index
                 marks=pytest.mark.slow),
    pytest.param(r"$$L_3 = a I_3 \sqrt{I_2(I_2-I_1)}", r"$$L_3 = a I_2 \sqrt{I_2(I_2-I_1)}",        # Lᵢ ≠ Iᵢωᵢ of it
                 marks=pytest.mark.slow),
    (r"\frac{(I_3-I_1)(I_2-I_1)}{I_2 I_3}\Omega^2\omega_2", r"\frac{(I_3-I_1)(I_2-I_1)}{I_2 I_3}\Omega\omega_2"),
])  # a solution's slip and a second-order form's in make test; the others in make test-slow
def test_a_slip_in_a_linearised_solution_or_its_second_order_form_is_flagged(old, new):
    assert old in LINEARISED
    text = LINEARISED.replace(old, new, 1)
    claims, by_line = _verdicts(text)
    line = _line(text, new.split("\\frac")[0] if new.startswith("$$") else "$$\\ddot{\\omega}_2")
    assert set(by_line[line]) & {"typo", "fails"}, by_line[line]
    flagged = {c.line for c in claims if c.verdict in ("typo", "fails")}
    solution_rows = {_line(text, r"$$\omega_2 = a"), _line(text, r"$$\omega_3 = a")}
    assert flagged <= {line} | (solution_rows if line in solution_rows else set())


def test_a_solution_whose_frequency_the_text_never_gives_is_unchecked():
    text = LINEARISED.replace(r"and $\omega_0 = \sqrt{\frac{(I_3-I_1)(I_2-I_1)}{I_2 I_3}}\Omega$", "and")
    claims, by_line = _verdicts(text)
    row = by_line[_line(text, r"$$\omega_2 = a")]
    assert row == ["unchecked"]
    assert any("\\omega_{0}" in c.why for c in claims if c.line == _line(text, r"$$\omega_2 = a"))


def test_later_identities_use_the_solution_and_its_constants():
    text = HEAD + r"""For a symmetric body, $I_1 = I_2$, with

$$\omega_3 = \Omega$$

the equations are

$$\dot{\omega}_1 + n\omega_2 = 0$$

$$\dot{\omega}_2 - n\omega_1 = 0$$

where $n = \frac{I_3 - I_1}{I_1}\Omega$. Their solution:

$$\omega_1 = \omega_0 \cos(nt + \varepsilon)$$

$$\omega_2 = \omega_0 \sin(nt + \varepsilon)$$

so that

$$\omega = \sqrt{\omega_1^2 + \omega_2^2 + \omega_3^2} = \sqrt{\omega_0^2 + \Omega^2}$$

$$\omega = \sqrt{\omega_1^2 + \omega_2^2 + \omega_3^2} = \sqrt{\omega_0^2 + 2\Omega^2}$$
"""
    claims, by_line = _verdicts(text)
    lines = [k for k, row in enumerate(text.split("\n"), start=1) if row.startswith(r"$$\omega = ")]
    assert by_line[lines[0]] == ["holds"]
    assert set(by_line[lines[1]]) & {"typo", "fails"}


SMALL = HEAD + r"""The torque-free Euler equations:

$$I_1\dot{\omega}_1-(I_2-I_3)\omega_2\omega_3 = 0$$

Suppose the body turns nearly about the first axis, so $\omega_2, \omega_3$ are first-order small. To first order

$$I_1\dot{\omega}_1 = 0$$
"""


def test_an_equation_to_first_order_in_components_the_prose_calls_small_holds():
    claims, by_line = _verdicts(SMALL)
    line = _line(SMALL, r"$$I_1\dot{\omega}_1 = 0")
    assert by_line[line] == ["holds"]
    assert "first order" in next(c.why for c in claims if c.line == line)


def test_without_the_prose_saying_so_the_first_order_equation_is_flagged():
    text = SMALL.replace(r"so $\omega_2, \omega_3$ are first-order small", "so")
    claims, by_line = _verdicts(text)
    assert set(by_line[_line(text, r"$$I_1\dot{\omega}_1 = 0")]) & {"typo", "fails"}


ALONG_L = HEAD + r"""The fixed $Z$ axis is taken along the angular momentum, of magnitude $L$:

$$I_1\omega_1 = L\sin\theta\sin\psi$$

$$I_2\omega_2 = L\sin\theta\cos\psi$$

$$I_3\omega_3 = L\cos\theta$$

With the body components of the angular velocity,

$$\dot{\phi} = \frac{\omega_1\sin\psi+\omega_2\cos\psi}{\sin \theta}$$

the precession rate is

$$\dot{\phi} = L\frac{I_1\omega_1^2+I_2\omega_2^2}{L^2-I_3^2\omega_3^2}$$
"""


def test_relations_for_the_orientation_with_the_fixed_axis_along_l_hold():
    claims, by_line = _verdicts(ALONG_L)
    assert not [c for c in claims if c.verdict in ("typo", "fails")], [(c.line, c.why) for c in claims]
    for start in (r"$$I_1\omega_1 = L", r"$$I_3\omega_3", r"$$\dot{\phi} = L"):
        assert by_line[_line(ALONG_L, start)] == ["holds"], start


def test_a_slip_under_the_chosen_orientation_is_still_flagged():
    text = ALONG_L.replace(r"{L^2-I_3^2\omega_3^2}", r"{L^2+I_3^2\omega_3^2}")
    claims, by_line = _verdicts(text)
    assert set(by_line[_line(text, r"$$\dot{\phi} = L")]) & {"typo", "fails"}


OSCILLATOR = HEAD + r"""The principal axes are $x$, $y$, $z$, with principal moments $I_x$, $I_y$, $I_z$. Euler's equations:

$$I_{x} \dot{\omega}_{x} = -(I_z - I_y) \omega_{y} \omega_{z}$$

$$I_{y} \dot{\omega}_{y} = (I_z - I_x) \omega_{z} \omega_{x}$$

$$I_{z} \dot{\omega}_{z} = -(I_y - I_x) \omega_{x} \omega_{y}$$

Rotation mostly about $x$: $0 \approx \omega_y, \omega_z \ll \omega_x$. Differentiating,

$$\ddot{\omega}_{y} = - \frac{(I_z - I_x)(I_y - I_x) \omega_{x}^2}{I_y I_z} \omega_{y}$$

The bracket is named $k^2 = \frac{(I_z - I_x)(I_y - I_x) \omega_{x}^2}{I_y I_z} > 0$, so

$$\ddot{\omega}_y = - k^2 \omega_y \quad\implies\quad \omega_y(t) = \omega_y(0) \cos(k t) + \frac{1}{k}\dot{\omega}_y(0) \sin(k t)$$
"""


def test_an_oscillator_equation_in_the_texts_axes_and_its_solution_hold():
    claims, by_line = _verdicts(OSCILLATOR)
    assert not [c for c in claims if c.verdict in ("typo", "fails")], [(c.line, c.latex, c.why) for c in claims]
    assert by_line[_line(OSCILLATOR, r"$$\ddot{\omega}_{y} =")] == ["holds"]
    assert by_line[_line(OSCILLATOR, r"$$\ddot{\omega}_y = - k^2")] == ["holds", "holds"]


def _numbered(text):
    """The text with axes 1, 2, 3 for x, y, z (no names learned from the prose)."""
    text = text.replace("The principal axes are $x$, $y$, $z$, with principal moments $I_x$, $I_y$, $I_z$. ", "")
    for a, k in zip("xyz", "123"):
        text = text.replace("_{" + a + "}", "_" + k).replace("_" + a, "_" + k)
    return text


def test_a_second_order_equation_that_drops_a_power_is_flagged():
    text = _numbered(OSCILLATOR).replace(r"$$\ddot{\omega}_2 = - k^2 \omega_2", r"$$\ddot{\omega}_2 = - k \omega_2")
    assert not [c for c in kept.check_text(_numbered(OSCILLATOR)) if c.verdict in ("typo", "fails")]
    claims, by_line = _verdicts(text)
    assert set(by_line[_line(text, r"$$\ddot{\omega}_2 = - k")]) & {"typo", "fails"}


def test_a_label_set_twice_in_a_block_is_a_typo_for_the_one_left_out():
    text = HEAD + r"""A box of sides $a$, $b$, $c$ and mass $M$ has

$$
I_{x} = \frac{1}{12}M(b^2 + c^2), \quad I_{x} = \frac{1}{12}M(c^2 + a^2), \quad I_{z} = \frac{1}{12}M(a^2 + b^2)
$$
"""
    claims = kept.check_text(text)
    typos = [c for c in claims if c.verdict == "typo"]
    assert len(typos) == 1 and typos[0].correction.startswith("I_{y} =")
    assert not [c for c in kept.check_text(text.replace("I_{x} = \\frac{1}{12}M(c", "I_{y} = \\frac{1}{12}M(c"))
                if c.verdict in ("typo", "fails")]


ORDERED = HEAD + r"""A box has sides

$$a > b > c$$

so that

$$b^2 + c^2 < c^2 + a^2 < a^2 + b^2$$

Since $I_1<I_2<I_3$,

$$- \frac{(I_2-I_1)(I_3-I_2)}{I_1I_3}\Omega^2 < 0$$
"""


def test_inequalities_follow_from_the_orderings_the_text_states():
    claims, by_line = _verdicts(ORDERED)
    assert by_line[_line(ORDERED, "$$b^2")] == ["holds"]
    assert by_line[_line(ORDERED, "$$- \\frac")] == ["holds"]


def test_a_reversed_inequality_under_a_stated_ordering_is_a_typo_and_an_undecided_one_unchecked():
    text = ORDERED.replace(r"\Omega^2 < 0", r"\Omega^2 > 0")
    assert "typo" in _verdicts(text)[1][_line(text, "$$- \\frac")]
    text = ORDERED.replace(r"(I_2-I_1)(I_3-I_2)", r"(I_2-I_1)(I_3-\Omega)")
    assert _verdicts(text)[1][_line(text, "$$- \\frac")] == ["unchecked"]


# ω_x, ω_z are the angular velocity only by the prose's principal axes x, y, z: a second-order
# form that fails is judged only where a row of its display, read with the same names, holds
SLAB = r"""---
title: Spin about the intermediate axis
---

# Unstable rotation

Rotations about the $x$, $y$ and $z$ axes are called $\boldsymbol{\omega}_{x}$, $\boldsymbol{\omega}_{y}$, $\boldsymbol{\omega}_{z}$.
$I_{x}$, $I_{y}$, $I_{z}$ denote the moments of inertia about the $x$, $y$, $z$ axes, which are principal axes. Euler's equations in components:

$$
\begin{align}
    &\tau_x = I_{x} \dot{\omega}_{x} + (I_{z} - I_{y}) \omega_{y} \omega_{z} \\
    &\tau_y = I_{y} \dot{\omega}_{y} + (I_{x} - I_{z}) \omega_{z} \omega_{x} \\
    &\tau_z = I_{z} \dot{\omega}_{z} + (I_{y} - I_{x}) \omega_{x} \omega_{y}
\end{align}
$$

With zero torque and $k_{1} \equiv I_{z} - I_{y}$, $k_{3} \equiv I_{y} - I_{x}$ the equations are

$$
\begin{align}
    &I_{x} \dot{\omega}_{x} = -k_{1} \omega_{y} \omega_{z} \\
    &I_{z} \dot{\omega}_{z} = -k_{3} \omega_{x} \omega_{y}
\end{align}
$$

Rotation mostly about $y$: $0 \approx \omega_x, \omega_z \ll \omega_y$, so $\omega_{y}$ is constant. Differentiating and substituting:

$$
\begin{align}
    &\ddot{\omega}_{x} = \left ( \frac{ k_{1} k_{3} \omega_{y}^2 }{I_x I_z} \right ) \omega_{x} \\
    &\ddot{\omega}_{z} = \left ( \frac{ k_{1} k_{3} \omega_{y}^2 }{I_x I_z} \right ) \omega_{z}
\end{align}
$$

The bracket is named $k_5^2 = \frac{ k_{1} k_{3} \omega_{y}^2 }{I_x I_z} > 0$. Then

$$
"""


def _last_display(rows):
    claims = kept.check_text(SLAB + "\n\\\\\n".join(rows) + "\n$$\n")
    last = max(c.line for c in claims)
    return {c.latex.strip(): c for c in claims if c.line == last}


@pytest.mark.parametrize("rows", [
    [r"\ddot{\omega}_x = k_5^2 \omega_x", r"\ddot{\omega}_z = k_5 \omega_z"],
    [r"\ddot{\omega}_z = k_5 \omega_z", r"\ddot{\omega}_x = k_5^2 \omega_x"],
])
def test_a_row_that_fails_only_by_the_prose_names_is_a_typo_where_a_row_read_with_them_holds(rows):
    got = _last_display(rows)
    sibling, slip = got[r"\ddot{\omega}_x = k_5^2 \omega_x"], got[r"\ddot{\omega}_z = k_5 \omega_z"]
    assert sibling.verdict == "holds"
    assert (slip.verdict, slip.correction) == ("typo", r"\ddot{\omega}_z = k_5^2 \omega_z")
    assert r"confirmed by \ddot{\omega}_x = k_5^2 \omega_x" in slip.why


def test_a_row_that_fails_only_by_the_prose_names_stays_unchecked_alone_in_its_display():
    slip = _last_display([r"\ddot{\omega}_z = k_5 \omega_z"])[r"\ddot{\omega}_z = k_5 \omega_z"]
    assert (slip.verdict, slip.correction) == ("unchecked", None)
    assert "the text may mean something else" in slip.why


def test_a_row_that_holds_with_another_learned_name_does_not_confirm_the_reading():
    # I_z is bound by the prose as its own symbol; the holding row reads I_x, not I_z
    got = _last_display([r"I_x \ddot{\omega}_x = I_x k_5^2 \omega_x", r"I_z \ddot{\omega}_z = I_z k_5 \omega_z"])
    assert got[r"I_x \ddot{\omega}_x = I_x k_5^2 \omega_x"].verdict == "holds"
    assert got[r"I_z \ddot{\omega}_z = I_z k_5 \omega_z"].verdict == "unchecked"
