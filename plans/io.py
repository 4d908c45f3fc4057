"""Writing files the safe way: to a temporary file beside the target, then rename,
so a failure never leaves a half-written output."""

from __future__ import annotations

import json
import os
import tempfile
import tomllib
from pathlib import Path
from typing import Any

from plans.errors import InputError, OutputError


def atomic_write(path: str | Path, data: bytes | str) -> None:
    """Write to a temporary file in the same folder, then rename over ``path``;
    a failure leaves nothing behind and is one OutputError line."""
    target = Path(path)
    raw = data.encode("utf-8") if isinstance(data, str) else data
    folder = target.parent
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
    except OSError as exc:
        raise OutputError(f"cannot write to {folder}: {exc.strerror}") from None
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(raw)
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


def dumps(data: Any) -> str:
    """Deterministic JSON; refuses NaN and inf (they must never reach an output)."""
    return json.dumps(data, ensure_ascii=False, indent=2, allow_nan=False) + "\n"


def read_toml(path: str | Path) -> dict[str, Any]:
    """A TOML file as a dict; an unreadable or malformed file is one InputError line."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as exc:
        raise InputError(f"cannot read file ({exc.strerror})", file=str(path)) from None
    return loads_toml(text, str(path))


def loads_toml(text: str, path: str) -> dict[str, Any]:
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"malformed TOML: {exc}", file=path) from None
