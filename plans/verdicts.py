"""What every check report counts: its figures by verdict (a sheet's check,
:mod:`plans.check.report`; a cycle's tables, :mod:`plans.cycle.check`)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any


class Tally:
    """``passed`` and ``failed`` of a report's ``items`` (each with a ``verdict``)."""

    __slots__ = ()
    items: Sequence[Any]

    @property
    def passed(self) -> int:
        return sum(1 for i in self.items if i.verdict == "pass")

    @property
    def failed(self) -> int:
        return sum(1 for i in self.items if i.verdict == "fail")

    def counts(self) -> dict[str, int]:
        """The figures checked, passed and failed, as a report's summary opens."""
        return {"items": len(self.items), "passed": self.passed, "failed": self.failed}
