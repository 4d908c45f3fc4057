"""What the workbench hands back besides the solve: a synthesis file designed, the
demonstration page, the explanatory note and the sheets, each as its own command makes it
(``plans design``, ``plans demo``, ``plans note``, ``plans draw``), from the page's text."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path
from typing import Any

from plans.errors import InputError, Said

#: The kinds of file the explanatory note has a section for, and its figures' resolution.
NOTE_KINDS = ("linkage", "gears", "cam", "engine")
NOTE_DPI = 150.0


def jsonable(x: Any) -> Any:
    """A parsed TOML table as JSON can write it (a date as its text, NaN as null)."""
    if isinstance(x, dict):
        return {str(k): jsonable(v) for k, v in x.items()}
    if isinstance(x, list | tuple):
        return [jsonable(v) for v in x]
    if isinstance(x, float) and x != x:
        return None
    if isinstance(x, str | int | float | bool) or x is None:
        return x
    return str(x)  # TOML dates and times


def design_json(text: str, name: str) -> bytes:
    """A synthesis file designed (``plans design``): the scene written and the JSON of
    ``plans design --json`` (its ``scene`` the scene's text)."""
    from plans.io import loads_toml
    from plans.synthesis.cli import check_scene, results
    from plans.synthesis.model import task_from_dict
    from plans.synthesis.scene import scene_text
    from plans.synthesis.solution import solve_task

    d = solve_task(task_from_dict(loads_toml(text, name), name)).design
    scene = scene_text(d)
    check_scene(scene, name)
    return json.dumps({"scene": scene, "data": jsonable(tomllib.loads(scene)), "design": results(d, scene)},
                      ensure_ascii=False,
                      allow_nan=False, separators=(",", ":")).encode("utf-8")


def demo_page(text: str, name: str, lang: str | None = None) -> bytes:
    """``plans demo`` of the edited scene, in the workbench page's language (None: the scene's)."""
    from drawings.demo import page
    from plans.kinematics.placing import parse_scene

    return page(parse_scene(text, name), language=lang).encode("utf-8")


def note_file(text: str, stem: str, lang: str | None) -> bytes:
    """``plans note`` of one file: solved as its own command solves it, in a temporary folder
    (the note reads files by their paths)."""
    import tempfile

    from drawings.note.cli import note_bytes
    from plans.io import loads_toml
    from plans.kinds import kind_of

    kind = kind_of(loads_toml(text, f"{stem}.toml"), f"{stem}.toml")
    if kind not in NOTE_KINDS:
        raise InputError(Said("wo_note_has_section", kind=kind, v=', '.join(NOTE_KINDS)),
                         file=f"{stem}.toml", field="kind")
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / f"{stem}.toml"
        src.write_text(text, encoding="utf-8")  # guard: a temporary folder
        return note_bytes([str(src)], lang, dpi=NOTE_DPI)


def draw_file(text: str, stem: str, fmt: str) -> tuple[bytes, str]:
    import importlib
    import tempfile
    import zipfile

    from drawings.paper.export import save
    from plans.io import loads_toml
    from plans.kinds import KINDS, kind_of

    kind = kind_of(loads_toml(text, f"{stem}.toml"), f"{stem}.toml")
    module = importlib.import_module(KINDS[kind][1])
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / f"{stem}.toml"
        src.write_text(text, encoding="utf-8")  # guard: a temporary folder
        drawing = module.draw(str(src))
        written = save(drawing.sheets, Path(tmp) / "out", stem, [fmt], source=str(src))
        if len(written) == 1:
            return written[0].read_bytes(), written[0].name
        import io

        buf = io.BytesIO()
        with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
            for p in sorted(written):
                info = zipfile.ZipInfo(p.name, date_time=(2000, 1, 1, 0, 0, 0))
                z.writestr(info, p.read_bytes(), zipfile.ZIP_DEFLATED)
        return buf.getvalue(), f"{stem}-{fmt}.zip"
