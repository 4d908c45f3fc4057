"""SVG -> PDF and PNG with cairosvg, the sheets' text drawn faster, the page unchanged.

cairosvg draws a ``text`` twice: once as glyph outlines added to the path (for a stroke),
once as glyphs (the fill), each letter with its own save, moves, rotation, measure and
restore.  Our labels have no stroke, no per-letter offsets, rotations or spacing, no
anchor and no text path: for such a node the outlines are never painted (cairo paints
nothing with a clear source) and the glyphs stand at ``x``, ``x + advance``, ... .
:func:`_text` draws exactly that with the same cairo calls for the glyphs (move to the
letter's point, show the letter) and each letter's advance measured once per font; any
other node goes to cairosvg's own drawer.  The pixels (tests compare them with cairosvg's
own rendering) and the PDF's bytes are the same.

The document is parsed once and drawn on each surface asked for (:func:`convert`).
"""

from __future__ import annotations

import io
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

#: Attributes of a text node that the fast drawer leaves to cairosvg.
_OWN = ("dx", "dy", "rotate", "letter-spacing", "text-anchor", "display-anchor", "dominant-baseline",
        "alignment-baseline", "font-style", "font-weight", "textLength", "lengthAdjust")
_CLEAR_STROKES = (None, "", "none", "transparent")
_LOCK = threading.RLock()


def _plain(surface: Any, node: Any) -> bool:
    """A label our sheets write: one x and one y at most, plain fill, no stroke."""
    if node.tag not in ("text", "tspan") or any(k in node for k in _OWN):
        return False
    if node.get("stroke") not in _CLEAR_STROKES or "url(" in (node.get("fill") or ""):
        return False
    parent = getattr(node, "parent", None)
    if node.get_href() or (parent is not None and parent.get_href()):
        return False
    for key in ("x", "y"):
        v = node.get(key)
        if v is not None and len(str(v).replace(",", " ").split()) > 1:
            return False
    return list(surface.cursor_d_position) == [0, 0]


def _text(surface: Any, node: Any, draw_as_text: bool = False) -> None:
    """cairosvg's ``text`` for a plain label (see the module's note), its own otherwise."""
    from cairosvg import text as _cs_text
    from cairosvg.helpers import size

    if not _plain(surface, node):
        _cs_text.text(surface, node, draw_as_text)
        return
    x = size(surface, node["x"], "x") if "x" in node else None
    y = size(surface, node["y"], "y") if "y" in node else None
    letters = node.text
    if not letters:
        cx, cy = surface.cursor_position
        surface.cursor_position = (cx if x is None else x, cy if y is None else y)
        return
    ctx = surface.context
    family = (node.get("font-family") or "sans-serif").split(",")[0].strip("\"' ")
    font_size = surface.font_size
    cache = surface.__dict__.setdefault("_advances", {})
    key = (family, font_size, tuple(ctx.get_matrix()))
    adv = cache.get(key)
    if adv is None:
        adv = cache[key] = {}
    ctx.select_font_face(family, 0, 0)  # FONT_SLANT_NORMAL, FONT_WEIGHT_NORMAL
    ctx.set_font_size(font_size)
    cx, cy = surface.cursor_position
    px = cx if x is None else x
    py = cy if y is None else y
    for letter in letters:
        a = adv.get(letter)
        if a is None:
            a = adv[letter] = ctx.text_extents(letter)[4]
        if draw_as_text and not letter.isspace():
            ctx.move_to(px, py)
            ctx.show_text(letter)
        px += a
    surface.cursor_position = (px, py)


@contextmanager
def _fast_text() -> Iterator[None]:
    """cairosvg's surfaces use :func:`_text` for ``text`` and ``tspan`` while converting
    (restored after: other callers in the process get cairosvg as it is)."""
    from cairosvg import surface as cs

    with _LOCK:
        saved = cs.TAGS["text"], cs.TAGS["tspan"], cs.text
        cs.TAGS["text"] = cs.TAGS["tspan"] = cs.text = _text
        try:
            yield
        finally:
            cs.TAGS["text"], cs.TAGS["tspan"], cs.text = saved


def tree(svg: bytes) -> Any:
    """The parsed document, drawn by :func:`draw` on any number of surfaces."""
    from cairosvg.parser import Tree

    return Tree(bytestring=svg)


def draw(surface_class: Any, doc: Any, dpi: float = 96.0) -> bytes:
    """The document drawn on a cairosvg surface class (PDF, PNG, ...): its output bytes."""
    out = io.BytesIO()
    with _fast_text():
        instance = surface_class(doc, out, dpi, None, None, None, 1, None, None, None)
        instance.finish()
    return out.getvalue()
