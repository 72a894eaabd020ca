"""The one Jinja2 environment every generator renders through, and where its data lives.

Templates live in the repository's top-level ``templates/`` folder and the committed output in
``generated/`` (the design card's layout). An installed wheel carries both inside the package,
as ``derive/_templates`` and ``derive/_generated`` (the ``package-dir`` mapping in
``pyproject.toml``), found through :mod:`importlib.resources`. A source checkout (this package
beside a ``pyproject.toml`` and ``templates/``, also an editable install) always uses its
top-level folders, so editing a template takes effect without reinstalling.

The environment is strict (an undefined name is an error, not an empty string) and keeps output
byte-stable: no timestamps, trailing newline kept, block tags leave no stray whitespace.
"""
from __future__ import annotations

import functools
import importlib.resources
from pathlib import Path

#: The folder holding the ``derive`` package: the repository root in a checkout; in an installed
#: package it is ``site-packages`` (no ``scenes/`` or ``derive/bench/baselines/`` there).
ROOT = Path(__file__).resolve().parents[2]
#: The source checkout's root, or None when running from an installed package.
CHECKOUT: Path | None = (ROOT if (ROOT / "pyproject.toml").is_file() and (ROOT / "templates").is_dir()
                         else None)


def data_dir(name: str) -> Path:
    """``<checkout>/<name>`` in a checkout, else the copy shipped in the package (``derive/_<name>``)."""
    if CHECKOUT is not None:
        return CHECKOUT / name
    # A wheel installs as plain files, so the resource is a real directory (Jinja2 needs a path).
    return Path(str(importlib.resources.files("derive") / f"_{name}"))


TEMPLATES = data_dir("templates")
#: The C runtime every model's solvers share (``derive.codegen.sources.runtime_sources``), one
#: copy in ``generated/c`` beside the models.
RUNTIME_FILES = ("derive_runtime.h", "derive_runtime.c", "derive_libm.h", "derive_solvers.inc")
#: The Taylor methods' shared text every model's Taylor solvers include: the sizes and vector
#: types its jet is written against, then the drivers (``derive.codegen.taylor.taylor_shared``).
TAYLOR_INCS = ("derive_taylor_base.inc", "derive_taylor.inc")
GENERATED = data_dir("generated")


def c_double(x) -> str:
    """A float as a C double literal that round-trips exactly (17 significant digits)."""
    x = float(x)
    if x == int(x) and abs(x) < 1e15:
        return f"{int(x)}.0"
    return repr(x)


def c_id(prefix: str | None, rest: str) -> str:
    """A model's C name: ``<prefix>_<rest>``, or ``DERIVE_M(rest)`` in the shared solver file
    (``derive_solvers.inc``), whose model is a macro (``DERIVE_MODEL``)."""
    return f"DERIVE_M({rest})" if prefix is None else f"{prefix}_{rest}"


def c_static_id(prefix: str | None, rest: str) -> str:
    """A model's file-local C name: ``<prefix><rest>`` (``prefix`` ends in ``_``), or
    ``DERIVE_S(rest)`` in the shared solver file (``derive_<model>_<rest>`` once expanded)."""
    return f"DERIVE_S({rest})" if prefix is None else f"{prefix}{rest}"


@functools.lru_cache(maxsize=None)
def environment():
    # Jinja2 is imported here, not at module level: the warm path (a model already generated)
    # reads GENERATED but renders nothing.
    import jinja2

    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(TEMPLATES)),
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
        autoescape=False,
    )
    env.filters["c_double"] = c_double
    env.globals.update(cid=c_id, sid=c_static_id)
    return env


def render(template: str, **context) -> str:
    """Render ``templates/<template>`` with ``context``."""
    return environment().get_template(template).render(**context)
