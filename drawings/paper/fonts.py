"""The sheets' fonts and text metrics.

``[sheet] font = "dejavu"`` (the default): DejaVu Sans (Latin, Cyrillic, Greek, the
symbols) writes everything.  ``font = "gost"``: osifont, a free font drawn after
GOST 2.304 type B / ISO 3098 (GPL-3 with the font exception; Debian's fonts-osifont),
and DejaVu Sans for each character osifont lacks (⊥ ∥ † ′ ″ −, arrows, ...): cairo's toy
font API, which cairosvg draws with, takes one font per text node and no fallback, so
a label is cut into runs, each in one font (:func:`pieces`), each its own ``tspan``.

Text is measured for layout without rendering it: cairo's toy font API (the same
path cairosvg takes when it renders the SVG) with hinting off, so advances scale
linearly with the size.  Metrics are taken at 100 units and scaled.  The font being
laid out is the drawing's (:func:`use`, :func:`current`); each run keeps its family.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar, copy_context
from dataclasses import dataclass, field
from functools import lru_cache, wraps
from pathlib import Path
from typing import Any, TypeVar

from plans.errors import InputError, PlansError, Said

FONT_FAMILY = "DejaVu Sans"
#: The GOST 2.304 type B font (``[sheet] font = "gost"``) and its Debian/Ubuntu package.
GOST_FAMILY = "osifont"
GOST_PACKAGE = "fonts-osifont"
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
    """Advance widths and vertical extents of one font, in the caller's units per size."""

    _ctx: object = field(repr=False)
    ascent: float  # per unit size
    descent: float
    cap: float = 0.73  # the capitals' height per unit size (DejaVu Sans: 1493/2048)
    _cache: dict[str, float] = field(default_factory=dict, repr=False)
    _has: dict[str, bool] = field(default_factory=dict, repr=False)

    def width(self, text: str, size: float) -> float:
        w = self._cache.get(text)
        if w is None:
            w = self._ctx.text_extents(text)[4] / _REF  # type: ignore[attr-defined]
            self._cache[text] = w
        return w * size

    def has(self, ch: str) -> bool:
        """Whether the font draws ``ch``: a glyph of its own, not the .notdef box, and not a
        filled box in its place (osifont 2015 has ``Ё ё Э э`` so, mapped but never drawn)."""
        got = self._has.get(ch)
        if got is None:
            glyphs = self._ctx.get_scaled_font().text_to_glyphs(0, 0, ch, False)  # type: ignore[attr-defined]
            got = bool(glyphs) and all(g[0] != 0 for g in glyphs) and not _solid_box(self._ctx, ch)
            self._has[ch] = got
        return got


def _solid_box(ctx: Any, ch: str) -> bool:
    """Whether ``ch`` in ``ctx``'s font (at 100 units) is drawn as a filled box at least half
    a letter tall: ink over nine tenths of its ink extents."""
    import cairocffi as cairo

    xb, yb, w, h = ctx.text_extents(ch)[:4]
    if w < 0.15 * _REF or h < 0.4 * _REF:
        return False  # a dash, a rule, a dot: thin shapes are solid and real
    cols, rows = math.ceil(w) + 2, math.ceil(h) + 2
    surface = cairo.ImageSurface(cairo.FORMAT_A8, cols, rows)
    pen = cairo.Context(surface)
    pen.set_font_face(ctx.get_font_face())
    pen.set_font_options(ctx.get_font_options())
    pen.set_font_size(_REF)
    pen.move_to(1 - xb, 1 - yb)
    pen.show_text(ch)
    surface.flush()
    data, stride = bytes(surface.get_data()), surface.get_stride()
    ink = sum(sum(data[r * stride:r * stride + cols]) for r in range(rows)) / 255.0
    return ink > 0.9 * w * h


def _context(family: str):  # -> cairocffi.Context
    import cairocffi as cairo

    surface = cairo.ImageSurface(cairo.FORMAT_A8, 1, 1)
    ctx = cairo.Context(surface)
    ctx.select_font_face(family)
    options = cairo.FontOptions()
    options.set_hint_style(cairo.HINT_STYLE_NONE)
    options.set_hint_metrics(cairo.HINT_METRICS_OFF)
    ctx.set_font_options(options)
    ctx.set_font_size(_REF)
    return ctx


@lru_cache(maxsize=4)
def metrics(family: str = FONT_FAMILY) -> Metrics:
    """The process-wide text measurer of ``family`` (checks the font is installed first)."""
    if family == FONT_FAMILY:
        find_font()
    else:
        require(next(k for k, v in FAMILIES.items() if v == family))
    ctx = _context(family)
    ascent, descent = ctx.font_extents()[:2]
    # The glyph box of capitals and descenders is tighter than the font's line box.
    out = Metrics(ctx, ascent=min(ascent / _REF, 0.76), descent=min(descent / _REF, 0.24))
    if family != FONT_FAMILY:
        out.cap = -ctx.text_extents("H")[1] / _REF
    return out


@lru_cache(maxsize=4)
def installed(family: str) -> bool:
    """Whether fontconfig finds ``family`` itself, not a substitute: the font cairo picks
    for it sets some text otherwise than the one it picks for a family nobody has."""
    sample = "AHMWaimw0123АБЖЫЯабжыя"
    got, other = _context(family), _context("plans-no-such-font")
    return any(got.text_extents(ch)[4] != other.text_extents(ch)[4] for ch in sample)


# --------------------------------------------------------------------------- the drawing's font

#: The fonts ``[sheet] font`` chooses (plans.scene.sheet.SHEET_FONTS) -> the family laid out.
FAMILIES = {"dejavu": FONT_FAMILY, "gost": GOST_FAMILY}
_FONT: ContextVar[str] = ContextVar("sheet_font", default="dejavu")


def current() -> str:
    """The font the labels being laid out are written in ("dejavu" or "gost")."""
    return _FONT.get()


def require(font: str, file: str | None = None, field: str = "sheet.font") -> None:
    """An InputError naming ``field`` and how to install the font when ``font`` is not installed."""
    family = FAMILIES[font]
    if family != FONT_FAMILY and not installed(family):
        raise InputError(Said("e_font_missing", font=font, family=family,
                                   install=f"apt-get install {GOST_PACKAGE}"),
                         file=file, field=field)


@contextmanager
def use(font: str, file: str | None = None, field: str = "sheet.font") -> Iterator[None]:
    """Labels laid out in ``font`` inside the block (InputError first if it is not installed)."""
    require(font, file, field)
    token = _FONT.set(font)
    try:
        yield
    finally:
        _FONT.reset(token)


def choose(font: str, file: str | None, override: str | None = None) -> None:
    """The rest of a :func:`drawing` laid out in ``font`` (``[sheet] font``, or the command's
    ``--font`` when ``override`` is given): InputError naming that field if not installed."""
    require(font, file, "--font" if override else "sheet.font")
    _FONT.set(font)


F = TypeVar("F", bound=Callable[..., Any])


def drawing(fn: F) -> F:
    """A kind's ``draw`` run in a copy of the caller's context: the font it chooses
    (:func:`choose`) holds until it returns, and the caller's is untouched."""
    @wraps(fn)
    def run(*args: Any, **kwargs: Any) -> Any:
        return copy_context().run(fn, *args, **kwargs)

    return run  # type: ignore[return-value]


def pieces(text: str, font: str) -> list[tuple[str, str]]:
    """``text`` cut into (piece, family) runs to be written in ``font``: one run in DejaVu
    Sans (family "", the sheet's default) for "dejavu"; for "gost", osifont runs and a
    DejaVu Sans run for each stretch of characters osifont lacks.  A space after such a
    stretch stays in it (DejaVu has every space), so an osifont run begins with a letter."""
    if font == "dejavu" or not text:
        return [(text, "")]
    gost = metrics(GOST_FAMILY)
    out: list[list[str]] = []
    for ch in text:
        fam = GOST_FAMILY if gost.has(ch) else ""
        if out and (out[-1][1] == fam or ch.isspace() and out[-1][1] == ""):
            out[-1][0] += ch
        else:
            out.append([ch, fam])
    return [(t, f) for t, f in out]
