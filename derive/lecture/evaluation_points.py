"""Rates among the formula reader's tokens: whether a bracket after one is the point it is evaluated
at.

``\\dot\\phi(t + T)``, ``\\frac{d\\omega_1}{dt}(0)``: a derivative followed by a bracket holding the
time (or only numbers) is evaluated at that point. ``\\frac{d\\alpha}{dt} \\left(p_\\gamma - I_1
\\frac{d\\alpha}{dt} \\cos\\beta\\right)``: a bracket holding other quantities multiplies it, as a
reader reads it. Takes the formula reader's tokens (`derive.lecture.vocabulary.Tok`); imports
nothing of derive's.
"""
from __future__ import annotations


def holds_a_point(toks: list, i: int) -> bool:
    """Whether the bracket opening at ``toks[i]`` holds a point in time.

    Parameters
    ----------
    toks : list of Tok
        The formula's tokens; ``toks[i]`` is an opening bracket (``op`` ``(``).
    i : int
        Where the bracket opens.

    Returns
    -------
    bool
        True when the bracket's content names the time ``t`` (``t``, ``t_1``, ``t + T``) or holds
        only numbers and operators (``0``, ``2``); False when it holds other quantities, and also
        when the bracket is never closed (nothing to evaluate at).
    """
    depth, inside = 0, []
    for tok in toks[i:]:
        if tok.kind == "op" and tok.value == "(":
            depth += 1
        elif tok.kind == "op" and tok.value == ")":
            depth -= 1
            if depth == 0:
                break
        if depth and tok is not toks[i]:
            inside.append(tok)
    else:
        return False
    base = lambda t: getattr(t.value, "base", None) if t.kind == "atom" else None  # noqa: E731
    # the time itself, not the dt of a derivative inside the bracket
    if any(base(t) == "t" and (k == 0 or base(inside[k - 1]) != "d") for k, t in enumerate(inside)):
        return True
    return all(t.kind in ("num", "op") for t in inside)
