"""The notes reader on a derivative relative to a moving frame written with a bracket drawn half,
``\\left.\\frac{d\\mathbf{B}}{dt}\\right)_{\\text{rel}}``: the bracket ``\\left( … \\right)_{rel}`` it
stands for, "rel" (relative to the moving frame) naming the body frame as "body" and "rot" do; an
evaluation bar ``\\left. … \\right|_{t=0}`` is left as written."""
import kept_readings as kept
from derive.lecture import texmacros

verdicts, line_of = kept.verdicts_by_line, kept.line_of
PROSE = "# Notes\n\nA vector $\\boldsymbol{B}$ seen from a frame turning with angular velocity $\\boldsymbol{\\omega}$:\n\n"


def test_a_half_drawn_bracket_with_a_subscript_is_the_whole_bracket():
    assert texmacros.synonyms("\\left.\\frac{dB}{dt}\\right)_{\\text{rel}}") == "\\left(\\frac{dB}{dt}\\right)_{\\text{rel}}"
    assert texmacros.synonyms("\\left.\\frac{dB}{dt}\\right|_{t=0}") == "\\left.\\frac{dB}{dt}\\right|_{t=0}"


def test_the_transport_theorem_relative_to_the_moving_frame_holds():
    text = PROSE + ("$$\\frac{d\\boldsymbol{B}}{dt} = \\left.\\frac{d\\boldsymbol{B}}{dt}\\right)_{\\text{rel}} + "
                    "\\boldsymbol{\\omega}\\times\\boldsymbol{B}$$\n")
    assert verdicts(text)[line_of(text, "$$")] == {"holds"}


def test_the_transport_theorem_with_its_sign_wrong_is_flagged():
    text = PROSE + ("$$\\frac{d\\boldsymbol{B}}{dt} = \\left.\\frac{d\\boldsymbol{B}}{dt}\\right)_{\\text{rel}} - "
                    "\\boldsymbol{\\omega}\\times\\boldsymbol{B}$$\n")
    assert verdicts(text)[line_of(text, "$$")] & {"fails", "typo"}


def test_a_half_drawn_bracket_sized_by_hand_is_the_whole_bracket():
    for size in ("big", "Big", "bigg", "Bigg"):
        assert texmacros.synonyms(f"\\{size}l.\\frac{{dB}}{{dt}}\\{size}r)_{{\\text{{rel}}}}") == \
            "\\left(\\frac{dB}{dt}\\right)_{\\text{rel}}"
    text = PROSE + ("$$\\frac{d\\boldsymbol{B}}{dt} = \\bigl.\\frac{d\\boldsymbol{B}}{dt}\\bigr)_{\\text{rel}} + "
                    "\\boldsymbol{\\omega}\\times\\boldsymbol{B}$$\n")
    assert verdicts(text)[line_of(text, "$$")] == {"holds"}
