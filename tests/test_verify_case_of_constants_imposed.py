"""A case the prose sets by the constants of the motion alone ("a top that starts upright has $L_z =
Cn$") is imposed on the statements after it: one that vanishes on the motions of the case, with the
rate the case gives put in, holds there; one that does not stays unchecked, never flagged."""
import kept_readings as kept

TEXT = r"""---
convention: z-y-z
---
# Heavy top

The top has mass $M$ and a distance $l$ from the pivot to its centre of mass. Its moments are written
($A = I_1 = I_2$, $C = I_3$). Its spin and the momentum about the vertical are conserved:

$$
n = \dot\gamma + \dot\alpha\cos\beta
$$

$$
L_z = A\dot\alpha\sin^2\beta + Cn\cos\beta
$$

## Upright start

A top that starts upright has $L_z = Cn$, so

$$
Cn = A\dot\alpha\sin^2\beta + Cn\cos\beta
$$
"""


def _case_statement(text):
    claims = kept.by_line(text)[kept.line_of(text, r"Cn = A") - 1]
    return {c.verdict for c in claims}, " ".join(c.why for c in claims)


def test_a_statement_that_vanishes_in_the_case_the_text_sets_holds_there():
    verdicts, why = _case_statement(TEXT)
    assert verdicts == {"holds"} and "in the case L_z = Cn" in why


def test_a_statement_that_does_not_vanish_in_the_case_stays_unchecked():
    verdicts, why = _case_statement(TEXT.replace(r"Cn = A\dot\alpha\sin^2\beta + Cn", r"Cn = A\dot\alpha\sin^2\beta - Cn"))
    assert verdicts == {"unchecked"} and "does not impose" in why
