"""The notes reader on a LaTeX text that writes its formulas in the commands of a package it loads:
with ``\\usepackage[Mathematics]{semtex}``, ``\\pa{x}`` and ``\\of{x}`` are round brackets,
``\\TimeDerivative{\\omega}_1`` is ω̇₁ and ``\\DefineAs`` is the definition sign, as the package sets
them, so Euler's equation written in them is judged; a file that does not load the package keeps
them unread, and its own ``\\newcommand`` wins over the package's."""
import kept_readings as kept

from derive.lecture import package_macros

HEAD = "\\documentclass{article}\n\\usepackage[Mathematics]{semtex}\n\\begin{document}\n"
BODY = ("\\section*{Euler's equations}\nFor the torque-free body in its principal axes, the first of "
        "Euler's equations reads\n\\[\nI_1 \\TimeDerivative{\\omega}_1 = \\pa{SLIP} \\omega_2 \\omega_3\n\\]\n"
        "\\end{document}\n")


def _verdicts(tmp_path, text: str) -> set:
    path = tmp_path / "notes.tex"
    path.write_text(text)
    line = text[:text.index("I_1 \\TimeDerivative")].count("\n")
    return {c.verdict for c in kept.check_notes(path) if c.line == line}


def test_the_package_commands_are_read_as_the_package_sets_them():
    macros = package_macros.loaded(HEAD)
    assert {"pa", "of", "TimeDerivative", "DefineAs", "JacobiSN"} <= set(macros)
    assert package_macros.loaded("\\documentclass{article}\n% \\usepackage{semtex}\n") == {}


def test_euler_equation_in_the_package_commands_holds(tmp_path):
    assert _verdicts(tmp_path, HEAD + BODY.replace("SLIP", "I_2 - I_3")) == {"holds"}


def test_euler_equation_in_the_package_commands_with_its_sign_slipped_is_flagged(tmp_path):
    assert _verdicts(tmp_path, HEAD + BODY.replace("SLIP", "I_3 - I_2")) & {"fails", "typo"}


def test_without_the_package_the_commands_stay_unread(tmp_path):
    text = "\\documentclass{article}\n\\begin{document}\n" + BODY.replace("SLIP", "I_3 - I_2")
    assert _verdicts(tmp_path, text) == {"unchecked"}
