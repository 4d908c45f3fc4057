"""One failure family for the whole engine.

User errors (bad scene or check files) are :class:`InputError`: the CLI prints
their one-line message and exits with status 2.  Geometry that cannot be
constructed is :class:`ConstructionError`, which names the group, the point and
the crank angle, never returns NaN.
"""

from __future__ import annotations

import math
import re
from typing import Any

#: The run's language for its error lines and warnings: what ``--language`` asked for and
#: the input file whose ``[sheet] language`` is the default (set by the command line);
#: resolved only when a line is written (:func:`run_language`), so a run that says nothing
#: reads nothing more.
_RUN: dict[str, str | None] = {"asked": None, "path": None, "lang": None}


def set_run(asked: str | None, path: str | None) -> tuple[str | None, str | None]:
    """The run's ``--language`` and input file (:func:`run_language`); gives the ones before,
    for a command run inside another (``plans bench`` times ``plans check``) to hand back."""
    before = (_RUN["asked"], _RUN["path"])
    _RUN.update(asked=asked, path=path, lang=None)
    _WARNED.clear()
    return before


#: The warnings this run has written (a scene read twice warns once).
_WARNED: set[str] = set()


def warn(said: Said, data: Any = None) -> None:
    """A warning on stderr in the run's language (``plans: warning: ...``): the run goes on
    and its exit status is unchanged.  Outside a command's run (a library call), the language
    of ``data``'s ``[sheet] language`` (the scene's table), else the locale's."""
    import sys

    lang = run_language(data)
    text = said.text(lang)
    if text in _WARNED:
        return
    _WARNED.add(text)
    print(Said("w_prefix").text(lang) + " ".join(text.split()), file=sys.stderr)


def run_language(data: Any = None) -> str:
    """``--language``, else the input file's ``[sheet] language``, else the locale's; outside
    a command's run, ``data``'s ``[sheet] language`` (a file's table) else the locale's."""
    if _RUN["asked"] is None and _RUN["path"] is None and data is not None:
        from plans.language import choose

        return choose(None, data)
    if _RUN["lang"] is None:
        from plans.language import file_language, locale_language

        asked, path = _RUN["asked"], _RUN["path"]
        _RUN["lang"] = file_language(asked, path) if path else (asked if asked in ("ru", "en") else locale_language())
    return _RUN["lang"] or "en"


class Said:
    """A sentence of the catalogue not yet written (:data:`plans.language.ERRORS`): its key
    and its values, written in either language with the same values (a value may itself be
    a Said).  Field names and TOML keys among the values are the file's own words."""

    __slots__ = ("key", "values")

    def __init__(self, key: str, /, **values: Any) -> None:
        self.key, self.values = key, values

    def text(self, lang: str = "en") -> str:
        from plans.messages import sentence

        en, ru = sentence(self.key)
        values = {k: v.text(lang) if isinstance(v, Said) else _Comma(v) if lang == "ru" and isinstance(v, float)
                  else v.written(lang) if isinstance(v, Figures | Field) else v for k, v in self.values.items()}
        return (ru if lang == "ru" else en).format(**values)

    def __str__(self) -> str:
        return self.text("en")

    def __repr__(self) -> str:
        return f"Said({self.key!r}, {self.values!r})"


class Field(str):
    """A field named in a sentence, as :func:`field_name` writes it in the sentence's language."""

    __slots__ = ()

    def written(self, lang: str) -> str:
        return field_name(str(self), lang)


class Figures(tuple):
    """Numbers listed in a sentence (``0, 1.096, 30``), with a decimal comma in Russian."""

    __slots__ = ()

    def written(self, lang: str) -> str:
        text = ", ".join(f"{x:g}" for x in self)
        return text.replace(".", ",").replace(", ", "; ") if lang == "ru" and "." in text else text


class _Comma(float):
    """A number written with a decimal comma (a Russian sentence's)."""

    __slots__ = ()

    def __format__(self, spec: str) -> str:
        if self in (math.inf, -math.inf):
            return "∞" if self > 0 else "−∞"
        return float.__format__(self, spec).replace(".", ",")


#: Arrays of tables (``[[joints]]``): a message names their entries 1-based, as a reader
#: counts them in the file ("[[joints]] entry 4"), never by a 0-based index.
TABLE_ARRAYS = frozenset({"joints", "positions", "gas", "force", "moment", "cylinders", "variants", "shafts",
                          "meshes", "gears", "pairs", "stages", "points_of", "panels"})
_ENTRY = re.compile(r"^([A-Za-z_][\w.]*?)\[(\d+)\](?:\.(.*))?$")


def field_name(field: str, lang: str = "en") -> str:
    """A field as a message names it: ``joints[3].guide.link`` (the reader's 0-based index)
    is ``[[joints]] entry 4, guide.link`` (``[[joints]] № 4, guide.link`` in Russian)."""
    if lang == "ru" and "row " in field:  # a row of a CSV table ("t.csv, row 3", "row 3.name")
        field = re.sub(r"\brow (\d+)", r"строка \1", field)
    m = _ENTRY.match(field)
    if m is None or m.group(1).rsplit(".", 1)[-1] not in TABLE_ARRAYS:
        return field
    entry = f"[[{m.group(1)}]] {'№' if lang == 'ru' else 'entry'} {int(m.group(2)) + 1}"
    rest = m.group(3)
    return entry if not rest else f"{entry}, {field_name(rest, lang)}"


def os_reason(exc: OSError) -> Said | str:
    """Why the system refused a file, in the run's language where the catalogue has it."""
    import errno

    name = errno.errorcode.get(exc.errno or 0, "")
    from plans.language import ERRORS

    return Said(f"e_{name}") if f"e_{name}" in ERRORS else (exc.strerror or str(exc))


def error_prefix(lang: str | None = None) -> str:
    """``plans: error: `` in the run's language."""
    return "plans: ошибка: " if (lang or run_language()) == "ru" else "plans: error: "


class PlansError(Exception):
    """Base of every error the engine raises on purpose."""

    #: The input file the error is about, when the message does not name it already.
    source: str | None = None


def one_line(exc: BaseException, lang: str | None = None) -> str:
    """The error as the one line the command prints: the file first, whitespace folded; in
    ``lang`` (default: the run's, :func:`run_language`) where the message is the catalogue's."""
    lang = lang or run_language()
    text = exc.text(lang) if isinstance(exc, InputError | OutputError | ConstructionError) else str(exc)
    text = " ".join(text.split())
    source = getattr(exc, "source", None)
    if source and not text.startswith(source):
        text = f"{source}: {text}"
    return text


class InputError(PlansError):
    """A malformed or impossible input file: says file, field and what was expected."""

    def __init__(self, message: str | Said, *, file: str | None = None, field: str | None = None,
                 line: int | None = None) -> None:
        self.file = file
        self.field = field
        self.line = line
        self.said = message if isinstance(message, Said) else None
        self.detail = str(message)
        super().__init__(self.text("en"))

    def text(self, lang: str = "en") -> str:
        """The error in ``lang``: the file, its line, the field, then what was expected (a
        message that is not yet the catalogue's stays in English)."""
        where = self.file or "<scene>"
        if self.line is not None:
            where += f":{self.line}"
        if self.field:
            where += f": {field_name(self.field, lang)}"
        return f"{where}: {self.said.text(lang) if self.said is not None else self.detail}"


class OutputError(PlansError):
    """An output file or folder that cannot be written."""

    def __init__(self, message: str | Said = "") -> None:
        self.said = message if isinstance(message, Said) else None
        super().__init__(str(message))

    def text(self, lang: str = "en") -> str:
        return self.said.text(lang) if self.said is not None else str(self)


class ConstructionError(PlansError):
    """A construction that has no answer (not assemblable, locked)."""

    def __init__(self, message: str | Said, *, group: str | None = None, point: str | None = None,
                 phi_deg: float | None = None) -> None:
        self.group = group
        self.point = point
        self.phi_deg = phi_deg
        self.said = message if isinstance(message, Said) else None
        self.detail = str(message)
        super().__init__(self.text("en"))

    def text(self, lang: str = "en") -> str:
        """The error in ``lang``: the group, the point and the crank angle, then why."""
        parts = []
        if self.group:
            group = self.group.replace("class III ", Said("x_class_iii").text(lang), 1)
            if group == "loop equations":  # the second solver's "group": every loop at once
                group = Said("nw_loop_equations").text(lang)
            parts.append(Said("x_at_group", group=group).text(lang))
        if self.point:
            parts.append(Said("x_at_point", point=self.point).text(lang))
        if self.phi_deg is not None:
            parts.append(Said("x_at_phi", phi=self.phi_deg).text(lang))
        prefix = ", ".join(parts)
        message = self.said.text(lang) if self.said is not None else self.detail
        return f"{prefix}: {message}" if prefix else message


class NotAssemblable(ConstructionError):
    """The links of a group cannot be joined at this crank angle."""


class Locked(ConstructionError):
    """The group is at a locking position: its velocity equations are singular."""


class Indeterminate(Locked):
    """The group's construction lines coincide (a change point): its plan has no single answer."""
