"""Sheets: format, GOST 2.104 frame and title block, automatic layout of panels.

A sheet is paper millimetres, y down, the origin at the top-left corner of the
paper.  The frame leaves 20 mm for binding on the left and 5 mm elsewhere; the
title block (185 × 55, form 1) sits in the bottom-right corner of the frame.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

from drawings.paper.backend import Prim, Recording, Style, replay
from drawings.paper.blocks import Frame, frame_of, spread
from drawings.paper.fonts import use
from drawings.paper.i18n import tr
from drawings.paper.packing import blocks_of, free_spots, place_blocks, place_note
from drawings.paper.panel_frame import SLACK_MM, Panel
from drawings.paper.svg import SvgBackend, document
from drawings.paper.text import layout, wrap
from plans.errors import InputError, Said
from plans.scene.sheet import FORMATS, PANEL_KINDS, SHEET_FORMATS, Pin, SheetSpec, sheet_spec  # noqa: F401  (read by the sheets)

MARGIN_LEFT = 20.0
MARGIN = 5.0
TB_W, TB_H = 185.0, 55.0
GAP = 6.0  # between panels, and between panels and the frame
Box = tuple[float, float, float, float]


# --------------------------------------------------------------------------- the sheet


@dataclass(slots=True)
class Sheet:
    """One plate: paper size, the placed panels, the frame and the title block."""

    spec: SheetSpec
    number: int  # 1-based within this drawing
    count: int
    width: float
    height: float
    placed: list[tuple[Panel, float, float]] = field(default_factory=list)
    scale_text: str | None = ""  # the title block's "Scale" cell; None: the sheet's main image's
    prims: list[Prim] = field(default_factory=list)
    frames: list[Frame] = field(default_factory=list)  # borders and headings of position blocks

    @property
    def frame_box(self) -> tuple[float, float, float, float]:
        return (MARGIN_LEFT, MARGIN, self.width - MARGIN, self.height - MARGIN)

    @property
    def title_box(self) -> tuple[float, float, float, float]:
        return title_box(self.width, self.height)

    def panel_boxes(self) -> dict[str, tuple[float, float, float, float]]:
        return {p.pid: (x, y, x + p.width, y + p.height) for p, x, y in self.placed}

    def render(self) -> list[Prim]:
        """Frame, title block and placed panels as paper primitives."""
        rec = Recording()
        with use(getattr(self.spec, "font", "dejavu")):  # the title block in the sheet's font
            _frame(rec, self)
            _title_block(rec, self)
            _frames(rec, self)
        prims = list(rec.prims)
        for panel, x, y in self.placed:
            prims.extend(panel.at(x, y))
        self.prims = prims
        return prims

    def svg(self, debug: bool = False) -> str:
        """The sheet as SVG text (``debug``: through svgwrite with its validation on; the
        same characters either way)."""
        if not debug:
            return document(self.width, self.height, self.prims or self.render())
        be = SvgBackend(self.width, self.height, debug=debug)
        replay(self.prims or self.render(), be)
        return be.tostring()

    def dxf(self) -> bytes:
        """The sheet as DXF bytes: the same primitives at 1:1 in millimetres, panels as
        blocks, layers by content and line type (:mod:`drawings.paper.dxf`)."""
        from drawings.paper.dxf import document as dxf_document

        prims, bases = self._dxf_blocks()
        return dxf_document(self.width, self.height, prims, self.spec.language, self.spec.title, bases)

    def _dxf_blocks(self) -> tuple[list[Prim], dict[str, tuple[float, float]]]:
        """The sheet's primitives with each placed panel one group (its block in CAD, with
        whatever was drawn beside the panel's own group, such as a checked plan's marks),
        and each panel's base point: its box's lower-left corner on the paper."""
        prims = self.prims or self.render()
        sizes = [len(p.prims) for p, _, _ in self.placed]
        start = len(prims) - sum(sizes)
        out: list[Prim] = list(prims[:max(start, 0)])
        bases: dict[str, tuple[float, float]] = {}
        for (panel, x, y), n in zip(self.placed, sizes, strict=True):
            part = prims[start:start + n]
            if start < 0 or not part or part[0] != panel.prims[0].moved(x, y):
                return list(prims), {}  # drawn otherwise than render() draws: blocks by groups
            start += n
            whole = n > 1 and part[0].op == "begin" and _closes_at_end(part)
            if not whole:
                part = [Prim("begin", eid=panel.pid, cls=f"panel {panel.kind}"), *part, Prim("end")]
            out.extend(part)
            bases[panel.pid] = (x, y + panel.height)
        return out, bases

    def _repr_svg_(self) -> str:
        return self.svg()


def _closes_at_end(prims: Sequence[Prim]) -> bool:
    """Whether the group opened by the first primitive closes at the last one."""
    depth = 0
    for k, p in enumerate(prims):
        depth += (p.op == "begin") - (p.op == "end")
        if depth == 0:
            return k == len(prims) - 1
    return False


def _frame(rec: Recording, sh: Sheet) -> None:
    x0, y0, x1, y1 = sh.frame_box
    rec.begin("frame", "frame")
    rec.polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], Style(width=0.7, cls="frame"), "frame-border")
    rec.end()


def _frames(rec: Recording, sh: Sheet) -> None:
    """A thin border round each position's block, its heading in the top-left corner."""
    from drawings.paper.blocks import HEAD, HEAD_SIZE, INSET

    for f in sh.frames:
        x0, y0, x1, y1 = f.box
        tag = f"{f.phi:.6g}".replace("-", "m")
        rec.begin(f"block-{tag}", "block")
        rec.polygon(f.outline(), Style(width=0.35, cls="block"), f"block-{tag}-border")
        rec.text(layout(f.heading, f.head_x + INSET, y0 + HEAD / 2 + 1.0, HEAD_SIZE, "start", "middle"),
                 "heading", f"block-{tag}-heading")
        rec.end()


def _fit(text: str, x: float, y: float, w: float, size: float, anchor: str = "start"):
    """A label no wider than ``w``: the size shrinks (a text that does not wrap inside its
    cell at 1.8 mm goes smaller still rather than run over the cell's lines)."""
    lab = layout(text, x, y, size, anchor, "middle")
    width = lab.box[2] - lab.box[0]
    # GOST 2.304's 2.5 mm kept while the text stays inside the cell's lines (most of the 1 mm
    # padding on each side given up first: "Изм." in its 7 mm column)
    room = w + (1.4 if anchor == "middle" else 0.7)
    if width > room and width > 0:
        size = size * w / width
        lab = layout(text, x, y, size, anchor, "middle")
    return lab


def _title_block(rec: Recording, sh: Sheet) -> None:
    """GOST 2.104 form 1: change log and signatures on the left, designation, name,
    literal/mass/scale, sheet N of M, organisation."""
    lang = sh.spec.language
    X0, Y0, X1, Y1 = sh.title_box
    thick = Style(width=0.7, cls="tb")
    thin = Style(width=0.25, cls="tb")
    rec.begin("title-block", "title-block")
    rec.polygon([(X0, Y0), (X1, Y0), (X1, Y1), (X0, Y1)], Style(width=0.7, fill="#fff", cls="tb"),
                "title-block-border")
    for i in range(1, 11):  # rows of 5 mm in the left part
        y = Y0 + 5 * i
        rec.line((X0, y), (X0 + 65, y), thick if i in (5, 6) else thin)
    rec.line((X0 + 7, Y0), (X0 + 7, Y0 + 30), thick)  # "Rev." column: change log rows only
    for c in (17.0, 40.0, 55.0, 65.0):
        rec.line((X0 + c, Y0), (X0 + c, Y1), thick)
    # right part
    rec.line((X0 + 65, Y0 + 15), (X1, Y0 + 15), thick)
    rec.line((X0 + 65, Y0 + 40), (X1, Y0 + 40), thick)
    rec.line((X0 + 135, Y0 + 15), (X0 + 135, Y1), thick)
    rec.line((X0 + 135, Y0 + 20), (X1, Y0 + 20), thick)
    rec.line((X0 + 135, Y0 + 35), (X1, Y0 + 35), thick)
    for c in (150.0, 167.0):
        rec.line((X0 + c, Y0 + 15), (X0 + c, Y0 + 35), thick)
    for c in (140.0, 145.0):
        rec.line((X0 + c, Y0 + 20), (X0 + c, Y0 + 35), thin)
    rec.line((X0 + 155, Y0 + 35), (X0 + 155, Y0 + 40), thick)

    def cell(text: str, x: float, y: float, w: float, size: float, eid: str, anchor: str = "start",
             h: float = 5.0) -> None:
        if not text:
            return
        xx = x + 1.0 if anchor == "start" else x + w / 2
        lines = _cell_lines(text, w - 2.0, h, size)
        if len(lines) == 1:
            rec.text(_fit(text, xx, y, w - 2.0, size, anchor), "tb-text", eid)
            return
        sz = lines[0][1]
        for i, (ln, _) in enumerate(lines):  # wrapped inside the cell, centred on its middle
            yy = y + (i - (len(lines) - 1) / 2) * sz * 1.2
            rec.text(_fit(ln, xx, yy, w - 2.0, sz, anchor), "tb-text", eid if i == 0 else f"{eid}-{i}")

    heads = [("izm", 0, 7), ("list", 7, 10), ("ndoc", 17, 23), ("sign", 40, 15), ("date", 55, 10)]
    for key, x, w in heads:
        cell(tr(key, lang), X0 + x, Y0 + 27.5, w, 2.5, f"tb-h-{key}", "middle")
    sig = [("author", sh.spec.author), ("checked", sh.spec.checked_by), ("tcontr", ""), ("ncontr", ""),
           ("approved", sh.spec.approved_by)]
    for i, (key, name) in enumerate(sig):
        y = Y0 + 32.5 + 5 * i
        cell(tr(key, lang), X0, y, 17, 2.5, f"tb-{key}")
        cell(name, X0 + 17, y, 23, 2.5, f"tb-{key}-name", h=5.0)
        if key == "author" and sh.spec.date:
            cell(sh.spec.date, X0 + 55, y, 10, 2.2, "tb-date", "middle")
    cell(sh.spec.designation, X0 + 65, Y0 + 7.5, 120, 5.0, "tb-designation", "middle")
    # name field: the title over up to three lines
    lines = _wrap(sh.spec.title, 66.0, 4.0)
    if len(lines) <= 3 and len(lines[-1]) == len(" ".join(wrap(lines[-1], 66.0, 4.0))) and \
            len(wrap(lines[-1], 66.0, 4.0)) == 1:
        y = Y0 + 27.5 - (len(lines) - 1) * 3.0
        for i, ln in enumerate(lines):
            cell(ln, X0 + 65, y + 6.0 * i, 70, 4.0, f"tb-title-{i}", "middle")
    else:  # too long for three lines at 4 mm: smaller, wrapped inside the cell
        cell(sh.spec.title, X0 + 65, Y0 + 27.5, 70, 4.0, "tb-title-0", "middle", h=25.0)
    cell(sh.spec.subtitle, X0 + 65, Y0 + 47.5, 70, 3.5, "tb-subtitle", "middle", h=15.0)
    cell(tr("lit", lang), X0 + 135, Y0 + 17.5, 15, 2.5, "tb-h-lit", "middle")
    cell(tr("mass", lang), X0 + 150, Y0 + 17.5, 17, 2.5, "tb-h-mass", "middle")
    cell(tr("mscale", lang), X0 + 167, Y0 + 17.5, 18, 2.5, "tb-h-scale", "middle")
    scale = sheet_scale(sh.placed, lang) if sh.scale_text is None else sh.scale_text
    cell(scale, X0 + 167, Y0 + 27.5, 18, 3.5, "tb-scale", "middle")
    n = sh.spec.first_sheet + sh.number - 1
    m = sh.spec.total_sheets or (sh.spec.first_sheet - 1 + sh.count)
    cell(f"{tr('sheet', lang)} {n}", X0 + 135, Y0 + 37.5, 20, 2.5, "tb-sheet")
    cell(f"{tr('sheets', lang)} {m}", X0 + 155, Y0 + 37.5, 30, 2.5, "tb-sheets")
    org = [t for t in (sh.spec.organization, sh.spec.group) if t]
    for i, t in enumerate(org):
        cell(t, X0 + 135, Y0 + 47.5 + (i - (len(org) - 1) / 2) * 15.0 / len(org), 50, 3.5, f"tb-org-{i}",
             "middle", h=15.0 / len(org))
    rec.end()


def sheet_scale(placed: Sequence[tuple[Panel, float, float]], lang: str) -> str:
    """The "Scale" cell as GOST 2.104 fills it: the scale (GOST 2.302) of the sheet's main
    image (the others say "M 1:4" under their titles): the mechanism's (its schemes' and plan
    of positions', the scale they cover most of the sheet at) where the sheet draws it, else
    its largest panel's drawn at a length scale (free bodies drawn larger than the mechanism
    beside it do not make the sheet's scale theirs); a dash where nothing on the sheet is
    drawn at a length scale (plans, tables)."""
    from drawings.paper.panel_frame import ratio_text

    drawn = [(p.width * p.height, p.scale) for p, _, _ in placed if p.quantity == "length" and p.scale]
    if not drawn:
        return "—"
    mechanism: dict[float, float] = {}
    for p, _, _ in placed:
        if p.kind in MECHANISM_KINDS and p.quantity == "length" and p.scale:
            mechanism[p.scale] = mechanism.get(p.scale, 0.0) + p.width * p.height
    if mechanism:
        return ratio_text(max(mechanism.items(), key=lambda t: (t[1], t[0]))[0], lang)
    return ratio_text(max(drawn, key=lambda t: t[0])[1], lang)


#: The panels that draw the mechanism itself: the sheet's main image where there are any.
MECHANISM_KINDS = ("positions", "scheme")


def _cell_lines(text: str, width: float, height: float, size: float) -> list[tuple[str, float]]:
    """``text`` as it fits a title-block cell: one line at ``size`` if it fits, else the
    largest size (down to 1.8 mm) at which its words wrap into lines that fit the cell."""
    lab = layout(text, 0, 0, size)
    if lab.box[2] - lab.box[0] <= width:
        return [(text, size)]
    sz = size
    words = text.replace("-", "- ")  # a double-barrelled name may break after its hyphen
    while sz >= 1.8 - SLACK_MM:
        lines = [ln.replace("- ", "-") for ln in wrap(words, width, sz)]
        if len(lines) * sz * 1.2 <= height - 0.6 and all(
                layout(ln, 0, 0, sz).box[2] - layout(ln, 0, 0, sz).box[0] <= width for ln in lines):
            return [(ln, sz) for ln in lines]
        sz = round(sz - 0.1, 2)
    return [(text, size)]  # one line, shrunk by _fit


def _wrap(text: str, width: float, size: float) -> list[str]:
    """A title block cell holds three lines at most: the rest runs on in the third."""
    lines = wrap(text, width, size)
    if len(lines) > 3:
        lines = lines[:2] + [" ".join(lines[2:])]
    return lines or [""]


# --------------------------------------------------------------------------- layout


def usable(width: float, height: float) -> tuple[float, float, float, float]:
    """Where panels may go: inside the frame, GAP from it."""
    return (MARGIN_LEFT + GAP, MARGIN + GAP, width - MARGIN - GAP, height - MARGIN - GAP)


def title_box(width: float, height: float) -> tuple[float, float, float, float]:
    """The title block's box, in the frame's lower right corner."""
    x1, y1 = width - MARGIN, height - MARGIN
    return (x1 - TB_W, y1 - TB_H, x1, y1)


def _overlaps(a: Sequence[float], b: Sequence[float]) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def compose(panels: Sequence[Panel], spec: SheetSpec, scale_text: str | None = "",
            path: str = "<scene>", numbers: dict[float, int] | None = None, corners: bool = False,
            render: bool = True) -> list[Sheet]:
    """Place panels on sheets of ``spec.format`` (pins first), as a course lays them out.

    The drawing-wide panels (plan of positions) come first; then one bordered block per
    crank angle, in angle order, under a heading "Положение 3, φ = 90°" (``numbers`` maps an
    angle to its position number).  Each block is packed several ways (:mod:`.packing`) and
    the sheet takes the shape that fits the room left, below or right of the previous block
    (never above it), on the same sheet while it fits, else on the next (sheet order = angle
    order).  A position too big for one sheet flows over the sheets in
    parts ("continued").  The legend goes where there is room once the blocks are down,
    above the title block where it can; spare height is shared out between the bands of
    blocks.  With ``corners`` a block that finds no room as a rectangle may run round the
    title block and the plan of positions (:func:`.packing.round_corners`).  ``scale_text``
    fills the title block's Scale cell; None: each sheet's own (:func:`sheet_scale`).
    Without ``render`` the sheets are left undrawn (no primitives: ``svg`` draws them): a
    layout search that only measures its candidates draws the one it keeps once.
    """
    W, H = spec.size
    area = usable(W, H)
    tb = title_box(W, H)
    by_id = {p.pid: p for p in panels}
    for pin in spec.pins:
        if pin.panel not in by_id:
            raise InputError(Said("ps_panel_panel_this", panel=pin.panel, v=', '.join(by_id)),
                             file=path, field="sheet.pins")
    for p in panels:
        check_fits(p, spec, path)
    sheets: list[list[tuple[Panel, float, float]]] = [[]]
    taken: list[list[Box]] = [[tb]]

    def put(s: int, p: Panel, x: float, y: float) -> None:
        sheets[s].append((p, x, y))
        taken[s].append((x, y, x + p.width, y + p.height))

    pinned = {pin.panel for pin in spec.pins}
    for pin in spec.pins:
        p = by_id[pin.panel]
        while len(sheets) < pin.sheet:
            sheets.append([])
            taken.append([tb])
        box = (pin.x, pin.y, pin.x + p.width, pin.y + p.height)
        if box[0] < area[0] - GAP or box[1] < area[1] - GAP or box[2] > area[2] + GAP or box[3] > area[3] + GAP:
            raise InputError(Said("ps_panel_panel_width", panel=pin.panel, width=p.width, height=p.height, x=pin.x, y=pin.y, format=spec.format), file=path,
                             field="sheet.pins")
        if any(_overlaps(box, t) for t in taken[pin.sheet - 1]):
            raise InputError(Said("ps_pinned_panel_panel", panel=pin.panel),
                             file=path, field="sheet.pins")
        put(pin.sheet - 1, p, pin.x, pin.y)
    queue = [p for p in panels if p.pid not in pinned]
    legend = next((p for p in queue if p.kind == "legend"), None)
    if legend is not None:  # the notes go where there is room once the blocks are down
        queue.remove(legend)
    groups: list[list[Panel]] = []  # one per crank angle (drawing-wide panels alone)
    for p in queue:
        if not groups or p.kind in _SINGLE or groups[-1][0].kind in _SINGLE or groups[-1][0].phi != p.phi:
            groups.append([])
        groups[-1].append(p)
    aw, ah = area[2] - area[0], area[3] - area[1]

    def limit(w: float) -> float:  # a block beside the title block may run the full height
        return ah if w <= aw - TB_W - GAP + SLACK_MM else ah - TB_H - GAP

    spots = free_spots(GAP)
    blks = blocks_of(groups, area, spec.language, numbers or {}, limit, GAP, spots, _SINGLE,
                     keep_whole=spec.format in _WHOLE_POSITIONS, tb=tb if corners else None)
    note = None if legend is None else (legend.width, legend.height)
    best, tks = place_blocks(blks, taken, area, GAP, spots, note, corners)
    if legend is not None:
        s, x, y = place_note(legend.width, legend.height, area, tks, GAP, spots)
        while len(best) <= s:
            best.append([])
            tks.append([tb])
        while len(sheets) <= s:
            sheets.append([])
            taken.append([tb])
        sheets[s].append((legend, x, y))
        taken[s].append((x, y, x + legend.width, y + legend.height))
    out = []
    order = {p.pid: k for k, p in enumerate(panels)}
    for n, bl in enumerate(best):
        stays = list(taken[n]) if n < len(taken) else [tb]
        bl = spread(bl, area, stays, GAP)
        placed = list(sheets[n]) if n < len(sheets) else []
        frames = []
        for b, bx, by in bl:
            placed.extend((p, bx + x, by + y) for p, x, y in b.panels)
            if b.framed:
                frames.append(frame_of(b, bx, by))
        placed.sort(key=lambda t: order[t[0].pid])
        sh = Sheet(spec, n + 1, len(best), W, H, placed, scale_text, frames=frames)
        if render:
            sh.render()
        out.append(sh)
    return out


_SINGLE = ("positions", "legend")  # drawing-wide panels: a block of their own
_WHOLE_POSITIONS = ("A1", "A2")  # formats where each position stays whole on one sheet


class TooBig(InputError):
    """A panel too big for an empty sheet (``panel``): an InputError for whoever cannot draw it
    at a smaller scale, a cue to solve again at a smaller fit for :func:`drawings.linkage.draw`."""

    panel: Panel


def check_fits(p: Panel, spec: SheetSpec, path: str) -> None:
    """A panel too big for an empty sheet: one line saying what would fit."""
    try:
        _refuse(p, spec, path)
    except TooBig as e:
        e.panel = p
        raise


def _refuse(p: Panel, spec: SheetSpec, path: str) -> None:
    if fits_empty(p, spec.format, spec.orientation):
        return
    bigger = [f for f in SHEET_FORMATS if fits_empty(p, f, spec.orientation)]
    if bigger:
        raise TooBig(f"panel {p.pid} ({p.width:.0f}×{p.height:.0f} mm) does not fit on an empty "
                         f"{spec.format} {spec.orientation} sheet; use --sheet {bigger[0]} or a smaller scale",
                         file=path, field="sheet.format")
    w, h = FORMATS["A1"]
    a = usable(w, h)
    aw, ah = a[2] - a[0], a[3] - a[1] - TB_H - GAP
    factor = min(aw / p.width, ah / p.height)
    what = p.quantity or "length"
    if p.scale:
        hint = f"e.g. [scales] {what} = {{ mu = {_round_down(p.scale * factor * 0.9):g} }}"
    else:
        hint = f"a scale about {factor:.2g} times smaller"
    raise TooBig(f"panel {p.pid} ({p.width:.0f}×{p.height:.0f} mm) does not fit even on an empty A1 "
                     f"({aw:.0f}×{ah:.0f} mm free); choose a smaller scale, {hint}", file=path,
                     field=f"scales.{what}")


def _round_down(x: float) -> float:
    """A round number (1, 2, 2.5, 4, 5 × 10^k) not above x."""
    e = math.floor(math.log10(x))
    for m in (10.0, 5.0, 4.0, 2.5, 2.0, 1.0):
        if m * 10.0**e <= x:
            return m * 10.0**e
    return 10.0**e


def fits_empty(p: Panel, fmt: str, orientation: str) -> bool:
    w, h = FORMATS[fmt]
    W, H = (w, h) if orientation == "landscape" else (h, w)
    a = usable(W, H)
    if p.width > a[2] - a[0] or p.height > a[3] - a[1]:
        return False
    return p.height <= a[3] - a[1] - TB_H - GAP or p.width <= a[2] - a[0] - TB_W - GAP


def sheet_size_ok(sheet: Sheet) -> bool:  # pragma: no cover - convenience
    return math.isfinite(sheet.width) and math.isfinite(sheet.height)
