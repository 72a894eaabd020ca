"""The meanings a text may give its symbols, the registry `derive.lecture.names` binds them from.

Takes and gives nothing at run time: `MEANINGS` (meaning → how it binds, the phrases that say it),
`LETTERS` (the letters a reader takes for each meaning) and `ALIASES` (other spellings a front
matter's ``symbols:`` map may use). What each meaning stands for in the derivation is
`derive.lecture.names.Names.value`.

The meanings (`MEANINGS`, a registry: adding one adds a row):

==========================  =======  ===================================================
meaning                     binds    the text's symbol stands for
==========================  =======  ===================================================
angular momentum            letter   𝐋 (bold), Iᵢω̃ᵢ (index 1–3; with a dot Iᵢω̃̇ᵢ), p of the
                                     first angle (index z: about the vertical), |𝐋| (plain);
                                     Π named plain also gives Πᵢ (geometric mechanics)
vertical angular momentum   symbol   p of the first angle (L·ẑ)
axial angular momentum      symbol   p of the third angle (L·ê₃ = I₃ω̃₃)
angular velocity            letter   𝛚 (bold), ω̃ᵢ (index 1–3, or x y z for body axes), ω̃̇ᵢ
body angular velocity       symbol   𝛚 with the frame labels it was named with (𝛚ᵅ_{βα}), ω̃ᵢ;
                                     a bare letter (Ω) is the column 𝛚 and gives its components
                                     Ωᵢ; the text's hat map, Rᵀ Ṙ = Ω̂ (`hat_maps`), binds the
                                     symbol, and Ωᵢ in the hat map's own section
turn rate                   symbol   the text's own symbol: "turns at the rate § about ẑ" (a rate of one of
                                     the turns that add up to 𝛚, not a component of 𝛚)
force                       letter   the text's own symbol (a tension T, a thrust, a normal force:
                                     never the kinetic energy); also T written beside a weight, T − Mg
torque                      letter   the torque's body components τᵢ (Euler's equations
                                     with a torque: Iᵢω̃̇ᵢ − ((Iω̃)×ω̃)ᵢ = τᵢ)
mass                        symbol   M
centre-of-mass distance     symbol   l
gravity                     symbol   g
kinetic energy, energy,     symbol   T, E, L (the Lagrangian), V_eff
lagrangian, eff. potential
transverse moment           symbol   I₁ (= I₂)
axial moment                symbol   I₃
principal moments           list     I₁, I₂, I₃ in the order written
identity column             letter   𝐈ᵢ (bold, index 1–3): the i-th column of the 3×3 identity
roll, pitch and yaw rates   list     ω̃₁, ω̃₂, ω̃₃ in the order written (the aircraft's p, q, r)
vertical                    letter   the upward vertical's body components Rᵀẑ (Poisson's γᵢ, 𝐧)
centre-of-mass coordinates  coords   the centre of mass's body coordinates, in the order written
                                     (the text's own symbols: `euler_poisson` puts them in the
                                     moment of gravity)
==========================  =======  ===================================================

May import: :mod:`derive.lecture.gyro_names`.
"""
from __future__ import annotations

from derive.lecture import gyro_names

# meaning → (how it binds, the phrases that say it). Order matters: the more specific first.
MEANINGS = {**gyro_names.MEANINGS,      # the gyroscope's phrases (precession, spin, nutation rates), read first
    "vertical angular momentum": ("symbol", r"angular momentum (?:component )?(?:about|along|around|on) the (?:fixed |space |spatial |inertial )?(?:vertical|z|Z|\$z\$|\$Z\$)"),
    "axial angular momentum": ("symbol", r"angular momentum (?:component )?(?:about|along|around|on) the (?:body'?s? )?(?:symmetry|figure|body|top'?s?|spin)\s*(?:axis|x_3)"),
    "angular momentum": ("letter", r"angular momentum"),
    "body angular velocity": ("symbol", r"body angular velocity|angular velocity (?:resolved|expressed) in the body(?: frame)?"),
    "angular velocity": ("letter", r"angular velocit(?:y|ies)"),
    "turn rate": ("symbol", r"(?<!spins )(?<!spinning )(?<!precesses )(?<!precessing )\bat (?:the|a) rate\s*§\s*(?:about|around)\b"),
    "force": ("letter", r"\btension\b|\bthrust\b|normal (?:force|reaction)|force (?:of|in) the (?:string|rope|cable|thread)"),
    "torque": ("letter", r"torques?\b|moment of (?:the )?(?:external )?forces|\bthe (?:total |external )?moment\b(?! of inertia)|\b(?:gyroscopic|applied|restoring|precessing|driving|resultant|net) (?:moment|couple)s?\b(?! of inertia)"),
    "transverse moment": ("symbol", r"(?:transverse|perpendicular|equatorial|(?<!un)equal) moment|moment of inertia "
                                    r"(?:about|around) (?:either|any|each) of the (?:two )?(?:other|transverse|perpendicular|equatorial)"
                                    r"[\w ,]{0,24}?\bax[ie]s\b"),
    "axial moment": ("symbol", r"(?:axial|symmetry[- ]axis|polar) moment|moment of inertia (?:about|around) (?:the|its) "
                               r"(?:(?:symmetry|figure) axis|axis of (?:symmetry|the figure))"),
    "principal moments": ("list", r"principal moments(?: of inertia)?"),
    "vertical": ("letter", r"(?:unit vector|direction cosines?)\W{0,4}(?:[¤§]\W{0,4})?(?:of|along) the (?:upward |fixed |space "
                           r"|inertial )?vertical|(?:upward |fixed )?vertical unit vector"),
    "body rates": ("rates", r"roll,?\s+pitch,?\s+and\s+yaw\s+rates?|roll\s+rate,\s+pitch\s+rate,?\s+and\s+yaw\s+rate"),
    "roll rate": ("symbol", r"\broll(?:ing)?[- ]rate"),
    "pitch rate": ("symbol", r"\bpitch(?:ing)?[- ]rate"),
    "yaw rate": ("symbol", r"\byaw(?:ing)?[- ]rate"),
    "centre-of-mass distance": ("symbol", r"(?:distance|length|height)\b[^.;$]{0,60}(?:centre|center) of (?:mass|gravity)|(?:centre|center) of (?:mass|gravity)[^.;$]{0,40}(?:distance|from the (?:pivot|support|fixed point|origin|tip))"),
    "kinetic energy": ("symbol", r"kinetic energy"),
    "effective potential": ("symbol", r"effective potential"),
    "lagrangian": ("symbol", r"[Ll]agrangian"),
    "energy": ("symbol", r"\benergy"),
    "gravitational acceleration": ("symbol", r"(?:acceleration of|acceleration due to) gravity|gravitational acceleration"),
    "mass": ("symbol", r"(?<!of )(?<!of the )\bmass(?! ?(?:distribution|element|centre|center|density))"),
    "identity column": ("letter", r"the\s+\S+\s+columns? of the\s+(?:\S+\s+)?identity(?: matrix)?"),
    "second moment": ("symbol", r"(?!x)x"),          # I₂, bound only through "principal moments"
    "centre-of-mass coordinates": ("coords", r"(?:centre|center) of (?:mass|gravity)\b[^.;]{0,60}?coordinates"),
    "centre-of-mass coordinate 1": ("symbol", r"(?!x)x"),    # bound only through the coordinates' list
    "centre-of-mass coordinate 2": ("symbol", r"(?!x)x"),
    "centre-of-mass coordinate 3": ("symbol", r"(?!x)x"),
    "potential energy": ("symbol", r"potential(?: energy)?"),
}
"""The meanings a text may give its symbols: how each binds and the phrase that gives it."""

LETTERS = {
    "angular momentum": ("L", "M", "J", "H", "h", "Pi"), "angular velocity": ("omega", "Omega", "w", "W"),
    "torque": ("tau", "N", "T", "M", "G", "Gamma", "K"), "force": ("T", "F", "N"), "turn rate": ("omega", "Omega", "w", "W"), "mass": ("m", "M", "mu"),
    "centre-of-mass distance": ("l", "a", "h", "d", "s", "ell", "b", "R", "r"), "gravitational acceleration": ("g",),
    "kinetic energy": ("T", "K"), "energy": ("E", "H", "W"), "lagrangian": ("L",),
    "effective potential": ("V", "U"), "vertical angular momentum": ("L", "M", "J", "p"),
    "axial angular momentum": ("L", "M", "J", "p"), "potential energy": ("V", "U"),
    "identity column": ("I", "e", "E", "u", "1"), "body angular velocity": ("omega", "Omega", "w"),
    "roll rate": ("p", "P"), "pitch rate": ("q", "Q"), "yaw rate": ("r", "R"), "vertical": ("gamma", "n", "nu"),
    **gyro_names.LETTERS}
"""The letters a reader takes for each meaning: a phrase next to any other letter is about
something else (a point C, a matrix S), so it binds nothing."""

ALIASES = {"L": "angular momentum", "M": "angular momentum", "angular momentum body": "angular momentum",
           "omega": "angular velocity", "angular velocity body": "angular velocity",
           "l": "centre-of-mass distance", "distance": "centre-of-mass distance", "I_1": "transverse moment",
           "I1": "transverse moment", "I_3": "axial moment", "I3": "axial moment", "g": "gravitational acceleration",
           "T": "kinetic energy", "E": "energy", "V_eff": "effective potential", "p_alpha": "vertical angular momentum",
           "p_gamma": "axial angular momentum", "tau": "torque"}
"""Other spellings a front matter may use for a meaning (``a: l``, ``I_\\perp: I_1``)."""
