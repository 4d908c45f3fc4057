"""The ``[sheet]`` table of a scene (and of an engine, gear or cam file): paper, title block,
what is drawn, read and validated with the file, so a bad ``[sheet]`` fails every command
alike.  The sheets themselves are drawn by ``drawings``; this is only what the file says.
"""

from __future__ import annotations

import math
from typing import Any

from plans.errors import InputError
from plans.reader import check_keys
from plans.records import frozen

FORMATS: dict[str, tuple[float, float]] = {  # landscape width × height, mm (GOST 2.301)
    "A0": (1189.0, 841.0),
    "A1": (841.0, 594.0),
    "A2": (594.0, 420.0),
    "A3": (420.0, 297.0),
    "A4": (297.0, 210.0),
}
SHEET_FORMATS = ("A1", "A2", "A3", "A4")


@frozen
class Pin:
    panel: str  # panel id: "velocity-45"
    sheet: int  # 1-based
    x: float  # top-left of the panel box, mm from the paper's top-left corner
    y: float


@frozen
class SheetSpec:
    """The ``[sheet]`` table of a scene (every key optional)::

        [sheet]
        format = "A1"                 # A1 | A2 | A3 | A4  (CLI --sheet overrides)
        orientation = "landscape"     # or "portrait"
        language = "ru"               # or "en"
        title = "Механизм V-образного двигателя"   # name field (default: the scene's title);
                                      # or one per language: { ru = "...", en = "..." }
        designation = "ТММ.КП.07.00.00"
        subtitle = "Кинематический и силовой анализ"
        author = "Иванов И.И."
        checked_by = "Петров П.П."
        approved_by = ""
        group = "гр. МТ-31"
        organization = "МГТУ"
        date = "21.11.26"             # written as given (no clock: same scene, same bytes)
        first_sheet = 1               # number of this drawing's first sheet
        total_sheets = 4              # "Sheets" cell (default: first_sheet - 1 + sheets drawn)
        panels = ["positions", "scheme", "velocity", "acceleration", "table", "group", "crank", "lever",
                  "legend"]           # kinds to draw (default: all the scene's outputs ask for)
        positions = [45, 0]           # crank angles studied in detail: their schemes, plans, forces
                                      # and tables (default: plans etc. at every position of the
                                      # scene, schemes at the first two)
        trace = ["S2"]                # points whose trajectory the plan of positions traces
                                      # (default: the centres of mass of the connecting rods)
        [[sheet.pins]]                # fix a panel: top-left corner in mm from the paper's corner
        panel = "velocity-45"
        sheet = 1
        x = 300
        y = 20
    """

    format: str = "A1"
    orientation: str = "landscape"
    language: str = "ru"
    title: str = ""
    designation: str = ""
    subtitle: str = ""
    author: str = ""
    checked_by: str = ""
    approved_by: str = ""
    group: str = ""
    organization: str = ""
    date: str = ""
    first_sheet: int = 1
    total_sheets: int | None = None
    panels: tuple[str, ...] | None = None  # kinds to draw (subset of what the scene asks)
    positions: tuple[float, ...] | None = None  # crank angles to draw (subset of the scene's)
    trace: tuple[str, ...] | None = None  # trajectories on the plan of positions
    pins: tuple[Pin, ...] = ()

    @property
    def size(self) -> tuple[float, float]:
        w, h = FORMATS[self.format]
        return (w, h) if self.orientation == "landscape" else (h, w)

    @property
    def fit(self) -> float:
        """The fraction of the A1 target lengths the plans, polygons and lever are drawn at on
        this paper (``plans.solve(scene, fit=scene.sheet.fit)``): on a smaller sheet the square
        root of the ratio of the sheets' sizes (A3 about 0.7 of A1: smaller, still readable)."""
        return min(1.0, math.sqrt(max(self.size) / 841.0))


PANEL_KINDS = ("positions", "scheme", "velocity", "acceleration", "table", "group", "crank", "lever", "legend")
_KEYS = {"format", "orientation", "language", "title", "designation", "subtitle", "author",
         "checked_by", "approved_by", "group", "organization", "date", "first_sheet", "total_sheets",
         "panels", "positions", "trace", "pins"}


def sheet_spec(raw: dict[str, Any], path: str, default_title: str = "", **override: Any) -> SheetSpec:
    """Validate ``[sheet]`` (one-line InputError per problem); CLI options override it."""
    data = raw.get("sheet", {})
    if not isinstance(data, dict):
        raise InputError("expected a table [sheet]", file=path, field="sheet")
    check_keys(data, _KEYS, file=path, where="sheet.")
    out: dict[str, Any] = {}

    def string(key: str) -> None:
        if key in data:
            if not isinstance(data[key], str):
                raise InputError("expected a string", file=path, field=f"sheet.{key}")
            out[key] = data[key]

    for key in ("designation", "subtitle", "author", "checked_by", "approved_by", "group",
                "organization", "date"):
        string(key)
    fmt = str(override.get("format") or data.get("format", "A1"))
    if fmt.upper() not in SHEET_FORMATS:
        raise InputError(f"unknown sheet format {fmt!r}; expected one of {', '.join(SHEET_FORMATS)}",
                         file=path, field="sheet.format")
    out["format"] = fmt.upper()
    ori = override.get("orientation") or data.get("orientation", "landscape")
    if ori not in ("landscape", "portrait"):
        raise InputError(f"expected \"landscape\" or \"portrait\", got {ori!r}", file=path,
                         field="sheet.orientation")
    out["orientation"] = ori
    lang = override.get("language") or data.get("language", "ru")
    if lang not in ("ru", "en"):
        raise InputError(f"expected \"ru\" or \"en\", got {lang!r}", file=path, field="sheet.language")
    out["language"] = lang
    if "title" in data:  # a string, or one per language: { ru = "...", en = "..." }
        t = data["title"]
        if isinstance(t, dict) and t and all(k in ("ru", "en") and isinstance(v, str) for k, v in t.items()):
            t = t.get(lang, t.get("en", t.get("ru")))
        if not isinstance(t, str):
            raise InputError("expected a string or { ru = \"...\", en = \"...\" }", file=path, field="sheet.title")
        out["title"] = t
    for key in ("first_sheet", "total_sheets"):
        if key in data:
            v = data[key]
            if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= 9999:
                raise InputError(f"expected a whole number 1..9999, got {v!r}", file=path, field=f"sheet.{key}")
            out[key] = v
    if "panels" in data:
        v = data["panels"]
        if not isinstance(v, list) or not all(isinstance(x, str) and x in PANEL_KINDS for x in v):
            raise InputError(f"expected a list of panel kinds from {list(PANEL_KINDS)}", file=path,
                             field="sheet.panels")
        out["panels"] = tuple(v)
    if "positions" in data:
        v = data["positions"]
        v = v if isinstance(v, list) else [v]
        if not v or not all(isinstance(x, int | float) and not isinstance(x, bool) and abs(x) <= 1e300
                            and x == x for x in v):
            raise InputError("expected crank angles in degrees, e.g. positions = [45, 0]", file=path,
                             field="sheet.positions")
        out["positions"] = tuple(float(x) for x in v)
    if "trace" in data:
        v = data["trace"]
        v = v if isinstance(v, list) else [v]
        if not all(isinstance(x, str) and x for x in v):
            raise InputError("expected point names, e.g. trace = [\"S2\"] (or [] for none)", file=path,
                             field="sheet.trace")
        out["trace"] = tuple(v)
    if "pins" in data:
        pins = []
        v = data["pins"]
        if not isinstance(v, list):
            raise InputError("expected an array of tables [[sheet.pins]]", file=path, field="sheet.pins")
        for i, p in enumerate(v):
            f = f"sheet.pins[{i}]"
            if not isinstance(p, dict) or not isinstance(p.get("panel"), str):
                raise InputError("expected { panel = \"velocity-45\", x = mm, y = mm, sheet = 1 }", file=path,
                                 field=f)
            check_keys(p, ("panel", "x", "y", "sheet"), file=path, where=f"{f}.")
            for key in ("x", "y"):
                if not isinstance(p.get(key), int | float) or isinstance(p.get(key), bool) or \
                        not abs(p[key]) <= 10_000:
                    raise InputError(f"expected {key} in mm from the sheet's top-left corner", file=path,
                                     field=f"{f}.{key}")
            sh = p.get("sheet", 1)
            if isinstance(sh, bool) or not isinstance(sh, int) or not 1 <= sh <= 9999:
                raise InputError("expected a sheet number >= 1", file=path, field=f"{f}.sheet")
            pins.append(Pin(p["panel"], sh, float(p["x"]), float(p["y"])))
        out["pins"] = tuple(pins)
    out.setdefault("title", default_title)
    return SheetSpec(**out)


def sheet_of(raw: dict[str, Any], path: str, title: str, titles: dict[str, str]) -> SheetSpec:
    """The file's ``[sheet]``, its title in the sheet's language (InputError naming the field)."""
    return sheet_spec(raw, path, titles.get(_language(raw), title))


def _language(raw: dict) -> str:
    """The sheet's language as the file gives it (its title is the scene's in that language)."""
    sheet = raw.get("sheet")
    lang = sheet.get("language") if isinstance(sheet, dict) else None
    return lang if lang in ("ru", "en") else "ru"
