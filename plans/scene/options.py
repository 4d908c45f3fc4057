"""What a scene file asks of the solve besides its mechanism: the outputs (each with what it
needs first), the branch of each group's assembly, the title in each sheet language, and the
scales (μ or K per quantity, or the known vector's length, and how they are written)."""

from __future__ import annotations

from typing import Any

from plans.errors import Said
from plans.reader import Reader, did_you_mean, show

#: What a scene may ask for, and what each one needs first.
OUTPUTS: dict[str, tuple[str, ...]] = {
    "positions": (),
    "velocity_plan": ("positions",),
    "acceleration_plan": ("velocity_plan",),
    "force_polygons": ("acceleration_plan",),
    "lever": ("acceleration_plan",),
    "diagrams": ("positions",),  # kinematic diagrams over the cycle ([diagrams], plans.cycle)
    "dynamics": ("positions",),  # machine dynamics and the flywheel ([dynamics], plans.cycle)
    "instant_centres": ("velocity_plan",),  # Kennedy's centres (plans.kinematics.centres)
}


def read_branches(r: Reader, data: dict[str, Any]) -> dict[str, int]:
    raw = r.table(data, "branches", "", required=False)
    out = {}
    for key, value in raw.items():
        if isinstance(value, bool) or value not in (1, -1):
            raise r.fail(f"branches.{key}", Said("e_branch", got=show(value)))
        out[r.name(key, f"branches.{key}")] = int(value)
    return out


def read_outputs(r: Reader, data: dict[str, Any]) -> frozenset[str]:
    raw = data.get("outputs", ["positions", "velocity_plan", "acceleration_plan"])
    if not isinstance(raw, list) or not all(isinstance(x, str) for x in raw):
        raise r.fail("outputs", Said("e_outputs"))
    wanted: set[str] = set()

    def add(name: str) -> None:
        if name not in OUTPUTS:
            raise r.fail("outputs", Said("e_output", name=name, hint="", known=", ".join(OUTPUTS)))
        if name not in wanted:
            wanted.add(name)
            for dep in OUTPUTS[name]:
                add(dep)

    for name in raw:
        if name not in OUTPUTS:
            raise r.fail("outputs", Said("e_output", name=name, hint=did_you_mean(name, OUTPUTS),
                                         known=", ".join(OUTPUTS)))
        add(name)
    return frozenset(wanted)


def read_title(r: Reader, value: Any) -> tuple[str, dict[str, str]]:
    """``title = "..."`` or ``title = { ru = "...", en = "..." }`` (one per sheet language)."""
    if isinstance(value, str):
        return value, {}
    if isinstance(value, dict) and value and all(k in ("ru", "en") and isinstance(v, str)
                                                 for k, v in value.items()):
        return str(value.get("en") or value.get("ru") or ""), {str(k): str(v) for k, v in value.items()}
    raise r.fail("title", Said("e_title"))


_SCALE_UNITS = {"length": "mm/m", "velocity": "mm/(m/s)", "acceleration": "mm/(m/s^2)", "force": "mm/N"}


def read_scales(r: Reader, data: dict[str, Any]) -> tuple[dict[str, float], str]:
    raw = r.table(data, "scales", "", required=False)
    r.keys(raw, {"style", "symbol", "direction", *_SCALE_UNITS}, "scales.")
    style = "||"  # the scales' letter, their direction, the pole: the language's (plans.scene.notation)
    sheet = data.get("sheet")
    if {"style", "symbol", "direction"} & set(raw) or (isinstance(sheet, dict) and "acceleration_pole" in sheet):
        from plans.scene.notation import read

        style = read(r, raw, sheet)
    out = {}
    for key, value in raw.items():
        if key in ("style", "symbol", "direction"):
            continue
        if isinstance(value, dict) and set(value) == {"known_mm"} and key in ("velocity", "acceleration"):
            # the course habit: the known vector (crank pin) drawn this long, e.g. pa = 100 mm
            out[f"{key}_known_mm"] = r.number(value, "known_mm", f"scales.{key}.", positive=True, limit=1e4)
            continue
        if not isinstance(value, dict) or len(value) != 1 or not ({"mu", "K"} & set(value)):
            raise r.fail(f"scales.{key}", Said("e_scale_known" if key in ("velocity", "acceleration")
                                               else "e_scale"))
        kind = "mu" if "mu" in value else "K"
        x = r.number(value, kind, f"scales.{key}.", positive=True, limit=1e9, floor=1e-9)
        out[key] = x if kind == "mu" else 1.0 / x
    return out, style
