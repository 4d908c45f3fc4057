"""The designed mechanism as a record, the free choices as said, the one-line failure."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from plans.errors import InputError, Said

from .model import Task
from .proof import Measured


@dataclass(frozen=True)
class Design:
    """A designed mechanism, its construction and its proof (SI, the scene's frame)."""

    task: Task
    model: str  # central, offset, crank_rocker, three_positions, coulisse, v_engine
    lengths: dict[str, float]  # name -> metres (the JSON's names)
    mechs: tuple[Any, ...]  # the proof's mechanisms (two sliders for a V-engine)
    working: str  # which stroke is the working one (see proof.measure)
    points: dict[str, complex]  # the construction's points: O, C1, C2, D, Oc, C, ...
    circle: tuple[complex, float] | None  # the construction's circle (centre, radius)
    choice: tuple[str, float] | None  # how a free choice was made (see CHOICES), None when none was left
    measured: tuple[Measured, ...] = ()
    notes: tuple[str, ...] = field(default=())

    @property
    def theta(self) -> float:
        return self.task.theta


#: The free choices a model makes, as said in English and in Russian ({} is an angle or λ).
CHOICES = {
    "least_pressure": ("the crank's pivot on the arc with the least maximum pressure angle ({})",
                       "ось кривошипа на дуге — при наименьшем наибольшем угле давления ({})"),
    "lambda_from_pressure": ("λ = sin[ϑ] = {}: the shortest rod within the permissible pressure angle",
                             "λ = sin[ϑ] = {}: самый короткий шатун при допускаемом угле давления"),
    "two_pivots": ("of the pivots the condition leaves, the one with the best γmin ({})",
                   "из допустимых положений оси — с наибольшим γmin ({})"),
    "shortest_frame": ("the shortest frame with γmin >= [γ] (γmin grows toward {} as the frame lengthens)",
                       "самая короткая стойка с γmin >= [γ] (γmin растёт к {} с длиной стойки)"),
    "best_gamma": ("the crank's pivot on the arc with the best γmin ({})",
                   "ось кривошипа на дуге — при наибольшем γmin ({})"),
    "mid_sagitta": ("the ram's guide through the middle of the sagitta of D's arc (pressure angle {})",
                    "направляющая ползуна — через середину стрелки дуги точки D (угол давления {})"),
}


def choice_text(choice: tuple[str, float] | None, lang: str = "en") -> str:
    """The sentence saying how the free choice was made ("" when there was none)."""
    if choice is None:
        return ""
    key, v = choice
    shown = f"{v:.6g}" if key == "lambda_from_pressure" else f"{math.degrees(v):.6g}°"
    if lang == "ru":
        shown = shown.replace(".", ",")
    return CHOICES[key][1 if lang == "ru" else 0].format(shown)


def fail(t: Task, key: str, message: str | Said) -> InputError:
    return InputError(message, file=t.path, field=key)


def mirror(z: complex, sense: int) -> complex:
    return z if sense > 0 else z.conjugate()


def deg_text(x: float) -> str:
    return f"{math.degrees(x):.6g}°"


def stroke_of(t: Task) -> float:
    """H, given or from the mean speed: v_m = 2H·n/60."""
    if t.stroke is not None:
        return t.stroke
    assert t.mean_speed is not None and t.omega_rpm is not None
    return t.mean_speed * 30.0 / t.omega_rpm
