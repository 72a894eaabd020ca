"""A sum's index typed after a symbol without its underscore (``\\mathbf{ r}\\alpha``), where the display
writes that symbol indexed (``\\mathbf{r}_{\\alpha}``), is a typo corrected by the subscript
(derive/lecture/lost_underscore.py); an index that is no sum's, or a symbol the display never indexes, is left alone."""
import kept_readings as kept

from derive.lecture.lost_underscore import lost, restored

HEAD = "---\nconvention: z-x-z\n---\n# Angular momentum\n\n"
SLIP = (r"\mathbf{L} = \sum^N_{\alpha} m_{\alpha} \mathbf{r}_{\alpha} \times (\boldsymbol{\omega} "
        r"\times\mathbf{ r}\alpha )")


def test_a_sums_index_after_an_indexed_symbol_without_its_underscore_is_a_typo():
    claims = kept.check_text(HEAD + "$$\n" + SLIP + "\n$$\n")
    assert [c.verdict for c in claims] == ["typo"]
    assert restored(SLIP, lost(SLIP, SLIP)).endswith(r"\mathbf{ r}_{\alpha} )")


def test_an_index_that_is_no_sums_or_a_symbol_never_indexed_is_left_alone():
    assert lost(r"F = m a \alpha", r"F = m a \alpha") == []
    assert lost(r"\sum_{\alpha} m_{\alpha} c\alpha", r"\sum_{\alpha} m_{\alpha} c\alpha") == []
    assert lost(r"\sum_{\alpha} m_{\alpha} x_{\alpha}", r"\sum_{\alpha} m_{\alpha} x_{\alpha}") == []

