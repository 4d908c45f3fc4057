"""A table too tall for its sheet split into parts by rows ("(продолжение)"), each part
fitting an empty sheet, rather than refused: a table has no scale to make smaller."""

from __future__ import annotations

import math
from collections.abc import Callable

from drawings.linkage.panels import Panel
from drawings.paper.sheet import SheetSpec, fits_empty


def parts(make: Callable[[tuple[int, int, int] | None], Panel], spec: SheetSpec) -> list[Panel]:
    """``make(None)``, the whole table, when it fits an empty ``spec`` sheet; else
    ``make((start, stop, n))`` for as few parts of its rows as fit (the header repeated on
    each); the whole table again where even one row a part does not fit (refused then)."""
    whole = make(None)
    if fits_empty(whole, spec.format, spec.orientation):
        return [whole]
    rows = sum(1 for p in whole.prims if p.op == "begin" and p.cls == "row")
    for n in range(2, rows + 1):
        step = math.ceil(rows / n)
        out = [make((i, min(i + step, rows), j + 1)) for j, i in enumerate(range(0, rows, step))]
        if all(fits_empty(p, spec.format, spec.orientation) for p in out):
            return out
    return [whole]
