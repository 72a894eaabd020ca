"""The one reader of scene and sweep files: a regular UTF-8 TOML file of bounded size and depth,
every problem one line ``<file>: <where>: <what>``.

Takes: a path. Gives: the TOML document as a dict.
"""
from __future__ import annotations

import os
import re
import stat
import tomllib

from derive.errors import scene_error
from derive.sim import examples


#: Largest scene or sweep file read, in bytes (1 MiB; a scene is a few hundred bytes, a sweep a
#: few kilobytes): a bigger file is refused before it is read, so that a wrong path (a log, a
#: disk image) cannot exhaust memory.
MAX_SCENE_BYTES = 1 << 20


_BOMS = {b"\xef\xbb\xbf": None, b"\xff\xfe": "UTF-16", b"\xfe\xff": "UTF-16",
         b"\xff\xfe\x00\x00": "UTF-32", b"\x00\x00\xfe\xff": "UTF-32"}


def read_toml(source: str, kind: str = "scene") -> dict:
    """Read and parse a scene or sweep file: the one reader of both (``derive.sweeps`` too).

    Parameters
    ----------
    source : str
        The path, as the user gave it (it names the file in every message).
    kind : str
        "scene" or "sweep": the word in "not a <kind> file".

    Returns
    -------
    dict
        The TOML document.

    Raises
    ------
    SceneError
        ``<file>: file: <what>`` when the file is missing, unreadable, a directory, not a regular
        file (a FIFO, a device such as /dev/zero: refused before a byte is read, so nothing
        blocks or reads forever), larger than ``MAX_SCENE_BYTES``, not UTF-8 (a byte-order mark
        is skipped), nested deeper than ``MAX_SCENE_DEPTH``; ``<file>: line L, column C:
        invalid TOML: <what>`` for a syntax error (a key given twice among them).
    """
    shown = source.replace("\0", "\\0")  # a NUL byte would end the error line early

    def fail(what):
        return scene_error(shown, "file", what)

    if "\0" in source:  # open() would raise a bare ValueError
        raise fail("not a file name (it holds a NUL byte)")
    try:
        # O_NONBLOCK: opening a FIFO for reading would wait for a writer; with it, open returns
        # at once and fstat refuses the FIFO (regular files ignore the flag).
        fd = os.open(source, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except FileNotFoundError as err:
        raise fail("not found" + examples.did_you_mean(source, kind)) from err
    except IsADirectoryError as err:
        raise fail(f"is a directory, not a {kind} file") from err
    except PermissionError as err:
        raise fail("permission denied") from err
    except OSError as err:
        raise fail(f"cannot read ({err.strerror or err})") from err
    try:
        st = os.fstat(fd)
        if stat.S_ISDIR(st.st_mode):
            raise fail(f"is a directory, not a {kind} file")
        if not stat.S_ISREG(st.st_mode):
            raise fail("not a regular file")  # a device, FIFO or socket
        if st.st_size > MAX_SCENE_BYTES:
            raise fail(f"larger than {_size(MAX_SCENE_BYTES)}: not a {kind} file")
        with os.fdopen(fd, "rb") as f:
            fd = None
            raw = f.read(MAX_SCENE_BYTES + 1)  # + 1: a file that grew since fstat is caught too
    except OSError as err:
        raise fail(f"cannot read ({err.strerror or err})") from err
    finally:
        if fd is not None:
            os.close(fd)
    if len(raw) > MAX_SCENE_BYTES:
        raise fail(f"larger than {_size(MAX_SCENE_BYTES)}: not a {kind} file")
    for bom in sorted(_BOMS, key=len, reverse=True):
        if raw.startswith(bom):
            if _BOMS[bom]:
                raise fail(f"is {_BOMS[bom]} text; {kind} files are UTF-8")
            raw = raw[len(bom):]
            break
    try:
        data = tomllib.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as err:
        raise fail(f"not UTF-8 text (bad byte at offset {err.start})") from err
    except RecursionError as err:
        raise fail("invalid TOML: nested too deeply") from err
    except tomllib.TOMLDecodeError as err:
        # tomllib (3.11) puts the position at the end of its message: "... (at line 3, column 7)".
        match = re.fullmatch(r"(.*) \(at (line \d+, column \d+|end of document)\)", str(err))
        where, what = (match.group(2), match.group(1)) if match else ("file", str(err))
        raise scene_error(shown, where, f"invalid TOML: {what}") from err
    if _depth(data) > MAX_SCENE_DEPTH:
        raise fail(f"values nested deeper than {MAX_SCENE_DEPTH} levels: not a {kind} file")
    return data


def _size(n: int) -> str:
    """A byte count as the limit is documented: 1 MiB, 512 KiB."""
    return f"{n / 2**20:g} MiB" if n >= 2**20 else f"{n / 2**10:g} KiB"


MAX_SCENE_DEPTH = 16  # a scene needs 3 (table, key, vector); the checks recurse into values


def _depth(value) -> int:
    """How deeply lists and tables nest in ``value`` (without recursion: any depth is safe)."""
    deepest, stack = 0, [(value, 0)]
    while stack:
        v, d = stack.pop()
        deepest = max(deepest, d)
        if isinstance(v, dict):
            stack.extend((x, d + 1) for x in v.values())
        elif isinstance(v, list):
            stack.extend((x, d + 1) for x in v)
    return deepest
