"""One guard over a command's inputs and outputs, for every command by construction.

:func:`plans.cli.run` runs each command inside a :class:`Run`.  Every file read through
:func:`plans.io.read_toml` is recorded as an input (its device and inode, and its path
resolved); every file written through :mod:`plans.io` (``atomic_write``, ``atomic_file``,
``write_all``) goes to a temporary file beside its target and stays there; removals of
old outputs (:func:`plans.io.remove`) wait too.  When the command returns, every target is
checked (not an input by any spelling: a symbolic link, ``./``, a relative or absolute
path, a hard link; not a folder), and only then are the temporaries renamed over their
targets.  A command that fails (an error, Ctrl-C) leaves nothing of its run.

Outside a run (a library call, a test) the same functions write at once, as one file or
one set of files each.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from typing import Any

from plans.errors import OutputError, Said, os_reason

_ACTIVE: list[Run] = []


def current() -> Run | None:
    """The run in progress, or None outside a command."""
    return _ACTIVE[-1] if _ACTIVE else None


def abandon() -> None:
    """Drop everything the command in progress has staged: a command that catches its own
    error and answers with status 2 leaves nothing of its run."""
    run = current()
    if run is not None:
        run.discard()


def _identity(path: str) -> tuple[int, int] | None:
    try:
        st = os.stat(path)
    except (OSError, ValueError):
        return None
    return (st.st_dev, st.st_ino)


def _real(path: str) -> str:
    try:
        return os.path.realpath(path)
    except (OSError, ValueError):  # a loop of links: realpath(strict) is not used, but be safe
        return os.path.abspath(path)


class Run:
    """The inputs read and the outputs staged by one command."""

    def __init__(self) -> None:
        self.inputs: dict[str, tuple[tuple[int, int] | None, str]] = {}
        self.staged: dict[str, tuple[str, str]] = {}  # real target -> (temporary, target as given)
        self.removals: list[str] = []

    # ---------------------------------------------------------------- inputs
    def read(self, path: Any) -> None:
        """Record ``path`` as an input of the run."""
        p = os.fspath(path)
        self.inputs.setdefault(p, (_identity(p), _real(p)))

    def input_named(self, target: str) -> str | None:
        """The input ``target`` names by any spelling, or None."""
        real = _real(target)
        ident = _identity(target)
        for given, (iid, ireal) in self.inputs.items():
            if real == ireal or (ident is not None and ident == iid):
                return given
        return None

    def refuse_input(self, target: Any) -> None:
        """OutputError when ``target`` is one of the inputs read so far."""
        t = os.fspath(target)
        src = self.input_named(t)
        if src is not None:
            raise OutputError(Said("o_input", target=t, src=src))

    # ---------------------------------------------------------------- outputs
    def stage(self, tmp: str, target: Any) -> None:
        """Keep the written temporary ``tmp`` until the run commits (a target staged twice
        keeps its last content)."""
        t = os.fspath(target)
        self.refuse_input(t)
        key = _real(t)
        old = self.staged.pop(key, None)
        if old is not None:
            _unlink(old[0])
        self.staged[key] = (tmp, t)

    def staged_bytes(self, target: Any) -> bytes | None:
        """What the run has written for ``target`` so far (None: nothing yet)."""
        hit = self.staged.get(_real(os.fspath(target)))
        if hit is None:
            return None
        with open(hit[0], "rb") as fh:
            return fh.read()

    def remove(self, paths: Iterable[Any]) -> None:
        """Remove these old outputs when the run commits (an input is never removed)."""
        self.removals.extend(os.fspath(p) for p in paths)

    def commit(self) -> None:
        """Check every target, then rename every temporary over its target and make the
        removals; an error before the renames leaves every old file as it was."""
        for _key, (_tmp, target) in self.staged.items():
            self.refuse_input(target)
            if os.path.isdir(target):
                raise OutputError(Said("o_folder", target=str(target)))
        written = set(self.staged)
        for key, (tmp, target) in list(self.staged.items()):
            try:
                os.replace(tmp, target)
            except OSError as exc:
                raise OutputError(Said("o_write", target=str(target), why=os_reason(exc))) from None
            del self.staged[key]
        for p in self.removals:
            if self.input_named(p) is None and _real(p) not in written:
                _unlink(p)
        self.removals.clear()

    def discard(self) -> None:
        """Remove every temporary: the run leaves nothing."""
        for tmp, _target in self.staged.values():
            _unlink(tmp)
        self.staged.clear()
        self.removals.clear()

    def __enter__(self) -> Run:
        _ACTIVE.append(self)
        return self

    def __exit__(self, kind: Any, exc: Any, tb: Any) -> None:
        try:
            if kind is None:
                self.commit()
        finally:
            self.discard()
            _ACTIVE.remove(self)


def _unlink(path: str) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass
