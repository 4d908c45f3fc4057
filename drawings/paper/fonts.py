"""The one font of every sheet (DejaVu Sans: Latin, Cyrillic, Greek) and text metrics.

Text is measured for layout without rendering it: cairo's toy font API (the same
path cairosvg takes when it renders the SVG) with hinting off, so advances scale
linearly with the size.  Metrics are taken at 100 units and scaled.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from plans.errors import PlansError

FONT_FAMILY = "DejaVu Sans"
FONT_FILE = "DejaVuSans.ttf"
FONT_DIRS = (
    "/usr/share/fonts/truetype/dejavu",
    "/usr/share/fonts/dejavu",
    "/usr/share/fonts/TTF",
    "/usr/share/fonts/truetype",
    "/usr/local/share/fonts",
    "/Library/Fonts",
    "~/.fonts",
    "~/.local/share/fonts",
)
_REF = 100.0


class FontMissing(PlansError):
    """The sheet font is not installed."""

    def __init__(self, searched: tuple[str, ...]) -> None:
        super().__init__(
            f"font {FONT_FAMILY!r} ({FONT_FILE}) not found in {', '.join(searched)}; install it "
            "(Debian/Ubuntu: apt-get install fonts-dejavu-core) or set PLANS_FONT_DIR to its folder")


def find_font(dirs: tuple[str, ...] | None = None) -> Path:
    """Path of DejaVuSans.ttf, or :class:`FontMissing` naming the font and how to install it."""
    if dirs is None:
        extra = os.environ.get("PLANS_FONT_DIR")
        dirs = ((extra,) if extra else ()) + FONT_DIRS
    for d in dirs:
        p = Path(d).expanduser() / FONT_FILE
        if p.is_file():
            return p
    raise FontMissing(tuple(dirs))


@dataclass(slots=True)
class Metrics:
    """Advance widths and vertical extents of DejaVu Sans, in the caller's units per size."""

    _ctx: object = field(repr=False)
    ascent: float  # per unit size
    descent: float
    _cache: dict[str, float] = field(default_factory=dict, repr=False)

    def width(self, text: str, size: float) -> float:
        w = self._cache.get(text)
        if w is None:
            w = self._ctx.text_extents(text)[4] / _REF  # type: ignore[attr-defined]
            self._cache[text] = w
        return w * size


@lru_cache(maxsize=1)
def metrics() -> Metrics:
    """The process-wide text measurer (checks the font is installed first)."""
    find_font()
    import cairocffi as cairo

    surface = cairo.ImageSurface(cairo.FORMAT_A8, 1, 1)
    ctx = cairo.Context(surface)
    ctx.select_font_face(FONT_FAMILY)
    options = cairo.FontOptions()
    options.set_hint_style(cairo.HINT_STYLE_NONE)
    options.set_hint_metrics(cairo.HINT_METRICS_OFF)
    ctx.set_font_options(options)
    ctx.set_font_size(_REF)
    ascent, descent = ctx.font_extents()[:2]
    # The glyph box of capitals and descenders is tighter than the font's line box.
    return Metrics(ctx, ascent=min(ascent / _REF, 0.76), descent=min(descent / _REF, 0.24))
