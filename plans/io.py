"""Reading and writing files the safe way: every file read is an input of the command in
progress, every file written goes to a temporary file beside its target and is renamed
only when the whole command has succeeded and no target is an input (:mod:`plans.guard`),
so a failure never leaves a half-written output and no input is ever overwritten."""

from __future__ import annotations

import os
import sys
import tomllib
from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any, BinaryIO

from plans.errors import InputError, OutputError, Said, os_reason

if TYPE_CHECKING:  # pathlib is loaded where a file is written: reading a scene does without it
    from pathlib import Path


def atomic_write(path: str | Path, data: bytes | str) -> None:
    """Write to a temporary file in the same folder, then rename over ``path``;
    a failure leaves nothing behind and is one OutputError line."""
    raw = data.encode("utf-8") if isinstance(data, str) else data
    with atomic_file(path) as fh:
        fh.write(raw)


@contextmanager
def atomic_file(path: str | Path) -> Iterator[BinaryIO]:
    """A binary file to write in pieces, renamed over ``path`` only when the block ends
    without an error (inside a command: when the whole command has succeeded, see
    :mod:`plans.guard`); otherwise nothing is left behind (an OSError is one OutputError line)."""
    from plans import guard

    run = guard.current()
    target = os.fspath(path)
    if run is not None:
        run.refuse_input(target)
    tmp, fd = _temporary(target)
    try:
        with os.fdopen(fd, "wb") as fh:
            yield fh
        os.chmod(tmp, 0o644)
        if run is not None:
            run.stage(tmp, target)
        else:
            os.replace(tmp, target)
    except BaseException as exc:
        if run is None or tmp not in (t for t, _ in run.staged.values()):
            _unlink(tmp)
        if isinstance(exc, OSError):
            raise OutputError(Said("o_write", target=str(target), why=os_reason(exc))) from None
        raise


def _temporary(target: str) -> tuple[str, int]:
    """A new temporary file beside ``target`` (its path and descriptor)."""
    folder = os.path.dirname(target) or "."
    if os.path.isdir(target):
        raise OutputError(Said("o_folder", target=str(target)))
    try:
        return _mkstemp(folder, f".{os.path.basename(target)}.", ".tmp")
    except OSError as exc:
        raise OutputError(Said("o_write_to", folder=str(folder), why=os_reason(exc))) from None


def _mkstemp(folder: str, prefix: str, suffix: str) -> tuple[str, int]:
    """``tempfile.mkstemp`` as this module uses it (a new file only its owner may read,
    under a random name), without importing tempfile: with shutil, random and the
    compression modules it loads, that is a few milliseconds of every ``plans solve --json``."""
    flags = os.O_RDWR | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_BINARY", 0)
    for _ in range(10000):  # tempfile.TMP_MAX
        tmp = os.path.join(folder, f"{prefix}{os.urandom(6).hex()}{suffix}")
        try:
            return tmp, os.open(tmp, flags, 0o600)
        except FileExistsError:
            continue
    raise FileExistsError(f"no usable temporary name in {folder}")


def _unlink(path: str) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass


def write_all(files: Mapping[Path, bytes | str]) -> list[Path]:
    """Write several files as one: every temporary first, then (every target checked: not an
    input, not a folder) the renames, so an error (or Ctrl-C) before the renames leaves none
    of them and none of the old ones changed.  Inside a command the renames wait for the
    end of the whole command (:mod:`plans.guard`)."""
    from plans import guard

    run = guard.current()
    own = run is None
    if own:
        run = guard.Run()
    assert run is not None
    try:
        for target, data in files.items():
            raw = data.encode("utf-8") if isinstance(data, str) else data
            t = os.fspath(target)
            run.refuse_input(t)
            tmp, fd = _temporary(t)
            try:
                with os.fdopen(fd, "wb") as fh:
                    fh.write(raw)
                os.chmod(tmp, 0o644)
            except BaseException as exc:
                _unlink(tmp)
                if isinstance(exc, OSError):
                    raise OutputError(Said("o_write", target=str(t), why=os_reason(exc))) from None
                raise
            run.stage(tmp, t)
        if own:
            run.commit()
    finally:
        if own:
            run.discard()
    return [target for target in files]


def remove(paths: Iterable[str | Path]) -> None:
    """Remove old outputs (already gone is fine; an input is never removed); inside a
    command only when the whole command has succeeded."""
    from plans import guard

    run = guard.current()
    if run is not None:
        run.remove(paths)
        return
    for p in paths:
        _unlink(os.fspath(p))


def staged_bytes(path: str | Path) -> bytes | None:
    """What the command in progress has written for ``path`` so far (None: nothing)."""
    from plans import guard

    run = guard.current()
    return None if run is None else run.staged_bytes(path)


def refuse_input(output: str | Path | None, *inputs: str | Path | None) -> None:
    """An output path that names one of the inputs (by any spelling: links, relative or
    absolute, a hard link) is refused before anything is written."""
    if output is None or str(output) == "-":
        return
    from plans import guard

    check = guard.Run()
    for src in inputs:
        if src is not None:
            check.read(src)
    check.refuse_input(output)


def dumps(data: Any) -> str:
    """Deterministic JSON; refuses NaN and inf (they must never reach an output)."""
    import json

    return json.dumps(data, ensure_ascii=False, indent=2, allow_nan=False) + "\n"


def json_out(where: str | None, text: str) -> bool:
    """A command's JSON to stdout (``-``: then True, the command prints nothing else) or to
    the file ``where`` (none when ``where`` is empty)."""
    if where == "-":
        sys.stdout.write(text)
        return True
    if where:
        atomic_write(where, text)
    return False


def read_toml(path: str | Path) -> dict[str, Any]:
    """A TOML file as a dict; an unreadable or malformed file is one InputError line."""
    from plans import guard

    try:
        with open(path, "rb") as fh:
            raw = fh.read()
    except OSError as exc:
        raise InputError(Said("e_read", why=os_reason(exc)), file=str(path)) from None
    except ValueError as exc:  # a path holding a NUL
        raise InputError(Said("e_read", why=str(exc)), file=str(path)) from None
    run = guard.current()
    if run is not None:
        run.read(path)
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[:exc.start].count(b"\n") + 1
        raise InputError(Said("e_utf8", byte=raw[exc.start]), file=str(path), line=line) from None
    return loads_toml(text, str(path))


#: The deepest nesting of tables and arrays a file of the family may have (the deepest
#: sample has 5): every reader walks a file recursively.
MAX_DEPTH = 32


def _check_depth(data: Any, path: str) -> None:
    """Refuse tables and arrays nested deeper than MAX_DEPTH (walked without recursion; the
    field named only when there is one to name)."""
    flat: list[tuple[Any, int]] = [(data, 0)]
    while flat:
        node, depth = flat.pop()
        if depth > MAX_DEPTH:
            break
        if isinstance(node, dict):
            flat.extend((v, depth + 1) for v in node.values())
        elif isinstance(node, list):
            flat.extend((v, depth + 1) for v in node)
    else:
        return
    stack = [(data, 0, "")]
    while stack:
        node, depth, where = stack.pop()
        if depth > MAX_DEPTH:
            raise InputError(Said("e_depth", n=MAX_DEPTH),
                             file=path, field=where[:80] + ("..." if len(where) > 80 else ""))
        if isinstance(node, dict):
            stack.extend((v, depth + 1, f"{where}.{k}" if where else str(k)) for k, v in node.items())
        elif isinstance(node, list):
            stack.extend((v, depth + 1, f"{where}[{i}]") for i, v in enumerate(node))


def _toml_error(why: str) -> Said:
    """The TOML parser's complaint (its own words, in English) with its place in the file."""
    import re

    at = re.fullmatch(r"(.*) \(at line (\d+), column (\d+)\)", why, re.S)
    if at:
        return Said("e_toml_at", why=at.group(1), line=int(at.group(2)), col=int(at.group(3)))
    if why.endswith(" (at end of document)"):
        return Said("e_toml_end", why=why[:-len(" (at end of document)")])
    return Said("e_toml", why=why)


def _decimal_comma(text: str, why: str, path: str) -> InputError | None:
    """The error of a number written with a decimal comma (``omega = 1,5``: a bare TOML
    error otherwise), naming the line, its key and the number as it should be written."""
    import re

    at = re.search(r"at line (\d+)", why)
    lines = text.splitlines()
    if at is None or not 0 < int(at.group(1)) <= len(lines):
        return None
    n = int(at.group(1))
    line = lines[n - 1].split("#", 1)[0]
    key = re.match(r"\s*([\w.\"-]+)\s*=", line)
    got = re.search(r"=[^\"']*?(?<![\w.,])([-+]?\d+),(\d+)(?![\d.,])", line)
    if key is None or got is None:
        return None
    table = next((m.group(1).strip() for m in (re.match(r"\s*\[\[?([^\]]+)\]", s) for s in reversed(lines[:n - 1]))
                  if m), "")
    written = f"{got.group(1)},{got.group(2)}"
    return InputError(Said("e_decimal_comma", text=written, fixed=f"{got.group(1)}.{got.group(2)}"), file=path,
                      line=n, field=(f"{table}." if table else "") + key.group(1).strip('"'))


def loads_toml(text: str, path: str) -> dict[str, Any]:
    """TOML text as a dict; malformed TOML, or text a sheet cannot show (control characters,
    noncharacters), is one InputError line."""
    from plans.reader import check_text

    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise _decimal_comma(text, str(exc), path) or InputError(_toml_error(str(exc)), file=path) from None
    except RecursionError:
        raise InputError(Said("e_toml", why="nested too deeply"), file=path) from None
    _check_depth(data, path)
    check_text(data, file=path)
    return data
