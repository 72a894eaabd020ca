"""Euler's equations of a free body written as one vector equation without a torque,
``\\mathbf{I}\\dot{\\boldsymbol\\omega} = -\\boldsymbol\\omega \\times \\mathbf{I}\\boldsymbol\\omega``: the vector
reader's model reads a torque as d𝐋/dt, so such a statement is the law of motion of a body with
no torque, and holds once ω̇ is the free body's (as Iᵢω̃̇ᵢ = (Iⱼ − Iₖ)ω̃ⱼω̃ₖ does in components);
its sign slipped, it is flagged. A 0 set against a vector is the zero vector."""
from __future__ import annotations

import sympy as sp

import kept_readings as kept
from derive.lecture import free_rotation
from derive.lecture import vector_algebra_model as va

TORQUE = va.torque("body")


def _verdicts(latex: str) -> list:
    return [(c.verdict, c.why) for c in kept.check_text(f"# Euler\n\n$$\n{latex}\n$$\n") if c.line == 3]


def test_the_free_bodys_law_in_vector_form_holds_and_says_it_is_the_free_bodys():
    for latex in (r"I \dot{\boldsymbol{\omega}} = - \boldsymbol{\omega} \times I \boldsymbol{\omega}",
                  r"\mathbf{I} \dot{\boldsymbol{\omega}} + \boldsymbol{\omega} \times \mathbf{I} \boldsymbol{\omega} = 0"):
        [(verdict, why)] = _verdicts(latex)
        assert verdict == "holds" and "free body" in why


def test_the_free_bodys_law_with_its_sign_slipped_is_flagged():
    for latex in (r"I \dot{\boldsymbol{\omega}} = \boldsymbol{\omega} \times I \boldsymbol{\omega}",
                  r"\mathbf{I} \dot{\boldsymbol{\omega}} - \boldsymbol{\omega} \times \mathbf{I} \boldsymbol{\omega} = 0",
                  r"\mathbf{I} \dot{\boldsymbol{\omega}} = 0"):
        [(verdict, _)] = _verdicts(latex)
        assert verdict in ("typo", "fails"), latex


def test_a_torque_written_keeps_the_law_an_identity_of_the_model():
    [(verdict, why)] = _verdicts(r"I \dot{\boldsymbol{\omega}} + \boldsymbol{\omega} \times (I \boldsymbol{\omega}) = \boldsymbol{\tau}")
    assert verdict == "holds" and "free body" not in why


def test_a_difference_without_the_rate_or_with_a_symbol_outside_the_model_is_not_the_free_bodys():
    assert not free_rotation.vanishes_for_free_body(va.W[0] * va.W[1], TORQUE)
    assert not free_rotation.vanishes_for_free_body(va.WD[0] - sp.Symbol("tau_x"), TORQUE)
    assert not free_rotation.vanishes_for_free_body(sp.zeros(3, 1), TORQUE)


def test_a_vector_of_the_texts_added_to_the_law_is_its_torque_and_otherwise_nothing_is_flagged():
    [(verdict, why)] = _verdicts(r"I\mathbf{\dot\omega} = -\mathbf{\omega} \times I\mathbf{\omega} + \mathbf{M}")
    assert verdict == "holds" and "M read as the torque" in why
    for other in (r"I\mathbf{\dot\omega} = -\mathbf{\omega} \times I\mathbf{\omega} - \mathbf{M}",
                  r"I\mathbf{\dot\omega} = \mathbf{\omega} \times I\mathbf{\omega} + \mathbf{M}"):
        [(verdict, _)] = _verdicts(other)
        assert verdict == "unchecked", other


def test_a_system_whose_tensor_cannot_be_inverted_decides_nothing():
    # one point mass: its tensor has rank two at every point, so ω̇ is not the free body's anywhere
    single = va.torque("single")
    assert not free_rotation.vanishes_for_free_body(single, single)
