"""Frozen records: ``dataclass(frozen=True, slots=True)`` at a quarter of its cost to define.

Python 3.11's ``dataclass`` writes the source of six methods for each frozen class and
compiles each one: about a millisecond a class, and the scene, the plans, the forces and
the cycle define some thirty of them on the way to ``plans solve``'s first result.
:func:`frozen` lets ``dataclass`` lay out the fields (``dataclasses.fields``, ``replace``,
``asdict``, ``__match_args__``, the slots) and compiles ``__init__`` alone; ``__repr__``,
``__eq__``, ``__hash__``, the frozen ``__setattr__``/``__delattr__`` and the pickling of
slots are shared functions over the class's fields.  The behaviour is dataclass's (the
tests compare the two on every class made here).  Only what this code base uses is
offered: no ``InitVar``, no keyword-only fields.
"""

from __future__ import annotations

import reprlib
import weakref
from collections.abc import Callable
from dataclasses import MISSING, Field, FrozenInstanceError, dataclass, field, fields
from operator import attrgetter
from typing import Any, TypeVar, dataclass_transform, overload

T = TypeVar("T", bound=type)

#: Every class made by :func:`frozen` (the tests compare each with dataclass's own).
MADE: list[type] = []


@overload
def frozen(cls: T, /) -> T: ...


@overload
def frozen(*, slots: bool = True, weakref_slot: bool = False) -> Callable[[T], T]: ...


@dataclass_transform(frozen_default=True, field_specifiers=(field, Field))
def frozen(cls: T | None = None, /, *, slots: bool = True, weakref_slot: bool = False) -> Any:
    """``@frozen`` as ``@dataclass(frozen=True, slots=True)``; ``@frozen(slots=False)`` as
    ``@dataclass(frozen=True)``; ``weakref_slot=True`` as dataclass's (what is derived from
    the record is kept beside it, :func:`derived`).  A method the class writes
    itself is kept."""

    def wrap(cls: T) -> T:
        own = dict(cls.__dict__)
        if any(w in str(t) for t in own.get("__annotations__", {}).values() for w in ("InitVar", "KW_ONLY")):
            raise TypeError(f"{cls.__name__}: InitVar and keyword-only fields need dataclass itself")
        documented = bool(cls.__doc__)
        if not documented:
            cls.__doc__ = "-"  # written below, once __init__ exists (as dataclass writes it)
        out: Any = dataclass(cls, init=False, repr=False, eq=False, frozen=False, slots=slots,
                             weakref_slot=weakref_slot and slots)
        fs = fields(out)
        if any(f.kw_only for f in fs):
            raise TypeError(f"{out.__name__}: keyword-only fields need dataclass itself")
        MADE.append(out)
        if "__init__" not in own:
            out.__init__ = _init(out, fs, slots)
        if not documented:
            import inspect

            out.__doc__ = out.__name__ + str(inspect.signature(out)).replace(" -> None", "")
        names = tuple(f.name for f in fs)
        if "__repr__" not in own:
            out.__repr__ = _repr(tuple(f.name for f in fs if f.repr))
        if "__eq__" not in own:
            out.__eq__ = _eq(_values(tuple(f.name for f in fs if f.compare)))
        if own.get("__hash__") is None:  # none written, or None as Python sets it beside an own __eq__
            hashed = _values(tuple(f.name for f in fs if (f.compare if f.hash is None else f.hash)))
            out.__hash__ = lambda self: hash(hashed(self))
        out.__setattr__, out.__delattr__ = _frozen(out, names)
        if slots:
            out.__getstate__, out.__setstate__ = _state(names)
        return out

    return wrap if cls is None else wrap(cls)


def _init(cls: type, fs: tuple[Field, ...], slots: bool) -> Callable[..., None]:
    """``__init__`` as dataclass writes it for a frozen class: every field set through
    ``object.__setattr__``, defaults and default factories, then ``__post_init__``.  It is
    compiled bare (no closure, the annotations put on afterwards): half the compiling."""
    me = "__dataclass_self__" if "self" in (f.name for f in fs) else "self"
    ns: dict[str, Any] = {"__dataclass_setattr__": object.__setattr__, "__dataclass_factory__": _FACTORY}
    params, body = [me], []
    seen_default = False
    for f in fs:
        has_factory = f.default_factory is not MISSING
        if has_factory:
            ns[f"__factory_{f.name}"] = f.default_factory
        if f.default is not MISSING:
            ns[f"__default_{f.name}"] = f.default
        if f.init:
            if f.default is not MISSING:
                params.append(f"{f.name}=__default_{f.name}")
            elif has_factory:
                params.append(f"{f.name}=__dataclass_factory__")
                body.append(f"if {f.name} is __dataclass_factory__: {f.name} = __factory_{f.name}()")
            elif seen_default:
                raise TypeError(f"non-default argument {f.name!r} follows default argument")
            else:
                params.append(f.name)
            seen_default = seen_default or f.default is not MISSING or has_factory
            value = f.name
        elif has_factory:
            value = f"__factory_{f.name}()"
        elif f.default is not MISSING and slots:  # without slots the class attribute holds it
            value = f"__default_{f.name}"
        else:
            continue
        body.append(f"__dataclass_setattr__({me}, {f.name!r}, {value})")
    if hasattr(cls, "__post_init__"):
        body.append(f"{me}.__post_init__()")
    src = f"def __init__({', '.join(params)}):\n" + "".join(f" {line}\n" for line in body or ["pass"])
    exec(compile(src, "<record>", "exec", dont_inherit=True), ns)
    fn = ns["__init__"]
    fn.__qualname__ = f"{cls.__qualname__}.__init__"
    fn.__annotations__ = {**{f.name: f.type for f in fs if f.init}, "return": None}
    return fn


class _Factory:
    def __repr__(self) -> str:
        return "<factory>"


_FACTORY = _Factory()


def _values(names: tuple[str, ...]) -> Callable[[Any], tuple]:
    """The fields ``names`` of an object as a tuple (what dataclass compares and hashes)."""
    if len(names) > 1:
        return attrgetter(*names)
    if names:
        one = attrgetter(names[0])
        return lambda obj: (one(obj),)
    return lambda obj: ()


def _repr(names: tuple[str, ...]) -> Callable[[Any], str]:
    @reprlib.recursive_repr()
    def __repr__(self: Any) -> str:
        return f"{self.__class__.__qualname__}({', '.join(f'{n}={getattr(self, n)!r}' for n in names)})"

    return __repr__


def _eq(values: Callable[[Any], tuple]) -> Callable[[Any, Any], Any]:
    def __eq__(self: Any, other: Any) -> Any:
        if other.__class__ is self.__class__:
            return values(self) == values(other)
        return NotImplemented

    return __eq__


def _frozen(cls: Any, names: tuple[str, ...]) -> tuple[Callable[..., None], Callable[..., None]]:
    def __setattr__(self: Any, name: str, value: Any) -> None:
        if type(self) is cls or name in names:
            raise FrozenInstanceError(f"cannot assign to field {name!r}")
        super(cls, self).__setattr__(name, value)

    def __delattr__(self: Any, name: str) -> None:
        if type(self) is cls or name in names:
            raise FrozenInstanceError(f"cannot delete field {name!r}")
        super(cls, self).__delattr__(name)

    return __setattr__, __delattr__


def _state(names: tuple[str, ...]) -> tuple[Callable[[Any], list], Callable[[Any, list], None]]:
    """Pickling and copying a frozen class with slots, as dataclass does it."""

    def __getstate__(self: Any) -> list:
        return [getattr(self, n) for n in names]

    def __setstate__(self: Any, state: list) -> None:
        for n, value in zip(names, state, strict=False):
            object.__setattr__(self, n, value)

    return __getstate__, __setstate__


# --------------------------------------------------------------------------- beside a record
# What a solver derives from a record (a scene's structure, the exact solver's constants, a
# force analysis's largest reaction) is kept here, not in the record: a record is a value
# (equal fields, equal records; nothing in it changes once made).  The table is keyed by the
# record's identity (a replaced record, ``dataclasses.replace``, derives its own) and dropped
# with it (a weak reference: the class is made with ``@frozen(weakref_slot=True)``).

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


__all__ = ["MADE", "derived", "frozen"]
