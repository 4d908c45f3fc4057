"""The ``[sheet]`` table of a scene (and of an engine, gear or cam file): paper, title block,
what is drawn, read and validated with the file, so a bad ``[sheet]`` fails every command
alike.  The sheets themselves are drawn by ``drawings``; this is only what the file says.

The typed record (:class:`plans.scene.paper.SheetSpec`) is made when a reader asks for it:
``plans solve`` validates the table without defining the sheet's classes.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from plans.errors import InputError, Said
from plans.reader import check_keys

if TYPE_CHECKING:
    from plans.scene.paper import Pin, SheetSpec  # noqa: F401  (the records, typed where read)

SHEET_FORMATS = ("A1", "A2", "A3", "A4")


PANEL_KINDS = ("positions", "scheme", "velocity", "acceleration", "table", "group", "crank", "lever", "legend",
               "centres", "diagrams")
_KEYS = {"format", "orientation", "language", "title", "designation", "subtitle", "author",
         "checked_by", "approved_by", "group", "organization", "date", "first_sheet", "total_sheets",
         "panels", "positions", "trace", "pins", "set"}
#: The sheet sets: "course" (a kinematics sheet and a kinetostatics sheet, the default for a
#: scene of 12 positions or more) and "positions" (one bordered block per position).
SHEET_SETS = ("course", "positions")
#: What ``panels = { ... }`` may choose: the kinds drawn at chosen positions (a list of position
#: numbers, "all" or "none") and the drawing-wide ones (true or false).
PANEL_CHOICE_AT = ("scheme", "velocity", "acceleration", "forces", "lever", "table", "centres")
PANEL_CHOICE_WHOLE = ("positions", "legend", "diagrams")  # diagrams: the course's default ones of the output
_KEYS |= {"acceleration_pole"}  # the notation, read with the scales (plans.scene.notation)
_KEYS |= {"first_position"}  # the number of the first position on every panel (1 or 0)
#: The sheets' fonts: "dejavu" (DejaVu Sans) or "gost" (osifont, a GOST 2.304 type B font, with
#: DejaVu Sans for the characters it lacks); drawn by ``drawings.paper.fonts``.
SHEET_FONTS = ("dejavu", "gost")
_KEYS |= {"font"}


def sheet_spec(raw: dict[str, Any], path: str, default_title: str = "", **override: Any) -> SheetSpec:
    """Validate ``[sheet]`` (one-line InputError per problem); CLI options override it."""
    from plans.scene.paper import Pin, SheetSpec  # noqa: F401  (the records, typed where read)

    out = read_sheet(raw, path, default_title, **override)
    if "pins" in out:
        out["pins"] = tuple(Pin(*p) for p in out["pins"])
    return SheetSpec(**out)


def read_sheet(raw: dict[str, Any], path: str, default_title: str = "", **override: Any) -> dict[str, Any]:
    """``[sheet]`` validated into the fields of a SheetSpec (pins as (panel, sheet, x, y))."""
    data = raw.get("sheet", {})
    if not isinstance(data, dict):
        raise InputError(Said("sh_table_sheet"), file=path, field="sheet")
    check_keys(data, _KEYS, file=path, where="sheet.")
    out: dict[str, Any] = {}

    def string(key: str) -> None:
        if key in data:
            if not isinstance(data[key], str):
                raise InputError(Said("gm_string"), file=path, field=f"sheet.{key}")
            out[key] = data[key]

    for key in ("designation", "subtitle", "author", "checked_by", "approved_by", "group",
                "organization", "date"):
        string(key)
    fmt = str(override.get("format") or data.get("format", "A1"))
    if fmt.upper() not in SHEET_FORMATS:
        raise InputError(Said("sh_unknown_sheet_format", fmt=fmt, v=', '.join(SHEET_FORMATS)),
                         file=path, field="sheet.format")
    out["format"] = fmt.upper()
    ori = override.get("orientation") or data.get("orientation", "landscape")
    if ori not in ("landscape", "portrait"):
        raise InputError(Said("sh_landscape_portrait_ori", ori=ori), file=path,
                         field="sheet.orientation")
    out["orientation"] = ori
    lang = override.get("language") or data.get("language")
    if lang is None and "language" not in data:  # neither asked for nor the file's: the locale's, as the terminal's
        from plans.language import locale_language

        lang = locale_language()
    if lang not in ("ru", "en"):
        raise InputError(Said("sh_ru_en_lang", lang=lang), file=path, field="sheet.language")
    out["language"] = lang
    if "title" in data:  # a string, or one per language: { ru = "...", en = "..." }
        t = data["title"]
        if isinstance(t, dict) and t and all(k in ("ru", "en") and isinstance(v, str) for k, v in t.items()):
            t = t.get(lang, t.get("en", t.get("ru")))
        if not isinstance(t, str):
            raise InputError(Said("sh_string_ru_en"), file=path, field="sheet.title")
        out["title"] = t
    for key in ("first_sheet", "total_sheets"):
        if key in data:
            v = data[key]
            if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= 9999:
                raise InputError(Said("sh_whole_number", v=v), file=path, field=f"sheet.{key}")
            out[key] = v
    if "set" in data:
        v = data["set"]
        if v not in SHEET_SETS:
            raise InputError(Said("sh_one", v=', '.join(repr(x) for x in SHEET_SETS), v2=v), file=path,
                             field="sheet.set")
        out["set"] = v
    if "panels" in data:
        v = data["panels"]
        if isinstance(v, dict):
            out["choice"] = _panel_choice(v, path)
        elif not isinstance(v, list) or not all(isinstance(x, str) and x in PANEL_KINDS for x in v):
            raise InputError(Said("sh_list_panel_kinds", v=list(PANEL_KINDS)), file=path,
                             field="sheet.panels")
        else:
            out["panels"] = tuple(v)
    if "positions" in data:
        v = data["positions"]
        v = v if isinstance(v, list) else [v]
        if not v or not all(isinstance(x, int | float) and not isinstance(x, bool) and abs(x) <= 1e300
                            and x == x for x in v):
            raise InputError(Said("sh_crank_angles_degrees"), file=path,
                             field="sheet.positions")
        out["positions"] = tuple(float(x) for x in v)
    if "trace" in data:
        v = data["trace"]
        v = v if isinstance(v, list) else [v]
        if not all(isinstance(x, str) and x for x in v):
            raise InputError(Said("sh_point_names_trace"), file=path,
                             field="sheet.trace")
        out["trace"] = tuple(v)
    if "pins" in data:
        pins = []
        v = data["pins"]
        if not isinstance(v, list):
            raise InputError(Said("sh_array_tables_sheet"), file=path, field="sheet.pins")
        for i, p in enumerate(v):
            f = f"sheet.pins[{i}]"
            if not isinstance(p, dict) or not isinstance(p.get("panel"), str):
                raise InputError(Said("sh_panel_velocity_mm"), file=path,
                                 field=f)
            check_keys(p, ("panel", "x", "y", "sheet"), file=path, where=f"{f}.")
            for key in ("x", "y"):
                if not isinstance(p.get(key), int | float) or isinstance(p.get(key), bool) or \
                        not abs(p[key]) <= 10_000:
                    raise InputError(Said("sh_mm_from_sheet", k=key), file=path,
                                     field=f"{f}.{key}")
            sh = p.get("sheet", 1)
            if isinstance(sh, bool) or not isinstance(sh, int) or not 1 <= sh <= 9999:
                raise InputError(Said("sh_sheet_number"), file=path, field=f"{f}.sheet")
            pins.append((p["panel"], sh, float(p["x"]), float(p["y"])))
        out["pins"] = tuple(pins)
    if override.get("set"):
        if override["set"] not in SHEET_SETS:
            raise InputError(Said("sh_one", v=', '.join(repr(x) for x in SHEET_SETS), v2=override['set']),
                             file=path, field="sheet.set")
        out["set"] = override["set"]
    if "first_position" in data:
        v = data["first_position"]
        if isinstance(v, bool) or not isinstance(v, int) or v not in (0, 1):
            raise InputError(Said("sh_positions_positions", v=v), file=path,
                             field="sheet.first_position")
        out["first_position"] = int(v)
    if "font" in data or override.get("font"):
        font = override.get("font") or data["font"]
        if font not in SHEET_FONTS:
            from plans.reader import did_you_mean, show

            hint = did_you_mean(font, SHEET_FONTS) if isinstance(font, str) else ""
            raise InputError(Said("e_choice", options=", ".join(repr(f) for f in SHEET_FONTS), got=show(font),
                                  hint=hint), file=path, field="--font" if override.get("font") else "sheet.font")
        out["font"] = font
    own = raw.get("title")
    if isinstance(own, dict) and is_titles(own):  # the file's title in the sheet's language
        out.setdefault("title", own.get(lang, own.get("en", own.get("ru"))))
    out.setdefault("title", default_title)
    return out


def is_titles(t: Any) -> bool:
    """True for a title per language: ``{ ru = "...", en = "..." }`` (one of them at least)."""
    return isinstance(t, dict) and bool(t) and all(k in ("ru", "en") and isinstance(v, str) for k, v in t.items())


def own_title(t: Any) -> Any:
    """A file's top-level title as the terminal says it: the English one of a title per
    language (the Russian where it alone is given), else the value as read (checked by its reader)."""
    return t.get("en", t.get("ru")) if is_titles(t) else t


def _panel_choice(v: dict[str, Any], path: str) -> tuple[tuple[str, Any], ...]:
    """``panels = { velocity = "all", acceleration = [1, 4], forces = [4], positions = true }``
    as (kind, "all" | "none" | position numbers | bool) pairs, one-line errors naming the key."""
    out: list[tuple[str, Any]] = []
    for key, val in v.items():
        f = f"sheet.panels.{key}"
        if key in PANEL_CHOICE_WHOLE:
            if not isinstance(val, bool):
                raise InputError(Said("sh_true_false_val", val=val), file=path, field=f)
            out.append((key, val))
        elif key in PANEL_CHOICE_AT:
            if val in ("all", "none"):
                out.append((key, val))
                continue
            nums = val if isinstance(val, list) else [val]
            if isinstance(val, str) or not all(isinstance(x, int) and not isinstance(x, bool) and 0 <= x <= 100_000
                                               for x in nums):
                raise InputError(Said("sh_all_none_position", val=val),
                                 file=path, field=f)
            out.append((key, tuple(dict.fromkeys(nums))))
        else:
            from plans.reader import did_you_mean

            known = PANEL_CHOICE_AT + PANEL_CHOICE_WHOLE
            raise InputError(Said("sh_unknown_panel_kind", k=key, v=did_you_mean(key, known), v2=', '.join(known)),
                             file=path, field=f)
    return tuple(out)


def sheet_of(raw: dict[str, Any], path: str, title: str, titles: dict[str, str]) -> SheetSpec:
    """The file's ``[sheet]``, its title in the sheet's language (InputError naming the field)."""
    return sheet_spec(raw, path, titles.get(_language(raw), title))


def sheet_for(scene: Any, *, format: str | None = None, orientation: str | None = None,
              language: str | None = None, set: str | None = None, font: str | None = None) -> SheetSpec:
    """A scene's ``[sheet]`` with what a command overrides (``--sheet A3``, ``--language en``,
    ``--font gost``), the title in the sheet's language."""
    lang = language or _language(scene.raw)
    return sheet_spec(scene.raw, scene.path, scene.title_in(lang), format=format, orientation=orientation,
                      language=language, set=set, font=font)


def check_sheet(raw: dict[str, Any], path: str) -> None:
    """The file's ``[sheet]`` validated, as :func:`sheet_of` reads it (InputError naming the field)."""
    read_sheet(raw, path)


def _language(raw: dict) -> str:
    """The sheet's language as the file gives it, else the locale's (its title is the scene's
    in that language)."""
    from plans.language import choose

    return choose(None, raw)


def __getattr__(name: str) -> Any:
    """``Pin``, ``SheetSpec`` and the paper ``FORMATS`` (:mod:`plans.scene.paper`) where they
    were, defined when first used."""
    if name in ("Pin", "SheetSpec", "FORMATS"):
        from plans.scene import paper

        return getattr(paper, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
