"""The gear sheets laid out: each drawn meshing on a sheet of its own, its field (the part of
the pair drawn about P, at the pair's standard enlargement) grown to the largest the sheet
holds beside its specific sliding, the pairs' table and, on one of them, the train.

The train is laid out alone (its plan of velocities beside the scheme, at the scheme's
heights) in a few arrangements, its velocities at each round scale they may take, and moved
onto a meshing sheet as one piece (:mod:`drawings.paper.merge`).  Each field is tried as a
box of its panel's size first; the meshing is drawn once, at the field chosen."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from drawings.gears_meshing import meshing_panel
from drawings.gears_train import train_figures, train_scales
from drawings.linkage.panels import Panel, ratio_text
from drawings.paper.fill import boxes_part
from drawings.paper.merge import merged, moved_onto
from drawings.paper.sheet import Sheet, SheetSpec, compose, fits_empty, usable
from plans.gears.meshing import Meshing
from plans.gears.solution import GearsSolution
from plans.gears.solve import GearSolution

W_STEP, H_STEP = 10.0, 20.0  # mm: the meshing's field grown in these steps
#: The sheets the train is laid out alone on, for its arrangements: a row across the sheet,
#: or the plan of angular velocities and the tables under the plan of velocities
ARRANGEMENTS = (None, ("A2", "landscape"), ("A2", "portrait"))


@dataclass(frozen=True)
class TrainBlock:
    """The train's figures laid out alone on one sheet (moved on as one piece)."""

    panels: tuple[Panel, ...]
    sheet: Sheet
    scale: str


def train_blocks(sol: GearSolution, lang: str, f: float, spec: SheetSpec, path: str) -> list[TrainBlock]:
    """The train's figures at magnification ``f``, its plans of velocities at each round scale
    worth drawing (:func:`drawings.gears_train.train_scales`), in each arrangement that keeps
    it one sheet (the same arrangement once); none without a plan."""
    if sol.plan is None:
        return []
    out: list[TrainBlock] = []
    text = ratio_text(sol.plan.mu_l * f, lang)
    for scales in train_scales(sol, f):
        panels = train_figures(sol, lang, scales)
        seen: set[tuple] = set()
        for shape in ARRANGEMENTS:
            on = spec if shape is None else dataclasses.replace(spec, format=shape[0], orientation=shape[1])
            if not all(fits_empty(p, on.format, on.orientation) for p in panels):
                continue
            laid = compose(panels, on, text, path)
            key = tuple((p.pid, round(x, 6), round(y, 6)) for p, x, y in laid[0].placed)
            if len(laid) == 1 and key not in seen:
                seen.add(key)
                out.append(TrainBlock(tuple(panels), laid[0], text))
    return out


def field_sizes(mg: Meshing, spec: SheetSpec) -> tuple[list[float], list[float]]:
    """The meshing's field's half-widths and half-heights about P worth trying on a sheet,
    smallest first: from the least that shows its teeth and line of action (in height, half
    of that) up to the sheet's field, no farther than the wheels reach (their largest circles
    and 12 mm)."""
    x0, y0, x1, y1 = usable(*spec.size)
    reach = max(max(dw.radii.values()) for dw in mg.wheels) + 12.0
    lo = min(dw.centre.imag - max(dw.radii.values()) for dw in mg.wheels) - 12.0
    hi = max(dw.centre.imag + max(dw.radii.values()) for dw in mg.wheels) + 12.0
    wmax = min((x1 - x0 - BOX[0]) / 2, reach)
    hmax = min((y1 - y0 - BOX[1]) / 2, (hi - lo) / 2)
    low = 0.5 * mg.window
    ws = [mg.window + W_STEP * j for j in range(int((wmax - mg.window) // W_STEP) + 1)]
    hs = [low + H_STEP * j for j in range(int((hmax - low) // H_STEP) + 1)]
    return ws, hs


#: What a meshing panel has beyond its field: its frame's padding across, the title and scale
#: above and the contact ratio's line under it in height (mm; a little over, as drawn)
BOX = (5.0, 27.0)


class FieldSearch:
    """One meshing's sheet: the fields that keep it one sheet, with its other panels and the
    train or without, each tried as a box of the meshing panel's size (kept per field)."""

    def __init__(self, mg: Meshing, rest: list[Panel], spec: SheetSpec, path: str) -> None:
        self.mg, self.rest, self.spec, self.path = mg, rest, spec, path
        # the rest as boxes too: a layout places boxes, and a sheet of boxes is drawn at once
        self.boxes = [dataclasses.replace(p, prims=()) for p in rest]
        self.ws, self.hs = field_sizes(mg, spec)
        self.laid: dict[tuple[float, float], Sheet | None] = {}
        self.found: dict[int, list[tuple[float, tuple[float, float]]]] = {}

    def sheet(self, field: tuple[float, float]) -> Sheet | None:
        """The sheet of a box of the meshing panel's size over ``field`` and the rest, or None
        where they take more than one."""
        if field not in self.laid:
            box = Panel("meshing", "meshing", None, (), 2 * field[0] + BOX[0], 2 * field[1] + BOX[1], "")
            ok = fits_empty(box, self.spec.format, self.spec.orientation)
            laid = compose([box] + self.boxes, self.spec, "", self.path) if ok else []
            self.laid[field] = laid[0] if len(laid) == 1 else None
        return self.laid[field]

    def fits(self, field: tuple[float, float], block: TrainBlock | None) -> bool:
        sh = self.sheet(field)
        return sh is not None and (block is None or moved_onto(sh, block.sheet) is not None)

    def part(self, field: tuple[float, float], block: TrainBlock | None) -> float:
        """The sheet's drawn part with the meshing over ``field`` (and the train moved on)."""
        sh = self.sheet(field)
        assert sh is not None
        boxes = [(x, y, x + p.width, y + p.height) for p, x, y in sh.placed]
        if block is not None:
            shift = moved_onto(sh, block.sheet)
            assert shift is not None
            boxes += [(x + shift[0], y + shift[1], x + shift[0] + p.width, y + shift[1] + p.height)
                      for p, x, y in block.sheet.placed]
        return boxes_part(sh.width, sh.height, boxes)

    def candidates(self, block: TrainBlock | None) -> list[tuple[float, tuple[float, float]]]:
        """For each height the widest field that keeps one sheet (halving the widths), as
        (drawn part, field), fullest first (the larger field of equals)."""
        key = id(block)
        if key not in self.found:
            out = []
            for h in reversed(self.hs):
                lo, hi = -1, len(self.ws) - 1
                while lo < hi:
                    mid = (lo + hi + 1) // 2
                    if self.fits((self.ws[mid], h), block):
                        lo = mid
                    else:
                        hi = mid - 1
                if lo >= 0:
                    field = (self.ws[lo], h)
                    out.append((self.part(field, block), field))
            self.found[key] = sorted(out, key=lambda c: (-round(c[0], 9), -c[1][0] * c[1][1]))
        return self.found[key]

    def best(self, block: TrainBlock | None) -> tuple[tuple[float, float] | None, float]:
        """The fullest field and the sheet's drawn part with it (0 where none keeps one sheet)."""
        c = self.candidates(block)
        return (c[0][1], c[0][0]) if c else (None, 0.0)

    def lay_out(self, gs: GearsSolution, i: int, lang: str, block: TrainBlock | None) -> tuple[Panel, list[Sheet]]:
        """The meshing drawn over the fullest field whose drawing keeps one sheet (the least
        field, on as many sheets as it takes, where none does), the train moved on."""
        later = [block.sheet] if block is not None else []
        scale = ratio_text(self.mg.k * 1000.0, lang)
        for _, field in self.candidates(block):
            drawn = meshing_panel(gs.meshing_in(i, field), lang)
            laid = compose([drawn] + self.rest, self.spec, scale, self.path)
            if len(laid) == 1 and (block is None or moved_onto(laid[0], block.sheet) is not None):
                return drawn, merged(laid + later)
        drawn = meshing_panel(self.mg, lang)
        return drawn, merged(compose([drawn] + self.rest, self.spec, scale, self.path) + later)
