"""The notes reader on definitions that name one another through a matrix: a point's velocity
``\\dot{p} = R U_p`` with ``U_p = R^T \\dot{p}`` and ``R`` a product of turns. Putting one into the
other multiplies the turn matrices again with every round; the reader stops at a bound on the
nodes it builds (`text_matrices.PUT_NODES`) and leaves the display unchecked, saying so."""
import json
import os
import subprocess
import sys

import pytest
import sympy as sp

from derive.lecture import text_matrices as tm
from derive.lecture.latex import Generic

NOTE = r"""\documentclass{article}
\begin{document}
A cart's frame $\mathbf{c}$ moves, with $U_p=R^T\dot{p}$ the speed of its corner $p$ seen in $\mathbf{c}$.
Here $\mathbf{c}=\mathbf{e}\,R$ and $\dot{p}=RU_p$.

The frame turns by the angles $R=R_3(\theta)R_1(\alpha)R_2(\phi)$, so
\[
R=R_3(\theta)R_1(\alpha)R_2(\phi).
\]
The corner moves as
\[
\dot{p}=\left[\begin{array}{c} \dot{x}\\ \dot{y} \\ -h\dot{\alpha}\cos{\alpha}
\end{array}\right]
\]
\end{document}
"""


def test_a_product_past_the_bound_raises_naming_the_definitions_put_in():
    a, b = Generic("A", commutative=False), Generic("B", commutative=False)
    t = sp.Symbol("t", real=True)
    turn = sp.ImmutableMatrix(sp.rot_axis3(t))
    rep = {a: turn, b: turn.T}
    assert tm.matrices_put(a * b, rep) == turn * turn.T          # within the bound: multiplied out
    with pytest.raises(tm.TooLarge, match=r"definitions of A, B builds more than"):
        tm.matrices_put(a * b, rep, budget=[20])


def test_a_velocity_whose_definitions_name_one_another_is_unchecked_with_the_bound_named(tmp_path):
    note = tmp_path / "cart.tex"
    note.write_text(NOTE)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [os.getcwd(), os.environ.get("PYTHONPATH")]))}
    # a guard against the reader running without end, never a speed target
    done = subprocess.run([sys.executable, "-m", "derive", "verify", str(note), "--format", "json"],
                          capture_output=True, text=True, timeout=60, env=env)
    claims = json.loads(done.stdout)["claims"]
    velocity = [c for c in claims if c["latex"].startswith(r"\dot{p}=\left[")]
    assert [c["verdict"] for c in velocity] == ["unchecked"]
    assert f"builds more than {tm.PUT_NODES} terms" in velocity[0]["why"]
    assert {c["verdict"] for c in claims if c not in velocity} <= {"holds", "unchecked"}
