"""What the tests of the Taylor solver's own arithmetic share (tests/test_taylor_trig.py,
tests/test_taylor_acos.py): a C harness compiled against the generated reduced-u solver (or
the header it takes its sin, cos and acos from), its doubles passed both ways as their bits in
hex (no decimal rounding), and the distance of two results in units in the last place."""
from __future__ import annotations

import os
import re
import subprocess

import numpy as np

from derive.codegen.render import ROOT
from tests.compile_once import files_in, once

GEN = ROOT / "generated" / "c"
PREFIX = "derive_reduced_u_sym_gravity_taylor_"


def compile_harness(tmp_path, flags, name: str, text: str):
    """The executable of the C program ``text`` (it includes generated files from GEN),
    built with ``flags`` and the Taylor method selected; kept for these exact sources, flags and
    compiler (tests/compile_once.py), so ``tmp_path`` is not written."""
    cc = os.environ.get("CC", "cc")
    cmd = [*flags, "-DDERIVE_SELECT", "-DDERIVE_WITH_TAYLOR", f"-I{GEN}", "-lm"]

    def build(work):
        src = work / f"{name}.c"
        src.write_text(text)
        subprocess.run([cc, *flags, "-DDERIVE_SELECT", "-DDERIVE_WITH_TAYLOR", f"-I{GEN}", str(src),
                        "-o", str(work / name), "-lm"], check=True, capture_output=True, text=True)

    return once(["harness", name, *cmd], {**files_in(GEN), "harness": text}, build, cc) / name


def taylor_sizes(model: str) -> dict[str, int]:
    """The sizes a model's ``<model>_taylor.c`` defines for the shared Taylor text (``NW``,
    ``NTRIG``, ...: its ``#define DERIVE_T_<name> <number>``), and ``NV``, the values a sample
    of a block holds (the columns, then a sin and a cos per pointwise angle)."""
    text = (GEN / f"{model}_taylor.c").read_text()
    sizes = {k: int(v) for k, v in re.findall(r"^#define DERIVE_T_(\w+) (\d+)$", text, re.M)}
    sizes["NV"] = sizes["NW"] + 2 * sizes["NTRIG"]
    return sizes


def run_bits(exe, x: np.ndarray) -> np.ndarray:
    """The harness's rows of doubles for the arguments ``x``, bits in and bits out (each written
    as 16 hex digits, ``%016llx``, the same number on every line)."""
    text = "\n".join(f"{b:x}" for b in x.view(np.uint64))
    out = subprocess.run([str(exe)], input=text, capture_output=True, text=True, check=True).stdout
    lines = out.splitlines()
    width = len(lines[0].split()) if lines else 0
    digits = "".join(out.split())
    assert len(digits) == 16 * width * len(lines), "a value not written as 16 hex digits, or a short line"
    # (read in one call: the rows are long, and a Python int per value costs more than the run)
    bits = np.frombuffer(bytes.fromhex(digits), dtype=">u8").astype(np.uint64)
    return bits.reshape(len(lines), width).view(np.float64)


def ulps(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The distance in units in the last place (doubles as ordered integers)."""
    def ordered(z):
        i = z.view(np.int64).astype(np.int64)
        return np.where(i < 0, np.int64(-(2 ** 63)) - i, i)
    return np.abs(ordered(a) - ordered(b))
