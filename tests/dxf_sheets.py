"""Reading a sheet's SVG and its DXF into the same list of shapes, in drawing order, in
paper millimetres (y down), to compare them: what the SVG draws, read off its text, and
what the DXF holds, read back (by ezdxf, or by a plain tag reader fast enough for every
sample's every sheet), block insertions applied.

A shape is ``(type, points, extra)``: LINE (two ends), LWPOLYLINE (vertices; extra: closed),
CIRCLE and HATCH-circle (centre; extra: radius), ARC (two ends; extra: radius), SOLID and
HATCH (vertices), TEXT (baseline start; extra: (text, capital height)).  The SVG element
gives the DXF shapes it must become: a filled outline a fill and a stroke, a white fill
nothing, a support's hatching one LINE per stroke, a label one TEXT per run.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from typing import Any

SVG = "{http://www.w3.org/2000/svg}"
CAP = 1493 / 2048  # DejaVu Sans: capitals' height per em (a DXF height is the capitals')
WHITE = {"#fff", "#ffffff", "white"}
Shape = tuple[str, tuple[tuple[float, float], ...], Any]
_NUM = r"-?\d+(?:\.\d+)?"


def _filled(el: ET.Element) -> bool:
    f = el.get("fill", "none")
    return f not in ("none", "") and f.lower() not in WHITE


def _stroked(el: ET.Element) -> bool:
    return el.get("stroke", "none") != "none"


def _pts(text: str) -> tuple[tuple[float, float], ...]:
    nums = [float(v) for v in re.findall(_NUM, text)]
    return tuple(zip(nums[0::2], nums[1::2], strict=True))


def svg_shapes(svg: str) -> list[Shape]:
    out: list[Shape] = []
    root = ET.fromstring(svg)
    for el in root.iter():
        tag = el.tag.replace(SVG, "")
        if tag == "line" and _stroked(el):
            out.append(("LINE", ((float(el.get("x1")), float(el.get("y1"))),
                                 (float(el.get("x2")), float(el.get("y2")))), None))
        elif tag == "circle":
            c = ((float(el.get("cx")), float(el.get("cy"))),)
            if _filled(el):
                out.append(("HATCH-circle", c, float(el.get("r"))))
            if _stroked(el):
                out.append(("CIRCLE", c, float(el.get("r"))))
        elif tag == "path":
            d = el.get("d", "")
            if " A" in d:
                m = re.fullmatch(rf"M({_NUM}),({_NUM}) A({_NUM}),{_NUM} 0 [01] [01] ({_NUM}),({_NUM})", d)
                assert m, d
                x0, y0, r, x1, y1 = (float(v) for v in m.groups())
                if _stroked(el):
                    out.append(("ARC", ((x0, y0), (x1, y1)), r))
            elif "hatch" in el.get("class", "").split():
                if _stroked(el) and d != "M0,0":
                    for part in d.split("M")[1:]:
                        out.append(("LINE", _pts(part), None))
            else:
                closed = d.endswith(" Z")
                pts = _pts(d)
                if _filled(el) and len(pts) >= 3:
                    out.append(("SOLID" if len(pts) == 3 else "HATCH", pts, None))
                if _stroked(el) and len(pts) >= 2:
                    out.append(("LWPOLYLINE", pts, closed))
        elif tag == "text":
            size = float(el.get("font-size"))
            spans = list(el.iter(f"{SVG}tspan"))
            if not spans:
                if (el.text or "").strip():
                    out.append(("TEXT", ((float(el.get("x")), float(el.get("y"))),), (el.text, size * CAP)))
                continue
            for ts in spans:
                if (ts.text or "").strip():
                    s = float(ts.get("font-size", size))
                    out.append(("TEXT", ((float(ts.get("x")), float(ts.get("y"))),), (ts.text, s * CAP)))
    return out


# --------------------------------------------------------------------------- DXF


def _shape(kind: str, attrs: dict[str, list[str]], dx: float, dy: float, H: float) -> Shape | None:
    """One entity's shape from its tags (``attrs``: code -> values in order)."""

    def p(xc: str, yc: str, i: int = 0) -> tuple[float, float]:
        return (float(attrs[xc][i]) + dx, H - (float(attrs[yc][i]) + dy))

    if kind == "LINE":
        return ("LINE", (p("10", "20"), p("11", "21")), None)
    if kind == "CIRCLE":
        return ("CIRCLE", (p("10", "20"),), float(attrs["40"][0]))
    if kind == "ARC":
        import math

        (cx, cy), r = p("10", "20"), float(attrs["40"][0])
        ends = []
        for code in ("50", "51"):
            a = math.radians(float(attrs[code][0]))
            ends.append((cx + r * math.cos(a), cy - r * math.sin(a)))
        return ("ARC", tuple(ends), r)
    if kind == "LWPOLYLINE":
        pts = tuple(p("10", "20", i) for i in range(len(attrs["10"])))
        return ("LWPOLYLINE", pts, bool(int(attrs["70"][0]) & 1))
    if kind == "SOLID":
        return ("SOLID", (p("10", "20"), p("11", "21"), p("12", "22")), None)
    if kind == "HATCH":
        if attrs.get("72", ["0"])[0] == "2":  # one edge: a full-circle arc
            return ("HATCH-circle", (p("10", "20", 1),), float(attrs["40"][0]))
        return ("HATCH", tuple(p("10", "20", i) for i in range(1, len(attrs["10"]))), None)
    if kind == "TEXT":
        return ("TEXT", (p("10", "20"),), (attrs["1"][0], float(attrs["40"][0])))
    return None


def _entities(lines: list[str], start: int, stop: int) -> Iterator[tuple[str, dict[str, list[str]]]]:
    kind, attrs = "", {}
    for i in range(start, stop, 2):
        code, value = lines[i].strip(), lines[i + 1]
        if code == "0":
            if kind:
                yield kind, attrs
            kind, attrs = value, {}
        else:
            attrs.setdefault(code, []).append(value)
    if kind:
        yield kind, attrs


def dxf_tags_shapes(dxf: bytes) -> tuple[list[Shape], dict[str, Any]]:
    """A plain reading of the DXF's tags: the shapes of every INSERT's block (and of model
    space), in the order of model space; and the header variables asked for by tests."""
    lines = dxf.decode("utf-8").split("\n")
    sections: dict[str, tuple[int, int]] = {}
    i = 0
    while i < len(lines) - 1:
        if lines[i].strip() == "0" and lines[i + 1] == "SECTION":
            name = lines[i + 3]
            j = i + 4
            while not (lines[j].strip() == "0" and lines[j + 1] == "ENDSEC"):
                j += 2
            sections[name] = (i + 4, j)
            i = j
        i += 2
    header: dict[str, Any] = {}
    hs, he = sections["HEADER"]
    for k in range(hs, he, 2):
        if lines[k].strip() == "9":
            header[lines[k + 1]] = lines[k + 3]
    blocks: dict[str, list[tuple[str, dict[str, list[str]]]]] = {}
    name = None
    for kind, attrs in _entities(lines, *sections["BLOCKS"]):
        if kind == "BLOCK":
            name = attrs["2"][0]
            blocks[name] = []
        elif kind == "ENDBLK":
            name = None
        elif name is not None:
            blocks[name].append((kind, attrs))
    H = float(_header_point(lines, sections["HEADER"], "$EXTMAX")[1])
    out: list[Shape] = []
    for kind, attrs in _entities(lines, *sections["ENTITIES"]):
        if kind == "INSERT":
            dx, dy = float(attrs["10"][0]), float(attrs["20"][0])
            for k2, a2 in blocks[attrs["2"][0]]:
                s = _shape(k2, a2, dx, dy, H)
                if s is not None:
                    out.append(s)
        else:
            s = _shape(kind, attrs, 0.0, 0.0, H)
            if s is not None:
                out.append(s)
    return out, header


def _header_point(lines: list[str], span: tuple[int, int], var: str) -> tuple[str, str]:
    for k in range(span[0], span[1], 2):
        if lines[k].strip() == "9" and lines[k + 1] == var:
            return lines[k + 3], lines[k + 5]
    raise KeyError(var)


def dxf_shapes(doc: Any) -> list[Shape]:
    """The same shapes read through ezdxf's document (``ezdxf.read``)."""
    import math

    H = doc.header["$EXTMAX"][1]
    out: list[Shape] = []

    def P(v: Any, dx: float, dy: float) -> tuple[float, float]:
        return (v[0] + dx, H - (v[1] + dy))

    def walk(entities: Any, dx: float, dy: float) -> None:
        for e in entities:
            t = e.dxftype()
            if t == "INSERT":
                walk(doc.blocks.get(e.dxf.name), dx + e.dxf.insert.x, dy + e.dxf.insert.y)
            elif t == "LINE":
                out.append(("LINE", (P(e.dxf.start, dx, dy), P(e.dxf.end, dx, dy)), None))
            elif t == "CIRCLE":
                out.append(("CIRCLE", (P(e.dxf.center, dx, dy),), e.dxf.radius))
            elif t == "ARC":
                c, r = P(e.dxf.center, dx, dy), e.dxf.radius
                ends = tuple((c[0] + r * math.cos(math.radians(a)), c[1] - r * math.sin(math.radians(a)))
                             for a in (e.dxf.start_angle, e.dxf.end_angle))
                out.append(("ARC", ends, r))
            elif t == "LWPOLYLINE":
                out.append(("LWPOLYLINE", tuple(P(v, dx, dy) for v in e.get_points("xy")), e.closed))
            elif t == "SOLID":
                out.append(("SOLID", tuple(P(e.dxf.get(f"vtx{k}"), dx, dy) for k in range(3)), None))
            elif t == "HATCH":
                path = e.paths[0]
                if hasattr(path, "edges"):
                    arc = path.edges[0]
                    out.append(("HATCH-circle", (P(arc.center, dx, dy),), arc.radius))
                else:
                    out.append(("HATCH", tuple(P(v, dx, dy) for v in path.vertices), None))
            elif t == "TEXT":
                out.append(("TEXT", (P(e.dxf.insert, dx, dy),), (e.dxf.text, e.dxf.height)))

    walk(doc.modelspace(), 0.0, 0.0)
    return out


def differences(svg: list[Shape], dxf: list[Shape], tol: float = 0.01) -> list[str]:
    """Where the two lists differ (empty: the same shapes in the same order, within ``tol`` mm)."""
    out = []
    if len(svg) != len(dxf):
        out.append(f"{len(svg)} shapes in the SVG, {len(dxf)} in the DXF")
    for k, (a, b) in enumerate(zip(svg, dxf, strict=False)):
        if a[0] != b[0]:
            out.append(f"#{k}: {a[0]} in the SVG, {b[0]} in the DXF")
            break
        pa, pb = a[1], b[1]
        if a[0] == "ARC":  # the DXF runs counter-clockwise: its ends may be the SVG's swapped
            pb = pb if _near(pa[0], pb[0], tol) else pb[::-1]
        if len(pa) != len(pb) or not all(_near(p, q, tol) for p, q in zip(pa, pb, strict=False)):
            out.append(f"#{k} {a[0]}: {pa} in the SVG, {pb} in the DXF")
        elif a[0] == "TEXT":
            if a[2][0] != b[2][0] or abs(a[2][1] - b[2][1]) > tol:
                out.append(f"#{k} TEXT: {a[2]} in the SVG, {b[2]} in the DXF")
        elif a[0] in ("CIRCLE", "HATCH-circle", "ARC"):
            if abs(a[2] - b[2]) > tol:
                out.append(f"#{k} {a[0]}: radius {a[2]} in the SVG, {b[2]} in the DXF")
        elif a[0] == "LWPOLYLINE" and a[2] != b[2]:
            out.append(f"#{k} LWPOLYLINE: closed {a[2]} in the SVG, {b[2]} in the DXF")
        if len(out) > 5:
            break
    return out


def _near(p: tuple[float, float], q: tuple[float, float], tol: float) -> bool:
    return abs(p[0] - q[0]) <= tol and abs(p[1] - q[1]) <= tol
