"""Which sheets in an output folder belong to which input file.

``plans draw`` keeps ``.plans-manifest.json`` in the output folder: for every input file
drawn there (by its absolute path), the files written for it.  With it a redraw removes
the input's own old sheets that the new drawing no longer has (a scene now with fewer
sheets, or another set of formats), and a sheet of another input that would be
overwritten (two scenes ``a/x.toml`` and ``b/x.toml`` drawn into one folder) is refused
before anything is written.  Files the manifest does not list are never removed.
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from pathlib import Path

from plans.errors import OutputError, Said
from plans.io import remove as remove_files
from plans.io import staged_bytes, write_all

NAME = ".plans-manifest.json"


def _load(folder: Path) -> dict[str, list[str]]:
    try:
        raw = staged_bytes(folder / NAME)  # this command's own manifest, written a sheet ago
        data = json.loads(raw if raw is not None else (folder / NAME).read_bytes())
    except (OSError, ValueError):
        return {}
    if not isinstance(data, dict) or not isinstance(data.get("sources"), dict):
        return {}
    out: dict[str, list[str]] = {}
    for src, files in data["sources"].items():
        if isinstance(src, str) and isinstance(files, list):
            out[src] = [f for f in files if isinstance(f, str) and "/" not in f and f not in ("", ".", "..")]
    return out


def plan_sheets(folder: Path, files: dict[Path, bytes], source: str | Path) -> tuple[dict[Path, bytes], list[Path]]:
    """``files`` plus the folder's updated manifest, and the old files of ``source`` to remove
    once they are written; OutputError when a file belongs to another input."""
    me = str(Path(source).resolve())
    sources = _load(folder)
    names = {p.name for p in files}
    for other, owned in sources.items():
        if other == me or not Path(other).is_file():
            continue
        clash = sorted(names & set(owned))
        if clash:
            raise OutputError(Said("pm_holds_sheet_other", v=folder / clash[0], other=other, source=source))
    stale = [folder / n for n in sources.get(me, []) if n not in names]
    sources = {src: owned for src, owned in sources.items() if Path(src).is_file() or src == me}
    sources[me] = sorted(names)
    manifest = json.dumps({"format": 1, "sources": sources}, indent=1, sort_keys=True, ensure_ascii=False) + "\n"
    return {**files, folder / NAME: manifest.encode("utf-8")}, stale


def write_sheets(folder: Path, files: dict[Path, bytes], source: str | Path | None) -> list[Path]:
    """Write ``files`` (all in ``folder``) as one, record them for ``source`` and remove the
    files ``source`` had there before that the new set no longer holds."""
    if source is None:
        return write_all(dict(files))
    staged, stale = plan_sheets(folder, files, source)
    written = write_all(staged)
    remove(stale)
    return [p for p in written if p.name != NAME]


def forget(folder: Path, source: str | Path) -> None:
    """Remove the sheets ``source`` had in ``folder`` and its line of the manifest: a file
    that fails in a batch keeps no sheet of an earlier run that would look current."""
    me = str(Path(source).resolve())
    sources = _load(folder)
    if me not in sources:
        return
    owned = sources.pop(me)
    manifest = json.dumps({"format": 1, "sources": sources}, indent=1, sort_keys=True, ensure_ascii=False) + "\n"
    write_all({folder / NAME: manifest.encode("utf-8")})
    remove(folder / n for n in owned)


def remove(paths: Iterable[Path]) -> None:
    """Remove old sheets (already gone is fine; when the command has succeeded)."""
    remove_files(paths)
