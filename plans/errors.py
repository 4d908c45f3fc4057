"""One failure family for the whole engine.

User errors (bad scene or check files) are :class:`InputError`: the CLI prints
their one-line message and exits with status 2.  Geometry that cannot be
constructed is :class:`ConstructionError`, which names the group, the point and
the crank angle, never returns NaN.
"""

from __future__ import annotations


class PlansError(Exception):
    """Base of every error the engine raises on purpose."""

    #: The input file the error is about, when the message does not name it already.
    source: str | None = None


def one_line(exc: BaseException) -> str:
    """The error as the one line the command prints: the file first, whitespace folded."""
    text = " ".join(str(exc).split())
    source = getattr(exc, "source", None)
    if source and not text.startswith(source):
        text = f"{source}: {text}"
    return text


class InputError(PlansError):
    """A malformed or impossible input file: says file, field and what was expected."""

    def __init__(self, message: str, *, file: str | None = None, field: str | None = None,
                 line: int | None = None) -> None:
        self.file = file
        self.field = field
        self.line = line
        self.detail = message
        where = file or "<scene>"
        if line is not None:
            where += f":{line}"
        if field:
            where += f": {field}"
        super().__init__(f"{where}: {message}")


class OutputError(PlansError):
    """An output file or folder that cannot be written."""


class ConstructionError(PlansError):
    """A construction that has no answer (not assemblable, locked)."""

    def __init__(self, message: str, *, group: str | None = None, point: str | None = None,
                 phi_deg: float | None = None) -> None:
        self.group = group
        self.point = point
        self.phi_deg = phi_deg
        parts = []
        if group:
            parts.append(f"group {group}")
        if point:
            parts.append(f"point {point}")
        if phi_deg is not None:
            parts.append(f"phi = {phi_deg:g} deg")
        prefix = ", ".join(parts)
        super().__init__(f"{prefix}: {message}" if prefix else message)


class NotAssemblable(ConstructionError):
    """The links of a group cannot be joined at this crank angle."""


class Locked(ConstructionError):
    """The group is at a locking position: its velocity equations are singular."""


class Indeterminate(Locked):
    """The group's construction lines coincide (a change point): its plan has no single answer."""
