"""Sheets of a planar-linkage analysis: A1–A4 plates in SVG, PDF and PNG.

``drawings`` draws what :func:`plans.solve` solved (a :class:`plans.solution.Solution`:
kinematics, plans, forces, lever, cycle) and never the reverse; it calls no solver.
Typical use::

    import plans
    from drawings import draw, save
    d = draw(plans.solve("samples/v_engine.toml"))   # or a Scene, or the path: a Drawing
    save(d.sheets, "out", "v_engine", ("svg", "pdf", "png"), dpi=150)

In Jupyter a :class:`Drawing`, a :class:`Sheet`, a :class:`Panel` and
``show_plan(plan)`` display inline (``_repr_svg_``).
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from drawings.linkage import Drawing, build_panels
    from drawings.linkage.panels import Panel, plan_panel
    from drawings.paper.export import atomic_write, pdf_bytes, png_bytes, save
    from drawings.paper.sheet import Sheet, SheetSpec, compose, sheet_spec

#: Loaded on first use (PEP 562): ``plans --help`` does not pay for svgwrite and numpy.
_LAZY = {"Drawing": "linkage", "build_panels": "linkage", "atomic_write": "paper.export",
         "pdf_bytes": "paper.export", "png_bytes": "paper.export", "save": "paper.export", "Panel": "linkage.panels",
         "plan_panel": "linkage.panels", "Sheet": "paper.sheet", "SheetSpec": "paper.sheet", "compose": "paper.sheet",
         "sheet_spec": "paper.sheet"}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        value = getattr(importlib.import_module(f"drawings.{_LAZY[name]}"), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def draw(source: Any, *, format: str | None = None, orientation: str | None = None,
         language: str | None = None, font: str | None = None) -> Any:
    """The sheets of what ``plans.solve`` solved (a linkage's Solution, an engine's, gears', a
    cam's or a synthesis task's solution), of a record of any kind, or of the path of a file
    of the family (dispatched on its ``kind``): the drawing of that kind's sheets module."""
    from plans.kinds import KINDS

    kind = "linkage"
    if isinstance(source, str) or hasattr(source, "__fspath__"):
        from plans.kinds import read_kind

        kind = read_kind(source)[0]
    else:
        from plans.solution import ROOMS

        room = type(source).__module__.rpartition(".")[0]
        kind = next((k for k, (_, entry) in ROOMS.items() if entry.rpartition(".")[0] == room), kind)
    module = importlib.import_module(KINDS[kind][1])
    if font is None:  # a kind's draw without the option is called as before
        return module.draw(source, format=format, orientation=orientation, language=language)
    return module.draw(source, format=format, orientation=orientation, language=language, font=font)


class PlanView:
    """A plan (velocity, acceleration, force polygon) alone, for Jupyter."""

    def __init__(self, plan, language: str = "en", scale_style: str = "mu") -> None:
        from drawings.linkage.panels import plan_panel

        if plan.kind in ("velocity", "acceleration"):
            self.panel = plan_panel(plan, language, scale_style)
        else:
            from drawings.linkage.forces_panels import polygon_panel

            self.panel = polygon_panel(plan, language, scale_style, f"{plan.kind}-plan", plan.kind)

    def _repr_svg_(self) -> str:
        return self.panel.svg()


def show_plan(plan, language: str = "en", scale_style: str = "mu") -> PlanView:
    """``show_plan(plans.velocity)`` in a notebook cell draws it at true size."""
    return PlanView(plan, language, scale_style)


def panel_svg(panel: Panel, debug: bool = False) -> str:
    """One panel as a standalone SVG document in true millimetres."""
    return panel.svg(debug)


__all__ = ["Drawing", "Panel", "PlanView", "Sheet", "SheetSpec", "atomic_write", "build_panels", "compose",
           "draw", "panel_svg", "pdf_bytes", "plan_panel", "png_bytes", "save", "sheet_spec", "show_plan"]
