"""A Jupyter notebook is read through its Markdown cells: code cells and outputs are not read, a
claim's line is the notebook file's line, a first cell's front matter sets the convention, and a
file that is not a notebook is bad input naming what is missing."""
import json

import pytest

from derive.errors import SceneError
from derive.lecture import notes_check as nc
from derive.lecture import notebook

EULER_1 = "I_1 \\dot\\omega_1 = (I_2 - I_3)\\omega_2\\omega_3"
SLIP_2 = "I_2 \\dot\\omega_2 = (I_3 - I_1)\\omega_1\\omega_2"


def write(tmp_path, cells):
    nb = {"cells": cells, "metadata": {}, "nbformat": 4, "nbformat_minor": 5}
    path = tmp_path / "notes.ipynb"
    path.write_text(json.dumps(nb, indent=1, ensure_ascii=False), encoding="utf-8")
    return path


def md(*lines):
    return {"cell_type": "markdown", "metadata": {}, "source": [f"{x}\n" for x in lines[:-1]] + [lines[-1]]}


def file_line(path, needle):
    return next(n for n, row in enumerate(path.read_text(encoding="utf-8").split("\n"), 1) if needle in row)


def test_markdown_cells_are_read_at_their_lines_in_the_file_and_code_cells_are_not(tmp_path):
    code = {"cell_type": "code", "metadata": {}, "execution_count": None, "outputs": [],
            "source": ["# $$T = 5$$\n", "x = 1"]}
    path = write(tmp_path, [md("# Euler", "$$", EULER_1, "$$"), code, md("A slip, ω:", "$$", SLIP_2, "$$")])
    claims = nc.check_notes(path)
    assert [(c.line, c.verdict) for c in claims] == [(file_line(path, '"$$\\n"'), "holds"),
                                                     (file_line(path, '"A slip') + 1, "typo")]


def test_a_display_written_as_one_string_is_still_read(tmp_path):
    path = write(tmp_path, [{"cell_type": "markdown", "metadata": {}, "source": f"Euler:\n$${SLIP_2}$$"}])
    assert [c.verdict for c in nc.check_notes(path)] == ["typo"]


def test_a_first_cells_front_matter_sets_the_convention(tmp_path):
    omega1 = "\\omega_1 = \\dot\\phi \\sin\\theta \\sin\\psi + \\dot\\theta \\cos\\psi"
    cells = [md("---", "convention: z-x-z", "angles: [\\phi, \\theta, \\psi]", "---", "# Angles"),
             md("$$", omega1, "$$")]
    assert [c.verdict for c in nc.check_notes(write(tmp_path, cells))] == ["holds"]


@pytest.mark.parametrize("text, key", [('{"metadata": {}}', "cells"), ("{not json", "file"),
                                       ('{"cells": [{"cell_type": "markdown", "source": [1]}]}', "source")])
def test_a_file_that_is_not_a_notebook_is_bad_input_naming_the_key(text, key):
    with pytest.raises(SceneError, match=f"^nb.ipynb: {key}: "):
        notebook.markdown(text, "nb.ipynb")
