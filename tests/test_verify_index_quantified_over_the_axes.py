"""The notes reader on a display quantified over the body axes: ``\\forall i \\in \\mathbb{Z}_3:`` opens a
statement written once for all three axes, the index taken modulo three so that i+1 and i-1 run
cyclically; the display states its three instances. Euler's equations so written are judged axis
by axis, a slip in them flagged; a set {1, 2, 3} with a shifted index, or the index outside a
subscript, is left as written. A plain-TeX row end ``\\cr`` cuts rows as ``\\\\`` does, and
``\\color{red}{+}`` is read as the + it colours."""
from kept_readings import by_line, line_of

from derive.lecture import index_quantifier, statements

EULER = r"\forall i ~\in~\mathbb{Z}_3:~~ I_i \dot{\omega}_i~=~\omega_{i+1}(I_{i+1}-I_{i-1}) \omega_{i-1} \tag{1}"
SLIP = r"\forall i ~\in~\mathbb{Z}_3:~~ I_i \dot{\omega}_i~=~\omega_{i+1}(I_{i-1}-I_{i+1}) \omega_{i-1} \tag{1}"


def _verdicts(display):
    text = "# Euler\n\nEuler's equations of the free body:\n\n$$" + display + "$$\n"
    return [c.verdict for c in by_line(text)[line_of(text, "$$" + display)]]


def test_euler_s_equations_written_once_for_the_three_axes_hold_axis_by_axis():
    assert _verdicts(EULER) == ["holds", "holds", "holds"]


def test_a_sign_slip_in_the_cyclic_form_is_flagged_on_every_axis():
    assert all(v in ("typo", "fails") for v in _verdicts(SLIP)) and len(_verdicts(SLIP)) == 3


def test_the_shifted_indices_run_cyclically_modulo_three():
    got = index_quantifier.instances(r"\forall i \in \mathrm{Z}_3: a_{i} = b_{i+1} c_{i-1}")
    assert [g.strip() for g in got] == ["a_{1} = b_{2} c_{3}", "a_{2} = b_{3} c_{1}", "a_{3} = b_{1} c_{2}"]


def test_the_set_one_two_three_with_a_shifted_index_or_the_index_outside_a_subscript_is_left_as_written():
    for body in (r"\forall i \in \{1,2,3\}: a_i = b_{i+1}", r"\forall i \in \mathrm{Z}_3: a_i = i b_i"):
        assert index_quantifier.instances(body) == [body]
    got = index_quantifier.instances(r"\forall i \in \{1, 2, 3\}: a_i = b_i")
    assert [g.strip() for g in got] == ["a_{1} = b_{1}", "a_{2} = b_{2}", "a_{3} = b_{3}"]


def test_a_quantifier_on_its_own_row_of_an_align_ended_by_cr_quantifies_the_next_row():
    display = (r" \begin{align}\forall i ~\in~\mathbb{Z}_3:&~~\cr I_1I_2 I_3 \ddot{\omega}_i~&\stackrel{(1)}{=}~(I_{i+1}-I_{i-1})"
               r" \omega_i\left\{(I_i -I_{i+1}) I_{i+1}\omega_{i+1}^2- (I_i -I_{i-1}) I_{i-1}\omega_{i-1}^2\right\} . \end{align}")
    assert _verdicts(display) == ["holds", "holds", "holds"]


def test_cr_ends_a_row_and_a_colour_s_name_is_no_mathematics():
    from derive.lecture import source
    rows = statements.statements(source.normalize(r"\begin{align} a &= b \cr c &= d \end{align}"))
    assert [r.split() for r in rows] == [["a", "=", "b"], ["c", "=", "d"]]
    assert "red" not in source.normalize(r"\ddot{x} = \color{red}{+} x")


def test_a_quantifier_spaced_by_medium_spaces_still_quantifies_its_statement():
    spaced = EULER.replace(r"\forall i", r"\forall \; i").replace(r"I_i \dot", r"I_i \; \dot")
    assert _verdicts(spaced) == ["holds", "holds", "holds"]
