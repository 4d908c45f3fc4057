"""SVG -> PDF and PNG with cairosvg, the sheets' labels drawn faster, the page unchanged.

cairosvg draws every ``text`` and ``tspan`` through its general node drawer (transforms,
clips, masks, dashes, markers, font options, a stroke pass) and draws the letters twice:
as outlines added to the path (for a stroke) and as glyphs (the fill), each letter with
its own save, moves, rotation, measure and restore.  The labels of our sheets have none
of that: no stroke (cairo paints nothing with a clear source, so the outlines are never
seen), no transform, opacity, clip or filter, no per-letter offsets, rotations or
spacing, no anchor and no text path.  For such a node :func:`_label` makes the cairo
calls that leave a mark, in the same order with the same numbers: the fill colour, the
font, and for each letter a move to its point and the letter shown (each letter's
advance measured once per font); the glyphs stand at ``x``, ``x + advance``, ... as in
cairosvg.  Every other node goes through cairosvg as it is.  The pixels of a PNG and the
bytes of a PDF are those of cairosvg's own drawing (the tests compare them).

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


class Labels:
    """Mixed into a cairosvg surface class: plain labels drawn by :func:`_label`."""

    def draw(self, node: Any) -> None:
        if node.tag in ("text", "tspan") and _plain(self, node):
            _label(self, node)
        else:
            super().draw(node)  # type: ignore[misc]


def tree(svg: bytes) -> Any:
    """The parsed document, drawn by :func:`draw` on any number of surfaces."""
    from cairosvg.parser import Tree

    return Tree(bytestring=svg)


def draw(surface_class: Any, doc: Any, dpi: float = 96.0) -> bytes:
    """The document drawn on a cairosvg surface class (PDF, PNG, ...) with :class:`Labels`
    mixed in: its output bytes."""
    out = io.BytesIO()
    cls = type(surface_class.__name__, (Labels, surface_class), {})
    cls(doc, out, dpi, None, None, None, 1, None, None, None).finish()
    return out.getvalue()
