"""The gear sheets of a gear file: a sheet per drawn pair, its meshing
(:mod:`drawings.gears_meshing`) over a field as large as the sheet holds, its specific sliding
(:mod:`drawings.gears_sliding`) and the pairs' table; the train (:mod:`drawings.gears_train`:
its unfolded scheme, plan of linear velocities and plan of angular velocities, each at its own
round scale, the speeds) moved onto one of them or on a sheet of its own
(:mod:`drawings.gears_layout`), from :mod:`plans.gears`."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from drawings.gears_layout import FieldSearch, TrainBlock, train_blocks
from drawings.gears_sliding import sliding_panel
from drawings.gears_train import (
    TrainScales,
    grid,
    magnification,
    magnifications,
    tr,
    train_panels,
    train_scales,
    train_tables,
    unit_word,
)
from drawings.linkage.panels import Panel, finish, ratio_text
from drawings.paper.fill import drawn_part
from drawings.paper.fonts import choose, drawing
from drawings.paper.sheet import Sheet, SheetSpec, compose, sheet_spec
from plans.errors import InputError, Said
from plans.gears.meshing import Meshing
from plans.gears.model import GearFile
from plans.gears.solution import GearsSolution, solve_file
from plans.gears.solve import GearSolution


@dataclass(frozen=True)
class GearDrawing:
    """Everything drawn for a gear file: the solution, the meshing, the panels and sheets."""

    file: GearFile
    solution: GearSolution
    meshing: Meshing | None
    spec: SheetSpec
    panels: tuple[Panel, ...]
    sheets: tuple[Sheet, ...]

    def _repr_svg_(self) -> str:
        return self.sheets[0].svg()


def results_panel(sol: GearSolution, lang: str) -> Panel:
    gf = sol.file
    k = gf.to_unit
    head = [tr("quantity", lang)]
    cols = []
    for p in sol.pairs:
        for w in p.wheels:
            head.append(f"{p.gears[0]}–{p.gears[1]}: {w.name}")
            cols.append((p, w))

    def f(v: float, d: int = 4) -> str:
        s = f"{v:.{d}f}"
        return s.replace(".", ",") if lang == "ru" else s

    rows = [head]
    spec = [
        ("z", lambda p, w: str(w.z)),
        ("x", lambda p, w: f(w.x, 5)),
        ("α_w, °", lambda p, w: f(math.degrees(p.alpha_w), 4)),
        (f"a_w, {unit_word(gf.unit, lang)}", lambda p, w: f(p.a_w * k, 3)),
        ("y", lambda p, w: f(p.y, 5)),
        ("Δy", lambda p, w: f(p.delta_y, 5)),
        ("r", lambda p, w: f(w.pitch * k, 3)),
        ("r_b", lambda p, w: f(w.base * k, 3)),
        ("r_a", lambda p, w: f(w.tip * k, 3)),
        ("r_f", lambda p, w: f(w.root * k, 3)),
        ("r_w", lambda p, w: f(w.working * k, 3)),
        ("α_a, °", lambda p, w: f(math.degrees(w.tip_angle), 3)),
        ("s", lambda p, w: f(w.thickness * k, 3)),
        ("s_a", lambda p, w: f(w.tip_thickness * k, 3)),
        ("s_a/m", lambda p, w: f(w.tip_thickness / p.m, 3)),
        ("ε", lambda p, w: f(p.contact_ratio, 4)),
    ]
    for name, fn in spec:
        rows.append([name] + [fn(p, w) for p, w in cols])
    rec = grid(rows, "results")
    return finish("results", "table", None, rec, tr("results", lang))


#: The drawn part of a sheet the layout aims at (every A1 sheet of the samples reaches it)
TWO_THIRDS = 2.0 / 3.0


def train_alone(sol: GearSolution, lang: str, spec: SheetSpec, path: str, table: list[Panel]
                ) -> tuple[list[Panel], list[Sheet]]:
    """The train (and ``table``) on a sheet of its own, as large as the sheet holds: its scheme
    at the largest round magnification (from the least that keeps it within half the sheet),
    each with its plans of velocities at the round scales worth drawing, the fullest of the
    largest that keeps one sheet; else the least, on as many sheets as it takes."""
    from drawings.paper.fill import fullest_on_one_sheet

    f = magnification(sol, spec) if sol.plan is not None else 1.0
    fs = [g for g in (magnifications(sol) if sol.plan is not None else [1.0]) if g >= f]
    groups = [[train_panels(sol, lang, s) + table for s in
               (train_scales(sol, g) if sol.plan is not None else [TrainScales(g, 1.0, 1.0)])] for g in fs]
    made = {id(t[0]): g for g, ts in zip(fs, groups, strict=True) for t in ts}

    def scale(panels: Sequence[Panel]) -> str:
        return ratio_text(sol.plan.mu_l * made[id(panels[0])], lang) if sol.plan is not None else ""

    alone = fullest_on_one_sheet(groups, spec, path, scale)
    least = groups[-1][0]
    return alone if alone is not None else (least, compose(least, spec, scale(least), path))


@drawing
def draw(source: GearsSolution | GearFile | str | Path, *, format: str | None = None,
         orientation: str | None = None, language: str | None = None, font: str | None = None) -> GearDrawing:
    """The meshing sheet (when the file has an external pair) and the train sheet (when it
    gives speeds): of a solved gear file (``plans.solve``), or of a file or its path, solved here."""
    from plans.language import choose as run_language

    gs = source if isinstance(source, GearsSolution) else solve_file(source)
    gf = gs.file
    sol = gs.solution
    spec = sheet_spec(gf.raw, gf.path, gf.title or tr("title", run_language(language, gf.raw)),
                      format=format, orientation=orientation, language=language, font=font)
    choose(spec.font, gf.path, font)
    lang = spec.language
    if not gs.meshings and not sol.pairs and sol.plan is None and sol.synthesis is None:
        raise InputError(Said("dg_nothing_draw_meshes"), file=gf.path, field="meshes")
    f = magnification(sol, spec) if sol.plan is not None else 1.0
    if not gs.meshings:  # the train alone, as large as its sheet holds
        panels, sheets = train_alone(sol, lang, spec, gf.path, [results_panel(sol, lang)] if sol.pairs else [])
        return GearDrawing(gf, sol, None, spec, tuple(panels), tuple(sheets))
    # a sheet for each meshing drawn: its field as large as the sheet holds, its specific
    # sliding beside it, the pairs' table on the first; the train (laid out alone, moved on as
    # one piece) on the sheet where the emptier sheet is fullest
    rests = [[sliding_panel(mg, lang)] + ([results_panel(sol, lang)] if i == 0 else [])
             for i, mg in enumerate(gs.meshings)]
    tables = train_tables(sol, lang)  # on the sheet that carries the train's figures
    blocks = train_blocks(sol, lang, f, spec, gf.path)
    if not blocks:
        rests[0] += tables
    search = [[FieldSearch(mg, rest + extra, spec, gf.path) for extra in ([], tables)]
              for mg, rest in zip(gs.meshings, rests, strict=True)]
    # the train on each sheet in turn, in each of its layouts: the emptier sheet the fullest
    # (the first of equals); sheet j carries layout t
    trains: list[TrainBlock | None] = list(blocks) or [None]
    options = [[search[i][i == j].best(blk if i == j else None)[1] for i in range(len(search))]
               for j in range(len(search) if blocks else 1) for blk in trains]
    pick = max(range(len(options)), key=lambda k: (round(min(options[k]), 9), -k))
    j, t = divmod(pick, len(trains)) if blocks else (-1, -1)
    own: tuple[list[Panel], list[Sheet]] = ([], [])
    if blocks and min(options[pick]) < TWO_THIRDS:  # or the train on a sheet of its own
        panels, sheets = train_alone(sol, lang, spec, gf.path, [])
        if min([search[i][0].best(None)[1] for i in range(len(search))] + [drawn_part(sh) for sh in sheets]) > \
                min(options[pick]):
            j, own = -1, (panels, sheets)
    out: list[Sheet] = []
    every: list[Panel] = []
    for i in range(len(search)):
        block = trains[t] if i == j else None
        drawn, sheets = search[i][i == j].lay_out(gs, i, lang, block)
        every += [drawn] + search[i][i == j].rest + (list(block.panels) if block is not None else [])
        out += sheets
    every += own[0]
    out += own[1]
    for n, sh in enumerate(out):
        sh.number, sh.count = n + 1, len(out)
        sh.prims = []
        sh.render()
    return GearDrawing(gf, sol, gs.meshings[0], spec, tuple(every), tuple(out))
