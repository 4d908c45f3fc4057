"""DXF sheets: the recorded primitives of a sheet as a draftsman's CAD file.

The sheet at 1:1 in model space, 1 unit = 1 mm, x right, y up, the paper's
lower-left corner at the origin (the sheet's own y runs down: ``y_dxf = H − y``).
Every top-level group of the sheet (frame, title block, each panel) is a block,
inserted where it stands, so it moves as one in CAD.  Layers follow the content
(scheme, velocity plan, ...) and the ESKD line types of GOST 2.303 (solid main,
solid thin, dash-dot, dashed) with true lineweights; text is on one layer.

Lines are LINE, joints and circles CIRCLE, arcs ARC, curves LWPOLYLINE, filled
arrowheads SOLID, filled dots and areas solid HATCH, each run of a label (base,
subscript, superscript) one TEXT from the run's own baseline start to its end as
measured in the SVG's font ("fit" alignment), so ``a^n_BA`` reads as on the SVG
whatever font the CAD program draws it in.  White fills (a joint's paper-coloured disc) have no CAD
counterpart and are left out; their outlines stay.

ezdxf writes the document (header, tables, blocks, objects).  The entities are
written as text by :class:`_Tags`, the tags ezdxf itself writes for them, in the
same order, with the handles ezdxf would give them: :func:`document` and
:func:`document_ezdxf` (every entity through ezdxf's API, the reference) give the
same bytes, the first several times faster.  Dates and GUIDs are ezdxf's fixed
ones: the same sheet gives the same bytes.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator, Sequence
from contextlib import contextmanager
from functools import lru_cache
from typing import Any

from drawings.paper.backend import Prim, Pt, Style, hatch_segments

#: DejaVu Sans (the SVG's font, whose metrics laid the runs out): capital height per em
#: (a run in osifont, ``[sheet] font = "gost"``, has that font's own).
#: A DXF text height is the capitals' height, an SVG font size the em.
CAP = 1493 / 2048
#: The text style: a GOST 2.304-like ISO 3098 font with Cyrillic that CAD programs have
#: (AutoCAD ships ISOCPEUR; KOMPAS and LibreCAD put their own GOST/ISO font in its place).
STYLE = "GOST"
FONT = "isocpeur.ttf"
#: The lineweights DXF knows, 1/100 mm.
LINEWEIGHTS = (0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120, 140,
               158, 200, 211)
#: Line types of GOST 2.303 and the layer's own lineweight (1/100 mm; entities carry their own).
LINES = {"main": 50, "thin": 25, "centre": 25, "dashed": 35}
#: The dash-dot and dashed layers' own line types (GOST 2.303: strokes 5–30 mm, gaps 3–5 mm;
#: strokes 2–8 mm, gaps 1–2 mm): DXF patterns, total length first, gaps negative.
LAYER_LINETYPES = {"ESKD_CENTRE": (19.0, 12.0, -3.0, 1.0, -3.0), "ESKD_DASHED": (6.0, 4.0, -2.0)}
LAYER_LINETYPE = {"centre": "ESKD_CENTRE", "dashed": "ESKD_DASHED"}
#: Panel kinds by the layer of their content (the frame, text and marks come from the groups).
CONTENT = {
    "scheme": ("positions", "scheme", "meshing", "train-scheme", "cam-profile", "synthesis-construction"),
    "velocity": ("velocity", "velocity-plan", "ray-diagram"),
    "acceleration": ("acceleration",),
    "forces": ("polygon", "group", "crank"),
    "lever": ("lever",),
    "tables": ("table", "cycle-table", "cam-results", "legend"),
}
_CONTENT_OF = {k: c for c, kinds in CONTENT.items() for k in kinds}
DEFAULT_CONTENT = "diagrams"  # diagrams of motion, dynamics, cams; any kind to come
LAYER_WORDS = {
    "ru": {"frame": "Рамка", "scheme": "Схема", "velocity": "План скоростей",
           "acceleration": "План ускорений", "forces": "Силы", "lever": "Рычаг",
           "diagrams": "Диаграммы", "tables": "Таблицы", "marks": "Пометки", "text": "Текст",
           "main": "основная", "thin": "тонкая", "centre": "штрихпунктирная", "dashed": "штриховая"},
    "en": {k: k for k in ("frame", "scheme", "velocity", "acceleration", "forces", "lever", "diagrams",
                          "tables", "marks", "text", "main", "thin", "centre", "dashed")},
}
_WHITE = {"#fff", "#ffffff", "white"}
_BAD_NAME = str.maketrans({c: "_" for c in '<>/\\":;?*|=,`'})


@lru_cache(maxsize=256)
def lineweight(width: float) -> int:
    """The DXF lineweight nearest a stroke width in mm (a tie: the heavier)."""
    w = width * 100.0
    return min(LINEWEIGHTS, key=lambda v: (abs(v - w), -v))


def line_kind(style: Style) -> str:
    """GOST 2.303 line type of a stroke: dash-dot (a dash pattern of four or more),
    dashed, else main or thin by width."""
    if len(style.dash) >= 4:
        return "centre"
    if style.dash:
        return "dashed"
    return "main" if style.width >= 0.45 else "thin"


@lru_cache(maxsize=256)
def rgb(color: str | None) -> int | None:
    """A CSS ``#rgb``/``#rrggbb`` colour as a DXF true colour; None for black (by layer)."""
    if not color or not color.startswith("#"):
        return None
    h = color[1:]
    if len(h) == 3:
        h = "".join(c * 2 for c in h)
    v = int(h, 16)
    return None if v == 0 else v


def linetype_name(kind: str, dash: Sequence[float]) -> str:
    from drawings.paper.svg import num

    return f"ESKD_{kind.upper()}_" + "_".join(num(d) for d in dash)


# --------------------------------------------------------------------------- entities

#: One entity: (type, layer, linetype, lineweight or None, true colour or None, data)
Ent = tuple[str, str, str, Any, Any, tuple]


def _r(v: float) -> float:
    return round(float(v), 4) + 0.0  # 0.1 µm; a Python float (repr), never -0.0


class DxfBackend:
    """The drawing backend (:class:`drawings.paper.backend.Backend`) that collects DXF entities
    per block, in DXF coordinates local to the block's base point."""

    def __init__(self, width: float, height: float, language: str = "en",
                 bases: dict[str, Pt] | None = None) -> None:
        self.width, self.height = width, height
        self.words = LAYER_WORDS.get(language, LAYER_WORDS["en"])
        self.bases = bases or {}
        self.blocks: dict[str, list[Ent]] = {}  # name -> entities, in order of appearance
        self.base_of: dict[str, tuple[float, float]] = {}
        self.layers: dict[str, str] = {}  # name -> line kind
        self.linetypes: dict[str, tuple[float, ...]] = {}
        self.stack: list[tuple[str, str]] = []
        self._names: set[str] = set()
        self._strokes: dict[tuple[Style, str], tuple[str, str, int, int | None]] = {}
        self._ents: list[Ent] | None = None  # the open block's entities
        self._content = "frame"
        self._bx = 0.0
        self._by = 0.0

    # ---- groups: a top-level group is a block; the panel's kind names its layers

    def begin(self, gid: str, cls: str = "") -> None:
        if not self.stack:
            self._open(gid)
        self.stack.append((gid, cls))
        self._content = self._content_now()

    def _open(self, gid: str) -> list[Ent]:
        """A new block for a top-level group (or for what is drawn outside every group,
        named "sheet"): the sheet's drawing order is model space's order of INSERTs."""
        name = (gid or "sheet").translate(_BAD_NAME).lstrip("*") or "sheet"
        k, base = 2, name
        while name.casefold() in self._names:  # CAD block names ignore case (dyn-W, dyn-w)
            name, k = f"{base}-{k}", k + 1
        self._names.add(name.casefold())
        ents: list[Ent] = []
        self.blocks[name] = self._ents = ents
        bx, by = self.bases.get(gid, (0.0, self.height))
        self._bx, self._by = _r(bx), _r(self.height - by)
        self.base_of[name] = (self._bx, self._by)
        return ents

    def _list(self) -> list[Ent]:
        return self._ents if self._ents is not None else self._open("")

    def end(self) -> None:
        self.stack.pop()
        if not self.stack:
            self._ents = None
            self._bx, self._by = 0.0, 0.0
        self._content = self._content_now()

    def _content_now(self) -> str:
        content = "frame"
        for _, cls in self.stack:
            words = cls.split()
            if words[:1] == ["panel"] and len(words) > 1:
                content = _CONTENT_OF.get(words[1], DEFAULT_CONTENT)
            elif words[:1] == ["check-mark"]:
                content = "marks"
        return content

    # ---- attributes

    def _p(self, p: Pt) -> tuple[float, float]:
        return (round(float(p[0] - self._bx), 4) + 0.0, round(float(self.height - p[1] - self._by), 4) + 0.0)

    def _layer(self, kind: str) -> str:
        w = self.words
        name = w["text"] if kind == "text" else f"{w[self._content]}-{w[kind]}"
        self.layers.setdefault(name, kind)
        return name

    def _stroke(self, style: Style) -> tuple[str, str, int, int | None]:
        key = (style, self._content)
        got = self._strokes.get(key)
        if got is None:  # a sheet draws with a few dozen styles
            kind = line_kind(style)
            lt = ""
            if style.dash:
                lt = linetype_name(kind, style.dash)
                self.linetypes.setdefault(lt, tuple(style.dash))
            got = self._strokes[key] = (self._layer(kind), lt, lineweight(style.width), rgb(style.stroke))
        return got

    def _fill(self, style: Style) -> tuple[str, int | None] | None:
        f = style.fill
        if not f or f == "none" or f.lower() in _WHITE:
            return None
        kind = line_kind(style) if style.stroke else "main"
        return self._layer(kind), rgb(f)

    # ---- Backend

    def line(self, p0: Pt, p1: Pt, style: Style, eid: str = "") -> None:
        if style.stroke:
            self._list().append(("LINE", *self._stroke(style), (self._p(p0), self._p(p1))))

    def polyline(self, pts: Sequence[Pt], style: Style, eid: str = "") -> None:
        self._poly(pts, style, closed=False)

    def polygon(self, pts: Sequence[Pt], style: Style, eid: str = "") -> None:
        self._poly(pts, style, closed=True)

    def _poly(self, pts: Sequence[Pt], style: Style, closed: bool) -> None:
        q = [self._p(p) for p in pts]
        fill = self._fill(style)
        if fill is not None and len(q) >= 3:
            layer, color = fill
            if len(q) == 3:
                self._list().append(("SOLID", layer, "", None, color, tuple(q)))
            else:
                self._list().append(("HATCH", layer, "", None, color, ("poly", tuple(q))))
        if style.stroke and len(q) >= 2:
            self._list().append(("LWPOLYLINE", *self._stroke(style), (closed, tuple(q))))

    def circle(self, c: Pt, r: float, style: Style, eid: str = "") -> None:
        q, rr = self._p(c), _r(r)
        fill = self._fill(style)
        if fill is not None:
            self._list().append(("HATCH", fill[0], "", None, fill[1], ("circle", q, rr)))
        if style.stroke:
            self._list().append(("CIRCLE", *self._stroke(style), (q, rr)))

    def arc(self, c: Pt, r: float, a0: float, a1: float, style: Style, eid: str = "") -> None:
        if not style.stroke:
            return
        if abs(a1 - a0) >= 2 * math.pi - 1e-12:
            self.circle(c, r, Style(style.stroke, style.width, None, style.dash, style.cls))
            return
        # paper angles run clockwise (y down); DXF arcs run counter-clockwise from the start
        lo, hi = min(a0, a1), max(a0, a1)
        start, stop = math.degrees(-hi) % 360.0, math.degrees(-lo) % 360.0
        self._list().append(("ARC", *self._stroke(style), (self._p(c), _r(r), _r(start), _r(stop))))

    def text(self, label: Any, cls: str = "", eid: str = "", fill: str = "#000") -> None:
        from drawings.paper.fonts import FONT_FAMILY, metrics

        layer = self._layer("text")
        color = rgb(fill)
        for run in label.runs:
            if run.text.strip():
                value = run.text.replace("%%", "%%%")
                x, y = self._p((run.x, run.y))
                m = metrics(run.font or FONT_FAMILY)  # the font that laid the run out
                end = _r(x + m.width(run.text, run.size))
                cap = m.cap if run.font else CAP
                self._list().append(("TEXT", layer, "", None, color,
                                     ((x, y), _r(run.size * cap), value, (end, y))))

    def hatch(self, p0: Pt, p1: Pt, side: int, style: Style, step: float = 2.5,
              length: float = 2.5, eid: str = "") -> None:
        """The short strokes of a fixed support, each a LINE."""
        for a, b in hatch_segments(p0, p1, side, step, length):
            self.line(a, b, style)


# --------------------------------------------------------------------------- the document


def _bases(prims: Sequence[Prim], known: dict[str, Pt]) -> dict[str, Pt]:
    """Each top-level group's base point: ``known``'s, else the lower-left corner of its
    box, in whole millimetres (paper mm)."""
    out: dict[str, Pt] = dict(known)
    depth = 0
    gid = ""
    box: list[float] = []
    skip = False
    for p in prims:
        if p.op == "begin":
            if depth == 0:
                gid, box = p.eid, [math.inf, -math.inf]
                skip = gid in out
            depth += 1
        elif p.op == "end":
            depth -= 1
            if depth == 0 and gid not in out:
                out[gid] = (math.floor(box[0]) if box[0] < math.inf else 0.0,
                            math.ceil(box[1]) if box[1] > -math.inf else 0.0)
        elif depth and not skip:
            b = p.box()
            if b is not None:
                box[0] = min(box[0], b[0])
                box[1] = max(box[1], b[3])
    return out


def collect(width: float, height: float, prims: Iterable[Prim], language: str = "en",
            bases: dict[str, Pt] | None = None) -> DxfBackend:
    """The entities of recorded primitives, by block (``bases``: a group's base point on the
    paper, by its id; a group not named there: its box's lower-left corner)."""
    from drawings.paper.backend import replay

    prims = list(prims)
    be = DxfBackend(width, height, language, _bases(prims, bases or {}))
    replay(prims, be)
    return be


def _skeleton(be: DxfBackend, title: str = "") -> Any:
    """The ezdxf document of a sheet without its entities: header (mm, extents, limits),
    line types, layers, the text style, the blocks and their INSERTs."""
    import ezdxf

    W, H = be.width, be.height
    doc = ezdxf.new("R2010", setup=False, units=4)
    hdr = doc.header
    hdr["$MEASUREMENT"] = 1
    hdr["$LUNITS"] = 2
    hdr["$LUPREC"] = 2
    hdr["$LTSCALE"] = 1.0
    hdr["$CELTSCALE"] = 1.0
    hdr["$PSLTSCALE"] = 0
    hdr["$LWDISPLAY"] = 1
    hdr["$LIMMIN"] = (0.0, 0.0)
    hdr["$LIMMAX"] = (W, H)
    hdr["$EXTMIN"] = (0.0, 0.0, 0.0)
    hdr["$EXTMAX"] = (W, H, 0.0)
    hdr["$TEXTSTYLE"] = STYLE
    hdr["$TEXTSIZE"] = 3.5
    if title:
        hdr["$PROJECTNAME"] = title
    msp = doc.modelspace()
    msp.dxf.extmin = (0.0, 0.0, 0.0)
    msp.dxf.extmax = (W, H, 0.0)
    msp.dxf.limmin = (0.0, 0.0)
    msp.dxf.limmax = (W, H)
    doc.styles.add(STYLE, font=FONT)
    for name, dash in sorted(be.linetypes.items()):
        pattern = [float(sum(dash))] + [float(d) if i % 2 == 0 else -float(d) for i, d in enumerate(dash)]
        doc.linetypes.add(name, pattern=pattern, description=name)
    for name, own in LAYER_LINETYPES.items():
        doc.linetypes.add(name, pattern=list(own), description=name)
    for name, kind in sorted(be.layers.items()):
        layer = doc.layers.add(name, color=7)
        if kind != "text":  # what a line drawn on the layer in CAD gets; ours carry their own
            layer.dxf.lineweight = LINES[kind]
            layer.dxf.linetype = LAYER_LINETYPE.get(kind, "Continuous")
    doc.set_modelspace_vport(height=H * 1.05, center=(W / 2, H / 2))
    # the paper layout: the sheet's own paper, one viewport showing model space at 1:1
    paper: Any = doc.layouts.get("Layout1")  # a Paperspace
    paper.page_setup(size=(W, H), margins=(0, 0, 0, 0), units="mm", scale=(1, 1), name="plans")
    paper.add_viewport(center=(W / 2, H / 2), size=(W, H), view_center_point=(W / 2, H / 2), view_height=H)
    for vp in paper.viewports():
        vp.dxf.layer = "Defpoints"  # a viewport's border never prints
    for name in be.blocks:
        doc.blocks.new(name)
    for name in be.blocks:
        msp.add_blockref(name, be.base_of[name])
    return doc


@contextmanager
def _fixed() -> Iterator[None]:
    """ezdxf's fixed dates, GUIDs and creation marks while a document is made and written."""
    import ezdxf

    fixed = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        yield
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = fixed


def _write(doc: Any) -> str:
    import io

    # ezdxf adds the CLASS entries of the object types in use in a set's order (it changes
    # with the process's string hashes): added first here, in one order, they stay put
    doc.classes.add_required_classes(doc.dxfversion)
    doc.classes.classes = dict(sorted(doc.classes.classes.items()))
    out = io.StringIO()
    doc.write(out)
    return out.getvalue()


def document(width: float, height: float, prims: Iterable[Prim], language: str = "en",
             title: str = "", bases: dict[str, Pt] | None = None) -> bytes:
    """The DXF bytes of recorded primitives on a ``width`` × ``height`` mm sheet: each
    top-level group a block (``bases``: see :func:`collect`)."""
    be = collect(width, height, prims, language, bases)
    with _fixed():
        return _document(be, title)


def _document(be: DxfBackend, title: str) -> bytes:
    doc = _skeleton(be, title)
    handles = doc.entitydb.handles
    parts: dict[str, str] = {}
    tags = _Tags()
    for name, ents in be.blocks.items():
        blk = doc.blocks.get(name)
        owner = blk.block_record_handle
        parts[blk.endblk.dxf.handle] = "".join(tags.entity(e, handles.next(), owner) for e in ents)
    text = _write(doc)
    out: list[str] = []
    pos = 0
    for endblk, body in parts.items():
        mark = f"  0\nENDBLK\n  5\n{endblk}\n"
        i = text.index(mark, pos)
        out += [text[pos:i], body]
        pos = i
    out.append(text[pos:])
    return "".join(out).encode("utf-8")


def document_ezdxf(width: float, height: float, prims: Iterable[Prim], language: str = "en",
                   title: str = "", bases: dict[str, Pt] | None = None) -> bytes:
    """:func:`document` with every entity made through ezdxf's API (the reference)."""
    be = collect(width, height, prims, language, bases)
    with _fixed():
        return _document_ezdxf(be, title)


def _document_ezdxf(be: DxfBackend, title: str) -> bytes:
    doc = _skeleton(be, title)
    for name, ents in be.blocks.items():
        blk = doc.blocks.get(name)
        for e in ents:
            _add(blk, e)
    return _write(doc).encode("utf-8")


def _attribs(e: Ent) -> dict[str, Any]:
    kind, layer, lt, lw, color, _ = e
    a: dict[str, Any] = {"layer": layer}
    if lt:
        a["linetype"] = lt
    if lw is not None:
        a["lineweight"] = lw
    if color is not None:
        a["true_color"] = color
    return a


def _add(layout: Any, e: Ent) -> None:
    kind, data = e[0], e[5]
    a = _attribs(e)
    if kind == "LINE":
        layout.add_line(data[0], data[1], dxfattribs=a)
    elif kind == "LWPOLYLINE":
        layout.add_lwpolyline(data[1], close=data[0], dxfattribs=a)
    elif kind == "CIRCLE":
        layout.add_circle(data[0], data[1], dxfattribs=a)
    elif kind == "ARC":
        layout.add_arc(data[0], data[1], data[2], data[3], dxfattribs=a)
    elif kind == "SOLID":
        layout.add_solid(data, dxfattribs=a)
    elif kind == "TEXT":
        from ezdxf.enums import TextEntityAlignment

        a["style"] = STYLE
        layout.add_text(data[2], height=data[1], dxfattribs=a).set_placement(
            data[0], data[3], align=TextEntityAlignment.FIT)
    elif kind == "HATCH":
        h = layout.add_hatch(dxfattribs=a)
        h.dxf.discard("color")
        if data[0] == "circle":
            h.paths.add_edge_path().add_arc(data[1], data[2], 0.0, 360.0)
        else:
            h.paths.add_polyline_path(data[1])
    else:  # pragma: no cover
        raise ValueError(kind)


class _Tags:
    """An entity's DXF tags as ezdxf writes them (same codes, order and numbers)."""

    def entity(self, e: Ent, handle: str, owner: str) -> str:
        kind, layer, lt, lw, color, data = e
        head = [f"  0\n{kind}\n  5\n{handle}\n330\n{owner}\n100\nAcDbEntity\n  8\n{layer}\n"]
        if lt:
            head.append(f"  6\n{lt}\n")
        if lw is not None:
            head.append(f"370\n{lw}\n")
        if color is not None:
            head.append(f"420\n{color}\n")
        return "".join(head) + getattr(self, kind)(data)

    @staticmethod
    def LINE(d: tuple) -> str:
        (x0, y0), (x1, y1) = d
        return f"100\nAcDbLine\n 10\n{x0!r}\n 20\n{y0!r}\n 30\n0.0\n 11\n{x1!r}\n 21\n{y1!r}\n 31\n0.0\n"

    @staticmethod
    def LWPOLYLINE(d: tuple) -> str:
        closed, pts = d
        body = "".join(f" 10\n{x!r}\n 20\n{y!r}\n" for x, y in pts)
        return f"100\nAcDbPolyline\n 90\n{len(pts)}\n 70\n{1 if closed else 0}\n{body}"

    @staticmethod
    def CIRCLE(d: tuple) -> str:
        (x, y), r = d
        return f"100\nAcDbCircle\n 10\n{x!r}\n 20\n{y!r}\n 30\n0.0\n 40\n{r!r}\n"

    @staticmethod
    def ARC(d: tuple) -> str:
        (x, y), r, a0, a1 = d
        return (f"100\nAcDbCircle\n 10\n{x!r}\n 20\n{y!r}\n 30\n0.0\n 40\n{r!r}\n"
                f"100\nAcDbArc\n 50\n{a0!r}\n 51\n{a1!r}\n")

    @staticmethod
    def SOLID(d: tuple) -> str:
        p = list(d) + [d[-1]] * (4 - len(d))
        return "100\nAcDbTrace\n" + "".join(
            f" 1{i}\n{x!r}\n 2{i}\n{y!r}\n 3{i}\n0.0\n" for i, (x, y) in enumerate(p))

    @staticmethod
    def TEXT(d: tuple) -> str:
        (x, y), h, value, (x1, y1) = d
        return (f"100\nAcDbText\n 10\n{x!r}\n 20\n{y!r}\n 30\n0.0\n 40\n{h!r}\n  1\n{value}\n"
                f"  7\n{STYLE}\n 72\n5\n 11\n{x1!r}\n 21\n{y1!r}\n 31\n0.0\n100\nAcDbText\n")

    @staticmethod
    def HATCH(d: tuple) -> str:
        head = ("100\nAcDbHatch\n 10\n0.0\n 20\n0.0\n 30\n0.0\n210\n0.0\n220\n0.0\n230\n1.0\n"
                "  2\nSOLID\n 70\n1\n 71\n0\n 91\n1\n")
        if d[0] == "circle":
            (x, y), r = d[1], d[2]
            path = f" 92\n1\n 93\n1\n 72\n2\n 10\n{x!r}\n 20\n{y!r}\n 40\n{r!r}\n 50\n0.0\n 51\n360.0\n 73\n1\n"
        else:
            pts = d[1]
            path = f" 92\n3\n 72\n0\n 73\n1\n 93\n{len(pts)}\n" + "".join(
                f" 10\n{x!r}\n 20\n{y!r}\n" for x, y in pts)
        return head + path + " 97\n0\n 75\n0\n 76\n1\n 98\n0\n"
