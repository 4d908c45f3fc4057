"""Reading the tables of an input file: one InputError line for every problem.

Every room that reads a file of the family (scenes, loads, check files, engines, gears,
cams) uses :class:`Reader`, so that they all keep the same promise: a key that is not
known is refused with "did you mean ...", a number is finite and within the engine's
range, a name is a short plain string, an angle is reduced exactly.

.. code-block:: python

    r = Reader(path)
    r.keys(data, {"format", "kind", "title", "pair"}, "")   # top level
    pair = r.table(data, "pair", "")
    z1 = r.integer(pair, "z1", "pair.", at_least=1, at_most=10_000)
    m = r.length(pair.get("module"), "pair.module", "mm", positive=True)
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

from plans.errors import InputError, Said
from plans.units import parse_length

#: The largest magnitude of a plain number in a file (forces, masses, pressures, ω, ...).
#: Beyond it products of two quantities could overflow a float; nobody's linkage needs more.
NUMBER_LIMIT = 1e12
#: The smallest non-zero magnitude: below it squares vanish and plan scales become infinite.
NUMBER_FLOOR = 1e-12
#: Lengths and coordinates, metres: 1 µm .. 10 km.
LENGTH_LIMIT = 1e4
LENGTH_FLOOR = 1e-6
#: A name (point, link, load) or a title may hold this many characters.
NAME_LIMIT = 200
TEXT_LIMIT = 2000


def did_you_mean(word: str, choices: Iterable[str]) -> Said | str:
    """``"; did you mean 'omega_rpm'?"`` when a choice is close to ``word``, else ``""``."""
    options = [c for c in choices if isinstance(c, str)]
    cutoff = 0.5 if len(str(word)) <= 3 else 0.6  # "S3" for "S2"
    import difflib  # only when a key is misspelt

    match = difflib.get_close_matches(str(word), options, n=1, cutoff=cutoff)
    if not match:
        low = {c.lower(): c for c in options}
        match = [low[str(word).lower()]] if str(word).lower() in low else []
    return Said("e_did_you_mean", word=match[0]) if match else ""


def unknown_key(word: str, known: Iterable[str], *, file: str, field: str) -> InputError:
    """The one-line error for a key that is not known here."""
    known = sorted(known)
    return InputError(Said("e_unknown_key", hint=did_you_mean(word, known), known=", ".join(known)),
                      file=file, field=field)


def check_keys(table: dict[str, Any], known: Iterable[str], *, file: str, where: str) -> None:
    """Refuse every key of ``table`` not in ``known`` (``where`` is the field prefix, ``"driver."``)."""
    known = set(known)
    for key in table:
        if key not in known:
            raise unknown_key(key, known, file=file, field=f"{where}{key}")


def bad_character(text: str) -> Said | None:
    """A description of the first character that cannot stand in a name or on a sheet
    (control characters, Unicode noncharacters, surrogates), or None."""
    if text.isprintable():  # each of them is a control, unassigned or surrogate code point: not printable
        return None
    for ch in text:
        o = ord(ch)
        if (o < 0x20 and ch not in "\t\n") or 0x7F <= o < 0xA0:
            return Said("e_control", code=f"{o:04X}")
        if 0xFDD0 <= o <= 0xFDEF or (o & 0xFFFE) == 0xFFFE:
            return Said("e_nonchar", code=f"{o:04X}")
        if 0xD800 <= o <= 0xDFFF:
            return Said("e_surrogate", code=f"{o:04X}")
    return None


def check_text(data: Any, *, file: str, where: str = "") -> None:
    """Walk a whole file's table: every key and string must be printable text (no control
    characters or noncharacters, which would make a sheet that is not well-formed XML)."""
    if isinstance(data, dict):
        for key, value in data.items():
            field = f"{where}.{key}" if where else str(key)
            bad = bad_character(str(key))
            if bad:
                raise InputError(Said("e_key_char", bad=bad), file=file,
                                 field=field.encode("unicode_escape").decode("ascii"))
            check_text(value, file=file, where=field)
    elif isinstance(data, list):
        for k, value in enumerate(data):
            check_text(value, file=file, where=f"{where}[{k}]")
    elif isinstance(data, str):
        bad = bad_character(data)
        if bad:
            raise InputError(Said("e_char", bad=bad), file=file, field=where)
        if len(data) > TEXT_LIMIT:
            raise InputError(Said("e_text_long", n=len(data), limit=TEXT_LIMIT), file=file, field=where)


def reduce_deg(x: float) -> float:
    """An angle in degrees reduced exactly to [0, 360) (fmod is exact for floats)."""
    r = math.fmod(x, 360.0)
    return r + 360.0 if r < 0 else r


class Reader:
    """Field access that turns every problem into one InputError line naming file and field."""

    def __init__(self, path: str) -> None:
        self.path = path

    def fail(self, field: str, expected: str | Said) -> InputError:
        return InputError(expected, file=self.path, field=field)

    def keys(self, data: dict[str, Any], known: Iterable[str], where: str) -> None:
        check_keys(data, known, file=self.path, where=where)

    def table(self, data: dict[str, Any], key: str, where: str, required: bool = True) -> dict[str, Any]:
        if key not in data:
            if required:
                raise self.fail(f"{where}{key}", Said("e_missing_table"))
            return {}
        value = data[key]
        if not isinstance(value, dict):
            raise self.fail(f"{where}{key}", Said("e_table"))
        return value

    def value(self, value: Any, field: str, *, positive: bool = False, nonneg: bool = False,
              limit: float = NUMBER_LIMIT, floor: float | None = None) -> float:
        """A plain number: finite, |x| <= limit, and 0 or |x| >= floor (1e-12 by default:
        below it squares vanish, and positive quantities become infinite scales)."""
        floor = NUMBER_FLOOR if floor is None else floor
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise self.fail(field, Said("e_number", got=show(value)))
        if isinstance(value, float) and not math.isfinite(value):
            raise self.fail(field, Said("e_finite", got=repr(value)))
        if abs(value) > limit:
            raise self.fail(field, Said("e_magnitude", limit=limit, got=show(value)))
        if positive and value <= 0:
            raise self.fail(field, Said("e_positive", got=show(value)))
        if nonneg and value < 0:
            raise self.fail(field, Said("e_nonneg", got=show(value)))
        if value != 0 and abs(value) < floor:
            raise self.fail(field, Said("e_between", floor=floor, limit=limit, got=show(value)) if positive
                            else Said("e_floor", floor=floor, got=show(value)))
        return float(value)

    def number(self, data: dict[str, Any], key: str, where: str, *, default: float | None = None,
               positive: bool = False, nonneg: bool = False, limit: float = NUMBER_LIMIT,
               floor: float | None = None) -> float:
        if key not in data:
            if default is None:
                raise self.fail(f"{where}{key}", Said("e_missing_number"))
            return default
        return self.value(data[key], f"{where}{key}", positive=positive, nonneg=nonneg, limit=limit,
                          floor=floor)

    def angle(self, data: dict[str, Any], key: str, where: str, *, default: float = 0.0) -> float:
        """An angle in degrees (any finite size), reduced exactly to [0, 360)."""
        if key not in data:
            return default
        value = data[key]
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise self.fail(f"{where}{key}", Said("e_angle", got=show(value)))
        if isinstance(value, int):
            return float(value % 360)
        if not math.isfinite(value):
            raise self.fail(f"{where}{key}", Said("e_finite_angle", got=repr(value)))
        return reduce_deg(value)

    def integer(self, data: dict[str, Any], key: str, where: str, *, default: int | None = None,
                at_least: int | None = None, at_most: int | None = None) -> int:
        if key not in data:
            if default is None:
                raise self.fail(f"{where}{key}", Said("e_missing_whole"))
            return default
        value = data[key]
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.fail(f"{where}{key}", Said("e_whole", got=show(value)))
        if at_least is not None and value < at_least:
            raise self.fail(f"{where}{key}", Said("e_whole_min", n=at_least, got=show(value)))
        if at_most is not None and value > at_most:
            raise self.fail(f"{where}{key}", Said("e_whole_max", n=at_most, got=show(value)))
        return value

    def text(self, data: dict[str, Any], key: str, where: str, *, default: str | None = None,
             limit: int = TEXT_LIMIT) -> str:
        if key not in data:
            if default is None:
                raise self.fail(f"{where}{key}", Said("e_missing_text"))
            return default
        return self.string(data[key], f"{where}{key}", limit=limit)

    def string(self, value: Any, field: str, *, limit: int = NAME_LIMIT) -> str:
        """A name or a text: a string of printable characters, at most ``limit`` long."""
        if not isinstance(value, str):
            raise self.fail(field, Said("e_string", got=show(value)))
        bad = bad_character(value)
        if bad:
            raise self.fail(field, Said("e_char", bad=bad))
        if len(value) > limit:
            raise self.fail(field, Said("e_chars", limit=limit, n=len(value)))
        return value

    def name(self, value: Any, field: str) -> str:
        """A point or link name: a non-empty string without spaces at its ends."""
        out = self.string(value, field)
        if not out.strip():
            raise self.fail(field, Said("e_name_empty"))
        return out

    def choice(self, data: dict[str, Any], key: str, where: str, choices: Iterable[str],
               default: str | None = None) -> str:
        options = list(choices)
        value = data.get(key, default)
        if not isinstance(value, str) or value not in options:
            hint = did_you_mean(value, options) if isinstance(value, str) else ""
            raise self.fail(f"{where}{key}", Said("e_choice", options=", ".join(repr(o) for o in options),
                                                  got=show(value), hint=hint))
        return value

    def length(self, value: Any, field: str, unit: str, *, positive: bool = False) -> float:
        """A length in metres from a number in the file's unit or a string like ``"35 mm"``;
        finite, at most 10 km, and 0 or at least 1 µm."""
        try:
            out = parse_length(value, unit)
        except ValueError as exc:
            raise self.fail(field, _length_said(str(exc))) from None
        except OverflowError:
            raise self.fail(field, Said("e_length_max", limit=LENGTH_LIMIT, got=show(value))) from None
        if not math.isfinite(out):
            raise self.fail(field, Said("e_length_finite", got=show(value)))
        if abs(out) > LENGTH_LIMIT:
            raise self.fail(field, Said("e_length_max", limit=LENGTH_LIMIT, got=show(value)))
        if positive and out <= 0:
            raise self.fail(field, Said("e_length_positive", got=show(value)))
        if positive and abs(out) < LENGTH_FLOOR:  # a size; a coordinate or offset of dust is kept
            raise self.fail(field, Said("e_length_min", got=show(value)))
        return out


#: parse_length's reasons (plans.units stays free of messages) as catalogue sentences.
_LENGTH_REASONS = {"expected a length (number or string like '35 mm')": "e_length_bool",
                   "expected a finite length": "e_length_inf",
                   "expected a length: a number in the file's unit or a string like '35 mm'": "e_length_of"}


def _length_said(reason: str) -> Said | str:
    import re

    digits = re.fullmatch(r"expected a length of a sensible size, got an integer of (\d+) digits", reason)
    if digits:
        return Said("e_length_digits", n=int(digits.group(1)))
    return Said(_LENGTH_REASONS[reason]) if reason in _LENGTH_REASONS else reason


def show(value: Any) -> Any:
    """A value for a message, shortened (a 400-digit integer is not repeated in full, a
    float is shown with at most 6 significant digits)."""
    if isinstance(value, bool):  # as the file writes it
        return "true" if value else "false"
    if isinstance(value, int) and abs(value) > 10**15:
        return Said("e_digits", n=len(str(abs(value))))
    if isinstance(value, float):
        return f"{value:.6g}"
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."
