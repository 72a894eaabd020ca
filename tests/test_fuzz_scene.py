"""The scene contract under fuzzing: whatever the file holds, `derive simulate` exits 0, 2 or 3;
on failure exactly one stderr line starting with ``error:``; never a traceback or a warning; no
output file and nothing else left in the output folder; on success every float array finite.

Hypothesis mutates small valid scenes (wrong types, non-finite and out-of-range numbers, unknown
and misspelt keys and tables, impossible bodies, mutually exclusive keys, missing keys) and then
their bytes (truncation, byte-order marks, UTF-16, stray bytes, CRLF, duplicated headers). Every
example is cheap: the bases run 0.05 s of motion with 3 samples, a small step budget bounds what a
mutation can ask for, and the CLI runs in-process. The hand-written corpus ``tests/malformed/``
goes through the same checks, and a few of its files through a real process.
"""
import contextlib
import datetime
import io
import json
import math
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from derive import cli
from derive.codegen.render import ROOT
from derive.sim.scene import METHODS

MALFORMED = Path(__file__).parent / "malformed"

# Three cheap valid scenes: a heavy symmetric top given by rates, an asymmetric free body given
# by omega, a damped top whose centre of mass is given as a vector.
BASES = [
    {"title": "fuzz top",
     "body": {"I1": 1.0, "I3": 0.5},
     "gravity": {"M": 1.0, "g": 9.81, "l": 0.1},
     "initial": {"alpha": 0.0, "beta": 0.5, "gamma": 0.0,
                 "alpha_dot": 0.0, "beta_dot": 0.0, "gamma_dot": 10.0},
     "simulate": {"t_end": 0.05, "samples": 3, "max_steps": 20000}},
    {"body": {"I1": 1.0, "I2": 2.0, "I3": 2.5},
     "initial": {"alpha": 0.1, "beta": 1.0, "gamma": 0.2, "omega": [0.1, 3.0, 0.1]},
     "simulate": {"t_end": 0.05, "samples": 3, "max_steps": 20000}},
    {"body": {"I1": 0.8, "I2": 0.8, "I3": 0.3},
     "gravity": {"M": 0.5, "g": 9.81, "com": [0.0, 0.0, 0.05]},
     "damping": {"c": 0.01},
     "initial": {"alpha": 0.0, "beta": 0.3, "gamma": 0.0, "gamma_dot": 20.0},
     "simulate": {"t_end": 0.05, "samples": 3, "max_steps": 20000, "rtol": 1e-8}},
]

KEYS = {
    "body": ["I1", "I2", "I3"],
    "gravity": ["M", "g", "l", "com"],
    "damping": ["c"],
    "initial": ["alpha", "beta", "gamma", "alpha_dot", "beta_dot", "gamma_dot", "omega"],
    "simulate": ["t_end", "samples", "method", "rtol", "atol", "formulation", "max_steps", "h"],
}
COMPILED_METHODS = [m for m in METHODS if not m.startswith("scipy-")]
FORMULATIONS = ["auto", "reduced", "quaternion", "euler-angles", "euler-poisson"]


# --- values -----------------------------------------------------------------------------------

finite_odd = st.sampled_from([0.0, -0.0, -1.0, 1e-300, -1e-300, 5e-324, 1e-12, 1e300, -1e300,
                              1.7976931348623157e308, math.pi, 4.0, 1e15, 2.0**53])
non_finite = st.sampled_from([math.inf, -math.inf, math.nan])
numbers = st.one_of(finite_odd, non_finite,
                    st.floats(-1e6, 1e6, allow_nan=False),
                    st.integers(-2**70, 2**70))
texts = st.one_of(st.sampled_from(["", "1.0", "nan", "rk4 ", "RK4", "dop 853", "quaternions",
                                   "auto\n", "ñ", "\u202e", "\x00"]),
                  st.text(max_size=8))
scalars = st.one_of(numbers, st.booleans(), texts,
                    st.dates(min_value=datetime.date(1900, 1, 1),
                             max_value=datetime.date(2100, 1, 1)))
values = st.recursive(scalars, lambda inner: st.one_of(
    st.lists(inner, max_size=4),
    st.dictionaries(st.sampled_from(["x", "I1", "c", "M"]), inner, max_size=2)), max_leaves=6)
# Keys whose valid values could ask for real work only get cheap or invalid values.
BOUNDED = {
    "t_end": st.one_of(non_finite, st.sampled_from([0.0, -1.0, 1e-300, 0.01, "1", True])),
    "samples": st.sampled_from([0, 1, 2, 5, -3, 2.5, "3", 10**13, 10**7 + 1, True]),
    "max_steps": st.sampled_from([0, -1, 1, 10, 2.5, "many", 10**13, math.inf, True]),
    "method": st.one_of(st.sampled_from(COMPILED_METHODS), texts, numbers),
    "formulation": st.one_of(st.sampled_from(FORMULATIONS), texts, numbers),
}


def misspell(key: str) -> st.SearchStrategy:
    variants = {key.lower(), key.upper(), key + "s", key[:-1] or "x", key.replace("_", "-"),
                key.replace("_", ""), " " + key, key[::-1]} - {key}
    return st.sampled_from(sorted(variants))


@st.composite
def mutation(draw):
    kind = draw(st.sampled_from(["set", "set", "set", "extreme", "extreme", "extreme", "delete",
                                 "misspell", "unknown-key", "unknown-table", "exclusive",
                                 "impossible-body", "title"]))
    table = draw(st.sampled_from(sorted(KEYS)))
    key = draw(st.sampled_from(KEYS[table]))
    if kind == "extreme":  # absurd but finite numbers that pass the checks of their key
        table = draw(st.sampled_from(["body", "gravity", "damping", "initial"]))
        key = draw(st.sampled_from([k for k in KEYS[table] if k != "omega"]))
        if key == "com":
            return ("set", table, key, draw(st.lists(finite_odd, min_size=3, max_size=3)))
        return ("set", table, key, draw(finite_odd))
    if kind == "set":
        return ("set", table, key, draw(BOUNDED.get(key, values)))
    if kind == "delete":
        return ("delete", table, draw(st.one_of(st.none(), st.just(key))))
    if kind == "misspell":
        return ("rename", table, key, draw(misspell(key)))
    if kind == "unknown-key":
        return ("set", table, draw(st.from_regex(r"[a-z][a-z0-9_]{0,7}", fullmatch=True)),
                draw(values))
    if kind == "unknown-table":
        name = draw(st.one_of(st.sampled_from(["Body", "bodies", "gravitation", "damper",
                                               "initials", "simulation", "output"]),
                              st.from_regex(r"[a-z]{1,8}", fullmatch=True)))
        return ("set", name, "x", draw(values))
    if kind == "exclusive":  # both of a one-of pair
        return draw(st.sampled_from([("set", "initial", "omega", [0.0, 0.0, 10.0]),
                                     ("set", "initial", "gamma_dot", 5.0),
                                     ("set", "gravity", "com", [0.0, 0.0, 0.1]),
                                     ("set", "gravity", "l", 0.1),
                                     ("set", "simulate", "h", 1e-3)]))
    if kind == "impossible-body":
        return ("body", draw(st.sampled_from([(1.0, 1.0, 3.0), (1.0, 2.0, 0.5), (0.0, 1.0, 1.0),
                                              (-1.0, -1.0, -1.0), (1.0, 1.0, 2.0000001)])))
    return ("title", draw(values))


def apply(scene: dict, op) -> None:
    kind = op[0]
    if kind == "set":
        _, table, key, value = op
        scene.setdefault(table, {})
        if isinstance(scene[table], dict):
            scene[table][key] = value
    elif kind == "delete":
        _, table, key = op
        if key is None:
            scene.pop(table, None)
        elif isinstance(scene.get(table), dict):
            scene[table].pop(key, None)
    elif kind == "rename":
        _, table, key, new = op
        if isinstance(scene.get(table), dict) and key in scene[table]:
            scene[table][new] = scene[table].pop(key)
    elif kind == "body":
        scene["body"] = dict(zip(("I1", "I2", "I3"), op[1]))
    elif kind == "title":
        scene["title"] = op[1]


# --- TOML text --------------------------------------------------------------------------------


def toml_key(k: str) -> str:
    return k if re.fullmatch(r"[A-Za-z0-9_-]+", k) else json.dumps(k)


def toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)  # a JSON string is a TOML basic string (\uXXXX escapes)
    if isinstance(v, datetime.date):
        return v.isoformat()
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{toml_key(k)} = {toml_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(type(v))


def to_toml(scene: dict) -> str:
    lines = [f"{toml_key(k)} = {toml_value(v)}" for k, v in scene.items()
             if not isinstance(v, dict)]
    for table, keys in scene.items():
        if isinstance(keys, dict):
            lines += ["", f"[{toml_key(table)}]"]
            lines += [f"{toml_key(k)} = {toml_value(v)}" for k, v in keys.items()]
    return "\n".join(lines) + "\n"


@st.composite
def byte_damage(draw, text: str) -> bytes:
    raw = text.encode()
    kind = draw(st.sampled_from(["none", "none", "none", "truncate", "bom", "utf16", "stray",
                                 "crlf", "duplicate-header", "nul"]))
    if kind == "truncate":
        return raw[:draw(st.integers(0, max(len(raw) - 1, 0)))]
    if kind == "bom":
        return b"\xef\xbb\xbf" + raw
    if kind == "utf16":
        return text.encode(draw(st.sampled_from(["utf-16", "utf-16-le", "utf-32"])))
    if kind == "stray":
        at = draw(st.integers(0, len(raw)))
        return raw[:at] + draw(st.sampled_from([b"\xff", b"\xc3", b"\x80\x80", b"\xed\xa0\x80",
                                                b"=", b"[", b'"', b"\n[body]\n"])) + raw[at:]
    if kind == "crlf":
        return raw.replace(b"\n", b"\r\n")
    if kind == "duplicate-header":
        return raw + b"\n[body]\nI1 = 1.0\n"
    if kind == "nul":
        return raw.replace(b"\n", b"\n\x00", 1)
    return raw


@st.composite
def malformed_scenes(draw) -> bytes:
    scene = json.loads(json.dumps(draw(st.sampled_from(BASES))))  # a deep copy
    for op in draw(st.lists(mutation(), min_size=1, max_size=3)):
        apply(scene, op)
    return draw(byte_damage(to_toml(scene)))


# --- the contract -----------------------------------------------------------------------------


def run_in_process(argv):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = cli.main([str(a) for a in argv])
    return rc, out.getvalue(), err.getvalue()


def check_contract(content: bytes, runner=run_in_process, flags=()) -> tuple[int, str]:
    """Simulate ``content`` as a scene file in a fresh folder; assert the contract; return the
    exit status and stderr."""
    folder = Path(tempfile.mkdtemp(prefix="derive-fuzz-"))
    try:
        scene = folder / "scene.toml"
        scene.write_bytes(content)
        npz = folder / "out.npz"
        rc, out, err = runner(["simulate", scene, "-o", npz, *flags])
        # the cache's healing note is the one other line a run may print (a stale cache)
        lines = [ln for ln in err.splitlines() if not ln.startswith("note: cached library")]
        assert "Traceback" not in out + err and "Warning" not in err, err
        assert rc in (0, 2, 3), f"exit {rc}: {err}"
        if rc == 0:
            assert lines == [], err
            with np.load(npz) as data:
                for name in data.files:
                    if data[name].dtype.kind in "fc":
                        assert np.all(np.isfinite(data[name])), f"{name} not finite, exit 0"
            assert sorted(p.name for p in folder.iterdir()) == ["out.npz", "scene.toml"]
        else:
            assert len(lines) == 1 and lines[0].startswith("error: "), err
            assert sorted(p.name for p in folder.iterdir()) == ["scene.toml"]
        return rc, err
    finally:
        shutil.rmtree(folder, ignore_errors=True)


#: ``make test`` draws a sample of each fuzz; its ``slow`` twin (``make test-slow``) the long run.
QUICK, LONG = 0.25, 1.0


def _fuzz(max_examples: int, share: float, *strategies, health=(HealthCheck.too_slow,)):
    """``given(*strategies)`` with ``share`` of ``max_examples`` drawn and no deadline."""
    return lambda f: settings(max_examples=max(1, round(max_examples * share)), deadline=None,
                              suppress_health_check=list(health))(given(*strategies)(f))


def _fuzzed_scenes_keep_the_contract(content):
    check_contract(content)


SCENE_HEALTH = (HealthCheck.too_slow, HealthCheck.data_too_large)
test_fuzzed_scenes_keep_the_contract = _fuzz(
    250, QUICK, malformed_scenes(), health=SCENE_HEALTH)(_fuzzed_scenes_keep_the_contract)
test_fuzzed_scenes_keep_the_contract_at_length = pytest.mark.slow(_fuzz(
    250, LONG, malformed_scenes(), health=SCENE_HEALTH)(_fuzzed_scenes_keep_the_contract))


number_texts = st.one_of(
    st.sampled_from(["nan", "inf", "-inf", "0", "-1", "1e-300", "1e400", "1e-13", "0.5", "",
                     "1,5", "0x10", "1e", "--", "1_000", " 1e-8", "\u0661"]),
    st.floats(allow_nan=True).map(repr), st.text(max_size=6))
FLAGS = {
    "--rtol": number_texts, "--atol": number_texts, "--h": number_texts,
    "--max-steps": st.sampled_from(["0", "-5", "1", "100", "1e3", "20000", "x", "99999999999999999999"]),
    "--t-end": number_texts,  # bounded by the bases' max_steps (an adaptive run) or refused
    "--samples": st.sampled_from(["0", "1", "2", "7", "-3", "2.5", "x", "99999999999", "1e3"]),
    "--method": st.one_of(st.sampled_from(list(METHODS)), texts),
    "--formulation": st.one_of(st.sampled_from(FORMULATIONS), texts),
}


@st.composite
def flag_lists(draw):
    names = draw(st.lists(st.sampled_from(sorted(FLAGS)), min_size=1, max_size=3, unique=True))
    out = []
    for name in names:
        value = draw(FLAGS[name])
        out += [f"{name}={value}"]  # "=": a value starting with "-" stays a value
    return out


def _fuzzed_flags_keep_the_contract(base, flags):
    """Command-line overrides go through the same checks, named `simulate.<key>`."""
    rc, err = check_contract(to_toml(base).encode(), flags=flags)
    if rc == 2 and "argument" not in err:
        assert "simulate." in err or "file:" in err, err


test_fuzzed_flags_keep_the_contract = _fuzz(
    100, QUICK, st.sampled_from(BASES), flag_lists())(_fuzzed_flags_keep_the_contract)
test_fuzzed_flags_keep_the_contract_at_length = pytest.mark.slow(_fuzz(
    100, LONG, st.sampled_from(BASES), flag_lists())(_fuzzed_flags_keep_the_contract))


# Values only a Python caller can pass (a dict shaped like the TOML, not a file).
python_values = st.one_of(
    values, st.none(), st.complex_numbers(max_magnitude=10, allow_nan=False),
    st.sampled_from([np.float32(1.5), np.float64("nan"), np.int64(3), np.bool_(True),
                     np.array([1.0, 2.0, 3.0]), np.array(2.0), np.array([[1.0]]), (0.0, 0.0, 1.0),
                     {1.0, 2.0}, b"1.0", bytearray(b"x"), object(),
                     __import__("fractions").Fraction(1, 3),
                     __import__("decimal").Decimal("NaN"), __import__("decimal").Decimal("0.5")]))


@st.composite
def python_mutation(draw):
    op = draw(mutation())
    if op[0] == "set" and draw(st.booleans()):
        return ("set", op[1], op[2], draw(python_values))
    return op


def _fuzzed_dicts_through_the_api(base, ops):
    """The Python API on a dict: a result with finite arrays, or SceneError / IntegrationError
    with a one-line message; nothing else escapes, and no warning."""
    import warnings

    import derive

    scene = json.loads(json.dumps(base))
    for op in ops:
        apply(scene, op)
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        try:
            res = derive.simulate(scene)
        except (derive.SceneError, derive.IntegrationError) as err:
            assert str(err) and "\n" not in str(err)
        else:
            for name, a in res.arrays().items():
                if isinstance(a, np.ndarray) and a.dtype.kind in "fc":
                    assert np.all(np.isfinite(a)), name
    assert [str(w.message) for w in seen if issubclass(w.category, RuntimeWarning)] == []


DICT_FUZZ = (st.sampled_from(BASES), st.lists(python_mutation(), min_size=1, max_size=3))
test_fuzzed_dicts_through_the_api = _fuzz(150, QUICK, *DICT_FUZZ)(_fuzzed_dicts_through_the_api)
test_fuzzed_dicts_through_the_api_at_length = pytest.mark.slow(
    _fuzz(150, LONG, *DICT_FUZZ)(_fuzzed_dicts_through_the_api))


def test_the_bases_are_valid_and_cheap():
    """The fuzz starts from scenes that run (else it would only test the parser)."""
    for base in BASES:
        assert check_contract(to_toml(base).encode())[0] == 0


def test_the_generator_reaches_every_outcome():
    """Not a vacuous fuzz: a fixed sample of its scenes ends in success and in bad input."""
    from hypothesis import Phase, find

    for status in (0, 2):  # the first scene found is enough: no shrinking it to a minimal one
        find(malformed_scenes(), lambda c: check_contract(c)[0] == status,
             settings=settings(max_examples=500, database=None, deadline=None, phases=[Phase.generate]))


# --- the hand-written corpus ------------------------------------------------------------------


CORPUS = sorted(MALFORMED.glob("*.toml"))


def test_the_corpus_is_there():
    assert len(CORPUS) >= 30


# Files whose first line cannot carry the expectation (not UTF-8 from the first byte).
EXPECTED_BINARY = {"utf16.toml": (2, "is UTF-16 text")}


def expected(path: Path):
    """The expected exit status and message fragment, from the file's first line
    ``# expect: <status> [<fragment>]`` (the rest may be anything)."""
    if path.name in EXPECTED_BINARY:
        return EXPECTED_BINARY[path.name]
    first = path.read_bytes().split(b"\n", 1)[0].decode("utf-8", "replace").lstrip("\ufeff")
    m = re.fullmatch(r"# expect: (\d) ?(.*)", first.strip())
    assert m, f"{path.name}: first line must be '# expect: <status> [<fragment>]'"
    return int(m.group(1)), m.group(2)


@pytest.mark.parametrize("path", CORPUS, ids=lambda p: p.name)
def test_malformed_corpus(path):
    status, fragment = expected(path)
    rc, err = check_contract(path.read_bytes())
    assert rc == status, err
    assert fragment in err, err


@pytest.mark.parametrize("name", ["bad_utf8.toml", pytest.param("truncated_table.toml", marks=pytest.mark.slow),
                                  "nan_moment.toml", pytest.param("both_rates_and_omega.toml", marks=pytest.mark.slow),
                                  pytest.param("triangle.toml", marks=pytest.mark.slow)])  # a byte and a value
def test_malformed_corpus_in_a_real_process(name):
    def runner(argv):
        r = subprocess.run([sys.executable, "-m", "derive", *map(str, argv)], cwd=ROOT,
                           capture_output=True, text=True, timeout=120)
        return r.returncode, r.stdout, r.stderr

    assert check_contract((MALFORMED / name).read_bytes(), runner)[0] == 2
