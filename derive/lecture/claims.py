"""The lecture's formulas, typed by hand as written on the slides: the thing being *checked*.

Source: PHY 711 Lecture 26 (Fall 2022, Fetter & Walecka ch. 5), a machine transcript of the
slides (the course's notes file; the tests quote it when it is at hand). Every formula on the
slides is one `Claim` below, with

* ``section`` and ``quote`` — where it is: the slide title and a short verbatim piece of the line
  (both are searched for in the notes file by the tests, so they cannot drift);
* ``latex`` — the LaTeX exactly as in the transcript (one string per display line used);
* ``expr`` — the same formula as a sympy expression, typed from the slide, slips and all;
* ``target`` — the name of the derived quantity it claims to equal (see `derive.lecture.targets.DERIVED`);
* ``correction`` — where the slide has an evident slip, the corrected form (and what it equals).

Nothing in the package computes *with* these expressions; `derive.lecture.verify` compares each one with
the result derived independently in `rotations`, `inertia`, `lagrangian` and `stability`.

Notation used in the typing:

* vectors written on the slides as sums over unit vectors (ω̃₁ ê₁ + …) are typed as linear forms
  in basis *symbols*: ``e1 e2 e3`` (body), ``e1' e2' e3'`` (the frame after the α and β turns),
  ``e3^0`` (inertial z). `derive.lecture.verify` expresses the primed and inertial ones in the body basis;
  anything that is not a basis symbol (the transcript's "ẽ₃") stays a plain scalar;
* column vectors and matrices on the slides are sympy matrices;
* Σ_p over particles is typed for two particles with symbolic masses and positions: every line
  is a sum of identical per-particle terms, so two generic particles test both the per-particle
  identity and the sum;
* ``given`` records what a symbol stands for on the slides (Ω ≡ …, V_eff(β) = …, p_γ = …), either
  a slide formula or a derived quantity (`Derived`), substituted into the claim before checking;
* ``cases`` records the slide's hypotheses (I₂ = I₁; "Ω₁ and Ω₂ both positive or both negative"),
  substituted into both sides; a claim holds only if it holds in every case.

The symbols, slide definitions and the `Claim` records are in `derive.lecture.slides`.

`EXPECTED` pins the verdict of every claim; `derive verify` exits non-zero when a computed
verdict differs from it (the tests pin the same table).
"""
from __future__ import annotations

import sympy as sp

from derive.lecture.slides import (
    A, ASSIGNMENT_ANGLES, Claim, Correction, DUP_NOTE, Derived, Lb, Lbd, OMEGA_SYM_CASE,
    OPPOSITE_SIGN_CASES, Omega, Omega1, Omega2, ROOT, SAME_SIGN_CASES, SLIDE_I, SLIDE_L_BETA,
    SLIDE_OMEGA, SLIDE_OMEGA1, SLIDE_OMEGA2, SLIDE_PASSIVE, SLIDE_VEFF, SYM_SOLUTION, S_ANGLES,
    S_ASSIGN, S_ASYM, S_ASYM2, S_CONST, S_CONTINUED, S_DESCR, S_EULER, S_INERTIA, S_STAB,
    S_SUMMARY, S_SYM, S_SYM2, S_T, S_TOP, S_TORQUE, Veff, Vx, Vy, Vz, W0, X, c, dot, e1, e1p,
    e2, e2p, e3, e30, e3p, etilde3, half, phi, psum, s, slide_Ry, slide_Rz, t, w1, w2, w3,
    w_vec, wd1, wd2, wd3,
)
from derive.symbolic.lagrangian import E, I1, I2, I3, Mass, g, l, p_alpha, p_gamma
from derive.symbolic.rotations import alpha, alpha_d, beta, beta_d, gamma, gamma_d

CLAIMS: tuple[Claim, ...] = (
    # ---- summary of previous results -----------------------------------------------------------
    Claim(
        "velocity", S_SUMMARY, r"\left(\frac{d\mathbf{r}}{dt}\right)_{inertial} = \mathbf{\omega} \times \mathbf{r}",
        (r"\left(\frac{d\mathbf{r}}{dt}\right)_{inertial} = \mathbf{\omega} \times \mathbf{r}",),
        sp.Matrix(W0).cross(sp.Matrix(X)), "velocity",
        note="a point fixed in the body: dr/dt = Ṙ Rᵀ r, with ω = R ω̃ (skew route); repeated on the next summary slide",
        given={W0[i]: Derived("omega-inertial", i) for i in range(3)},
    ),
    Claim(
        "T-sum", S_SUMMARY, r"\left( \left| \mathbf{\omega} \times \mathbf{r}_p \right| \right)^2",
        (r"T = \sum_{p} \frac{1}{2} m_p v_p^2 = \sum_{p} \frac{1}{2} m_p \left( \left| \mathbf{\omega} \times \mathbf{r}_p \right| \right)^2",),
        psum(lambda m, r: half * m * w_vec.cross(r).norm() ** 2), "T-particles",
    ),
    Claim(
        "T-dot", S_SUMMARY, r"\left( \mathbf{\omega} \times \mathbf{r}_p \right) \cdot \left( \mathbf{\omega} \times \mathbf{r}_p \right)",
        (r"= \sum_{p} \frac{1}{2} m_p \left( \mathbf{\omega} \times \mathbf{r}_p \right) \cdot \left( \mathbf{\omega} \times \mathbf{r}_p \right)",),
        psum(lambda m, r: half * m * dot(w_vec.cross(r), w_vec.cross(r))), "T-particles",
    ),
    Claim(
        "T-expanded", S_SUMMARY, r"(\boldsymbol{\omega} \cdot \boldsymbol{\omega}) (\mathbf{r}_{p} \cdot \mathbf{r}_{p})",
        (r"= \sum_{p} \frac{1}{2} m_{p} \left[ (\boldsymbol{\omega} \cdot \boldsymbol{\omega}) (\mathbf{r}_{p} \cdot \mathbf{r}_{p}) - (\mathbf{r}_{p} \cdot \boldsymbol{\omega})^{2} \right]",),
        psum(lambda m, r: half * m * (dot(w_vec, w_vec) * dot(r, r) - dot(r, w_vec) ** 2)), "T-particles",
    ),
    Claim(
        "T-tensor", S_SUMMARY, r"= \frac{1}{2} \boldsymbol{\omega} \cdot \mathbf{\ddot{I}} \cdot \boldsymbol{\omega}",
        (r"= \frac{1}{2} \boldsymbol{\omega} \cdot \mathbf{\ddot{I}} \cdot \boldsymbol{\omega}",),
        half * dot(w_vec, SLIDE_I * w_vec), "T-particles",
        note="Ï as defined on the slides; the transcript repeats this line three times",
    ),
    Claim(
        "inertia-tensor", S_INERTIA, r"I_{ij} \equiv \sum_{p} m_{p} \left( \delta_{ij} r_{p}^{2} - r_{pi} r_{pj} \right)",
        (r"I_{ij} \equiv \sum_{p} m_{p} \left( \delta_{ij} r_{p}^{2} - r_{pi} r_{pj} \right)",),
        sp.Matrix(3, 3, lambda i, j: psum(lambda m, r: m * ((1 if i == j else 0) * dot(r, r) - r[i] * r[j]))),
        "inertia-particles",
    ),
    Claim(
        "T-general", S_INERTIA, r"T = \frac{1}{2} \sum_{ij} I_{ij} \omega_i \omega_j",
        (r"T = \frac{1}{2} \sum_{ij} I_{ij} \omega_i \omega_j",),
        half * sum(SLIDE_I[i, j] * w_vec[i] * w_vec[j] for i in range(3) for j in range(3)), "T-particles",
    ),
    Claim(
        "principal-axes", S_INERTIA, r"\vec{\mathbf{I}} \cdot \hat{\mathbf{e}}_i = I_i \hat{\mathbf{e}}_i",
        (r"\vec{\mathbf{I}} \cdot \hat{\mathbf{e}}_i = I_i \hat{\mathbf{e}}_i",),
        sp.Matrix.hstack(*(Ii * sp.eye(3)[:, i] for i, Ii in enumerate((I1, I2, I3)))), "inertia-body-frame",
        note="columns: I_i ê_i in body components; the body frame is principal by definition, so this checks consistency with the core's diag(I₁, I₂, I₃)",
    ),
    Claim(
        "T-principal", S_INERTIA, r"\Rightarrow T = \frac{1}{2} \sum_i I_i \tilde{\omega}_i^2",
        (r"\Rightarrow T = \frac{1}{2} \sum_i I_i \tilde{\omega}_i^2",),
        half * (I1 * w1**2 + I2 * w2**2 + I3 * w3**2), "T-body",
    ),
    Claim(
        "L-sum", S_CONTINUED, r"\mathbf{r}_{p} \times (\boldsymbol{\omega} \times \mathbf{r}_{p})",
        (r"\mathbf{L} = \sum_{p} m_{p} \mathbf{r}_{p} \times \mathbf{v}_{p} = \sum_{p} m_{p} \mathbf{r}_{p} \times (\boldsymbol{\omega} \times \mathbf{r}_{p})",),
        psum(lambda m, r: m * r.cross(w_vec.cross(r))), "L-particles",
    ),
    Claim(
        "L-expanded", S_CONTINUED, r"\mathbf{\omega} \left( \mathbf{r}_{p} \cdot \mathbf{r}_{p} \right) - \mathbf{r}_{p}",
        (r"\mathbf{L} = \sum_{p} m_{p} \left[ \mathbf{\omega} \left( \mathbf{r}_{p} \cdot \mathbf{r}_{p} \right) - \mathbf{r}_{p} \left( \mathbf{r}_{p} \cdot \mathbf{\omega} \right) \right]",),
        psum(lambda m, r: m * (w_vec * dot(r, r) - r * dot(r, w_vec))), "L-particles",
    ),
    Claim(
        "L-tensor", S_CONTINUED, r"L = \ddot{I} \cdot \omega", (r"L = \ddot{I} \cdot \omega",),
        SLIDE_I * w_vec, "L-particles",
    ),
    Claim(
        "inertia-dyadic", S_CONTINUED, r"\mathbf{1} r_{p}^{2} - \mathbf{r}_{p} \mathbf{r}_{p}",
        (r"\ddot{\mathbf{I}} \equiv \sum_{p} m_{p} \left( \mathbf{1} r_{p}^{2} - \mathbf{r}_{p} \mathbf{r}_{p} \right)",),
        psum(lambda m, r: m * (sp.eye(3) * dot(r, r) - r * r.T)), "inertia-particles",
    ),
    # ---- angular momentum in the body frame, Euler's equations ---------------------------------
    Claim(
        "L-principal", S_DESCR, r"\mathbf{L} = I_{1}\tilde{\omega}_{1}\hat{\mathbf{e}}_{1}",
        (r"\mathbf{L} = I_{1}\tilde{\omega}_{1}\hat{\mathbf{e}}_{1} + I_{2}\tilde{\omega}_{2}\hat{\mathbf{e}}_{2} + I_{3}\tilde{\omega}_{3}\hat{\mathbf{e}}_{3}",),
        I1 * w1 * e1 + I2 * w2 * e2 + I3 * w3 * e3, "L-body",
        note="repeated on the symmetric-top slide",
    ),
    Claim(
        "dLdt-transport", S_DESCR, r"\left(\frac{d\mathbf{L}}{dt}\right)_{body} + \mathbf{\omega} \times \mathbf{L}$$",
        (r"\frac{d\mathbf{L}}{dt} = \left(\frac{d\mathbf{L}}{dt}\right)_{body} + \mathbf{\omega} \times \mathbf{L}",),
        sp.Matrix(Lbd) + w_vec.cross(sp.Matrix(Lb)), "dLdt-transport",
        note="body components of the inertial dL/dt: Rᵀ d(R L̃)/dt with ω̃ from the skew route; repeated (= τ) on the next slide",
        given={(w1, w2, w3)[i]: Derived("omega-body", i) for i in range(3)},
    ),
    Claim(
        "dLdt-body", S_DESCR, r"\tilde{\omega}_{2}\tilde{\mathbf{e}}_{3} + I_{2}\dot{\tilde{\omega}}_{2}",
        (r"\frac{d\mathbf{L}}{dt} = I_{1}\dot{\tilde{\omega}}_{1}\hat{\mathbf{e}}_{1} + I_{2}\dot{\tilde{\omega}}_{2}\hat{\mathbf{e}}_{2} + I_{3}\dot{\tilde{\omega}}_{3}\hat{\mathbf{e}}_{3} + \tilde{\omega}_{2}\tilde{\mathbf{e}}_{3} + I_{2}\dot{\tilde{\omega}}_{2}\hat{\mathbf{e}}_{2} + I_{3}\dot{\tilde{\omega}}_{3}\hat{\mathbf{e}}_{3} + \tilde{\omega}_{2}\tilde{\mathbf{e}}_{3}(I_{3} - I_{2})\hat{\mathbf{e}}_{1} + \tilde{\omega}_{3}\tilde{\omega}_{1}(I_{1} - I_{3})\hat{\mathbf{e}}_{2} + \tilde{\omega}_{1}\tilde{\omega}_{2}(I_{2} - I_{1})\hat{\mathbf{e}}_{3}",),
        (I1 * wd1 * e1 + I2 * wd2 * e2 + I3 * wd3 * e3 + w2 * etilde3 + I2 * wd2 * e2 + I3 * wd3 * e3
         + w2 * etilde3 * (I3 - I2) * e1 + w3 * w1 * (I1 - I3) * e2 + w1 * w2 * (I2 - I1) * e3),
        "dLdt-body",
        note="transcription garble: the terms I₂ω̇₂ê₂ + I₃ω̇₃ê₃ are repeated, a stray '+ ω̃₂ẽ₃' is inserted, and ω̃₂ω̃₃ reads 'ω̃₂ẽ₃'",
        correction=Correction(
            r"\frac{d\mathbf{L}}{dt} = \sum_i I_i\dot{\tilde\omega}_i\hat{\mathbf{e}}_i + \tilde\omega_2\tilde\omega_3(I_3-I_2)\hat{\mathbf{e}}_1 + \tilde\omega_3\tilde\omega_1(I_1-I_3)\hat{\mathbf{e}}_2 + \tilde\omega_1\tilde\omega_2(I_2-I_1)\hat{\mathbf{e}}_3",
            expr=(I1 * wd1 * e1 + I2 * wd2 * e2 + I3 * wd3 * e3 + w2 * w3 * (I3 - I2) * e1
                  + w3 * w1 * (I1 - I3) * e2 + w1 * w2 * (I2 - I1) * e3),
        ),
    ),
    Claim(
        "euler-vector", S_TORQUE, r"&= 0 = I_1 \dot{\tilde{\omega}}_1 \hat{\mathbf{e}}_1",
        (r"I_1 \dot{\tilde{\omega}}_1 \hat{\mathbf{e}}_1 + I_2 \dot{\tilde{\omega}}_2 \hat{\mathbf{e}}_2 + I_3 \dot{\tilde{\omega}}_3 \hat{\mathbf{e}}_3 + \\ & \tilde{\omega}_2 \tilde{\omega}_3 \left( I_3 - I_2 \right) \hat{\mathbf{e}}_1 + \tilde{\omega}_3 \tilde{\omega}_1 \left( I_1 - I_3 \right) \hat{\mathbf{e}}_2 + \tilde{\omega}_1 \tilde{\omega}_2 \left( I_2 - I_1 \right) \hat{\mathbf{e}}_3",),
        (I1 * wd1 * e1 + I2 * wd2 * e2 + I3 * wd3 * e3 + w2 * w3 * (I3 - I2) * e1
         + w3 * w1 * (I1 - I3) * e2 + w1 * w2 * (I2 - I1) * e3),
        "dLdt-body",
    ),
    Claim(
        "euler-3-duplicated", S_TORQUE, r"\left( I_1 - I_3 \right) = 0 \end{aligned}",
        (r"\\ & I_2 \dot{\tilde{\omega}}_2 + \tilde{\omega}_3 \tilde{\omega}_1 \left( I_1 - I_3 \right) = 0 \end{aligned}",),
        I2 * wd2 + w3 * w1 * (I1 - I3), "euler-residual-3",
        note="the aligned block lists the second equation twice, the duplicate standing where the third belongs (transcription); the third follows as its own display",
        correction=Correction(r"I_3\dot{\tilde\omega}_3 + \tilde\omega_1\tilde\omega_2(I_2 - I_1) = 0",
                              expr=I3 * wd3 + w1 * w2 * (I2 - I1)),
    ),
    Claim(
        "euler-1", S_EULER, r"I_1\dot{\widetilde{\omega}}_1 + \widetilde{\omega}_2\widetilde{\omega}_3(I_3 - I_2) = 0",
        (r"I_1\dot{\widetilde{\omega}}_1 + \widetilde{\omega}_2\widetilde{\omega}_3(I_3 - I_2) = 0",),
        I1 * wd1 + w2 * w3 * (I3 - I2), "euler-residual-1",
        note="left-hand side of '= 0' against I ω̇ − (Iω)×ω from stability.euler_rhs; repeated on four slides",
    ),
    Claim(
        "euler-2", S_EULER, r"I_2\dot{\widetilde{\omega}}_2 + \widetilde{\omega}_3\widetilde{\omega}_1(I_1 - I_3) = 0",
        (r"I_2\dot{\widetilde{\omega}}_2 + \widetilde{\omega}_3\widetilde{\omega}_1(I_1 - I_3) = 0",),
        I2 * wd2 + w3 * w1 * (I1 - I3), "euler-residual-2",
    ),
    Claim(
        "euler-3", S_EULER, r"I_3\dot{\widetilde{\omega}}_3 + \widetilde{\omega}_1\widetilde{\omega}_2(I_2 - I_1) = 0",
        (r"I_3\dot{\widetilde{\omega}}_3 + \widetilde{\omega}_1\widetilde{\omega}_2(I_2 - I_1) = 0",),
        I3 * wd3 + w1 * w2 * (I2 - I1), "euler-residual-3",
    ),
    # ---- symmetric top -------------------------------------------------------------------------
    Claim(
        "symmetric-euler-1", S_SYM, r"\widetilde{\omega}_2 \widetilde{\omega}_3 (I_3 - I_1) = 0",
        (r"I_1 \dot{\widetilde{\omega}}_1 + \widetilde{\omega}_2 \widetilde{\omega}_3 (I_3 - I_1) = 0",),
        I1 * wd1 + w2 * w3 * (I3 - I1), "euler-residual-1", cases=(OMEGA_SYM_CASE,),
    ),
    Claim(
        "symmetric-euler-2", S_SYM, r"I_1 \dot{\widetilde{\omega}}_2 + \widetilde{\omega}_3 \widetilde{\omega}_1 (I_1 - I_3) = 0",
        (r"I_1 \dot{\widetilde{\omega}}_2 + \widetilde{\omega}_3 \widetilde{\omega}_1 (I_1 - I_3) = 0",),
        I1 * wd2 + w3 * w1 * (I1 - I3), "euler-residual-2", cases=(OMEGA_SYM_CASE,),
    ),
    Claim(
        "symmetric-euler-3", S_SYM, r"I_3 \dot{\widetilde{\omega}}_3 = 0",
        (r"I_3 \dot{\widetilde{\omega}}_3 = 0 \qquad \Rightarrow \widetilde{\omega}_3 = (\text{constant})",),
        I3 * wd3, "euler-residual-3", cases=(OMEGA_SYM_CASE,),
    ),
    Claim(
        "symmetric-Omega", S_SYM, r"\Omega \equiv \widetilde{\omega}_3 \frac{I_3 - I_1}{I_1}",
        (r"\Omega \equiv \widetilde{\omega}_3 \frac{I_3 - I_1}{I_1}",),
        sp.Matrix([SLIDE_OMEGA, SLIDE_OMEGA]), "symmetric-frequencies",
        note="one Ω serves both equations: (Ω, Ω) against the two frequencies of SteadySpin(axis 3) with I₂ = I₁; repeated on the next slide",
    ),
    Claim(
        "symmetric-omega1-dot", S_SYM, r"\dot{\widetilde{\omega}}_1 = -\widetilde{\omega}_2 \Omega",
        (r"\dot{\widetilde{\omega}}_1 = -\widetilde{\omega}_2 \Omega",),
        -w2 * Omega, "euler-rhs-symmetric-1", given={Omega: SLIDE_OMEGA}, note=DUP_NOTE + " (three times)",
    ),
    Claim(
        "symmetric-omega2-dot", S_SYM, r"\dot{\widetilde{\omega}}_2 = \widetilde{\omega}_1 \Omega",
        (r"\dot{\widetilde{\omega}}_2 = \widetilde{\omega}_1 \Omega",),
        w1 * Omega, "euler-rhs-symmetric-2", given={Omega: SLIDE_OMEGA},
    ),
    Claim(
        "symmetric-solution", S_SYM2, r"A\cos(\Omega t + \varphi)",
        (r"\widetilde{\omega}_1(t) = A\cos(\Omega t + \varphi)", r"\widetilde{\omega}_2(t) = A\sin(\Omega t + \varphi)"),
        sp.Matrix([A * c(Omega * t + phi), A * s(Omega * t + phi)]), "euler-rhs-symmetric",
        given={Omega: SLIDE_OMEGA}, mode="solves", states=(w1, w2), time=t,
        note="substituted into ω̃̇ = f(ω̃) (derived: f from stability.euler_rhs, I₂ = I₁)",
    ),
    Claim(
        "symmetric-T", S_SYM2, r"\frac{1}{2} I_{1} A^{2} + \frac{1}{2} I_{3} \widetilde{\omega}_{3}^{2}",
        (r"T = \frac{1}{2} \sum_{i} I_{i} \widetilde{\omega}_{i}^{2} = \frac{1}{2} I_{1} A^{2} + \frac{1}{2} I_{3} \widetilde{\omega}_{3}^{2}",),
        half * I1 * A**2 + half * I3 * w3**2, "T-body", cases=({I2: I1, **SYM_SOLUTION},),
        note="derived T = ½ ω̃ᵀ I ω̃ on the solution, I₂ = I₁",
    ),
    Claim(
        "symmetric-L", S_SYM2, r"= I_1 A (\cos(\Omega t + \varphi) \hat{\mathbf{e}}_1",
        (r"= I_1 A (\cos(\Omega t + \varphi) \hat{\mathbf{e}}_1 + \sin(\Omega t + \varphi) \hat{\mathbf{e}}_2) + I_3 \widetilde{\omega}_3 \hat{\mathbf{e}}_3",),
        I1 * A * (c(Omega * t + phi) * e1 + s(Omega * t + phi) * e2) + I3 * w3 * e3, "L-body",
        cases=({I2: I1, **SYM_SOLUTION},),
    ),
    # ---- asymmetric top ------------------------------------------------------------------------
    Claim(
        "asym-omega3-dot", S_ASYM, r"\dot{\widetilde{\omega}}_3 \approx 0",
        (r"\dot{\widetilde{\omega}}_3 \approx 0",),
        sp.S.Zero, "asym-omega3-dot",
        note="to first order about spin ω̃₃ ê₃: ω̃̇₃ = ω̃₁ω̃₂(I₁ − I₂)/I₃ is second order; repeated four times",
    ),
    Claim(
        "asym-Omega1", S_ASYM, r"$\Omega_1 \equiv \widetilde{\omega}_3 \frac{I_3 - I_2}{I_1}$",
        (r"\Omega_1 \equiv \widetilde{\omega}_3 \frac{I_3 - I_2}{I_1}",),
        SLIDE_OMEGA1, "asym-Omega1", note="against Ω₁ of SteadySpin(axis 3).frequencies; repeated",
    ),
    Claim(
        "asym-Omega2", S_ASYM, r"\Omega_2 \equiv \widetilde{\omega}_3 \frac{I_3 - I_1}{I_2}",
        (r"\Omega_2 \equiv \widetilde{\omega}_3 \frac{I_3 - I_1}{I_2}",),
        SLIDE_OMEGA2, "asym-Omega2", note="repeated three times",
    ),
    Claim(
        "asym-linear", S_ASYM2, r"= -\Omega_{1}\widetilde{\omega}_{2}",
        (r"\dot{\widetilde{\omega}}_{1} = -\Omega_{1}\widetilde{\omega}_{2} \qquad \qquad \dot{\widetilde{\omega}}_{2} = \Omega_{2}\widetilde{\omega}_{1}",),
        sp.Matrix([-Omega1 * w2, Omega2 * w1]), "asym-linear",
        given={Omega1: SLIDE_OMEGA1, Omega2: SLIDE_OMEGA2},
        note="against the Jacobian of Euler's equations at ω̃ = ω̃₃ ê₃ (small ω̃₁, ω̃₂)",
    ),
    Claim(
        "asym-solution", S_ASYM2, r"A \sqrt{\frac{\Omega_2}{\Omega_1}}",
        (r"\widetilde{\omega}_1(t) \approx A \cos\left(\sqrt{\Omega_1 \Omega_2} t + \varphi\right)",
         r"\widetilde{\omega}_2(t) \approx A \sqrt{\frac{\Omega_2}{\Omega_1}} \sin(\sqrt{\Omega_1 \Omega_2} t + \varphi)"),
        sp.Matrix([A * c(ROOT * t + phi), A * sp.sqrt(Omega2 / Omega1) * s(ROOT * t + phi)]), "asym-linear-system",
        mode="solves", states=(w1, w2), time=t, cases=SAME_SIGN_CASES,
        note="substituted into the linear system (derived right-hand side); holds for Ω₁, Ω₂ > 0; for both negative ω̃̇₁ = −Ω₁ω̃₂ forces ω̃₂ = A√(Ω₁Ω₂)/Ω₁ sin(…) = −A√(Ω₂/Ω₁) sin(…)",
        correction=Correction(
            r"\tilde\omega_2(t) \approx A\,\frac{\sqrt{\Omega_1\Omega_2}}{\Omega_1}\sin(\sqrt{\Omega_1\Omega_2}\,t + \varphi)",
            expr=sp.Matrix([A * c(ROOT * t + phi), A * ROOT / Omega1 * s(ROOT * t + phi)]),
        ),
    ),
    Claim(
        "asym-oscillation", S_ASYM2, r"are both positive or both negative:",
        (r"If  $\Omega_1$  and  $\Omega_2$  are both positive or both negative:",),
        sp.Integer(-1), "asym-lambda-squared", cases=SAME_SIGN_CASES, mode="sign",
        note="oscillation ⇔ the eigenvalues ±λ of the linear system have λ² < 0",
    ),
    Claim(
        "asym-instability", S_ASYM2, r"have opposite signs, solution is unstable.",
        (r"If  $\Omega_1$  and  $\Omega_2$  have opposite signs, solution is unstable.",),
        sp.Integer(1), "asym-lambda-squared", cases=OPPOSITE_SIGN_CASES, mode="sign",
        note="instability ⇔ a real eigenvalue λ > 0, i.e. λ² > 0: growth rate √(−Ω₁Ω₂)",
    ),
    # ---- Euler angles --------------------------------------------------------------------------
    Claim(
        "omega-tilde-sum", S_ANGLES, r"\dot{\alpha} \; \hat{\mathbf{e}}_3^0 + \dot{\beta} \; \hat{\mathbf{e}}_2'",
        (r"\widetilde{\mathbf{\omega}} = \dot{\alpha} \; \hat{\mathbf{e}}_3^0 + \dot{\beta} \; \hat{\mathbf{e}}_2' + \dot{\gamma} \; \hat{\mathbf{e}}_3",),
        alpha_d * e30 + beta_d * e2p + gamma_d * e3, "omega-body-linear",
        note="the notes' sum route against the skew route Rᵀ Ṙ; repeated on six slides",
    ),
    Claim(
        "e2prime-expansion", S_ANGLES, r"\hat{\mathbf{e}}_2' = \sin \gamma \ \hat{\mathbf{e}}_1 + \cos \gamma \ \hat{\mathbf{e}}_2",
        (r"\hat{\mathbf{e}}_2' = \sin \gamma \ \hat{\mathbf{e}}_1 + \cos \gamma \ \hat{\mathbf{e}}_2",),
        s(gamma) * e1 + c(gamma) * e2, "e2prime-linear",
    ),
    Claim(
        "e2prime-matrix", S_ANGLES, r"\begin{pmatrix} 0 \\ 1 \\ 0 \end{pmatrix} = \begin{pmatrix} \sin \gamma \\ \cos \gamma \\ 0 \end{pmatrix}",
        (r"\hat{\mathbf{e}}_{2}' = \begin{pmatrix} \cos \gamma & \sin \gamma & 0 \\ -\sin \gamma & \cos \gamma & 0 \\ 0 & 0 & 1 \end{pmatrix} \begin{pmatrix} 0 \\ 1 \\ 0 \end{pmatrix}",),
        slide_Rz(gamma) * sp.Matrix([0, 1, 0]), "e2prime",
    ),
    Claim(
        "e2prime-column", S_ANGLES, r"= \begin{pmatrix} \sin \gamma \\ \cos \gamma \\ 0 \end{pmatrix}",
        (r"= \begin{pmatrix} \sin \gamma \\ \cos \gamma \\ 0 \end{pmatrix}",),
        sp.Matrix([s(gamma), c(gamma), 0]), "e2prime",
    ),
    Claim(
        "e30-expansion-primed", S_ANGLES, r"\hat{\mathbf{e}}_{3}^{0} = -\sin\beta \,\,\hat{\mathbf{e}}_{1}'",
        (r"\hat{\mathbf{e}}_{3}^{0} = -\sin\beta \,\,\hat{\mathbf{e}}_{1}' + \cos\beta \,\,\hat{\mathbf{e}}_{3}'",),
        -s(beta) * e1p + c(beta) * e3p, "e30-linear",
    ),
    Claim(
        "e30-expansion-body", S_ANGLES, r"\cos\beta \,\,\hat{\mathbf{e}}_{3}'$$",
        (r"= -\cos\gamma\sin\beta \,\,\hat{\mathbf{e}}_{1} + \sin\gamma\sin\beta \,\,\hat{\mathbf{e}}_{2} + \cos\beta \,\,\hat{\mathbf{e}}_{3}'",),
        -c(gamma) * s(beta) * e1 + s(gamma) * s(beta) * e2 + c(beta) * e3p, "e30-linear",
        note="ends with ê₃′ where the body expansion has ê₃ — harmless: the γ turn is about ê₃′, so ê₃′ = ê₃",
    ),
    Claim(
        "e30-matrix", S_ANGLES, r"\mathbf{\hat{e}}_{3}^{0} = \begin{pmatrix} \cos \gamma",
        (r"\mathbf{\hat{e}}_{3}^{0} = \begin{pmatrix} \cos \gamma & \sin \gamma & 0 \\ -\sin \gamma & \cos \gamma & 0 \\ 0 & 0 & 1 \end{pmatrix} \begin{pmatrix} \cos \beta & 0 & -\sin \beta \\ 0 & 1 & 0 \\ \sin \beta & 0 & \cos \beta \end{pmatrix} \begin{pmatrix} 0 \\ 0 \\ 1 \end{pmatrix}",),
        slide_Rz(gamma) * slide_Ry(beta) * sp.Matrix([0, 0, 1]), "e30",
    ),
    Claim(
        "e30-mislabelled", S_ANGLES, r"\mathbf{\hat{e}}_{2}^{\prime} = \begin{pmatrix} -\sin \beta \cos \gamma",
        (r"\mathbf{\hat{e}}_{2}^{\prime} = \begin{pmatrix} -\sin \beta \cos \gamma \\ \sin \beta \sin \gamma \\ \cos \beta \end{pmatrix}",),
        sp.Matrix([-s(beta) * c(gamma), s(beta) * s(gamma), c(beta)]), "e2prime",
        note="the result of the ê₃⁰ matrix product, labelled ê₂′ (label typo)",
        correction=Correction(
            r"\hat{\mathbf{e}}_3^0 = \begin{pmatrix} -\sin\beta\cos\gamma \\ \sin\beta\sin\gamma \\ \cos\beta \end{pmatrix}",
            target="e30",
        ),
    ),
    Claim(
        "omega-tilde-columns", S_ANGLES, r"\widetilde{\boldsymbol{\omega}} = \dot{\alpha} \begin{pmatrix}",
        (r"\widetilde{\boldsymbol{\omega}} = \dot{\alpha} \begin{pmatrix} -\sin\beta\cos\gamma \\ \sin\beta\sin\gamma \\ \cos\beta \end{pmatrix} + \dot{\beta} \begin{pmatrix} \sin\gamma \\ \cos\gamma \\ 0 \end{pmatrix} + \dot{\gamma} \begin{pmatrix} 0 \\ 0 \\ 1 \end{pmatrix}",),
        (alpha_d * sp.Matrix([-s(beta) * c(gamma), s(beta) * s(gamma), c(beta)])
         + beta_d * sp.Matrix([s(gamma), c(gamma), 0]) + gamma_d * sp.Matrix([0, 0, 1])),
        "omega-body", note=DUP_NOTE,
    ),
    Claim(
        "omega-tilde-1", S_ANGLES, r"\widetilde{\omega}_1 = \dot{\alpha}(-\sin\beta\cos\gamma) + \dot{\beta}\sin\gamma",
        (r"\widetilde{\omega}_1 = \dot{\alpha}(-\sin\beta\cos\gamma) + \dot{\beta}\sin\gamma",),
        alpha_d * (-s(beta) * c(gamma)) + beta_d * s(gamma), "omega-body-1",
    ),
    Claim(
        "omega-tilde-2", S_ANGLES, r"\widetilde{\omega}_2 = \dot{\alpha}(\sin\beta\sin\gamma) + \dot{\beta}\cos\gamma",
        (r"\widetilde{\omega}_2 = \dot{\alpha}(\sin\beta\sin\gamma) + \dot{\beta}\cos\gamma",),
        alpha_d * (s(beta) * s(gamma)) + beta_d * c(gamma), "omega-body-2",
    ),
    Claim(
        "omega-tilde-3", S_ANGLES, r"\widetilde{\omega}_3 = \dot{\alpha} \cos \beta + \dot{\gamma}",
        (r"\widetilde{\omega}_3 = \dot{\alpha} \cos \beta + \dot{\gamma}",),
        alpha_d * c(beta) + gamma_d, "omega-body-3",
    ),
    Claim(
        "omega-tilde-expanded", S_ANGLES, r"+ \dot{\beta} \sin \gamma \right] \hat{\mathbf{e}}_{1}",
        (r"\tilde{\boldsymbol{\omega}} = \left[ \dot{\alpha} \left( -\sin \beta \cos \gamma \right) + \dot{\beta} \sin \gamma \right] \hat{\mathbf{e}}_{1}",
         r"+ \left[ \dot{\alpha} \left( \sin \beta \sin \gamma \right) + \dot{\beta} \cos \gamma \right] \hat{\mathbf{e}}_{2}",
         r"+ \left[ \dot{\alpha} \cos \beta + \dot{\gamma} \right] \hat{\mathbf{e}}_{3}"),
        ((alpha_d * (-s(beta) * c(gamma)) + beta_d * s(gamma)) * e1
         + (alpha_d * (s(beta) * s(gamma)) + beta_d * c(gamma)) * e2 + (alpha_d * c(beta) + gamma_d) * e3),
        "omega-body-linear",
    ),
    Claim(
        "T-euler-angles", S_T, r"T(\alpha, \beta, \gamma, \dot{\alpha}, \dot{\beta}, \dot{\gamma}) = \frac{1}{2} I_1 \widetilde{\omega}_1^2",
        (r"= \frac{1}{2} I_1 \left[ \dot{\alpha} \left( -\sin \beta \cos \gamma \right) + \dot{\beta} \sin \gamma \right]^2",
         r"+ \frac{1}{2} I_2 \left[ \dot{\alpha} \left( \sin \beta \sin \gamma \right) + \dot{\beta} \cos \gamma \right]^2",
         r"+ \frac{1}{2} I_3 \left[ \dot{\alpha} \cos \beta + \dot{\gamma} \right]^2"),
        (half * I1 * (alpha_d * (-s(beta) * c(gamma)) + beta_d * s(gamma)) ** 2
         + half * I2 * (alpha_d * (s(beta) * s(gamma)) + beta_d * c(gamma)) ** 2
         + half * I3 * (alpha_d * c(beta) + gamma_d) ** 2),
        "kinetic-energy",
    ),
    Claim(
        "T-symmetric", S_T, r"\frac{1}{2} I_1(\dot{\alpha}^2 \sin^2 \beta + \dot{\beta}^2)",
        (r"T(\alpha, \beta, \gamma, \dot{\alpha}, \dot{\beta}, \dot{\gamma}) = \frac{1}{2} I_1(\dot{\alpha}^2 \sin^2 \beta + \dot{\beta}^2) + \frac{1}{2} I_3[\dot{\alpha} \cos \beta + \dot{\gamma}]^2",),
        half * I1 * (alpha_d**2 * s(beta) ** 2 + beta_d**2) + half * I3 * (alpha_d * c(beta) + gamma_d) ** 2,
        "kinetic-energy-symmetric",
    ),
    # ---- heavy symmetric top -------------------------------------------------------------------
    Claim(
        "L-heavy-top", S_TOP, r"- Mgl \cos \beta$$",
        (r"L(\alpha, \beta, \gamma, \dot{\alpha}, \dot{\beta}, \dot{\gamma}) = \frac{1}{2} I_1 (\dot{\alpha}^2 \sin^2 \beta + \dot{\beta}^2) + \frac{1}{2} I_3 [\dot{\alpha} \cos \beta + \dot{\gamma}]^2 - Mgl \cos \beta",),
        half * I1 * (alpha_d**2 * s(beta) ** 2 + beta_d**2) + half * I3 * (alpha_d * c(beta) + gamma_d) ** 2
        - Mass * g * l * c(beta),
        "heavy-top-lagrangian",
    ),
    Claim(
        "constants-of-motion", S_TOP, "Constants of the motion:", ("Constants of the motion:",),
        sp.Matrix([alpha, gamma]), "cyclic",
        note="p_α and p_γ are listed as constants: α and γ must be exactly the cyclic coordinates of L",
    ),
    Claim(
        "p-alpha", S_TOP, r"p_{\alpha} &= \frac{\partial L}{\partial \dot{\alpha}}",
        (r"p_{\alpha} &= \frac{\partial L}{\partial \dot{\alpha}} = I_{1} \dot{\alpha} \sin^{2} \beta + I_{3} \left[ \dot{\alpha} \cos \beta + \dot{\gamma} \right] \cos \beta",),
        I1 * alpha_d * s(beta) ** 2 + I3 * (alpha_d * c(beta) + gamma_d) * c(beta), "p-alpha",
        note="repeated on the last slide",
    ),
    Claim(
        "p-gamma", S_TOP, r"p_{\gamma} &= \frac{\partial L}{\partial \dot{\gamma}}",
        (r"p_{\gamma} &= \frac{\partial L}{\partial \dot{\gamma}} = I_{3} \left[ \dot{\alpha} \cos \beta + \dot{\gamma} \right]",),
        I3 * (alpha_d * c(beta) + gamma_d), "p-gamma", note="repeated on the last slide",
    ),
    Claim(
        "E", S_TOP, r"E &= \frac{1}{2} I_{1} \dot{\beta}^{2}",
        (r"E &= \frac{1}{2} I_{1} \dot{\beta}^{2} + \frac{p_{\gamma}^{2}}{2I_{3}} + V_{eff}(\beta)",),
        half * I1 * beta_d**2 + p_gamma**2 / (2 * I3) + Veff, "energy-reduced", given={Veff: SLIDE_VEFF},
        note="h = q̇·∂L/∂q̇ − L with α̇, γ̇ eliminated for p_α, p_γ; V_eff as on the same slide",
    ),
    Claim(
        "L-beta", S_TOP, r"L(\beta, \dot{\beta}) &=",
        (r"L(\beta, \dot{\beta}) &= \frac{1}{2} I_{1} \dot{\beta}^{2} + \frac{\left(p_{\alpha} - p_{\gamma} \cos \beta\right)^{2}}{2I_{1} \sin^{2} \beta} + \frac{p_{\gamma}^{2}}{2I_{3}} - Mgl \cos \beta",),
        SLIDE_L_BETA, "L-substituted",
        note="true as an identity (L with α̇, γ̇ replaced by their momentum expressions) but not a Lagrangian for β: see L-beta-as-lagrangian",
    ),
    Claim(
        "L-beta-as-lagrangian", S_TOP, r"L(\beta, \dot{\beta}) &=",
        (r"L(\beta, \dot{\beta}) &= \frac{1}{2} I_{1} \dot{\beta}^{2} + \frac{\left(p_{\alpha} - p_{\gamma} \cos \beta\right)^{2}}{2I_{1} \sin^{2} \beta} + \frac{p_{\gamma}^{2}}{2I_{3}} - Mgl \cos \beta",),
        SLIDE_L_BETA, "beta-acceleration", mode="beta-lagrangian",
        note="its Euler–Lagrange equation reverses the centrifugal force; the β motion follows from Routh's "
             "L_β = ½I₁β̇² − (p_α − p_γ cos β)²/(2I₁ sin²β) − p_γ²/(2I₃) − Mgl cos β = ½I₁β̇² − V_eff − p_γ²/(2I₃) "
             "(Reduction.routh_lagrangian), the centrifugal term with the opposite sign",
    ),
    Claim(
        "V-eff", S_TOP, r"V_{eff}(\beta) &=",
        (r"V_{eff}(\beta) &= \frac{\left(p_{\alpha} - p_{\gamma} \cos \beta\right)^{2}}{2I_{1} \sin^{2} \beta} + Mgl \cos \beta",),
        SLIDE_VEFF, "V-eff",
    ),
    Claim(
        "E-explicit", S_TOP, r"E = \frac{1}{2}I_{1}\dot{\beta}^{2} + \frac{p_{\gamma}^{2}}{2I_{3}} + \frac{(p_{\alpha}",
        (r"E = \frac{1}{2}I_{1}\dot{\beta}^{2} + \frac{p_{\gamma}^{2}}{2I_{3}} + \frac{(p_{\alpha} - p_{\gamma}\cos\beta)^{2}}{2I_{1}\sin^{2}\beta} + Mgl\cos\beta",),
        half * I1 * beta_d**2 + p_gamma**2 / (2 * I3) + (p_alpha - p_gamma * c(beta)) ** 2 / (2 * I1 * s(beta) ** 2)
        + Mass * g * l * c(beta),
        "energy-reduced",
    ),
    Claim(
        "E-prime-definition", S_TOP, r"E' = E - \frac{p_{\gamma}^{2}}{2I_{3}}",
        (r"E' = E - \frac{p_{\gamma}^{2}}{2I_{3}}",),
        E - p_gamma**2 / (2 * I3), "E-prime", given={E: Derived("energy-reduced")},
    ),
    Claim(
        "E-prime", S_TOP, r"= \frac{1}{2}I_{1}\dot{\beta}^{2} + \frac{(p_{\alpha} - p_{\gamma}\cos\beta)^{2}}{2I_{1}\sin^{2}\beta} + Mgl\cos\beta",
        (r"= \frac{1}{2}I_{1}\dot{\beta}^{2} + \frac{(p_{\alpha} - p_{\gamma}\cos\beta)^{2}}{2I_{1}\sin^{2}\beta} + Mgl\cos\beta",),
        half * I1 * beta_d**2 + (p_alpha - p_gamma * c(beta)) ** 2 / (2 * I1 * s(beta) ** 2) + Mass * g * l * c(beta),
        "E-prime",
        note="repeated on three later slides",
    ),
    # ---- stability of the sleeping top ---------------------------------------------------------
    Claim(
        "E-prime-small-beta", S_STAB, r"\left(1 - 1 + \frac{1}{2} \beta^2\right)^2",
        (r"E' \approx \frac{1}{2} I_1 \dot{\beta}^2 + \frac{p_{\gamma}^2}{2I_1} \frac{\left(1 - 1 + \frac{1}{2} \beta^2\right)^2}{\beta^2} + Mgl\left(1 - \frac{1}{2} \beta^2\right)",),
        half * I1 * beta_d**2 + p_gamma**2 / (2 * I1) * (1 - 1 + half * beta**2) ** 2 / beta**2
        + Mass * g * l * (1 - half * beta**2),
        "E-prime-series",
        note="with p_α = p_γ, to O(β²) (sin β ≈ β, cos β ≈ 1 − β²/2)",
    ),
    Claim(
        "E-prime-quadratic", S_STAB, r"\left(\frac{p_{\gamma}^2}{8I_1} - \frac{Mgl}{2}\right)\beta^2",
        (r"\approx \frac{1}{2}I_1\dot{\beta}^2 + \left(\frac{p_{\gamma}^2}{8I_1} - \frac{Mgl}{2}\right)\beta^2 + Mgl",),
        half * I1 * beta_d**2 + (p_gamma**2 / (8 * I1) - Mass * g * l / 2) * beta**2 + Mass * g * l,
        "E-prime-series",
    ),
    Claim(
        "stability-condition", S_STAB, r"p_{\gamma} \ge \sqrt{4MglI_1}",
        (r"p_{\gamma} \ge \sqrt{4MglI_1}",),
        sp.Ge(p_gamma, sp.sqrt(4 * Mass * g * l * I1)), "stability-condition",
        note="k₂ ≥ 0 solved for p_γ > 0 from the series of V_eff",
    ),
    Claim(
        "stability-marginal", S_STAB, r"p_{\gamma} \ge \sqrt{4MglI_1}",
        (r"p_{\gamma} \ge \sqrt{4MglI_1}",),
        sp.Integer(1), "threshold-quartic", mode="sign",
        note="'≥' counts the threshold itself as stable: there k₂ = 0, so the β⁴ coefficient k₄ (derived) must be positive",
    ),
    Claim(
        "p-gamma-omega3", S_STAB, r"p_{\gamma} = I_3 \omega_3", (r"p_{\gamma} = I_3 \omega_3",),
        I3 * w3, "p-gamma", given={w3: Derived("omega-body", 2)},
    ),
    Claim(
        "p-alpha-rewritten", S_CONST, r"= I_{1} \dot{\alpha} \sin^{2} \beta + p_{\gamma} \cos \beta",
        (r"= I_{1} \dot{\alpha} \sin^{2} \beta + p_{\gamma} \cos \beta",),
        I1 * alpha_d * s(beta) ** 2 + p_gamma * c(beta), "p-alpha", given={p_gamma: Derived("p-gamma")},
    ),
    # ---- Assignment #20 ------------------------------------------------------------------------
    Claim(
        "assignment-20-matrix", S_ASSIGN, r"$\alpha$ =90 deg,  $\beta$ =90 deg, and  $\gamma$ =0 deg",
        (r"Find the rotation matrix and the new vector components for the case that  $\alpha$ =90 deg,  $\beta$ =90 deg, and  $\gamma$ =0 deg.",),
        SLIDE_PASSIVE.subs(ASSIGNMENT_ANGLES), "assignment-20-matrix",
        note="the slides' passive matrices Rz(γ)Ry(β)Rz(α) (their 'Matrix representation'), against Rᵀ of the orientation matrix",
    ),
    Claim(
        "assignment-20-proper", S_ASSIGN, "Find the rotation matrix", ("Find the rotation matrix",),
        (sp.eye(3), sp.Integer(1)), "assignment-20-gram",
        note="a rotation matrix: Rᵀ R = 1 and det R = +1",
    ),
    Claim(
        "assignment-20-V", S_ASSIGN, "the vector has components", ("the vector has components  $(V_x, V_y, V_z)$",),
        SLIDE_PASSIVE.subs(ASSIGNMENT_ANGLES) * sp.Matrix([Vx, Vy, Vz]), "assignment-20-V",
        note="the slide gives no answer (and the transcript lost the primes on the new components): derived V′ = Rᵀ V",
    ),
)

EXPECTED: dict[str, str] = {
    "velocity": "holds",
    "T-sum": "holds",
    "T-dot": "holds",
    "T-expanded": "holds",
    "T-tensor": "holds",
    "inertia-tensor": "holds",
    "T-general": "holds",
    "principal-axes": "holds",
    "T-principal": "holds",
    "L-sum": "holds",
    "L-expanded": "holds",
    "L-tensor": "holds",
    "inertia-dyadic": "holds",
    "L-principal": "holds",
    "dLdt-transport": "holds",
    "dLdt-body": "typo",
    "euler-vector": "holds",
    "euler-3-duplicated": "typo",
    "euler-1": "holds",
    "euler-2": "holds",
    "euler-3": "holds",
    "symmetric-euler-1": "holds",
    "symmetric-euler-2": "holds",
    "symmetric-euler-3": "holds",
    "symmetric-Omega": "holds",
    "symmetric-omega1-dot": "holds",
    "symmetric-omega2-dot": "holds",
    "symmetric-solution": "holds",
    "symmetric-T": "holds",
    "symmetric-L": "holds",
    "asym-omega3-dot": "holds",
    "asym-Omega1": "holds",
    "asym-Omega2": "holds",
    "asym-linear": "holds",
    "asym-solution": "typo",
    "asym-oscillation": "holds",
    "asym-instability": "holds",
    "omega-tilde-sum": "holds",
    "e2prime-expansion": "holds",
    "e2prime-matrix": "holds",
    "e2prime-column": "holds",
    "e30-expansion-primed": "holds",
    "e30-expansion-body": "holds",
    "e30-matrix": "holds",
    "e30-mislabelled": "typo",
    "omega-tilde-columns": "holds",
    "omega-tilde-1": "holds",
    "omega-tilde-2": "holds",
    "omega-tilde-3": "holds",
    "omega-tilde-expanded": "holds",
    "T-euler-angles": "holds",
    "T-symmetric": "holds",
    "L-heavy-top": "holds",
    "constants-of-motion": "holds",
    "p-alpha": "holds",
    "p-gamma": "holds",
    "E": "holds",
    "L-beta": "holds",
    "L-beta-as-lagrangian": "fails",
    "V-eff": "holds",
    "E-explicit": "holds",
    "E-prime-definition": "holds",
    "E-prime": "holds",
    "E-prime-small-beta": "holds",
    "E-prime-quadratic": "holds",
    "stability-condition": "holds",
    "stability-marginal": "holds",
    "p-gamma-omega3": "holds",
    "p-alpha-rewritten": "holds",
    "assignment-20-matrix": "holds",
    "assignment-20-proper": "holds",
    "assignment-20-V": "holds",
}
"""The verdict each claim is expected to get; `derive verify` fails when one differs."""
