"""Frozen plan objects: what the draftsman has on the sheet after a construction.

A plan (velocity, acceleration, force polygon, lever) is a set of labelled
points in *plan millimetres* (pole at the origin, x right, y up), segments
between them that mean something (v_BA, a_BA^n, ...), the construction lines
drawn thin, and the protocol of steps that produced them.  ``scale`` is μ in
mm per SI unit (mm/(m/s), mm/(m/s²), mm/N).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import field
from typing import Any, Protocol

from plans.phrases import Phrase
from plans.records import frozen

#: Segment kinds, as the textbook distinguishes them.
SEGMENT_KINDS = ("absolute", "relative", "normal", "tangential", "coriolis", "sliding", "force", "closing")


@frozen
class PlanPoint:
    """A labelled point of a plan (plan mm)."""

    name: str  # textbook label: "p_v", "a", "b", "s2", "a3", "n_BA", "k_A2A3"
    xy: tuple[float, float]  # plan mm
    coincides_with: str | None = None  # drawn on top of another point (e.g. b on the pole)


@frozen
class Segment:
    """A vector drawn on the plan from ``start`` to ``end`` (point names)."""

    start: str
    end: str
    kind: str  # one of SEGMENT_KINDS
    label: str  # "v_B", "v_BA", "a_BA^n", "a^k_A3A2", "F_12"
    length_mm: float
    value: float  # the SI magnitude it stands for at the plan's scale (length_mm / scale)


@frozen
class ConstructionLine:
    """A thin line through ``point`` along unit ``direction`` (plan mm)."""

    point: tuple[float, float]
    direction: tuple[float, float]
    label: str  # "⟂ AB", "∥ guide of B"


@frozen
class Step:
    """One draftsman's step: operation, inputs, output, and a sentence for the protocol."""

    op: str  # "lay off", "parallel", "perpendicular", "intersect", "similarity", "coincide"
    inputs: tuple[str, ...]
    output: str
    text: str  # the sentence in English
    phrase: Phrase | None = field(default=None, compare=False, repr=False)  # to write it in another language

    @classmethod
    def of(cls, op: str, inputs: tuple[str, ...], output: str, words: Phrase) -> Step:
        """A step whose sentence is a phrase (written in English as ``text``)."""
        return cls(op, inputs, output, words.say("en"), words)

    def say(self, lang: str = "en") -> str:
        """The sentence in ``lang`` ("en" or "ru"), the same numbers either way."""
        return self.text if self.phrase is None or lang == "en" else self.phrase.say(lang)


class Recorded(Protocol):
    """What records a plan's steps as (operation, inputs, output, phrase) and writes them
    (:meth:`Step.of`) once, when first asked: the construction that drew the plan."""

    def recorded(self) -> int: ...

    def written(self) -> tuple[Step, ...]: ...


class Written(Sequence[Step]):
    """A plan's steps, written when first read (a sheet, a protocol or the JSON asks for them,
    a table of readings never does): an unchanging view of the steps its construction
    (:class:`Recorded`) writes once and keeps."""

    __slots__ = ("_source",)

    def __init__(self, source: Recorded) -> None:
        self._source = source

    def __getitem__(self, i: Any) -> Any:
        return self._source.written()[i]

    def __len__(self) -> int:
        return self._source.recorded()

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Sequence) and self._source.written() == tuple(other)

    def __hash__(self) -> int:
        return hash(self._source.written())

    def __repr__(self) -> str:
        return repr(self._source.written())


@frozen
class Plan:
    """A plan as drawn: points, vectors, construction lines and the steps that drew them."""

    kind: str  # "velocity" | "acceleration" | "force" | "lever"
    phi_deg: float
    scale: float  # mm per SI unit
    pole: str
    points: tuple[PlanPoint, ...]
    segments: tuple[Segment, ...]
    lines: tuple[ConstructionLine, ...]
    steps: Sequence[Step]  # a tuple, or written when first read
    degenerate: tuple[str, ...] = ()  # notes on dead centres / parallel lines met

    def xy(self, name: str) -> tuple[float, float]:
        for p in self.points:
            if p.name == name:
                return p.xy
        raise KeyError(name)

    def has(self, name: str) -> bool:
        return any(p.name == name for p in self.points)

    def segment(self, label: str) -> Segment:
        for s in self.segments:
            if s.label == label:
                return s
        raise KeyError(label)

    @property
    def extent(self) -> float:
        """Largest distance of a plan point from the pole (mm)."""
        return max((abs(complex(*p.xy)) for p in self.points), default=0.0)

    def protocol(self, lang: str = "en") -> str:
        return "\n".join(f"{k + 1:2d}. {s.say(lang)}" for k, s in enumerate(self.steps))

    def to_json(self) -> dict:
        return {
            "scale": self.scale,
            "pole": self.pole,
            "points": {p.name: [p.xy[0], p.xy[1]] for p in self.points},
            "coincident": {p.name: p.coincides_with for p in self.points if p.coincides_with},
            "segments": [{"label": s.label, "from": s.start, "to": s.end, "kind": s.kind,
                          "length_mm": s.length_mm, "value": s.value} for s in self.segments],
            "degenerate": list(self.degenerate),
        }
