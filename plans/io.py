"""Writing files the safe way: to a temporary file beside the target, then rename,
so a failure never leaves a half-written output."""

from __future__ import annotations

import os
import tomllib
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any, BinaryIO

from plans.errors import InputError, OutputError

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
    without an error; otherwise nothing is left behind (an OSError is one OutputError line)."""
    from pathlib import Path

    target = Path(path)
    folder = target.parent
    try:
        import tempfile  # loaded when a file is written: reading a scene does not pay for it

        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
    except OSError as exc:
        raise OutputError(f"cannot write to {folder}: {exc.strerror}") from None
    try:
        with os.fdopen(fd, "wb") as fh:
            yield fh
        os.chmod(tmp, 0o644)
        os.replace(tmp, target)
    except BaseException as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        if isinstance(exc, OSError):
            raise OutputError(f"cannot write {target}: {exc.strerror}") from None
        raise


def write_all(files: Mapping[Path, bytes | str]) -> list[Path]:
    """Write several files as one: every temporary first, then the renames, so an error
    (or Ctrl-C) before the renames leaves none of them and none of the old ones changed."""
    staged: list[tuple[str, Path]] = []
    try:
        for target, data in files.items():
            raw = data.encode("utf-8") if isinstance(data, str) else data
            try:
                import tempfile

                fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
            except OSError as exc:
                raise OutputError(f"cannot write to {target.parent}: {exc.strerror}") from None
            staged.append((tmp, target))
            try:
                with os.fdopen(fd, "wb") as fh:
                    fh.write(raw)
                os.chmod(tmp, 0o644)
            except OSError as exc:
                raise OutputError(f"cannot write {target}: {exc.strerror}") from None
        for tmp, target in staged:
            try:
                os.replace(tmp, target)
            except OSError as exc:
                raise OutputError(f"cannot write {target}: {exc.strerror}") from None
    finally:
        for tmp, _ in staged:
            try:
                os.unlink(tmp)
            except OSError:
                pass
    return [target for _, target in staged]


def refuse_input(output: str | Path | None, *inputs: str | Path | None) -> None:
    """An output path that names one of the inputs is refused before anything is written."""
    if output is None or str(output) == "-":
        return
    from pathlib import Path

    out = Path(output)
    for src in inputs:
        if src is None:
            continue
        try:
            same = out.exists() and Path(src).exists() and out.samefile(src)
        except OSError:
            same = False
        if same or out.resolve() == Path(src).resolve():
            raise OutputError(f"{output}: is the input file {src}; refusing to overwrite it "
                              f"(expected another path for the output)")


def dumps(data: Any) -> str:
    """Deterministic JSON; refuses NaN and inf (they must never reach an output)."""
    import json

    return json.dumps(data, ensure_ascii=False, indent=2, allow_nan=False) + "\n"


def read_toml(path: str | Path) -> dict[str, Any]:
    """A TOML file as a dict; an unreadable or malformed file is one InputError line."""
    try:
        with open(path, "rb") as fh:
            raw = fh.read()
    except OSError as exc:
        raise InputError(f"cannot read file ({exc.strerror})", file=str(path)) from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[:exc.start].count(b"\n") + 1
        raise InputError(f"not UTF-8 text (byte 0x{raw[exc.start]:02x}); expected a TOML file saved as UTF-8",
                         file=str(path), line=line) from None
    return loads_toml(text, str(path))


def loads_toml(text: str, path: str) -> dict[str, Any]:
    """TOML text as a dict; malformed TOML, or text a sheet cannot show (control characters,
    noncharacters), is one InputError line."""
    from plans.reader import check_text

    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"malformed TOML: {exc}", file=path) from None
    except RecursionError:
        raise InputError("malformed TOML: nested too deeply", file=path) from None
    check_text(data, file=path)
    return data
