"""The one Jinja2 environment every generator renders through.

Templates live in the repository's top-level ``templates/`` folder (the design card's layout).
The environment is strict (an undefined name is an error, not an empty string) and keeps output
byte-stable: no timestamps, trailing newline kept, block tags leave no stray whitespace.
"""
from __future__ import annotations

import functools
from pathlib import Path

import jinja2

ROOT = Path(__file__).resolve().parent.parent
TEMPLATES = ROOT / "templates"
GENERATED = ROOT / "generated"


def c_double(x) -> str:
    """A float as a C double literal that round-trips exactly (17 significant digits)."""
    x = float(x)
    if x == int(x) and abs(x) < 1e15:
        return f"{int(x)}.0"
    return repr(x)


@functools.lru_cache(maxsize=None)
def environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(TEMPLATES)),
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
        autoescape=False,
    )
    env.filters["c_double"] = c_double
    return env


def render(template: str, **context) -> str:
    """Render ``templates/<template>`` with ``context``."""
    return environment().get_template(template).render(**context)
