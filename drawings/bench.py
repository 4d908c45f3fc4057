"""Stage times of drawing a scene (for the record, not a timed test)::

    python -m drawings.bench samples/v_engine.toml
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from typing import Any

from plans.scene.model import load_scene

from .export import pdf_bytes
from .linkage import build_panels, draw
from .panels import ratio_text
from .sheet import compose, sheet_spec


def _best(f: Callable[[], Any], n: int) -> tuple[float, Any]:
    best, out = float("inf"), None
    for _ in range(n):
        t = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t)
    return best, out


def bench(path: str, repeat: int = 5) -> dict[str, float]:
    """Seconds per stage (best of ``repeat``): panels (engine, construction, label placement),
    layout, SVG serialisation, SVG -> PDF; plus counts."""
    scene = load_scene(path)
    draw(scene)  # warm up: font, imports
    spec = sheet_spec(scene.raw, scene.path, scene.title)
    t_panels, (panels, mu_l) = _best(lambda: build_panels(scene, spec), repeat)
    t_layout, sheets = _best(lambda: compose(panels, spec, ratio_text(mu_l), scene.path), repeat)
    t_svg, svgs = _best(lambda: [s.svg() for s in sheets], repeat)
    t_pdf, _ = _best(lambda: [pdf_bytes(s.encode()) for s in svgs], max(1, repeat // 2))
    return {"sheets": len(sheets), "panels": len(panels), "svg_bytes": sum(len(s) for s in svgs),
            "panels_s": t_panels, "layout_s": t_layout, "svg_s": t_svg, "pdf_s": t_pdf}


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    path = args[0] if args else "samples/v_engine.toml"
    r = bench(path)
    total = r["panels_s"] + r["layout_s"] + r["svg_s"] + r["pdf_s"]
    print(f"{path}: {r['sheets']} sheet(s), {r['panels']} panels, {r['svg_bytes']} bytes of SVG")
    for key, name in (("panels_s", "panels (engine + construction + labels)"), ("layout_s", "layout"),
                      ("svg_s", "SVG build + serialise (svgwrite)"), ("pdf_s", "SVG -> PDF (cairosvg)")):
        print(f"  {name:42s} {1000 * r[key]:8.1f} ms  {100 * r[key] / total:5.1f} %")
    return 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
