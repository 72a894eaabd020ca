"""Letters a text gives its own meaning by what it writes beside them (`derive.lecture.names`,
`derive.lecture.meanings`): a T added to a weight is a force, a rate "at the rate ω_z about ẑ" is a
turn's rate; neither is the lecture's quantity of that letter. And unit vectors of two frames in one
statement are not one basis (`derive.lecture.vector_algebra_model`)."""
import kept_readings as kept

YOYO = r"""# A yo-yo

Newton's second law for the centre and the string's pull,

$$T-Mg=-Ma_{cm}$$

and with the torque of the string,

$$T=\frac{1}{2}Ma_{cm}=\frac{1}{2}M\left(\frac{2}{3}g\right)=\frac{1}{3}Mg$$
"""

CONE = r"""# A cone on a table

The cone turns at the rate $\omega_z$ about $\hat{z}$ and at the rate $\omega_3$ about $\hat{x_3}$, its axis.

$$\vec{\omega} = -\omega_z\hat{z} + \omega_3\hat{x_3}$$
"""


def _by_line(text):
    return {line: [c.verdict for c in claims] for line, claims in kept.by_line(text).items()}


def test_a_t_added_to_a_weight_is_a_force_not_the_kinetic_energy():
    verdicts = _by_line(YOYO)
    assert not {"typo", "fails"} & set(verdicts[9])
    assert "holds" in verdicts[9]           # its last link, ½M(2g/3) = Mg/3, is plain algebra


def test_the_same_t_without_a_weight_beside_it_is_still_the_kinetic_energy():
    text = YOYO.replace("$$T-Mg=-Ma_{cm}$$", "$$F-Mg=-Ma_{cm}$$")
    assert {"typo", "fails"} & set(_by_line(text)[9])


def test_rates_of_turns_about_two_frames_axes_are_not_components_of_omega():
    verdicts = _by_line(CONE)[5]
    assert not {"typo", "fails"} & set(verdicts)
