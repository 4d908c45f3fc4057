"""The file family: every input file is TOML with ``format = 1`` and a ``kind``.

``kind`` tells which room reads the file: a linkage scene (the default, no ``kind``
needed), an engine for balancing, a gear pair or train, a cam.  The CLI and
``plans draw`` dispatch on it.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from plans.errors import InputError, Said
from plans.io import read_toml
from plans.reader import check_keys, did_you_mean, show

#: kind -> (the pure command that solves it, the module of drawings that draws it)
KINDS: dict[str, tuple[str, str]] = {
    "linkage": ("solve", "drawings.linkage"),
    "engine": ("balance", "drawings.balancing"),
    "gears": ("gears", "drawings.gears"),
    "cam": ("cam", "drawings.cams"),
    "synthesis": ("design", "drawings.synthesis"),
}

#: kind -> the reader of its table ("module:function(data, path)"), which keeps the promise
#: (every problem one InputError naming file and field); the fuzzer drives each one.
READERS: dict[str, str] = {
    "linkage": "plans.kinematics.placing:scene_from_dict",  # read, then positions placed
    "engine": "plans.balancing.engine:engine_from_dict",
    "gears": "plans.gears.model:parse_gears",
    "cam": "plans.cams.model:cam_from_dict",
    "synthesis": "plans.synthesis.model:task_from_dict",
}


def kind_of(data: dict[str, Any], path: str) -> str:
    """The file's kind (``"linkage"`` when absent); an unknown kind is one InputError line."""
    kind = data.get("kind", "linkage")
    if not isinstance(kind, str) or kind not in KINDS:
        raise InputError(Said("e_kind", kinds=", ".join(repr(k) for k in KINDS), got=show(kind), hint=""),
                         file=path, field="kind")
    return kind


def read_kind(path: str | Path) -> tuple[str, dict[str, Any]]:
    """Read a file of the family: its kind and its table."""
    data = read_toml(path)
    return kind_of(data, str(path)), data


def command_for(kind: str) -> Said | str:
    """A hint naming the command for a file of this kind ("" when unknown)."""
    if kind == "check":
        return Said("e_use", command="plans check")
    if isinstance(kind, str) and kind in KINDS:
        return Said("e_use", command=f"plans {KINDS[kind][0]}")
    return ""


def _name(kind: str) -> Said:
    """A kind as a message names it (a kind added later: "a synthesis file")."""
    from plans.language import ERRORS

    return Said(f"e_a_{kind}") if f"e_a_{kind}" in ERRORS else Said("e_a_kind", kind=kind)


def guess_kind(data: dict[str, Any]) -> str:
    """What a file is, for a message: its ``kind``, or a check file (a ``scene`` to check
    against), or a linkage scene."""
    kind = data.get("kind")
    if isinstance(kind, str) and kind in KINDS:
        return kind
    if kind is None and isinstance(data.get("scene"), str):
        return "check"
    return "linkage"


def check_top(data: dict[str, Any], path: str, kind: str, known: Any) -> None:
    """The top level of a file of ``kind`` (``"check"`` for a check file, which has no
    ``kind``): ``format = 1`` exactly, the right kind (a file of another kind is named as
    such, with its command), and no unknown key ("did you mean ...")."""
    fmt = data.get("format")
    kval = data.get("kind")
    if kind == "check":
        right = "kind" not in data and ("scene" in data or not {"links", "joints", "driver"} & set(data))
    elif kind == "linkage":
        right = kval == "linkage" or ("kind" not in data and guess_kind(data) == "linkage")
    else:
        right = kval == kind
    if not right:
        if "kind" in data and not (isinstance(kval, str) and kval in KINDS):
            hint = did_you_mean(kval, KINDS) if isinstance(kval, str) else ""
            want = Said("e_no_kind") if kind == "check" else f"kind = {kind!r}"
            raise InputError(Said("e_kind_here", kinds=", ".join(repr(k) for k in KINDS), want=want, got=show(kval),
                                  hint=hint), file=path, field="kind")
        other = guess_kind(data)
        raise InputError(Said("e_kind_other", other=_name(other), kind=_name(kind), command=command_for(other),
                              want=Said("e_want_check") if kind == "check" else Said("e_want_linkage")
                              if kind == "linkage" else f"kind = {kind!r}"), file=path, field="kind")
    if isinstance(fmt, bool) or not isinstance(fmt, int) or fmt != 1:
        raise InputError(Said("e_format", got=Said("e_nothing") if fmt is None else show(fmt)), file=path,
                         field="format")
    check_keys(data, known, file=path, where="")
