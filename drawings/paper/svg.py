"""The svgwrite backend: true millimetres, fixed number formatting, stable ids.

Every coordinate is written with :func:`num` (at most 3 decimals, no ``-0``), ids
come from the caller (never generated), no timestamps: the same sheet gives the
same bytes.  Arrowheads are filled polygons, scripts are positioned ``tspan``s
(PDF converters are weak with markers and baseline shifts).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from typing import Any

import svgwrite

from drawings.paper.backend import Prim, Pt, Style, hatch_segments
from drawings.paper.fonts import FONT_FAMILY
from drawings.paper.text import Label


def num(v: float) -> str:
    """Fixed formatting: 3 decimals, trailing zeros dropped, never ``-0``."""
    s = f"{v:.3f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _path(pts: Sequence[Pt], closed: bool) -> str:
    """Path data of a polyline; the first point is the ``M`` (an arrowhead's tip)."""
    d = "M" + " L".join(f"{num(x)},{num(y)}" for x, y in pts)
    return d + " Z" if closed else d



def paint(target: Any, style: Style, fill: str | None = "none") -> None:
    """The fill and stroke attributes of ``style`` set on ``target`` (an svgwrite element or
    an attribute dict, for the two backends alike); ``fill=None`` leaves the fill out."""
    if fill is not None:
        target["fill"] = style.fill or fill
    if style.stroke:
        target["stroke"] = style.stroke
        target["stroke-width"] = num(style.width)
        if style.dash:
            target["stroke-dasharray"] = " ".join(num(d) for d in style.dash)
    else:
        target["stroke"] = "none"

class SvgBackend:
    """Draws onto an svgwrite Drawing of ``width`` × ``height`` mm."""

    def __init__(self, width: float, height: float, *, debug: bool = False, title: str = "") -> None:
        self.dwg = svgwrite.Drawing(size=(f"{num(width)}mm", f"{num(height)}mm"), profile="full",
                                    debug=debug)
        self.dwg.viewbox(0, 0, width, height)
        if title:
            self.dwg.set_desc(title=title)
        self.dwg.add(self.dwg.rect((0, 0), (num(width), num(height)), fill="#fff", id="paper"))
        self.stack = [self.dwg]
        root = self.dwg.g(font_family=FONT_FAMILY, stroke_linecap="butt", stroke_linejoin="round")
        self.dwg.add(root)
        self.stack = [root]

    # ---- helpers

    def _add(self, el, eid: str, cls: str = "") -> None:
        if eid:
            el["id"] = eid
        if cls:
            el["class"] = cls
        self.stack[-1].add(el)

    @staticmethod
    def _style(el, style: Style, *, fill_default: str = "none") -> None:
        paint(el, style, fill_default)

    # ---- Backend

    def begin(self, gid: str, cls: str = "") -> None:
        g = self.dwg.g()
        self._add(g, gid, cls)
        self.stack.append(g)

    def end(self) -> None:
        self.stack.pop()

    def line(self, p0: Pt, p1: Pt, style: Style, eid: str = "") -> None:
        el = self.dwg.line((num(p0[0]), num(p0[1])), (num(p1[0]), num(p1[1])))
        self._style(el, style)
        del el.attribs["fill"]
        self._add(el, eid, style.cls)

    def polyline(self, pts: Sequence[Pt], style: Style, eid: str = "") -> None:
        el = self.dwg.path(d=_path(pts, closed=False))
        self._style(el, style)
        self._add(el, eid, style.cls)

    def polygon(self, pts: Sequence[Pt], style: Style, eid: str = "") -> None:
        """A closed path (``M … L … Z``): arrowheads are these, filled."""
        el = self.dwg.path(d=_path(pts, closed=True))
        self._style(el, style)
        self._add(el, eid, style.cls)

    def circle(self, c: Pt, r: float, style: Style, eid: str = "") -> None:
        el = self.dwg.circle((num(c[0]), num(c[1])), num(r))
        self._style(el, style)
        self._add(el, eid, style.cls)

    def arc(self, c: Pt, r: float, a0: float, a1: float, style: Style, eid: str = "") -> None:
        el = self.dwg.path(d=_arc(c, r, a0, a1))
        self._style(el, style)
        self._add(el, eid, style.cls)

    def text(self, label: Label, cls: str = "", eid: str = "", fill: str = "#000") -> None:
        """One ``text``; a label with scripts gets one positioned ``tspan`` per run."""
        if not label.runs:
            return
        first = label.runs[0]
        if len(label.runs) == 1:
            el = self.dwg.text(first.text, insert=(num(first.x), num(first.y)), font_size=num(first.size))
        else:
            el = self.dwg.text("", font_size=num(first.size))
            for run in label.runs:
                ts = self.dwg.tspan(run.text, x=[num(run.x)], y=[num(run.y)])
                if run.size != first.size:
                    ts["font-size"] = num(run.size)
                if run.font != first.font:
                    ts["font-family"] = run.font or FONT_FAMILY
                el.add(ts)
        if first.font:
            el["font-family"] = first.font
        if fill != "#000":
            el["fill"] = fill
        self._add(el, eid, cls)

    def hatch(self, p0: Pt, p1: Pt, side: int, style: Style, step: float = 2.5,
              length: float = 2.5, eid: str = "") -> None:
        el = self.dwg.path(d=_hatch(p0, p1, side, step, length))
        self._style(el, style)
        self._add(el, eid, style.cls or "hatch")

    def tostring(self) -> str:
        return serialize(self.dwg)


class SvgWriter:
    """The characters :class:`SvgBackend` writes for a sheet, built as text directly (no
    element objects): what :func:`document` uses.  Same elements, attributes in the same
    (sorted) order, the same numbers and escaping: the same bytes, several times faster."""

    def __init__(self, width: float, height: float) -> None:
        self.head = (f'<svg baseProfile="full" height="{num(height)}mm" version="1.1" '
                     f'viewBox="0,0,{width},{height}" width="{num(width)}mm" '
                     'xmlns="http://www.w3.org/2000/svg" xmlns:ev="http://www.w3.org/2001/xml-events" '
                     'xmlns:xlink="http://www.w3.org/1999/xlink">'
                     f'<defs /><rect fill="#fff" height="{num(height)}" id="paper" width="{num(width)}" '
                     'x="0" y="0" />')
        root = f'<g font-family="{_attr(FONT_FAMILY)}" stroke-linecap="butt" stroke-linejoin="round"'
        self.stack: list[tuple[str, str, list[str]]] = [("g", root, [])]

    def _el(self, tag: str, attrs: dict[str, str], body: str = "", kids: list[str] | None = None) -> None:
        head = "<" + tag + "".join(f' {k}="{_attr(v)}"' for k, v in sorted(attrs.items()) if v)
        if body or kids:
            self.stack[-1][2].append(f"{head}>{_cdata(body)}{''.join(kids or ())}</{tag}>")
        else:
            self.stack[-1][2].append(head + " />")

    @staticmethod
    def _paint(attrs: dict[str, str], style: Style, fill: bool = True) -> dict[str, str]:
        paint(attrs, style, "none" if fill else None)
        return attrs

    def begin(self, gid: str, cls: str = "") -> None:
        head = "<g" + "".join(f' {k}="{_attr(v)}"' for k, v in (("class", cls), ("id", gid)) if v)
        self.stack.append(("g", head, []))

    def end(self) -> None:
        tag, head, kids = self.stack.pop()
        self.stack[-1][2].append(f"{head}>{''.join(kids)}</{tag}>" if kids else head + " />")

    def line(self, p0: Pt, p1: Pt, style: Style, eid: str = "") -> None:
        self._el("line", self._paint({"x1": num(p0[0]), "y1": num(p0[1]), "x2": num(p1[0]), "y2": num(p1[1]),
                                      "id": eid, "class": style.cls}, style, fill=False))

    def polyline(self, pts: Sequence[Pt], style: Style, eid: str = "") -> None:
        self._el("path", self._paint({"d": _path(pts, closed=False), "id": eid, "class": style.cls}, style))

    def polygon(self, pts: Sequence[Pt], style: Style, eid: str = "") -> None:
        self._el("path", self._paint({"d": _path(pts, closed=True), "id": eid, "class": style.cls}, style))

    def circle(self, c: Pt, r: float, style: Style, eid: str = "") -> None:
        self._el("circle", self._paint({"cx": num(c[0]), "cy": num(c[1]), "r": num(r), "id": eid,
                                        "class": style.cls}, style))

    def arc(self, c: Pt, r: float, a0: float, a1: float, style: Style, eid: str = "") -> None:
        self._el("path", self._paint({"d": _arc(c, r, a0, a1), "id": eid, "class": style.cls}, style))

    def text(self, label: Label, cls: str = "", eid: str = "", fill: str = "#000") -> None:
        if not label.runs:
            return
        first = label.runs[0]
        attrs = {"font-size": num(first.size), "id": eid, "class": cls, "font-family": first.font}
        if fill != "#000":
            attrs["fill"] = fill
        if len(label.runs) == 1:
            attrs.update(x=num(first.x), y=num(first.y))
            self._el("text", attrs, first.text)
            return
        spans = []
        for run in label.runs:
            size = f' font-size="{_attr(num(run.size))}"' if run.size != first.size else ""
            if run.font != first.font:  # a character the sheet's font lacks, in DejaVu Sans
                size = f' font-family="{_attr(run.font or FONT_FAMILY)}"' + size
            head = f'<tspan{size} x="{_attr(num(run.x))}" y="{_attr(num(run.y))}"'
            spans.append(f"{head}>{_cdata(run.text)}</tspan>" if run.text else head + " />")
        self._el("text", attrs, "", spans)

    def hatch(self, p0: Pt, p1: Pt, side: int, style: Style, step: float = 2.5,
              length: float = 2.5, eid: str = "") -> None:
        self._el("path", self._paint({"d": _hatch(p0, p1, side, step, length), "id": eid,
                                      "class": style.cls or "hatch"}, style))

    def tostring(self) -> str:
        _, head, kids = self.stack[0]
        root = f"{head}>{''.join(kids)}</g>" if kids else head + " />"
        return f"{self.head}{root}</svg>"


def document(width: float, height: float, prims: Iterable[Prim]) -> str:
    """The SVG text of recorded primitives on a ``width`` × ``height`` mm page (the bytes
    :class:`SvgBackend` writes, see :class:`SvgWriter`)."""
    from drawings.paper.backend import replay

    w = SvgWriter(width, height)
    replay(prims, w)
    return w.tostring()


def _arc(c: Pt, r: float, a0: float, a1: float) -> str:
    x0, y0 = c[0] + r * math.cos(a0), c[1] + r * math.sin(a0)
    x1, y1 = c[0] + r * math.cos(a1), c[1] + r * math.sin(a1)
    large = 1 if abs(a1 - a0) > math.pi else 0
    sweep = 1 if a1 > a0 else 0  # increasing paper angle = clockwise on the sheet = SVG sweep 1
    return f"M{num(x0)},{num(y0)} A{num(r)},{num(r)} 0 {large} {sweep} {num(x1)},{num(y1)}"


def _hatch(p0: Pt, p1: Pt, side: int, step: float, length: float) -> str:
    segs = hatch_segments(p0, p1, side, step, length)
    return " ".join(f"M{num(a[0])},{num(a[1])} L{num(b[0])},{num(b[1])}" for a, b in segs) or "M0,0"


def serialize(dwg: svgwrite.Drawing) -> str:
    """``dwg.tostring()`` written directly: the same characters as svgwrite's route through
    ElementTree (sorted attributes, None and empty values dropped, ElementTree's escaping,
    ``<tag />`` when empty), in a fraction of its time.  Elements with their own XML
    (title, style, use, ...) still go through svgwrite."""
    from svgwrite.base import BaseElement
    from svgwrite.text import TSpan

    plain = BaseElement.get_xml
    spans = TSpan.get_xml
    out: list[str] = []
    write = out.append

    def walk(el) -> None:
        own = getattr(type(el), "get_xml", None)
        if own is not plain and own is not spans:
            import xml.etree.ElementTree as ET

            write(ET.tostring(el.get_xml(), encoding="unicode"))
            return
        write("<" + el.elementname)
        for key, value in sorted(el.attribs.items()):
            if value is None:
                continue
            text = str(value)
            if text:
                write(f' {key}="{_attr(text)}"')
        body = str(el.text) if own is spans else ""
        if body or el.elements:
            write(">")
            if body:
                write(_cdata(body))
            for child in el.elements:
                walk(child)
            write(f"</{el.elementname}>")
        else:
            write(" />")

    # what svgwrite's Drawing.get_xml sets on the root before serialising
    dwg.attribs["xmlns"] = "http://www.w3.org/2000/svg"
    dwg.attribs["xmlns:xlink"] = "http://www.w3.org/1999/xlink"
    dwg.attribs["xmlns:ev"] = "http://www.w3.org/2001/xml-events"
    dwg.attribs["baseProfile"] = dwg.profile
    dwg.attribs["version"] = dwg.version
    write("<svg")  # the root is written like any plain element
    for key, value in sorted(dwg.attribs.items()):
        if value is not None and str(value):
            write(f' {key}="{_attr(str(value))}"')
    if dwg.elements:
        write(">")
        for child in dwg.elements:
            walk(child)
        write("</svg>")
    else:
        write(" />")
    return "".join(out)


#: What XML escapes in character data, in this order (``&`` first), and what an attribute
#: value escapes besides (the quote it is written in, and whitespace that would be normalised).
_CDATA = (("&", "&amp;"), ("<", "&lt;"), (">", "&gt;"))
_ATTR = _CDATA + (('"', "&quot;"), ("\r", "&#13;"), ("\n", "&#10;"), ("\t", "&#09;"))


def _escape(text: str, table: tuple[tuple[str, str], ...]) -> str:
    for ch, entity in table:
        if ch in text:  # most text has none: the test is cheaper than a replace
            text = text.replace(ch, entity)
    return text


def _cdata(text: str) -> str:
    return _escape(text, _CDATA)


def _attr(text: str) -> str:
    return _escape(text, _ATTR)
