"""The note's figures: the same panels the sheets draw, each alone as a PNG.

A figure names its file and a panel: the sheets' panel id (``velocity-45``,
``group-2-3-45``, ``dyn-W``) or ``kind:KIND`` for the first panel of a kind (a gear
file's ``meshing``, a cam's ``cam-profile``).  Each file's panels are built once, for
the positions the note studies only, and only when a figure asks for them."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from plans.note.linkage import studied
from plans.note.model import Figure

#: Resolution of the figures: sharp when printed at their width on A4.
DPI = 200.0


class Figures:
    """The figures of the note's files in ``lang``, their words in ``font`` (None: each
    file's ``[sheet] font``)."""

    def __init__(self, items: list[Any], lang: str, dpi: float = DPI, font: str | None = None) -> None:
        self.items, self.lang, self.dpi, self.font = items, lang, dpi, font
        self._panels: dict[tuple[int, str], list[Any]] = {}

    def panels(self, i: int, group: str) -> list[Any]:
        if (i, group) not in self._panels:
            self._panels[(i, group)] = _build(self.items[i], group, self.lang, self.font)
        return self._panels[(i, group)]

    def find(self, f: Figure) -> Any:
        """The panel a figure shows."""
        ps = self.panels(f.file, _group(self.items[f.file].kind, f.panel))
        if f.panel.startswith("kind:"):
            kind = f.panel[5:]
            hit = next((p for p in ps if p.kind == kind), None)
        else:
            hit = next((p for p in ps if p.pid == f.panel), None)
        if hit is None:
            raise KeyError(f"{self.items[f.file].path}: no panel {f.panel!r} among {[p.pid for p in ps]}")
        return hit

    def __call__(self, f: Figure) -> tuple[bytes, float]:
        from drawings.paper.export import png_bytes

        from .docx_writer import TEXT_WIDTH_MM

        hit = self.find(f)
        # a panel wider than the text is shown smaller: drawn at the resolution it has on the page
        dpi = self.dpi * min(1.0, TEXT_WIDTH_MM / max(float(hit.width), 1e-9))
        return png_bytes(hit.svg().encode("utf-8"), dpi), float(hit.width)


def _group(kind: str, panel: str) -> str:
    """Which of a file's panels to build for a figure: a linkage's sheet panels, its
    diagrams or one dynamics panel; every panel of a gear or cam file."""
    if kind != "linkage":
        return "all"
    if panel.startswith("diagram-"):
        return "diagrams"
    if panel.startswith("dyn-"):
        return panel
    return "sheet"


#: The sheet's panels a note shows (its tables are Word tables, its legend is the text).
NOTE_PANELS = ("positions", "scheme", "velocity", "acceleration", "group", "crank", "lever")


def _build(item: Any, group: str, lang: str, font: str | None = None) -> list[Any]:
    if item.kind == "gears":
        from drawings.gears import draw

        return list(draw(item.path, language=lang, font=font).panels)
    if item.kind == "cam":
        from drawings.cams import draw as draw_cam

        return list(draw_cam(item.path, language=lang, font=font).panels)
    if item.kind != "linkage":
        return []
    from drawings.paper.fonts import use

    spec = item.solved.scene.sheet_for(language=lang, font=font)
    with use(spec.font, item.path, "--font" if font else "sheet.font"):  # the panels laid out in it
        return _linkage(item, group, lang, spec)


def _linkage(item: Any, group: str, lang: str, spec: Any) -> list[Any]:
    cyc = item.solved.cycle
    if group == "diagrams":
        from drawings.cycle import diagram_panels

        return [p for p in diagram_panels(cyc.diagrams, lang) if p.kind != "cycle-table"]
    if group.startswith("dyn-"):
        from drawings.cycle.dynamics_diagrams import DYNAMICS_DIAGRAMS

        make = DYNAMICS_DIAGRAMS[group.removeprefix("dyn-")]
        return [make(cyc.dynamics, lang)]
    from drawings.linkage import build_panels, fit_for

    sol = item.solved
    scene = sol.scene
    phis = tuple(float(item.data["positions"][k]["phi_deg"]) for k in studied(item))
    spec = replace(spec, positions=phis, pins=(), panels=NOTE_PANELS)
    if sol.fit != fit_for(spec):  # drawn at the paper's fit, as plans draw draws them
        from plans.solution import solve

        sol = solve(scene, fit=fit_for(spec))
    return build_panels(sol, spec)[0]
