"""Warnings of an implausible scene: what is legal but almost surely a slip.

* Lengths or speeds beyond any machine's: a file written in millimetres with ``unit = "m"``
  makes an 80 m crank whose pin runs at 1000 m/s.  A linkage of a machine is at most
  :data:`LENGTH_WARN` long and its points move slower than :data:`SPEED_WARN`.
* Look-alike letters: a point named with a Cyrillic «А» is not the Latin A beside it,
  though both print the same; a name mixing both alphabets is never meant.

Each warning is one line on stderr in the run's language (:func:`plans.errors.warn`); the
run goes on.  :func:`not_on_link` is the error that names the look-alike instead of saying
only that the point is not on the link.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from plans.errors import Said, warn
from plans.units import LENGTH_WARN, SPEED_WARN

#: Cyrillic letters drawn like Latin ones (capitals and small), and the Latin they look like.
_TWINS = dict(zip("АВЕКМНОРСТХУаеорсухіј", "ABEKMHOPCTXYaeopcyxij", strict=True))


def script(name: str) -> str | None:
    """``"cyrillic"``, ``"latin"``, ``"mixed"`` (letters of both) or None (no letters)."""
    cyr = any("\u0400" <= ch <= "\u04ff" for ch in name)
    lat = any(ch.isascii() and ch.isalpha() for ch in name)
    return "mixed" if cyr and lat else "cyrillic" if cyr else "latin" if lat else None


def looks(name: str) -> str:
    """The name as it looks: each Cyrillic letter drawn like a Latin one replaced by it."""
    return "".join(_TWINS.get(ch, ch) for ch in name)


def twin(name: str, names: Iterable[str]) -> str | None:
    """Another of ``names`` that looks exactly like ``name`` (but is not it)."""
    seen = looks(name)
    return next((n for n in names if n != name and looks(n) == seen), None)


def not_on_link(point: str, link: Any, names: Iterable[str]) -> Said:
    """"point 'А' is not on link 2", saying so when the link has a look-alike of it."""
    other = twin(point, names)
    if other is None:
        return Said("e_not_on_link", point=point, link=link)

    def letters(n: str) -> Said:
        return Said("e_cyrillic" if script(n) in ("cyrillic", "mixed") else "e_latin")

    return Said("e_lookalike", point=point, link=link, script=Said(
        "e_cyrillic_is" if script(point) in ("cyrillic", "mixed") else "e_latin_is"), other=other,
        other_script=letters(other))


def warn_scene(scene: Any, unit: str, path: str) -> None:
    """Every warning of a linkage scene, on stderr."""
    for lid, link in sorted(scene.links.items()):
        size = max((abs(a - b) for a in link.points.values() for b in link.points.values()), default=0.0)
        size = max(size, link.length or 0.0)
        if size > LENGTH_WARN:
            warn(Said("w_length" if unit == "m" else "w_length_figure", file=path, field=f"links.{lid}",
                      what=Said("w_link", link=lid), value=size, unit=unit), getattr(scene, "raw", None))
    d = scene.driver
    crank = scene.links.get(d.link)
    if crank is not None and len(crank.axis) == 2:
        v = abs(d.omega) * abs(crank.points[crank.axis[1]] - crank.points[crank.axis[0]])
        if v > SPEED_WARN:
            warn(Said("w_speed", file=path, point=crank.axis[1], v=v, limit=SPEED_WARN), getattr(scene, "raw", None))
    names = list(scene.frame_points) + [p for link in scene.links.values() for p in link.points]
    for name in dict.fromkeys(names):
        if script(name) == "mixed":
            letters = ", ".join(f"{ch!r}" for ch in name if ch in _TWINS)
            warn(Said("w_lookalike", file=path, where="points", name=name, letters=letters), getattr(scene, "raw", None))
    seen: dict[str, str] = {}
    for name in dict.fromkeys(names):
        other = seen.setdefault(looks(name), name)
        if other != name:
            warn(Said("w_twins", file=path, a=other, b=name), getattr(scene, "raw", None))
