"""From a solved scene to sheets: which panels the scene asks for, drawn and laid out.

Everything drawn is read off one :class:`plans.solution.Solution` (``plans.solve``): the
sheets compute nothing of the mechanism themselves.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from drawings.linkage.overview import legend_kinds, legend_panel, positions_panel
from drawings.linkage.panels import (
    Panel,
    auto_length_scale,
    cycle_size,
    plan_panel,
    scheme_panel,
    strokes_over_cycle,
    table_panel,
)
from drawings.paper.fonts import metrics, require, use
from drawings.paper.sheet import Sheet, SheetSpec, compose
from plans.kinematics.placing import load_scene
from plans.scene.model import Scene
from plans.solution import Solution
from plans.solution import solve as solve_scene


@dataclass(frozen=True)
class Drawing:
    """Everything drawn for one scene: the sheets and the panels on them."""

    scene: Scene
    spec: SheetSpec
    panels: tuple[Panel, ...]
    sheets: tuple[Sheet, ...]
    mu_l: float

    def _repr_svg_(self) -> str:
        return self.sheets[0].svg()


def _fitting_positions(sol: Solution, mu: float, lang: str, bold: list[int], strokes: Any,
                       spec: SheetSpec) -> Any:
    """The plan of positions as it fits the sheet: in full; else with its angles in brief; else
    (when its scale is not the file's own) at the next smaller standard scales."""
    from drawings.paper.sheet import fits_empty

    panel = positions_panel(sol, mu, lang, bold, strokes, spec.trace, first=spec.first_position)
    if fits_empty(panel, spec.format, spec.orientation):
        return panel
    panel = positions_panel(sol, mu, lang, bold, strokes, spec.trace, brief=True, first=spec.first_position)
    if sol.scene.scales.get("length"):
        return panel  # the student's scale is kept: a panel that does not fit says so
    from drawings.linkage.panels import STANDARD_RATIOS

    for r in STANDARD_RATIOS:
        if fits_empty(panel, spec.format, spec.orientation):
            break
        if 1000.0 * r < mu:
            panel = positions_panel(sol, 1000.0 * r, lang, bold, strokes, spec.trace, brief=True, first=spec.first_position)
    return panel


def build_panels(sol: Solution, spec: SheetSpec, sel: dict[str, Any] | None = None,
                 mu_positions: float | None = None, mu_l: float | None = None,
                 mu_bodies: float | None = None) -> tuple[list[Panel], float]:
    """Every panel the scene asks for, in the order they go on the sheet: the plan of
    positions, then position by position its scheme, plans, forces, lever and table.
    ``sel`` (kind -> positions, :func:`drawings.linkage.sheet_sets.selection`) says which positions
    each kind shows (default: the ``positions`` set's); ``mu_positions`` the plan of
    positions' scale (default: the largest standard one that fits two fifths of the sheet),
    ``mu_l`` the schemes' and groups' (default: the file's, else about 230 mm across on A1),
    ``mu_bodies`` the groups' and the initial link's cut free, where larger than the scheme's."""
    from drawings.linkage.sheet_sets import selection

    metrics()  # fail early, with the font's name, if it is missing
    scene = sol.scene
    lang, style = spec.language, scene.scale_style
    kin = sol.kinematics
    if sel is None:
        sel = selection(sol, spec, "positions")
    size = cycle_size(sol)
    w, _h = spec.size  # schemes about 230 mm across on A1, proportionally less on smaller sheets
    mu_l = mu_l or scene.scales.get("length") or auto_length_scale(size, 230.0 * min(1.0, max(w, _h) / 841.0))
    strokes = strokes_over_cycle(sol)
    plans_at: dict[int, Any] = dict(enumerate(sol.plans))
    at = {kind: set(ks) for kind, ks in sel.items() if kind not in ("positions", "legend", "bold")}
    kforces = sorted(at.get("forces", set()) | at.get("lever", set()) | at.get("table", set()))
    forces = _force_panels(sol, spec, kforces, plans_at, mu_bodies or mu_l, at) if (
        kforces and (scene.wants("force_polygons") or scene.wants("lever"))) else {}
    panels: list[Panel] = []
    if sel.get("positions"):  # the plan of positions at the largest standard scale that fits 2/5 of the sheet
        mu_pos = mu_positions or scene.scales.get("length") or auto_length_scale(size, 0.4 * (w - 37.0))
        panels.append(_fitting_positions(sol, mu_pos, lang, sel.get("bold", []), strokes, spec))
    for k in sorted(set().union(*at.values())) if at else []:
        if scene.wants("positions") and k in at.get("scheme", ()):
            panels.append(scheme_panel(scene, kin, k, mu_l, lang, strokes))
        if scene.wants("instant_centres") and k in at.get("centres", ()):
            from drawings.linkage.centres import centres_panels

            panels.extend(centres_panels(sol, k, mu_l, lang, strokes))
        pp = plans_at.get(k)
        if pp is not None:
            if pp.velocity is not None and k in at.get("velocity", ()):
                panels.append(plan_panel(pp.velocity, lang, style))
            if pp.acceleration is not None and k in at.get("acceleration", ()):
                panels.append(plan_panel(pp.acceleration, lang, style))
        panels.extend(forces.get(k, []))
        if pp is not None and pp.readings and k in at.get("table", ()):
            from drawings.linkage.table_parts import parts

            extra, rows, phi = forces.get(("table", k), []), _rows(scene, pp.readings), float(kin.phi_deg[k])

            def table(part: tuple[int, int, int] | None, rows: list = rows, extra: list = extra,
                      phi: float = phi) -> Panel:
                return table_panel(rows, lang, style, phi, extra=extra, part=part)

            panels.extend(parts(table, spec))
    panels.extend(forces.get("efficiency", []))  # η(φ) and its table, with friction over a turn
    kinds = legend_kinds(panels)
    if sel.get("legend") and any(k not in ("trace",) for k in kinds):
        panels.append(legend_panel(kinds, lang))
    return panels, mu_l


def fit_for(spec: SheetSpec) -> float:
    """The fraction of the A1 target lengths the plans, polygons and lever are solved at for
    ``spec``'s paper (:attr:`plans.scene.sheet.SheetSpec.fit`), the scales still round."""
    return spec.fit


def _rows(scene: Scene, readings) -> list:
    """Readings worth a row: not the rates of links that only slide on the frame."""
    fixed_sliders = {jt.slider for jt in scene.joints
                     if jt.kind == "P" and jt.guide is not None and jt.guide.link == scene.frame
                     and len(scene.links[jt.slider].axis) == 1}
    out = []
    for r in readings:
        head, _, rest = r.quantity.partition("_")
        if head in ("omega", "eps") and rest.isdigit() and int(rest) in fixed_sliders:
            continue
        out.append(r)
    return out


def _force_panels(sol: Solution, spec: SheetSpec, ks: list[int], plans_at, mu_l: float,
                  at: dict[str, set[int]] | None = None) -> dict:
    """Force panels (group free bodies and polygons, crank, lever) when plans.forces exists;
    with ``at`` only those of the positions it names for each kind (forces, lever, table)."""
    try:
        from drawings.linkage import forces_panels
    except ImportError:  # pragma: no cover - the force panels are optional
        return {}
    out = forces_panels.build(sol, spec, ks, plans_at, mu_l)
    if at is None:
        return out
    kind_of = {"group": "forces", "polygon": "forces", "crank": "forces", "lever": "lever", "table": "table"}
    for k in ks:
        if k in out:
            out[k] = [p for p in out[k] if k in at.get(kind_of.get(p.kind, "forces"), ())]
    return out


def draw(source: Solution | Scene | str | Path, *, format: str | None = None, orientation: str | None = None,
         language: str | None = None, sheet_set: str | None = None, font: str | None = None) -> Drawing:
    """The sheets of a solved scene (a :class:`Solution`), or of a Scene or the path of its
    file, solved once here at the paper's fit.  A Solution is drawn at the scales it was
    solved with (``plans.solve(scene, fit=...)``).  ``sheet_set`` overrides ``[sheet] set``,
    ``font`` ``[sheet] font``."""
    if isinstance(source, Solution):
        sol = source
        spec = sol.scene.sheet_for(format=format, orientation=orientation, language=language, set=sheet_set,
                                   font=font)
    else:
        sc = source if isinstance(source, Scene) else load_scene(source)
        spec = sc.sheet_for(format=format, orientation=orientation, language=language, set=sheet_set, font=font)
        require(spec.font, sc.path, "--font" if font else "sheet.font")  # before solving
        sol = solve_scene(sc, fit=fit_for(spec))
    from drawings.paper.sheet import TooBig

    while True:
        try:
            with use(spec.font, sol.scene.path, "--font" if font else "sheet.font"):
                return _draw(sol, spec)
        except TooBig as e:  # a plan, polygon or lever too big for the paper: smaller round scales
            fit = _smaller_fit(sol, e.panel, spec)
            if fit is None:
                raise
            sol = sol.at_fit(fit)  # shorter plans, polygons and lever; the rest as solved


#: The engine's scales a panel may be drawn at, and the ``[scales]`` keys that fix them.
_SOLVED = {"velocity": ("velocity", "velocity_known_mm"), "acceleration": ("acceleration", "acceleration_known_mm"),
           "force": ("force",)}


def _smaller_fit(sol: Solution, panel: Panel, spec: SheetSpec) -> float | None:
    """The fit to solve again at when ``panel`` does not fit an empty sheet: its plan, polygon
    or lever drawn at the next smaller round scales (the scales written on it change with
    them); None where its scale is not the engine's to change (the file's own, a length)."""
    from drawings.paper.sheet import GAP, TB_H, usable

    if panel.quantity not in _SOLVED or any(k in sol.scene.scales for k in _SOLVED[panel.quantity]):
        return None
    w, h = spec.size
    a = usable(w, h)
    room = min((a[2] - a[0]) / panel.width, (a[3] - a[1] - TB_H - GAP) / panel.height)
    fit = sol.fit * min(0.8, max(0.5, room))
    return fit if fit >= 0.02 else None


def _draw(sol: Solution, spec: SheetSpec) -> Drawing:
    """The sheets of ``sol`` on ``spec``'s paper (TooBig when a panel does not fit it)."""
    from drawings.linkage.sheet_sets import course_sheets, numbers, set_of

    sc = sol.scene
    if set_of(sol, spec) == "course":
        diagrams = []
        own_axis = None  # the φ axis of the scene's own diagrams, where its file leaves it to the sheet
        if sc.wants("diagrams") and sol.cycle is not None and sol.cycle.diagrams is not None:
            from drawings.cycle import fitting_diagrams

            diagrams = fitting_diagrams(sol, sol.cycle.diagrams, spec)
            if "length_mm" not in sc.raw.get("diagrams", {}):
                own_axis = sol.cycle.diagrams.spec.length_mm
        strokes = strokes_over_cycle(sol)

        def builders(s: Solution) -> tuple[Any, Any]:
            return (lambda sel, mp, ml, mb=None: build_panels(s, spec, sel, mp, ml, mb),
                    lambda mu, bold: positions_panel(s, mu, spec.language, bold, strokes, spec.trace))

        from drawings.linkage.larger import FORMATS, longer, longest_of, may_grow

        larger = [lambda t=t: builders(t()) for t in longer(sol)] if may_grow(sol, spec) else []
        longest = [lambda t=t: builders(t()) for t in longest_of(sol)] if larger else []
        offered: list[list[Panel]] = [diagrams]  # every diagram panel the sheets may have taken
        optional = [] if diagrams or not _output_diagrams_wanted(sol, spec) else [
            lambda axis=axis: _output_diagrams(sol, spec, axis, offered) for axis in OUTPUT_AXES_MM]
        axes = [] if own_axis is None or spec.format not in FORMATS else [
            lambda axis=axis: _diagrams_at(sol, spec, axis, offered) for axis in DIAGRAM_AXES_MM if axis > own_axis]
        sheets = course_sheets(sol, spec, *builders(sol), diagrams, larger, optional, longest, axes)
        theirs = {id(p) for ps in offered for p in ps}
        panels = [p for sh in sheets for p, _, _ in sh.placed if id(p) not in theirs]  # the linkage's
        if sc.wants("dynamics"):  # the dynamics' sheets follow
            from drawings.cycle import extend
            from drawings.linkage.sheet_sets import flat_sheets

            sheets = extend(sol, spec, sheets, None, diagrams=False, lay=flat_sheets)
        mu_l = next((p.scale for p in panels if p.kind == "scheme" and p.scale), None) or build_panels(
            sol, spec, {"positions": False, "legend": False})[1]
        return Drawing(sc, spec, tuple(panels), tuple(sheets), mu_l)
    panels, mu_l = build_panels(sol, spec)
    nums = {float(phi): n for phi, n in zip(sc.driver.phis_deg, numbers(sol, spec), strict=True)}
    sheets = compose(panels, spec, None, sc.path, nums, corners=True)  # each sheet's scale: its main image's
    panels, sheets = _fuller_blocks(sol, spec, nums, panels, sheets)
    if sc.wants("diagrams") or sc.wants("dynamics"):  # the cycle's sheets follow
        from drawings.cycle import extend

        sheets = extend(sol, spec, sheets, None)
    return Drawing(sc, spec, tuple(panels), tuple(sheets), mu_l)


#: The φ axes (mm) the output's kinematic diagrams are tried at on the course's kinematics
#: sheet, longest first (:func:`drawings.linkage.sheet_sets.course_sheets`).
OUTPUT_AXES_MM = (240.0, 200.0, 160.0, 120.0)


#: The longer φ axes (mm) the scene's own kinematic diagrams are tried at, shortest first, on an
#: A1 or A2 course kinematics sheet with room for them when its file gives none: 24 mm apart (a
#: whole number of mm between 12 or 24 positions), up to 1 mm per degree.
DIAGRAM_AXES_MM = (264.0, 288.0, 312.0, 336.0, 360.0)


def _diagrams_at(sol: Solution, spec: SheetSpec, axis: float, offered: list[list[Panel]]) -> list[Panel]:
    """The scene's kinematic diagrams' panels at a φ axis of ``axis`` mm (kept in ``offered``)."""
    from drawings.cycle import diagram_panels

    dg = sol.diagrams_drawn(axis)
    assert dg is not None, "a scene with kinematic diagrams"
    offered.append(diagram_panels(dg, spec.language, spec.first_position))
    return offered[-1]


def _output_diagrams_wanted(sol: Solution, spec: SheetSpec) -> bool:
    """The course's kinematics sheet draws the output's diagrams by default: unless the scene
    has ``[diagrams]`` of its own, or leaves them out (``panels = { diagrams = false }``, or a
    ``panels = [...]`` list without "diagrams")."""
    if sol.scene.wants("diagrams") or not dict(spec.choice).get("diagrams", True):
        return False
    return spec.panels is None or "diagrams" in spec.panels


def _output_diagrams(sol: Solution, spec: SheetSpec, axis: float, offered: list[list[Panel]]) -> list[Panel] | None:
    """The output's kinematic diagrams' panels at a φ axis of ``axis`` mm (kept in ``offered``);
    None where the scene has no output to draw."""
    from drawings.cycle import diagram_panels

    dg = sol.output_diagrams(axis)
    if dg is None:
        return None
    offered.append(diagram_panels(dg, spec.language, spec.first_position))
    return offered[-1]


def _fuller_blocks(sol: Solution, spec: SheetSpec, nums: dict[float, int], panels: list[Panel],
                   sheets: list[Sheet]) -> tuple[list[Panel], list[Sheet]]:
    """Each sheet of the block layout redrawn at longer plans where it has room for them
    (:mod:`drawings.linkage.larger`): its own panels, at the fullest longer solution that still
    holds them on one sheet.  Returns the panels drawn and the sheets."""
    from drawings.linkage.larger import BLOCK_STEPS, FULL, fill, longer, may_grow, once_each
    from drawings.paper.sheet import TooBig

    if not may_grow(sol, spec) or spec.pins:
        return panels, sheets
    size = spec.size
    makers = longer(sol, BLOCK_STEPS)

    def panels_of(make: Callable[[], Solution]) -> Callable[[], dict[str, Panel]]:
        return lambda: {p.pid: p for p in build_panels(make(), spec)[0]}

    at = once_each([panels_of(m) for m in makers])

    out = list(sheets)
    order = [p.pid for p in panels]
    for n, sh in enumerate(sheets):
        best, f0 = sh, fill(sh.placed, size)
        ids = sorted((p.pid for p, _, _ in sh.placed), key=order.index)
        for i in range(len(makers)):
            if f0 >= FULL:
                break
            more = at(i)
            if any(pid not in more for pid in ids):
                break
            try:
                laid = compose([more[pid] for pid in ids], spec, None, sol.scene.path, nums, corners=True,
                               render=False)  # drawn below once kept
            except TooBig:  # a panel too long for an empty sheet: no longer ones either
                break
            if len(laid) > 1:  # longer still would not fit one sheet either
                break
            f = fill(laid[0].placed, size)
            if f > f0 + 0.005:
                best, f0 = laid[0], f
        out[n] = best
    for n, sh in enumerate(out):
        sh.number, sh.count = n + 1, len(out)
        sh.prims = []
        sh.render()
    return [p for sh in out for p, _, _ in sorted(sh.placed, key=lambda t: order.index(t[0].pid))], out
