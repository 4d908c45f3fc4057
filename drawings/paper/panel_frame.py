"""A panel: one figure of a sheet drawn once onto its own :class:`Recording` in paper
millimetres and normalised so its box (labels included) starts at (0, 0); its title and the
scale it is drawn at, as the course writes scales.  Every sheet's panels are these."""

from __future__ import annotations

from collections.abc import Container, Sequence
from dataclasses import dataclass

from drawings.paper.backend import Prim, Recording, Style
from drawings.paper.common import fmt
from drawings.paper.i18n import tr
from drawings.paper.text import layout

TITLE_SIZE = 5.0
SCALE_SIZE = 3.5
LABEL_SIZE = 3.5
SMALL_SIZE = 2.5
PAD = 2.0
#: Millimetres of paper that count as none when placed boxes and sizes are compared: the
#: round-off of summed panel sizes, far below a pencil line (0.18 mm).
SLACK_MM = 1e-9


@dataclass(frozen=True, slots=True)
class Panel:
    """A finished figure: ``prims`` in panel mm with the box at (0, 0)–(width, height)."""

    pid: str  # "scheme-45", "velocity-45", ...
    kind: str  # positions | scheme | velocity | acceleration | table | group | polygon | crank | lever | legend
    phi: float | None
    prims: tuple[Prim, ...]
    width: float
    height: float
    title: str = ""
    quantity: str | None = None  # the scale this panel is drawn at: length, velocity, ...
    scale: float | None = None  # μ, mm per SI unit

    def at(self, x: float, y: float) -> list[Prim]:
        return [p.moved(x, y) for p in self.prims]

    def text_boxes(self) -> list[tuple[float, float, float, float]]:
        return [p.label.box for p in self.prims if p.op == "text" and p.label is not None]

    def svg(self, debug: bool = False) -> str:
        """The panel alone as an SVG document in true millimetres."""
        from drawings.paper.backend import replay
        from drawings.paper.svg import SvgBackend, document

        if not debug:
            return document(self.width, self.height, self.prims)
        be = SvgBackend(self.width, self.height, debug=debug)
        replay(self.prims, be)
        return be.tostring()

    def _repr_svg_(self) -> str:
        return self.svg()


def finish(pid: str, kind: str, phi: float | None, body: Recording, title: str,
           scale_line: str | None = None, note: str | None = None, quantity: str | None = None,
           scale: float | None = None) -> Panel:
    """Title (and scale) above the body, everything shifted to start at (0, 0); labels that a
    line of the finished figure crosses are moved clear of it (:func:`declutter`); a table's
    cells sit between its rules by construction and are not searched."""
    if kind not in ("table", "legend", "cycle-table"):
        from drawings.paper.declutter import declutter

        body = Recording(declutter(body.prims))
    x0, y0, x1, y1 = body.bbox()
    head = Recording()
    y = y0 - 2.5
    lines = []
    if note:
        lines.append((note, SCALE_SIZE, f"{pid}-note"))
    if scale_line:
        lines.append((scale_line, SCALE_SIZE, f"{pid}-scale"))
    for text, size, eid in reversed(lines):
        lab = layout(text, x0, y, size, "start", "bottom")
        head.text(lab, "scale" if eid.endswith("scale") else "note", eid)
        y = lab.box[1] - 1.2
    lab = layout(title, x0, y, TITLE_SIZE, "start", "bottom")
    head.text(lab, "title", f"{pid}-title")
    rec = Recording([Prim("begin", eid=pid, cls=f"panel {kind}")] + head.prims + body.prims + [Prim("end")])
    bx0, by0, bx1, by1 = rec.bbox()
    moved = rec.moved(PAD - bx0, PAD - by0)
    return Panel(pid, kind, phi, tuple(moved.prims), bx1 - bx0 + 2 * PAD, by1 - by0 + 2 * PAD, title,
                 quantity, scale)


# --------------------------------------------------------------------------- scales


_SCALE_UNITS = {
    "length": ("l", "mm/m", "m/mm"),
    "velocity": ("v", "mm/(m/s)", "(m/s)/mm"),
    "acceleration": ("a", "mm/(m/s^2)", "(m/s^2)/mm"),
    "force": ("F", "mm/N", "N/mm"),
}


def scale_text(quantity: str, mu: float, style: str, lang: str) -> str:
    """``μ_v = 6.667 mm/(m/s)``, ``μ_v = 0,15 (м/с)/мм`` or ``K_v = 0.15 (m/s)/mm``: the letter
    and the direction of the scene's notation in the sheet's language (plans.scene.notation)."""
    from plans.scene.notation import resolve

    sub, mu_unit, k_unit = _SCALE_UNITS[quantity]
    letter, per_mm, _ = resolve(style, lang)
    if per_mm:
        return f"{letter}_{sub} = {fmt(1.0 / mu, 4, lang)} {tr(k_unit, lang)}"
    return f"{letter}_{sub} = {fmt(mu, 4, lang)} {tr(mu_unit, lang)}"


def ratio_text(mu_l: float, lang: str = "en") -> str:
    """μl in mm/m as a drawing scale (GOST 2.302): 1000 -> ``1:1``, 250 -> ``1:4``,
    2000 -> ``2:1``, 400 -> ``1:2,5`` on a Russian sheet (``1:2.5`` in English)."""
    r = mu_l / 1000.0
    text = f"{r:.4g}:1" if r >= 1 else f"1:{1 / r:.4g}"
    return text.replace(".", ",") if lang == "ru" else text


STANDARD_RATIOS = (10.0, 5.0, 4.0, 2.5, 2.0, 1.0, 1 / 2, 1 / 2.5, 1 / 4, 1 / 5, 1 / 10, 1 / 15, 1 / 20,
                   1 / 25, 1 / 40, 1 / 50, 1 / 75, 1 / 100, 1 / 200, 1 / 500, 1 / 1000)


def auto_length_scale(size_m: float, target_mm: float = 230.0) -> float:
    """The largest standard drawing scale (GOST 2.302) that draws ``size_m`` within ``target_mm``."""
    for r in STANDARD_RATIOS:
        if size_m * 1000.0 * r <= target_mm:
            return 1000.0 * r
    return 1000.0 * STANDARD_RATIOS[-1]


def ruled_grid(rec: Recording, pid: str, edges: Sequence[float], rows: int, row_height: float, *,
               thick_rows: Container[int] = (1,), thick_column: int | None = None) -> None:
    """A table's rules (the group ``{pid}-grid``): its box, a rule between rows, drawn main
    under the header (and under ``thick_rows``, counted from the top), and between columns,
    main after column ``thick_column``; thin elsewhere."""
    W, H = edges[-1], rows * row_height
    rec.begin(f"{pid}-grid", "grid")
    rec.polygon([(0, 0), (W, 0), (W, H), (0, H)], Style(width=0.5, cls="grid"))
    for i in range(1, rows):
        rec.line((0, i * row_height), (W, i * row_height), Style(width=0.5 if i in thick_rows else 0.18, cls="grid"))
    for x in edges[1:-1]:
        main = thick_column is not None and x == edges[thick_column]
        rec.line((x, 0), (x, H), Style(width=0.5 if main else 0.18, cls="grid"))
    rec.end()

