"""Positions a scene asks for by what the mechanism does, read as a request.

``[driver] s_mm`` or ``s_fraction`` (with ``s_stroke``, ``piston``): the crank angles at
which the piston has travelled that far from its outer dead centre.  ``phi_start =
"extreme"`` (or ``"extreme_idle"``) with ``positions = N``: N positions from the output's
extreme.  Neither angle is in the file: the exact analysis finds it.  This room reads and
validates the request with the file (:func:`read_placing`, every problem one line naming
file and field); the kinematics places it (:func:`plans.kinematics.placing.place`), and
``plans.load_scene`` hands out only placed scenes.  A scene whose driver still carries a
request has no positions yet (``phis_deg == ()``).
"""

from __future__ import annotations

from typing import Any

from plans.errors import Said
from plans.reader import Reader
from plans.records import frozen

#: ``phi_start``: where the positions begin (the working stroke's extreme, or the idle one's).
STARTS = ("extreme", "extreme_idle")


@frozen
class ByTravel:
    """The positions at the piston's travels: ``values`` in metres (``s_mm``) or in
    fractions of the stroke (``s_fraction``), on the stroke ``stroke`` ("down": toward
    the crank, "up": back), of the piston whose prismatic pair with the frame is ``joint``
    (its name, ``Joint.name``)."""

    key: str  # "s_mm" | "s_fraction": the field a problem names
    values: tuple[float, ...]  # as written: mm or fractions of the stroke
    stroke: str
    joint: str


@frozen
class FromExtreme:
    """``n`` positions every 360°/n from the output's extreme: ``start`` = "extreme" (where
    the working stroke begins) or "extreme_idle"."""

    start: str
    n: int


Placing = ByTravel | FromExtreme


def wanted(d: Any) -> bool:
    """Whether ``[driver]`` asks for its positions by travel or from an extreme."""
    return isinstance(d, dict) and ("s_mm" in d or "s_fraction" in d or "phi_start" in d)


def read_placing(r: Reader, d: dict[str, Any], joints: tuple[Any, ...], frame: int) -> Placing:
    """The request of ``[driver]`` (:func:`wanted` is true), validated: the travel's keys and
    numbers and its piston among ``joints`` (the scene's :class:`plans.scene.model.Joint`, which
    imports this module), or the start and the positions it goes with."""
    if "s_mm" in d or "s_fraction" in d:
        return _by_travel(r, d, joints, frame)
    return _from_extreme(r, d)


def _by_travel(r: Reader, d: dict[str, Any], joints: tuple[Any, ...], frame: int) -> ByTravel:
    if "s_mm" in d and "s_fraction" in d:
        raise r.fail("driver.s_fraction", Said("kt_give_mm_fraction"))
    for other in ("phi_deg", "positions"):
        if other in d:
            raise r.fail(f"driver.{other}", Said("kt_positions_are_given", other=other))
    key = "s_mm" if "s_mm" in d else "s_fraction"
    raw = d[key] if isinstance(d[key], list) else [d[key]]
    if not raw or len(raw) > 360:
        raise r.fail(f"driver.{key}", Said("kt_travels"))
    values = tuple(r.value(v, f"driver.{key}", nonneg=True) for v in raw)
    stroke = r.choice(d, "s_stroke", "driver.", ("down", "up"), "down")
    pistons = [j for j in joints if j.kind == "P" and j.guide is not None and j.guide.link == frame]
    if "piston" in d:
        pistons = [j for j in pistons if j.slider == d["piston"] and not isinstance(d["piston"], bool)]
        if not pistons:
            raise r.fail("driver.piston", Said("kt_link_piston_sliding", v=d['piston']))
    elif len({j.slider for j in pistons}) != 1:
        raise r.fail("driver.piston" if pistons else f"driver.{key}",
                     "name the piston: piston = link number" if pistons else
                     "a position by travel needs a piston sliding on a guide of the frame")
    if "phi_start" in d:  # a start from the extreme goes with positions = N, which a travel excludes
        _from_extreme(r, d)
    return ByTravel(key, values, stroke, pistons[0].name)


def _from_extreme(r: Reader, d: dict[str, Any]) -> FromExtreme:
    start = r.choice(d, "phi_start", "driver.", STARTS, "extreme")
    for other in ("phi_deg", "phi0_deg"):
        if other in d:
            raise r.fail(f"driver.{other}", Said("kx_positions_start_extreme", other=other))
    if "positions" not in d:
        raise r.fail("driver.phi_start", Said("kx_phi_start_goes"))
    return FromExtreme(start, r.integer(d, "positions", "driver.", at_least=1))
