"""The ``[sheet]`` table as typed records: the paper (format, orientation, the drawing's fit),
the title block's fields, what is drawn, the pinned panels.  Read and validated by
:mod:`plans.scene.sheet`; these classes are defined only when a reader asks for the record.
"""

from __future__ import annotations

import math

from plans.records import frozen

FORMATS: dict[str, tuple[float, float]] = {  # landscape width × height, mm (GOST 2.301)
    "A0": (1189.0, 841.0),
    "A1": (841.0, 594.0),
    "A2": (594.0, 420.0),
    "A3": (420.0, 297.0),
    "A4": (297.0, 210.0),
}


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
        language = "ru"               # or "en"; default: the locale's (Russian for ru_*)
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
        set = "course"                # "course": a kinematics sheet and a kinetostatics sheet (the
                                      # default for 12 positions or more); "positions": a block per
                                      # position with all its panels (the default for fewer)
        panels = ["positions", "scheme", "velocity", "acceleration", "table", "group", "crank", "lever",
                  "legend"]           # kinds to draw (default: all the scene's outputs ask for); or
                                      # which positions each kind shows (numbers as on the sheet):
        # panels = { velocity = "all", acceleration = [1, 4], forces = [4], lever = [4],
        #            scheme = "none", table = "none", positions = true, legend = true }
        positions = [45, 0]           # crank angles studied in detail: their schemes, plans, forces
                                      # and tables (default: plans etc. at every position of the
                                      # scene, schemes at the first two)
        trace = ["S2"]                # points whose trajectory the plan of positions traces
                                      # (default: the centres of mass of the connecting rods)
        first_position = 1            # the first position's number on every panel: 1 (1, 2, …, 12,
                                      # as the course's tables number them) or 0 (0, 1, …, 11);
                                      # JSON and Python indices stay 0-based (label = index + this)
        font = "dejavu"               # or "gost": osifont, a free GOST 2.304 type B font (the
                                      # characters it lacks in DejaVu Sans); CLI --font overrides
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
    set: str | None = None  # "course" | "positions"; None: by the number of positions
    choice: tuple[tuple[str, object], ...] = ()  # panels = { kind = "all" | "none" | [numbers] | bool }
    first_position: int = 1  # the number of the first position on the panels (label = index + this)
    font: str = "dejavu"  # "dejavu" | "gost" (drawings.paper.fonts)

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


__all__ = ["Pin", "SheetSpec"]
