"""The notes reader on a chain headed by a name it holds in another shape: the inertia tensor
about a point summed from the text's own labelled tensors (𝐈 = 𝐈_C + 𝐈' = a written matrix)."""
import kept_readings as kept

_PARTS = ("# Disc\n\nThe disc about its centre,\n\n"
          "$$\n\\boldsymbol{I}' = \\begin{pmatrix} mr^2 & 0 & 0 \\\\ 0 & mr^2 & 0 \\\\ 0 & 0 & 2mr^2 \\end{pmatrix}\n$$\n\n"
          "and its mass at the centre, taken as a point,\n\n"
          "$$\n\\boldsymbol{I}_C = \\begin{pmatrix} mr^2 & 0 & 0 \\\\ 0 & mr^2 & 0 \\\\ 0 & 0 & 0 \\end{pmatrix}\n$$\n\n"
          "so that about the point\n\n"
          "$$\n\\boldsymbol{I} = \\boldsymbol{I}_C + \\boldsymbol{I}' = "
          "\\begin{pmatrix} 2mr^2 & 0 & 0 \\\\ 0 & 2mr^2 & 0 \\\\ 0 & 0 & {last} \\end{pmatrix}\n$$\n")


def _sum_line(last):
    claims = kept.check_text(_PARTS.replace("{last}", last))
    return [(c.verdict, c.why) for c in claims if c.line == 17]


def test_a_labelled_tensor_sum_under_a_head_of_another_shape_is_checked_link_by_link():
    said = _sum_line("2mr^2")
    assert [v for v, _ in said] == ["unchecked", "holds"]
    assert "compared with each other" in said[0][1]


def test_a_slipped_entry_in_a_labelled_tensor_sum_is_never_called_correct():
    assert "holds" not in [v for v, _ in _sum_line("3mr^2")]
