"""What is worked out once from a frozen record, kept beside it rather than in it.

A record (:func:`plans.records.frozen`) is a value: equal fields, equal records, and nothing
in it changes after it is made.  What a solver derives from one (a scene's structure, the
exact solver's constants, a force analysis's largest reaction) is kept here, keyed by the
record itself (its identity: a replaced record, ``dataclasses.replace``, derives its own) and
dropped when the record is (a weak reference: the record's class is made with
``@frozen(weakref=True)``).
"""

from __future__ import annotations

import weakref
from typing import Any

#: id(record) -> (a weak reference to it, what is derived from it)
_KEPT: dict[int, tuple[weakref.ref, dict[Any, Any]]] = {}


def derived(record: Any) -> dict[Any, Any]:
    """The table of what is derived from ``record`` (empty the first time it is asked for)."""
    key = id(record)
    got = _KEPT.get(key)
    if got is not None and got[0]() is record:
        return got[1]
    table: dict[Any, Any] = {}

    def forget(ref: weakref.ref, key: int = key) -> None:
        held = _KEPT.get(key)
        if held is not None and held[0] is ref:
            del _KEPT[key]

    _KEPT[key] = (weakref.ref(record, forget), table)
    return table


__all__ = ["derived"]
