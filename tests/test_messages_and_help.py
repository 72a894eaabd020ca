"""The command line speaks one language: the same words for the same error in every command, a
did-you-mean for a mistyped example, one rule for an output whose folder is missing, a
description for every command, and ``--help`` offering only what a command accepts.

In process (``derive.cli.main``): every case here fails or prints help before any work.
"""
from __future__ import annotations

import re

import pytest

from derive import cli
from derive.methods.registry import REFERENCE_METHODS
from derive.sim import examples
from derive.sweeps.measures import REGISTRY as MEASURES


def run(capsys, *argv):
    code = cli.main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


# --- a missing input file ---------------------------------------------------------------------

MISSING_FILE = [
    ("simulate", "{f}"), ("analyze", "{f}"), ("verify", "{f}"), ("sweep", "{f} -o {d}/out.csv"),
    ("export", "{f} --out {d}/folder"), ("export", "{f} --fmu {d}/x.fmu"),
]


@pytest.mark.parametrize("command,rest", MISSING_FILE)
def test_a_missing_file_reads_the_same_in_every_command(command, rest, tmp_path, capsys):
    missing = tmp_path / "missing.toml"
    argv = [command, *rest.format(f=missing, d=tmp_path).split()]
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == ""
    assert err.splitlines() == [f"error: {missing}: file: not found"]


# --- did you mean -----------------------------------------------------------------------------

@pytest.mark.parametrize("argv,meant", [
    (["simulate", "looping_tp"], "looping_top"),
    (["analyze", "kovalevskaya_tp"], "kovalevskaya_top"),
    (["export", "tennis_rackett", "--fmu", "x.fmu"], "tennis_racket"),
    (["sweep", "sleeping_thresold", "-o", "x.csv"], "sleeping_threshold"),
    (["examples", "--copy", "looping_tp"], "looping_top"),
])
def test_a_mistyped_example_name_gets_a_did_you_mean(argv, meant, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, *argv)
    assert code == 2 and len(err.splitlines()) == 1
    assert err.rstrip().endswith(f"(did you mean {meant}?)")


def test_a_name_near_no_example_gets_no_guess():
    assert examples.did_you_mean("qwertyuiop") == ""
    assert examples.did_you_mean("some/dir/looping_tp.toml") == ""  # a path, not a name


# --- an output whose folder is missing --------------------------------------------------------

OUTPUT_FLAGS = [
    ("simulate", "looping_top -o {o}.npz"), ("simulate", "looping_top --plot {o}.png"),
    ("sweep", "sleeping_threshold -o {o}.csv"), ("sweep", "sleeping_threshold -o x.csv --plot {o}.png"),
    ("export", "looping_top --fmu {o}.fmu"), ("export", "looping_top --out {o}"),
    ("bench", "-o {o}"), ("generate", "--out {o}"), ("examples", "--copy looping_top --to {o}"),
]


@pytest.mark.parametrize("command,rest", OUTPUT_FLAGS)
def test_every_output_flag_refuses_a_missing_folder_and_makes_none(command, rest, tmp_path, capsys,
                                                                   monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, command, *rest.format(o="nodir/sub/out").split())
    assert code == 2 and out == ""
    assert re.fullmatch(r"error: nodir/sub/out(\.\w+)?: output: directory 'nodir/sub' does not exist\n", err)
    assert list(tmp_path.iterdir()) == []


# --- help -------------------------------------------------------------------------------------

def _commands():
    p = cli.parser()
    sub = next(a for a in p._actions if a.dest == "command")
    return sub


def test_every_command_has_a_one_line_summary_and_a_description(capsys):
    sub = _commands()
    summaries = {a.dest: a.help for a in sub._choices_actions}
    assert set(summaries) == set(sub.choices)
    for name, parser in sub.choices.items():
        assert summaries[name] and "\n" not in summaries[name], name
        assert parser.description, name
    code, out, _ = run(capsys, "--help")
    for name in sub.choices:
        assert re.search(rf"^\s+{name}\s+\S", out, flags=re.M), name


def _help(capsys, command):
    with pytest.raises(SystemExit):
        cli.parser().parse_args([command, "--help"])
    return " ".join(capsys.readouterr().out.split())


def test_export_help_offers_no_method_it_refuses(capsys):
    text = _help(capsys, "export")
    assert "dop853" in text and "taylor" in text
    for name in REFERENCE_METHODS:
        assert name not in text


def test_simulate_help_offers_the_scipy_references(capsys):
    text = _help(capsys, "simulate")
    for name in REFERENCE_METHODS:
        assert name in text


def test_sweep_help_lists_every_measure(capsys):
    text = _help(capsys, "sweep")
    for name in MEASURES:
        assert re.search(rf"\b{name}\b", text), name


# --- derive examples --------------------------------------------------------------------------

@pytest.mark.parametrize("kind,name", [(k, n) for k in examples.KINDS for n in examples.names(k)])
def test_an_example_description_is_a_title_or_whole_sentences(kind, name):
    file = examples.path(name, kind)
    text = file.read_text(encoding="utf-8")
    line = examples.summary(file)
    assert line
    if not re.search(r"^title\s*=", text, flags=re.M):
        assert line[-1] in ".?!", line
        assert line.count("(") == line.count(")"), line


def test_a_first_sentence_ends_at_a_full_stop_outside_numbers_and_brackets():
    assert examples.first_sentence("Where does it stay up? Spin x tilt.") == "Where does it stay up?"
    assert examples.first_sentence("I1 = 1.8e-4 (e.g. a coin. Or a top.) is small. More.") == \
        "I1 = 1.8e-4 (e.g. a coin. Or a top.) is small."
    assert examples.first_sentence("no full stop at all") == "no full stop at all"


def test_examples_prints_no_line_cut_mid_sentence(capsys):
    code, out, _ = run(capsys, "examples")
    assert code == 0
    assert "Where does the lecture's toy top stay up?\n" in out
    assert "how fast does it\n" not in out
