"""Times of drawing a scene's sheets (for the record and ``plans bench``, never a timed test)::

    python -m drawings.bench samples/v_engine.toml            # stages, as a table
    python -m drawings.bench --json samples/v_engine.toml samples/v_engine_cycle.toml

With ``--json`` (what ``plans bench`` reads, through :func:`figures` registered by the
renderer: the engine never imports it): each sheet of the first scene written as SVG, PDF and PNG at
150 dpi and as DXF from its composed sheet (median of ``--repeat``), the sheets' build (engine,
panels, layout) per sheet, and, for a second scene, its cycle diagrams sheet to SVG.
"""

from __future__ import annotations

import functools
import json
import os
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any

import drawings
from drawings.linkage import build_panels, draw, fit_for
from drawings.linkage.panels import ratio_text
from drawings.paper.export import dxf_bytes, pdf_bytes, png_bytes, svg_bytes
from drawings.paper.sheet import compose
from plans.kinematics.placing import load_scene
from plans.solution import solve

PNG_DPI = 150.0


def _best(f: Callable[[], Any], n: int) -> tuple[float, Any]:
    best, out = float("inf"), None
    for _ in range(n):
        t = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t)
    return best, out


def _median(f: Callable[[], Any], n: int, cpu: list[float] | None = None) -> float:
    """Median wall time of ``n`` calls; with ``cpu``, the least processor time is appended
    to it (on a shared machine the load stretches the first, hardly the second: a call waits
    for the processor, and the least of its runs is what it costs)."""
    ts, cs = [], []
    for _ in range(max(1, n)):
        c, t = time.process_time(), time.perf_counter()
        f()
        ts.append(time.perf_counter() - t)
        cs.append(time.process_time() - c)
    if cpu is not None:
        cpu.append(min(cs))
    return statistics.median(ts)


def bench(path: str, repeat: int = 5) -> dict[str, float]:
    """Seconds per stage (best of ``repeat``): panels (engine, construction, label placement),
    layout, SVG serialisation, SVG -> PDF; plus counts."""
    scene = load_scene(path)
    draw(scene)  # warm up: font, imports
    spec = scene.sheet_for()
    t_panels, (panels, mu_l) = _best(lambda: build_panels(solve(scene, fit=fit_for(spec)), spec), repeat)
    t_layout, sheets = _best(lambda: compose(panels, spec, ratio_text(mu_l), scene.path), repeat)
    t_svg, svgs = _best(lambda: [s.svg() for s in sheets], repeat)
    t_pdf, _ = _best(lambda: [pdf_bytes(s.encode()) for s in svgs], max(1, repeat // 2))
    return {"sheets": len(sheets), "panels": len(panels), "svg_bytes": sum(len(s) for s in svgs),
            "panels_s": t_panels, "layout_s": t_layout, "svg_s": t_svg, "pdf_s": t_pdf}


def sheet_seconds(path: str, repeat: int = 3) -> dict[str, Any]:
    """Each sheet of ``path`` as SVG (serialised from the composed sheet), PDF and PNG at
    :data:`PNG_DPI` (each from the SVG bytes, parsing included): medians of ``repeat``, per
    sheet; the build of all the sheets (scene read, engine, panels, layout) once, median."""
    drawings.draw(path)  # warm up: fonts, imports
    build = _median(lambda: drawings.draw(path), repeat)
    sheets = drawings.draw(path).sheets
    out: dict[str, Any] = {"scene": str(path), "sheets": len(sheets),
                           "format": sheets[0].spec.format if sheets else "",
                           "build_s": build, "svg_s": [], "pdf_s": [], "png_s": [], "svg_bytes": [],
                           "svg_cpu_s": [], "pdf_cpu_s": [], "png_cpu_s": [], "dxf_s": [], "dxf_cpu_s": []}
    if sheets:
        dxf_bytes(sheets[0])  # warm up: ezdxf's import
    for sh in sheets:
        svg = sh.svg().encode("utf-8")
        out["svg_bytes"].append(len(svg))
        out["svg_s"].append(_median(functools.partial(svg_bytes, sh), repeat, out["svg_cpu_s"]))
        out["pdf_s"].append(_median(functools.partial(pdf_bytes, svg), repeat, out["pdf_cpu_s"]))
        out["png_s"].append(_median(functools.partial(png_bytes, svg, PNG_DPI), repeat, out["png_cpu_s"]))
        out["dxf_s"].append(_median(functools.partial(dxf_bytes, sh), repeat, out["dxf_cpu_s"]))
    return out


def figures(paths: list[str], repeat: int = 3) -> dict[str, Any]:
    """What ``plans bench`` reads: the sheets of the first scene, the diagrams sheet of the
    second (if given), and the machine's load average while they ran."""
    load0 = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    out: dict[str, Any] = {"sheets": sheet_seconds(paths[0], repeat)}
    if len(paths) > 1:
        from drawings.cycle import diagrams_sheet_seconds

        ts, cs = [], []
        for _ in range(max(1, repeat)):
            c = time.process_time()
            ts.append(diagrams_sheet_seconds(paths[1], 1))
            cs.append(time.process_time() - c)
        out["diagrams"] = {"scene": paths[1], "svg_s": statistics.median(ts), "svg_cpu_s": min(cs)}
    load1 = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    out["load"] = [load0, load1]
    return out


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if args and args[0] == "--json":
        rest = args[1:]
        repeat = 3
        if rest[:1] == ["--repeat"]:
            repeat, rest = int(rest[1]), rest[2:]
        print(json.dumps(figures(rest or ["samples/v_engine.toml"], repeat)))
        return 0
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
