"""The notes' formulas typed by hand from the slides (independent of the generator).

Each function takes a math namespace ``m`` (numpy or mpmath) so the same text evaluates in
double precision or at high precision as a reference. Heavy-top accelerations are the textbook
Euler–Lagrange equations of L = ½I₁(α̇² sin²β + β̇²) + ½I₃(α̇ cos β + γ̇)² − Mgl cos β,
worked out by hand.
"""


def omega(m, a, b, g, ad, bd, gd):
    """ω̃₁ = α̇(−sinβ cosγ) + β̇ sinγ; ω̃₂ = α̇ sinβ sinγ + β̇ cosγ; ω̃₃ = α̇ cosβ + γ̇."""
    return (ad * (-m.sin(b) * m.cos(g)) + bd * m.sin(g),
            ad * (m.sin(b) * m.sin(g)) + bd * m.cos(g),
            ad * m.cos(b) + gd)


def kinetic_symmetric(m, b, ad, bd, gd, I1, I3):
    """T = ½ I₁(α̇² sin²β + β̇²) + ½ I₃[α̇ cosβ + γ̇]²."""
    return I1 * (ad**2 * m.sin(b) ** 2 + bd**2) / 2 + I3 * (ad * m.cos(b) + gd) ** 2 / 2


def p_gamma(m, b, ad, gd, I3):
    """p_γ = I₃[α̇ cosβ + γ̇]."""
    return I3 * (ad * m.cos(b) + gd)


def p_alpha(m, b, ad, gd, I1, I3):
    """p_α = I₁ α̇ sin²β + I₃[α̇ cosβ + γ̇] cosβ."""
    return I1 * ad * m.sin(b) ** 2 + I3 * (ad * m.cos(b) + gd) * m.cos(b)


def energy_lagrangian(m, b, ad, bd, gd, I1, I3, M, g, l):
    """E = T + Mgl cosβ."""
    return kinetic_symmetric(m, b, ad, bd, gd, I1, I3) + M * g * l * m.cos(b)


def v_eff(m, b, pa, pg, I1, M, g, l):
    """V_eff(β) = (p_α − p_γ cosβ)²/(2I₁ sin²β) + Mgl cosβ."""
    return (pa - pg * m.cos(b)) ** 2 / (2 * I1 * m.sin(b) ** 2) + M * g * l * m.cos(b)


def energy_momenta(m, b, bd, pa, pg, I1, I3, M, g, l):
    """E = ½I₁β̇² + p_γ²/(2I₃) + V_eff(β)."""
    return I1 * bd**2 / 2 + pg**2 / (2 * I3) + v_eff(m, b, pa, pg, I1, M, g, l)


def euler_free(m, w1, w2, w3, I1, I2, I3):
    """I₁ω̇₁ + ω₂ω₃(I₃ − I₂) = 0 and cyclic."""
    return (-w2 * w3 * (I3 - I2) / I1, -w3 * w1 * (I1 - I3) / I2, -w1 * w2 * (I2 - I1) / I3)


def heavy_top_accel(m, b, ad, bd, gd, I1, I3, M, g, l):
    """(α̈, β̈, γ̈): ω₃ = α̇ cosβ + γ̇ is constant, d/dt p_α = 0 and the β equation."""
    s, c = m.sin(b), m.cos(b)
    w3 = ad * c + gd
    add = bd * (I3 * w3 - 2 * I1 * ad * c) / (I1 * s)
    bdd = (I1 * ad**2 * s * c - I3 * w3 * ad * s + M * g * l * s) / I1
    gdd = -add * c + ad * bd * s
    return add, bdd, gdd


def reduced_rates(m, b, pa, pg, I1, I3, M, g, l):
    """(α̇, γ̇, β̈) of the reduced top from the momenta: α̇ = (p_α − p_γ cosβ)/(I₁ sin²β),
    γ̇ = p_γ/I₃ − α̇ cosβ, I₁β̈ = −V_eff′(β)."""
    s, c = m.sin(b), m.cos(b)
    A = pa - pg * c
    ad = A / (I1 * s**2)
    gd = pg / I3 - ad * c
    dV = A * pg / (I1 * s) - A**2 * c / (I1 * s**3) - M * g * l * s
    return ad, gd, -dV / I1
