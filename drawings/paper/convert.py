"""SVG -> PDF and PNG with cairosvg, the sheets' nodes drawn faster, the page unchanged.

cairosvg draws every node through one general drawer (transforms, clips, masks, filters,
markers, font options, cursor bookkeeping, a fill and a stroke pass), and every ``text``
and ``tspan`` letter by letter twice: as outlines added to the path (for a stroke) and
as glyphs (the fill), each letter with its own save, moves, rotation, measure and
restore.  Most of that does nothing on our sheets: labels have no stroke (cairo paints
nothing with a clear source, so the outlines are never seen), no per-letter offsets,
rotations or spacing, no anchor, no text path; no node has a transform, opacity, clip,
mask, filter, marker or paint server.  For such a node :func:`_label` (text) and
:func:`_shape` (group, line, path, circle) make the cairo calls that leave a mark, in
the same order with the same numbers; a label's glyphs stand at ``x``, ``x + advance``,
... as in cairosvg (each letter's advance measured once per font).  Every other node
goes through cairosvg as it is.  The pixels of a PNG and the bytes of a PDF are those of
cairosvg's own drawing (the tests compare them).

The document is parsed once and can be drawn on several surfaces (:func:`tree`,
:func:`draw`).
"""

from __future__ import annotations

import io
from typing import Any

#: Attributes that send a text node to cairosvg's own drawer.
_OWN = frozenset(("dx", "dy", "rotate", "letter-spacing", "text-anchor", "display-anchor",
                  "dominant-baseline", "alignment-baseline", "font-style", "font-weight", "font",
                  "textLength", "lengthAdjust", "transform", "transform-origin", "opacity", "mask",
                  "filter", "clip", "clip-path", "display", "visibility", "text-rendering",
                  "shape-rendering", "fill-rule", "width", "height"))
_CLEAR = (None, "", "none", "transparent")


def _plain(surface: Any, node: Any) -> bool:
    """A label as our sheets write it (see the module's note)."""
    if node.tag not in ("text", "tspan") or not _OWN.isdisjoint(node):
        return False
    if node.get("stroke") not in _CLEAR or "url(" in (node.get("fill") or ""):
        return False
    parent = getattr(node, "parent", None)
    if node.get_href() or (parent is not None and parent.get_href()):
        return False
    for key in ("x", "y"):
        v = node.get(key)
        if v is not None and len(str(v).replace(",", " ").split()) > 1:
            return False
    return surface.stroke_and_fill and list(surface.cursor_d_position) == [0, 0]


def _label(surface: Any, node: Any) -> None:
    """What cairosvg's node drawer and its ``text`` leave on the page for a plain label."""
    from cairosvg.helpers import paint, size

    ctx = surface.context
    saved = surface.parent_node, surface.font_size, surface.context_width, surface.context_height
    surface.parent_node = node
    surface.font_size = size(surface, node.get("font-size", "12pt"))
    ctx.save()
    x = size(surface, node["x"], "x") if "x" in node else None
    y = size(surface, node["y"], "y") if "y" in node else None
    cx, cy = surface.cursor_position
    px = cx if x is None else x
    py = cy if y is None else y
    if node.text:
        ctx.save()
        _, colour = paint(node.get("fill", "black"))
        ctx.set_source_rgba(*surface.map_color(colour, float(node.get("fill-opacity", 1))))
        family = (node.get("font-family") or "sans-serif").split(",")[0].strip("\"' ")
        ctx.select_font_face(family, 0, 0)  # FONT_SLANT_NORMAL, FONT_WEIGHT_NORMAL
        ctx.set_font_size(surface.font_size)
        cache = surface.__dict__.setdefault("_advances", {})
        adv = cache.setdefault((family, surface.font_size, tuple(ctx.get_matrix())), {})
        for letter in node.text:
            a = adv.get(letter)
            if a is None:
                a = adv[letter] = ctx.text_extents(letter)[4]
            if not letter.isspace():
                ctx.move_to(px, py)
                ctx.show_text(letter)
            px += a
        ctx.restore()
    surface.cursor_position = (px, py)
    ctx.new_path()  # cairosvg's (clear) stroke ends the node's path
    for child in node.children:
        surface.draw(child)
    if node.tag == "text":
        surface.cursor_position = [0, 0]
        surface.cursor_d_position = [0, 0]
        surface.text_path_width = 0
    ctx.restore()
    surface.parent_node, surface.font_size, surface.context_width, surface.context_height = saved


#: What sends a group or a shape to cairosvg's own drawer.
_SHAPE_OWN = frozenset(("transform", "transform-origin", "opacity", "mask", "filter", "clip", "clip-path",
                        "display", "visibility", "shape-rendering", "text-rendering", "fill-rule", "font",
                        "width", "height", "marker", "marker-start", "marker-mid", "marker-end"))
_SHAPES = ("g", "line", "path", "circle")


def _plain_shape(surface: Any, node: Any) -> bool:
    """A group or a line, path or circle as our sheets write them: no transform, opacity,
    clip, mask, filter, marker or paint server."""
    return (surface.stroke_and_fill and node.tag in _SHAPES and _SHAPE_OWN.isdisjoint(node)
            and "url(" not in (node.get("fill") or "") and "url(" not in (node.get("stroke") or ""))


def _shape(surface: Any, node: Any) -> None:
    """What cairosvg's node drawer leaves on the page for a plain group or shape: the same
    state (join, cap, dashes, miter) and, for a shape, its path from cairosvg's own
    function, filled then stroked; without the transform, clip, mask, marker, font and
    cursor bookkeeping such a node does not use."""
    import cairocffi as cairo
    from cairosvg.helpers import PointError, normalize, paint, size
    from cairosvg.surface import TAGS

    ctx = surface.context
    saved = surface.parent_node, surface.font_size, surface.context_width, surface.context_height
    surface.parent_node = node
    surface.font_size = size(surface, node.get("font-size", "12pt"))
    ctx.save()
    ctx.move_to(size(surface, node.get("x"), "x"), size(surface, node.get("y"), "y"))
    cap, join = node.get("stroke-linecap"), node.get("stroke-linejoin")
    if cap == "square":
        ctx.set_line_cap(cairo.LINE_CAP_SQUARE)
    if cap == "round":
        ctx.set_line_cap(cairo.LINE_CAP_ROUND)
    if join == "round":
        ctx.set_line_join(cairo.LINE_JOIN_ROUND)
    if join == "bevel":
        ctx.set_line_join(cairo.LINE_JOIN_BEVEL)
    if node.get("stroke-dasharray"):
        dashes = [size(surface, d) for d in normalize(node["stroke-dasharray"]).split()]
        if sum(dashes):
            ctx.set_dash(dashes, size(surface, node.get("stroke-dashoffset")))
    ctx.set_miter_limit(float(node.get("stroke-miterlimit", 4)))
    if node.tag != "g":
        try:
            TAGS[node.tag](surface, node)
        except PointError:
            pass
        ctx.save()
        _, colour = paint(node.get("fill", "black"))
        ctx.set_source_rgba(*surface.map_color(colour, float(node.get("fill-opacity", 1))))
        ctx.fill_preserve()
        ctx.restore()
        ctx.save()
        ctx.set_line_width(size(surface, node.get("stroke-width", "1")))
        _, colour = paint(node.get("stroke"))
        ctx.set_source_rgba(*surface.map_color(colour, float(node.get("stroke-opacity", 1))))
        ctx.stroke()
        ctx.restore()
    for child in node.children:
        surface.draw(child)
    ctx.restore()
    surface.parent_node, surface.font_size, surface.context_width, surface.context_height = saved


class PlainNodes:
    """Mixed into a cairosvg surface class: plain labels drawn by :func:`_label`, plain
    groups and shapes by :func:`_shape`."""

    def draw(self, node: Any) -> None:
        if node.tag in ("text", "tspan") and _plain(self, node):
            _label(self, node)
        elif _plain_shape(self, node):
            _shape(self, node)
        else:
            super().draw(node)  # type: ignore[misc]


def tree(svg: bytes) -> Any:
    """The parsed document, drawn by :func:`draw` on any number of surfaces."""
    from cairosvg.parser import Tree

    return Tree(bytestring=svg)


def draw(surface_class: Any, doc: Any, dpi: float = 96.0) -> bytes:
    """The document drawn on a cairosvg surface class (PDF, PNG, ...) with :class:`PlainNodes`
    mixed in: its output bytes."""
    out = io.BytesIO()
    cls = type(surface_class.__name__, (PlainNodes, surface_class), {})
    cls(doc, out, dpi, None, None, None, 1, None, None, None).finish()
    return out.getvalue()
