"""Sheet sets: which positions each kind of panel shows, and the course's two sheets.

``[sheet] set = "course"`` (the default for a scene of 12 positions or more) lays a drawing out
as a department expects a course project: a *kinematics sheet* (the plan of positions, the
velocity plans of every position, the acceleration plans asked for, the kinematic diagrams)
and a *kinetostatics sheet* (one or two positions: the mechanism, each group cut free with its
force polygon, the initial link, the Zhukovsky lever).  ``set = "positions"`` keeps one bordered
block per position holding all its panels.  ``[sheet] panels = { velocity = "all",
acceleration = [1, 4], forces = [4] }`` picks the positions of each kind in either set.

Panels go in the order the method builds them: positions, velocity, acceleration, forces,
lever, diagrams, a point's kinematic diagrams one under another.  The sizes the layout
chooses itself (the plan of positions' scale, the mechanism's and the groups' on the
kinetostatics sheet, the kinematic diagrams' φ axis) grow by standard scales while the sheets
stay as few, so an A1 sheet is not left half empty (the kinetostatics' mechanism is first
drawn a standard scale or two smaller where its positions then share fewer sheets).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from drawings.linkage.kinetic_scales import fewest, kinetic_layout, lever_apart
from drawings.linkage.panels import STANDARD_RATIOS, Panel
from drawings.paper.i18n import tr
from drawings.paper.packing import free_spots
from drawings.paper.panel_frame import SLACK_MM
from drawings.paper.sheet import (
    GAP,
    MARGIN,
    TB_H,
    TB_W,
    Sheet,
    SheetSpec,
    check_fits,
    compose,
    usable,
)
from plans.errors import InputError, Said
from plans.solution import Solution
from plans.tolerances import SAME_ANGLE_DEG

#: A scene with at least this many positions is drawn as the course's sheet set by default.
COURSE_FROM = 12
#: The kinds ``panels = { ... }`` names at positions, as :mod:`plans.scene.sheet` reads them.
#: The kinematics sheet's order: the method's (positions, then velocity, then acceleration).
ORDER = ("positions", "scheme", "centres", "velocity", "acceleration", "table")
AT = ("scheme", "velocity", "acceleration", "forces", "lever", "table", "centres")


def numbers(sol: Solution, spec: SheetSpec) -> list[int]:
    """Each position's number as the sheets write it (the plan of positions, the headings)."""
    return [k + spec.first_position for k in range(sol.kinematics.n)]


def set_of(sol: Solution, spec: SheetSpec) -> str:
    """The sheet set drawn: the file's, else "course" for 12 positions or more ("positions"
    when panels are pinned: pins place the panels of the block layout)."""
    if spec.set is not None:
        if spec.set == "course" and spec.pins:
            raise InputError(Said("ss_pinned_panels_need"), file=sol.scene.path, field="sheet.pins")
        return spec.set
    return "course" if sol.kinematics.n >= COURSE_FROM and not spec.pins else "positions"


def _studied(sol: Solution, spec: SheetSpec) -> list[int]:
    """The positions studied in detail: ``[sheet] positions`` (crank angles), else the first two."""
    kin = sol.kinematics
    if spec.positions is None:
        return list(range(min(2, kin.n)))
    out = []
    for phi in spec.positions:
        hits = [k for k in range(kin.n) if abs(float(kin.phi_deg[k]) - phi) < SAME_ANGLE_DEG]
        if not hits:
            raise InputError(Said("ss_crank_angle_phi", phi=phi, v=[float(x) for x in kin.phi_deg]), file=sol.scene.path, field="sheet.positions")
        out.append(hits[0])
    return out


def selection(sol: Solution, spec: SheetSpec, set_name: str) -> dict[str, Any]:
    """Kind -> the positions (indices, in the scene's order) it is drawn at, "positions" and
    "legend" -> whether drawn, "bold" -> the positions drawn whole on the plan of positions.

    Defaults: in the ``positions`` set every kind at every position (at the listed ``[sheet]
    positions`` when given), schemes at the positions studied in detail; in the ``course``
    set the velocity plans at every position, the forces at the positions studied in detail,
    the lever and the mechanism where the forces are, the acceleration plans at those and the
    studied positions, the instant centres (where the scene asks for them) at the studied
    positions, no tables.  ``panels = { ... }`` overrides
    a kind, ``panels = [...]`` (kinds) leaves out the kinds it does not list."""
    scene, kin = sol.scene, sol.kinematics
    every = list(range(kin.n))
    studied = _studied(sol, spec)
    chosen = dict(spec.choice)
    overlay = kin.n > 1 and scene.wants("positions") and bool(chosen.get("positions", True)) and (
        spec.panels is None or "positions" in spec.panels)
    sel: dict[str, Any]
    if set_name == "course":  # the mechanism drawn alone only on the kinetostatics sheet
        kinetic = scene.wants("force_polygons") or scene.wants("lever")
        sel = {"velocity": every, "acceleration": studied, "forces": studied, "lever": studied,
               "scheme": studied if kinetic else [], "table": [],
               "centres": studied if scene.wants("instant_centres") else []}
    else:
        ks = every if spec.positions is None else studied
        schemes = ks if spec.positions is not None or not overlay else ks[:2]
        sel = {kind: ks for kind in ("velocity", "acceleration", "forces", "lever", "table")}
        sel.update(scheme=schemes, centres=schemes)
    sel.update(positions=overlay, legend=bool(chosen.get("legend", True)))
    nums = numbers(sol, spec)
    for kind, val in spec.choice:
        if kind in ("positions", "legend") or not isinstance(val, str | tuple):
            continue
        if val == "all":
            sel[kind] = every
        elif val == "none":
            sel[kind] = []
        else:
            bad = [x for x in val if x not in nums]
            if bad:
                raise InputError(Said("ss_position_positions_are", v=bad[0], v2=nums[0], v3=nums[-1]),
                                 file=scene.path, field=f"sheet.panels.{kind}")
            sel[kind] = sorted(nums.index(int(x)) for x in val)
    if set_name == "course":  # what follows the forces' positions unless chosen itself
        if "lever" not in chosen:
            sel["lever"] = sel["forces"]
        if "scheme" not in chosen:
            sel["scheme"] = sel["forces"] if kinetic else []
        if "acceleration" not in chosen:  # the inertia forces are read off these plans
            sel["acceleration"] = sorted(set(sel["acceleration"]) | set(sel["forces"]) if kinetic else
                                         sel["acceleration"])
    if spec.panels is not None:  # the list of kinds: what it leaves out is not drawn
        also = {"forces": ("group", "crank")}
        for kind in AT:
            if not any(x in spec.panels for x in also.get(kind, (kind,))):
                sel[kind] = []
        sel["legend"] = sel["legend"] and "legend" in spec.panels
    sel["bold"] = sorted(set(sel["scheme"]) | set(sel["acceleration"]) | set(sel["forces"])) \
        if set_name == "course" else sorted(sel["scheme"])
    return sel


# --------------------------------------------------------------------------- the course's set


def _flat(panels: Sequence[Panel], spec: SheetSpec, path: str = "<scene>") -> list[list[tuple[Panel, float, float]]]:
    """Panels in order, each where it keeps the sheet's skyline lowest, clear of the title
    block; what one sheet cannot hold goes on the next.  Each subject's kinematic diagrams
    go as one column (:func:`_columns`) unless that takes another sheet; a column the sheet
    has no room for leaves there as many of its diagrams from the top as fit, the rest a
    column on the next sheet."""
    for p in panels:
        check_fits(p, spec, path)
    units = _columns(panels)
    together = _packed(units, spec)
    if len(units) == len(panels) or len(together) == 1:  # no column, or none costs a sheet
        return together
    apart = _packed([[p] for p in panels], spec)
    return together if len(together) <= len(apart) else apart


def _packed(units: list[list[Panel]], spec: SheetSpec) -> list[list[tuple[Panel, float, float]]]:
    """The sheets of :func:`_flat`: each unit (panels one under another, :func:`_stacked`) where
    it keeps the skyline lowest, or as many of its panels from the top as fit there."""
    W, H = spec.size
    area = usable(W, H)
    aw, ah = area[2] - area[0], area[3] - area[1]
    notch = (W - MARGIN - TB_W - GAP - area[0], H - MARGIN - TB_H - GAP - area[1])
    spots = free_spots(GAP)
    out: list[list[tuple[Panel, float, float]]] = []
    rest = units
    while rest:
        taken = [(notch[0] + GAP, notch[1] + GAP, aw + GAP, ah + GAP)]  # kept clear of the title block
        placed: list[tuple[Panel, float, float]] = []
        left: list[list[Panel]] = []
        tops: list[float] = []  # where the columns on this sheet start
        for unit in rest:
            for k in range(len(unit), 0, -1):
                laid, w, h = _stacked(unit[:k])
                free = spots(w, h, (0.0, 0.0, aw, ah), taken)
                if len(free):
                    X, Y = free[:, 0], free[:, 1]
                    cost = Y + h + 0.05 * X
                    i = int(np.lexsort((X, Y, cost))[0])
                    if k > 1 and tops:  # a column beside another starts level with it, if nearly as low
                        level = (np.abs(Y[:, None] - np.asarray(tops)[None, :]).min(axis=1) < SLACK_MM) & (
                            cost <= cost[i] + 2 * GAP)
                        if level.any():
                            j = np.flatnonzero(level)
                            i = int(j[np.lexsort((X[j], cost[j]))[0]])
                    x, y = float(X[i]), float(Y[i])
                    taken.append((x, y, x + w, y + h))
                    if k > 1:
                        tops.append(y)
                    placed += [(p, area[0] + x + dx, area[1] + y + dy) for p, dx, dy in laid]
                    if k < len(unit):
                        left.append(unit[k:])
                    break
            else:
                left.append(unit)
        if not placed:  # pragma: no cover - every panel fits an empty sheet (checked before)
            raise ValueError(f"panel {rest[0][0].pid} does not fit an empty {spec.format} sheet")
        out.append(placed)
        rest = left
    return out


def _columns(panels: Sequence[Panel]) -> list[list[Panel]]:
    """``panels`` in order, each alone but for the kinematic diagrams: those of one subject
    (s, v, a of a point; φ, ω, ε of a link) together in the first one's place, in the order
    they are derived (the graphical differentiation runs down the column)."""
    subject: dict[str, list[Panel]] = {}
    out: list[list[Panel]] = []
    for p in panels:
        if p.kind == "diagram" and p.pid.startswith("diagram-") and "_" in p.pid:
            key = p.pid.split("_", 1)[1]
            if key in subject:
                subject[key].append(p)
                continue
            subject[key] = [p]
            out.append(subject[key])
        else:
            out.append([p])
    return out


def _stacked(ps: Sequence[Panel]) -> tuple[list[tuple[Panel, float, float]], float, float]:
    """Panels one under another, GAP apart; kinematic diagrams moved sideways so that their
    φ axes start on one vertical (a vertical through a position crosses each diagram there).
    Returns each panel with its offset, and the width and height of the whole."""
    if len(ps) == 1:
        return [(ps[0], 0.0, 0.0)], ps[0].width, ps[0].height
    from drawings.cycle.column import axis_origin

    left = max(axis_origin(p)[0] for p in ps)
    laid, y = [], 0.0
    for p in ps:
        laid.append((p, left - axis_origin(p)[0], y))
        y += p.height + GAP
    return laid, max(dx + p.width for p, dx, _ in laid), y - GAP


def flat_sheets(panels: Sequence[Panel], spec: SheetSpec, path: str = "<scene>") -> list[Sheet]:
    """Panels in order on as few sheets as hold them (:func:`_flat`), each sheet's Scale cell
    its main image's."""
    W, H = spec.size
    return [Sheet(spec, i + 1, 0, W, H, placed, None) for i, placed in enumerate(_flat(panels, spec, path))]


def course_sheets(sol: Solution, spec: SheetSpec, build: Any, positions: Any,
                  diagrams: Sequence[Panel] = (), larger: Sequence[Any] = (),
                  optional: Sequence[Callable[[], Sequence[Panel] | None]] = (),
                  longest: Sequence[Any] = (),
                  axes: Sequence[Callable[[], Sequence[Panel]]] = ()) -> list[Sheet]:
    """The kinematics sheet(s), then the kinetostatics sheet(s).  ``build(sel, mu_positions,
    mu_l)`` makes the panels of a selection (:func:`drawings.linkage.build_panels`),
    ``positions(mu, bold)`` the plan of positions at μl = ``mu``; ``diagrams`` (the kinematic
    diagrams) go on the kinematics sheet after the plans.  ``larger``: thunks giving the
    (build, positions) of the scene solved with longer plans (:mod:`drawings.linkage.larger`),
    tried in turn for each of the two sheets: the one that keeps as few sheets and leaves the
    least of them empty is drawn.  ``optional``: thunks of panels (the output's kinematic
    diagrams at φ axes from the longest) the kinematics sheet takes after the plans, the first
    whose panels fit an empty sheet and, laid out with the rest, add no sheet and leave none
    emptier than two thirds or than it is without them (a thunk giving None ends the search);
    the kinetostatics sheet is laid out once whatever they are.  ``longest``: thunks like
    ``larger``'s, longer still, tried after them while a sheet is not full (the kinematics
    sheet's few acceleration plans, the kinetostatics sheet's polygons and lever).
    ``axes``: thunks of ``diagrams`` at longer φ axes, shortest first, that a kinematics sheet
    not yet full tries in turn (:func:`_longest_axis`)."""
    from drawings.paper.sheet import fits_empty

    sel = selection(sol, spec, "course")
    scene = sol.scene
    forces = sorted(set(sel["forces"]) | set(sel["lever"]))
    if not (scene.wants("force_polygons") or scene.wants("lever")):
        forces = []  # no kinetostatics sheet: every panel on the kinematics sheet
    kin_sel = dict(sel, forces=[], lever=[], table=[k for k in sel["table"] if k not in forces],
                   scheme=[k for k in sel["scheme"] if k not in forces])
    kin_sel["centres"] = [k for k in sel["centres"] if k not in forces]
    dyn_sel: dict[str, Any] = {kind: [] for kind in AT}
    dyn_sel.update(forces=sel["forces"], lever=sel["lever"], scheme=[k for k in sel["scheme"] if k in forces],
                   centres=[k for k in sel["centres"] if k in forces], table=[k for k in sel["table"] if k in forces],
                   positions=False, legend=False, bold=[])

    #: per solution (its index): the length scale its kinematics panels were first built at,
    #: those panels but the legend, the legend; built once whatever diagrams are tried with them
    built: dict[int, tuple[float | None, list[Panel], list[Panel]]] = {}

    def kinematics(i: int, dia: Sequence[Panel]) -> Any:
        build, positions = builders(i)

        def kinematic(mu: float | None) -> list[Panel]:
            """The kinematics sheet's panels, the plan of positions at ``mu`` (the others drawn once)."""
            if i not in built:
                panels, _ = build(kin_sel, mu, None)  # the plans of one kind together, in position order
                panels = sorted(panels, key=_order)
                built[i] = (mu, [p for p in panels if p.kind != "legend"], [p for p in panels if p.kind == "legend"])
            mu0, rest, legend = built[i]
            first = rest + list(dia) + legend
            if mu == mu0:
                return first
            return [positions_at(i, mu) if p.kind == "positions" else p for p in first]

        return kinematic

    drawn_at: dict[tuple[int, float | None], Panel] = {}

    def positions_at(i: int, mu: float | None) -> Panel:
        """The plan of positions of solution ``i`` at μl = ``mu``, drawn once."""
        if (i, mu) not in drawn_at:
            drawn_at[i, mu] = builders(i)[1](mu, kin_sel["bold"])
        return drawn_at[i, mu]

    def grow(make, start: float | None, lay, own: bool) -> tuple[float | None, list]:
        """The largest standard scale from ``start`` up that keeps as few sheets, and the
        sheets of ``make``'s panels at it."""
        panels = make(start)
        sheets = lay(panels)
        if own or start is None:
            return start, sheets
        for r in reversed(STANDARD_RATIOS):
            mu = 1000.0 * r
            if mu <= start * (1 + 1e-9):
                continue
            bigger = make(mu)
            if not all(fits_empty(p, spec.format, spec.orientation) for p in bigger):
                break
            laid = lay(bigger)
            if len(laid) > len(sheets):
                break
            start, sheets = mu, laid
        return start, sheets

    own = bool(scene.scales.get("length"))
    base_pos = _base_positions_scale(sol, spec) if sel["positions"] else None
    def lay_flat(ps: list[Panel]) -> list:
        return _flat(ps, spec, scene.path)

    from drawings.linkage.larger import better, full, once_each
    from drawings.linkage.mixing import OWN, ascend, memo, swapped
    from drawings.paper.sheet import TooBig

    W, H = spec.size
    made = once_each(list(larger) + list(longest))  # each longer solution's builders, once, when first needed
    kin_fits = len(larger) + len(longest)  # the longer solutions the kinematics sheet tries

    def builders(i: int) -> Any:
        return (build, positions) if i == OWN else made(i)

    def shown(sheets: list) -> float:
        """The plan of positions' scale on ``sheets`` (0 without one)."""
        return max((p.scale or 0.0 for sh in sheets for p, _, _ in getattr(sh, "placed", sh) if p.kind == "positions"), default=0.0)

    def improves(a: list, b: list) -> bool:
        """``b`` beats ``a`` (as few sheets, fuller) with the plan of positions no smaller."""
        return better(a, b, (W, H)) and shown(b) >= shown(a) * (1 - 1e-9)

    def fullest(grown: tuple[float | None, list], lay_at: Any) -> tuple[int, float | None, list]:
        """Of the sheets ``grown`` (the sheet's own solution: its length scale and sheets) and the
        same sheet drawn at each longer solution (``lay_at(i)``, likewise), the best, with its
        index (:data:`OWN`: ``grown``), tried in order while not yet full."""
        chosen, (mu, sheets) = OWN, grown
        for i in range(kin_fits):
            if full(sheets, (W, H)):
                break
            try:
                mu_i, bigger = lay_at(i)
            except TooBig:  # a panel too long for an empty sheet: no longer ones either
                break
            if len(bigger) > len(sheets):  # longer still would not take fewer
                break
            if improves(sheets, bigger):
                chosen, mu, sheets = i, mu_i, bigger
        return chosen, mu, sheets

    def mixed(at: Any, parts: list, best: tuple[int, float | None, list], lay: Any) -> list:
        """The sheets ``best`` (every part at the solution ``best[0]``, the length scale
        ``best[1]``) with each part's fit then raised in turn (:func:`drawings.linkage.mixing.ascend`):
        ``at(i)(mu)`` the panels of solution ``i`` at the length scale ``mu``."""
        start, mu, sheets = best
        if len(parts) < 2 or full(sheets, (W, H)):
            return sheets
        def ids(key: tuple[int, Any, int]) -> dict[str, Panel]:
            i, m, _ = key
            return {p.pid: p for p in at(i)(m)}

        by_id = memo(ids)
        base = at(OWN)(mu)

        def lay_fits(fits: tuple[int, ...]) -> list:
            return lay(swapped(base, parts, [(i, mu, j) for j, i in enumerate(fits)], by_id))

        def done(s: list) -> bool:
            return full(s, (W, H))

        def more(a: list, b: list) -> bool:
            return len(b) > len(a)

        return ascend((start,) * len(parts), kin_fits, lay_fits, improves, done, more, sheets)[1] \
            if kin_fits else sheets

    # the velocity and the acceleration plans each at its own longer scale (one part with a
    # table of readings: it reads both kinds at their scales)
    kin_parts = [lambda p: p.kind in ("velocity", "acceleration", "table")] if kin_sel["table"] else [
        lambda p: p.kind == "velocity", lambda p: p.kind == "acceleration"]

    def kin_layout(dia: Sequence[Panel]) -> list:
        """The kinematics sheet(s) with ``dia`` after the plans, at their fullest."""
        def kin_of(i: int) -> Any:
            return memo(kinematics(i, dia))

        kin_at = memo(kin_of)
        best = fullest(grow(kin_at(OWN), base_pos, lay_flat, own), lambda i: grow(kin_at(i), base_pos, lay_flat, own))
        return mixed(kin_at, kin_parts, best, lay_flat)

    if optional:
        kin_sheets = _with_optional(kin_layout, list(diagrams), optional, spec,
                                    lambda: bool(built[OWN][1] or built[OWN][2]))
    else:
        kin_sheets = _longest_axis(kin_layout, list(diagrams), axes, spec, shown)
    out: list[Sheet] = []
    named = dataclasses.replace(spec, subtitle=spec.subtitle or tr("kinematics_sheet", spec.language))
    for placed in kin_sheets:
        out.append(Sheet(named, 0, 0, W, H, placed, None))
    if forces and (scene.wants("force_polygons") or scene.wants("lever")):
        nums = {float(sol.kinematics.phi_deg[k]): n for k, n in enumerate(numbers(sol, spec))}
        sub = dataclasses.replace(spec, pins=(), subtitle=spec.subtitle or tr("kinetostatics_sheet", spec.language))

        def kinetic(build: Any) -> Any:
            """``mu`` -> the panels: the mechanism and its free bodies at μl = ``mu``, or
            at ``mu = (μl, μl of the free bodies)``."""
            return lambda mu: build(dyn_sel, None, *(mu if isinstance(mu, tuple) else (mu,)))[0]

        def lay(ps: list[Panel]) -> list:
            return compose(ps, sub, None, scene.path, nums, corners=True, render=False) if ps else []

        base_l = _base_length_scale(sol, spec)
        def dyn_of(i: int) -> Any:
            return memo(kinetic(builders(i)[0]))

        dyn_at = memo(dyn_of)
        # one standard scale for the mechanism at every position (the largest that keeps the
        # sheets fewest), one for the free bodies; each position's polygons and lever longer
        if not own:
            base_l = fewest(lambda m: lay(dyn_at(OWN)(m)), base_l, STANDARD_RATIOS)
        mu, _ = grow(dyn_at(OWN), base_l, lay, own)
        assert mu is not None
        # each position's free bodies with their polygons, and its lever, at a fit of their own
        # (a lever as tall as the sheet leaves the polygons room to grow all the same)
        dyn_parts = [part for k in forces for part in lever_apart(float(sol.kinematics.phi_deg[k]))]
        alone = [{kind: [x for x in ks if x == k] if isinstance(ks, list) else ks for kind, ks in dyn_sel.items()}
                 for k in forces]  # each position's selection, its panels built alone

        def part_at(key: tuple[int, tuple[float, float], int]) -> dict[str, Panel]:
            i, scales, j = key
            return {p.pid: p for p in builders(i)[0](alone[j], None, *scales)[0]}

        by_id = memo(part_at)

        def lay_at(fits: tuple[int, ...], mu_l: float, mu_b: float) -> list:
            base = dyn_at(OWN)((mu_l, mu_b))
            keys = [(i, (mu_l, mu_b), j // 2) for j, i in enumerate(fits)]
            return lay(swapped(base, dyn_parts, keys, by_id))

        out.extend(kinetic_layout(lay_at, len(forces), len(larger), mu, STANDARD_RATIOS, own, (W, H),
                                  len(longest)))
    for i, sh in enumerate(out):
        sh.number, sh.count = i + 1, len(out)
        sh.prims = []
        sh.render()
    return out


def _with_optional(kin_layout: Callable[[list[Panel]], list], diagrams: list[Panel],
                   optional: Sequence[Callable[[], Sequence[Panel] | None]], spec: SheetSpec,
                   drawn: Callable[[], bool]) -> list:
    """The kinematics sheets with the first of ``optional`` that keeps them as few and none
    emptier than :data:`drawings.linkage.larger.FULL` or than they are without it (see
    :func:`course_sheets`), else without any.  ``drawn()``: whether the sheets have panels of
    their own (read once one layout is made); one full sheet needs no layout without them."""
    from drawings.linkage.larger import FULL, score
    from drawings.paper.sheet import fits_empty

    size = spec.size
    bare: list | None = None
    for make in optional:
        extra = make()
        if extra is None:
            break
        if not all(fits_empty(p, spec.format, spec.orientation) for p in extra):
            continue
        laid = kin_layout(diagrams + list(extra))
        got = score(laid, size)
        if got[0] == -1 and got[1] >= FULL and drawn():
            return laid  # one sheet two thirds full passes whatever the sheets without them are
        if bare is None:
            bare = kin_layout(diagrams)
        was = score(bare, size)
        if got[0] >= was[0] and got[1] >= min(was[1], FULL):
            return laid
    return kin_layout(diagrams) if bare is None else bare


def _longest_axis(kin_layout: Callable[[list[Panel]], list], diagrams: list[Panel],
                  axes: Sequence[Callable[[], Sequence[Panel]]], spec: SheetSpec,
                  shown: Callable[[list], float]) -> list:
    """The kinematics sheets with the kinematic diagrams at the longest of ``axes`` (longer φ
    axes, shortest first) reached while the sheets are not yet full and each longer axis keeps
    them as few, none emptier than :data:`drawings.linkage.larger.FULL` or than they are at
    the axis before, and the plan of positions (its scale: ``shown``) no smaller; else with
    ``diagrams``."""
    from drawings.linkage.larger import FULL, score
    from drawings.paper.sheet import fits_empty

    laid = kin_layout(diagrams)
    for make in axes:
        was = score(laid, spec.size)
        if was[1] >= FULL:
            break
        longer = list(make())
        if not all(fits_empty(p, spec.format, spec.orientation) for p in longer):
            break
        trial = kin_layout(longer)
        got = score(trial, spec.size)
        if got[0] < was[0] or got[1] < min(was[1], FULL) or shown(trial) < shown(laid):
            break
        laid = trial
    return laid


def _order(p: Panel) -> int:
    """A panel's place in the kinematics sheet's order (:data:`ORDER`): the instant centres'
    circle diagram and table of velocities with their scheme."""
    kind = "centres" if p.kind == "circle-diagram" or p.pid.startswith("centre-table") else p.kind
    return ORDER.index(kind) if kind in ORDER else len(ORDER)


def _base_positions_scale(sol: Solution, spec: SheetSpec) -> float:
    from drawings.linkage.panels import auto_length_scale, cycle_size

    w, _ = spec.size
    return auto_length_scale(cycle_size(sol), 0.4 * (w - 37.0))


def _base_length_scale(sol: Solution, spec: SheetSpec) -> float:
    from drawings.linkage.panels import auto_length_scale, cycle_size

    w, h = spec.size
    return auto_length_scale(cycle_size(sol), 230.0 * min(1.0, max(w, h) / 841.0))
