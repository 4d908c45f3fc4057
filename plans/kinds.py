"""The file family: every input file is TOML with ``format = 1`` and a ``kind``.

``kind`` tells which room reads the file: a linkage scene (the default, no ``kind``
needed), an engine for balancing, a gear pair or train, a cam.  The CLI and
``plans draw`` dispatch on it.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from plans.errors import InputError
from plans.io import read_toml

#: kind -> (the pure command that solves it, the module of drawings that draws it)
KINDS: dict[str, tuple[str, str]] = {
    "linkage": ("solve", "drawings.linkage"),
    "engine": ("balance", "drawings.balancing"),
    "gears": ("gears", "drawings.gears"),
    "cam": ("cam", "drawings.cams"),
    "synthesis": ("design", "drawings.synthesis"),
}


def kind_of(data: dict[str, Any], path: str) -> str:
    """The file's kind (``"linkage"`` when absent); an unknown kind is one InputError line."""
    kind = data.get("kind", "linkage")
    if not isinstance(kind, str) or kind not in KINDS:
        raise InputError(f"expected one of {', '.join(repr(k) for k in KINDS)}, got {kind!r}",
                         file=path, field="kind")
    return kind


def read_kind(path: str | Path) -> tuple[str, dict[str, Any]]:
    """Read a file of the family: its kind and its table."""
    data = read_toml(path)
    return kind_of(data, str(path)), data


def command_for(kind: str) -> str:
    """A hint naming the command for a file of this kind ("" when unknown)."""
    if isinstance(kind, str) and kind in KINDS:
        return f"use 'plans {KINDS[kind][0]}' for it; "
    return ""
