"""The gyroscope's names as a text's prose gives them: the precession rate, the spin rate, the
nutation rate, and the axial moment and the centre's distance in the words gyroscope texts use.

Takes: an inline symbol and the phrase nearest it, as `derive.lecture.names` reads the prose
("the precession rate $\\Omega_p$", "spinning at $\\omega_s$", "the nutation frequency $\\omega_n$",
"a rotor of moment $I_s$ about its spin axis", "$d$ the distance of its centre from the pivot").
Gives: `MEANINGS` and `LETTERS`, rows of the names' registries (the more specific phrases, read
before the general "angular velocity"), and `value`, what such a name stands for in the heavy
symmetric top the reader derives:

* the precession rate is the rate of the first Euler angle (the turn about the fixed vertical);
* the spin rate is the body's angular velocity about its symmetry axis, ω̃₃ (Iω̃₃ = p_γ): what a
  text means by "spinning at ω_s" whether it goes on to a fast top or a free one;
* the nutation rate has no symbol of its own in the derivation: it stays the text's symbol, and
  `derive.lecture.gyro_rates` judges what a display sets it to.

A name is bound only as a plain scalar (no bold, no dot): Ω⃗_p, the precession vector, is not the
rate. May import: :mod:`derive.lecture.latex`, :mod:`derive.symbolic.rotations`.
"""
from __future__ import annotations

from derive.lecture import latex as lx
from derive.symbolic.rotations import RATES

_AXIS = r"(?:its |the )(?:own |symmetry |figure |spin |rotor'?s? )?axis"
MEANINGS = {
    "precession rate": ("symbol", r"precession(?:al)? (?:rate|frequency|angular (?:velocity|speed|frequency))|"
                                  r"rate of (?:the )?precession|angular (?:velocity|speed|frequency) of (?:the )?precession|"
                                  r"precess(?:es)? (?:steadily )?(?:at|with) (?:the|a) (?:rate|angular velocity)"),
    "nutation rate": ("symbol", r"nutation(?:al)? (?:rate|frequency|angular (?:velocity|frequency))|"
                                r"(?:rate|frequency) of (?:the )?nutation"),
    "spin rate": ("symbol", r"spin (?:rate|angular velocity|speed)|rate of (?:the )?spin\b|angular (?:velocity|speed) of "
                            r"(?:the )?spin\b|\bspin(?:s|ning)? (?:at|with (?:the )?angular velocity)"),
    "axial moment (about the spin axis)": ("symbol", r"moment(?: of inertia)?\W{0,3}(?:§\W{0,3})?(?:about|around|along) " + _AXIS.replace(
        "(?:own |symmetry |figure |spin |rotor'?s? )?", "(?:own )?(?:symmetry|figure|spin|rotor'?s?) ") +
        r"|spin\w*[^.;§]{0,40}(?:about|around) " + _AXIS + r",? with (?:a |the |its )?moment(?: of inertia)?"),
    "centre-of-mass distance (from the pivot)": ("symbol", r"(?:distance|length|height) of (?:its|the) (?:centre|center)\b[^.;]{0,20}?"
                                       r"from the (?:pivot|support|fixed point|point of support)"),
}
"""The gyroscope's meanings (`derive.lecture.names.MEANINGS` rows); the last two are the axial
moment and the centre-of-mass distance said in other words (`SAME`)."""

LETTERS = {"precession rate": ("Omega", "omega", "w", "W", "nu"), "nutation rate": ("Omega", "omega", "w", "W", "nu"),
           "spin rate": ("omega", "Omega", "w", "n", "s", "nu"), "axial moment (about the spin axis)": ("I", "J", "C"),
           "centre-of-mass distance (from the pivot)": ("l", "a", "h", "d", "s", "ell", "b", "R", "r")}
"""The letters each meaning takes (any other letter near the phrase is something else)."""

SAME = {"axial moment (about the spin axis)": "axial moment", "centre-of-mass distance (from the pivot)": "centre-of-mass distance"}
"""A meaning said in other words → the registry's meaning it is."""


def value(meaning: str, a, vocab):
    """What a symbol bound to one of `MEANINGS` stands for, or None (a vector, a rate of it)."""
    if a.bold or a.dots or a.primes or a.hat or a.tilde:
        return None
    if meaning == "precession rate":
        return RATES[0]
    if meaning == "spin rate":
        return lx.W[vocab.axial]      # ω̃ about the third turn's axis, the body's symmetry axis
    if meaning == "nutation rate":
        return vocab._generic(a) if vocab.open else None
    return None

