"""An FMI 2.0 FMU's packaging, shared by every model's export: the units its variables may
carry, the standard's headers, the platform's binaries folder, compiling ``fmu.c`` with the C
compiler alone, and the byte-stable archive.
"""
from __future__ import annotations

import hashlib
import platform
import subprocess
import sys
import tempfile
import zipfile
from dataclasses import dataclass
from pathlib import Path
from xml.sax.saxutils import escape

from derive.codegen.render import render
from derive.errors import CompilerError, SceneError
from derive.runtime.cbuild import compiler

#: The standard's headers, copied unchanged into every FMU's sources/.
HEADERS = ("fmi2Functions.h", "fmi2FunctionTypes.h", "fmi2TypesPlatform.h")

#: The units the FMU's variables may carry, as SI base-unit exponents.
UNITS = {
    "rad": (("rad", 1),),
    "rad/s": (("rad", 1), ("s", -1)),
    "s": (("s", 1),),
    "kg": (("kg", 1),),
    "m": (("m", 1),),
    "m/s^2": (("m", 1), ("s", -2)),
    "kg m^2": (("kg", 1), ("m", 2)),
    "kg m^2/s": (("kg", 1), ("m", 2), ("s", -1)),
    "N m s": (("kg", 1), ("m", 2), ("s", -1)),
    "J": (("kg", 1), ("m", 2), ("s", -2)),
    "kg^2 m^4/s^2": (("kg", 2), ("m", 4), ("s", -2)),
    "m/s": (("m", 1), ("s", -1)),
    "N": (("kg", 1), ("m", 1), ("s", -2)),
    "N s/m": (("kg", 1), ("s", -1)),
    "kg m^3/s": (("kg", 1), ("m", 3), ("s", -1)),
}


@dataclass
class Var:
    """One ScalarVariable: ``vr`` its value reference, ``kind``/``index`` where fmu.c keeps it."""

    name: str
    vr: int
    kind: str
    index: int
    type: str
    causality: str | None
    variability: str
    initial: str | None
    start: str | None
    unit: str
    doc: str
    derivative: int | None = None


def guid(*parts) -> str:
    """An FMU's GUID: the SHA-256 of what it is built from (``repr(parts)``), as 8-4-4-4-12 hex."""
    d = hashlib.sha256(repr(parts).encode()).hexdigest()
    return "{%s-%s-%s-%s-%s}" % (d[:8], d[8:12], d[12:16], d[16:20], d[20:32])


def platform_folder() -> tuple[str, str]:
    """(binaries folder, shared-library suffix) of this machine, as FMI 2.0 names them."""
    bits = "64" if sys.maxsize > 2**32 else "32"
    system = platform.system()
    if system == "Linux":
        return f"linux{bits}", ".so"
    if system == "Darwin":
        return f"darwin{bits}", ".dylib"
    raise SceneError(f"derive export: --fmu: building an FMU on {system} is not supported "
                     f"(Linux or macOS)")


def model_identifier(b) -> str:
    """An FMU's model identifier (a C identifier, the binary's name): model and method."""
    return f"{b.name}_{b.method}"


def version() -> str:
    """derive's version for generationTool (the distribution's; the package root is a layer
    above this stage)."""
    from importlib.metadata import PackageNotFoundError, packages_distributions, version

    try:    # the distribution that installs the package derive (derive.DISTRIBUTION)
        return version(packages_distributions().get("derive", ["derive-rigid-body"])[0])
    except PackageNotFoundError:
        return "(source checkout)"


def model_description(template: str, vs: list[Var], **context) -> str:
    """``modelDescription.xml`` from ``templates/<template>`` with the variables ``vs`` (in
    value-reference order): the units they carry and the ModelStructure's outputs, derivatives
    and initial unknowns, which count the variables from 1."""
    return render(template, x=lambda text: escape(str(text), {'"': "&quot;"}), version=version(),
                  variables=vs, units=[(u, UNITS[u]) for u in sorted({v.unit for v in vs if v.unit})],
                  outputs=[v.vr + 1 for v in vs if v.causality == "output"],
                  derivatives=[v.vr + 1 for v in vs if v.kind == "V_DERIV"],
                  initial_unknowns=[v.vr + 1 for v in vs if v.initial == "calculated"], **context)


def archive(src: dict[str, str], xml: str, ID: str) -> dict[str, bytes]:
    """The FMU's files from its ``sources/`` (``fmu.c`` includes the rest) and
    modelDescription.xml: the binary ``ID`` compiled here with the C compiler alone."""
    folder, suffix = platform_folder()
    with tempfile.TemporaryDirectory(prefix="derive-fmu-") as tmp:
        work = Path(tmp)
        for name, text in src.items():
            (work / name).write_text(text, encoding="utf-8")
        lib = work / f"{ID}{suffix}"
        cmd = [*compiler(), "-std=c99", "-O2", "-fPIC", "-shared",
               "-Werror=implicit-function-declaration", "-o", str(lib), "fmu.c", "-lm"]
        try:
            proc = subprocess.run(cmd, cwd=work, capture_output=True, text=True)
        except OSError as exc:
            raise CompilerError(f"no working C compiler: {cmd[0]!r} cannot be run "
                                f"({exc.strerror or exc}); install gcc or set CC") from None
        if proc.returncode != 0:
            head = "\n".join(proc.stderr.strip().splitlines()[:20])
            raise CompilerError(f"compiling the FMU failed ({' '.join(cmd)}):\n{head}")
        binary = lib.read_bytes()
    files = {"modelDescription.xml": xml.encode("utf-8"),
             f"binaries/{folder}/{ID}{suffix}": binary}
    files.update({f"sources/{name}": text.encode("utf-8") for name, text in src.items()})
    return files


def zip_files(files: dict[str, bytes], fh) -> None:
    """The archive, byte-stable: entries in a fixed order with a fixed time stamp."""
    with zipfile.ZipFile(fh, "w", compression=zipfile.ZIP_DEFLATED) as zf:
        for name in sorted(files, key=lambda n: (n != "modelDescription.xml", n)):
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            info.external_attr = 0o644 << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            zf.writestr(info, files[name])


