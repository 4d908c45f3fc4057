"""What the fuzz feeds the commands: a file's table mutated as a hostile user would (hostile
numbers, wrong types, misspelt and unknown keys, control characters and markup in names),
damaged bytes (not UTF-8, truncated TOML), and the table written back as TOML."""

from __future__ import annotations

import json
import math
import random
import re
from typing import Any

# --------------------------------------------------------------------------- TOML out


def _key(k: str) -> str:
    return k if re.fullmatch(r"[A-Za-z0-9_-]+", k) else _string(k)


def _string(s: str) -> str:
    out = ['"']
    for ch in s:
        o = ord(ch)
        if ch == '"':
            out.append('\\"')
        elif ch == "\\":
            out.append("\\\\")
        elif o < 0x20 or o == 0x7F:
            out.append(f"\\u{o:04X}")
        elif 0xD800 <= o <= 0xDFFF:
            out.append("?")
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def _value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(str(k))} = {_value(x)}" for k, x in v.items()) + "}"
    return _string(str(v))


def to_toml(data: dict[str, Any]) -> str:
    """A table as TOML text (every sub-table inline: enough to carry any mutation)."""
    return "".join(f"{_key(str(k))} = {_value(v)}\n" for k, v in data.items())


# --------------------------------------------------------------------------- mutations

HOSTILE_NUMBERS: tuple[Any, ...] = (
    0, -1, 1, 2, 3, 7, -0.0, 0.5, 1e-300, 5e-324, 1e-154, 1e-12, 1e-7, 1e300, -1e300, 1e308, 1.7e308,
    10**400, -(10**400), 2**63, 2**64 + 1, 1.234567e21, -1.234567e21, 1e400, float("nan"), 1e16, 360, 720,
    90, 180, 270, 1e6, 1e7, 3601, 10_000_000, 123456789012, 0.1, 1e-9)
HOSTILE_STRINGS: tuple[str, ...] = (
    "", " ", "A", "B", "S2", "O", "<script>alert(1)</script>", "a & b < c > d \" '", "]]>", "\x01", "\x7f",
    "\ufffe", "\uffff", "\ufdd0", "\u202e", "x" * 300, "title\nsecond line", "\t", "1e400 mm", "35 mm",
    "0.035 m", "-5 mm", "10 furlongs", "1e300 m", "mm", "ccw", "cw", "force", "moment", "linkage", "engine",
    "gears", "cam", "R", "P", "A1", "A9", "draftsman", "lever", "MPa", "down", "up", "π", "ω2", "\U0001F600",
    '<image href="file:///etc/passwd"/>', "&amp;", "../../etc/passwd", "/dev/zero")


def _hostile(rng: random.Random, old: Any) -> Any:
    pick = rng.random()
    if isinstance(old, int | float) and not isinstance(old, bool) and pick < 0.35:
        factor = rng.choice((1e-300, 1e-12, -1, 0, 1e12, 1e300, 10, 0.1, 1.0000001))
        try:
            out = old * factor
        except OverflowError:
            out = 1e308
        return int(out) if isinstance(old, int) and isinstance(out, float) and math.isfinite(out) else out
    if pick < 0.6:
        return rng.choice(HOSTILE_NUMBERS)
    if pick < 0.8:
        return rng.choice(HOSTILE_STRINGS)
    return rng.choice((True, False, [], {}, [1], ["A"], [[1, 2]], {"x": 1}, [1, 2, 3], [0, 0], ["A", "A"],
                       [1e300, 1e300], {"mu": 0}, {"K": 1e-300}, [-1, 1]))


def _number(rng: random.Random, old: float) -> float:
    """Another number for a numeric field: near the engine's limits, near zero, scaled."""
    pick = rng.random()
    if pick < 0.4:
        factor = rng.choice((1e-6, 1e-3, 0.01, 0.5, 0.999999, 1.000001, 2, 10, 100, 1e3, 1e6, -1, 0))
        try:
            out = old * factor
        except OverflowError:
            return 1e308
        return int(out) if isinstance(old, int) and abs(out) < 1e15 and out == int(out) else out
    if pick < 0.7:
        return rng.choice((0, 1, -1, 1e-6, 1.0000001e-6, 9.99e-7, 1e4, 1e7, 1e12, 1e-12, 9.9e11, 1.01e-12, 0.5e-3,
                           1e6, 1e5, 360, 3601, 1.234567e21, 89.99999999, 90.0000001, 180, 359.9999999, 1e-9))
    return rng.choice(HOSTILE_NUMBERS)


def _typo(rng: random.Random, key: str) -> str:
    if not key:
        return "x"
    i = rng.randrange(len(key))
    how = rng.randrange(4)
    if how == 0:
        return key[:i] + key[i + 1:] or key + "_"
    if how == 1 and len(key) > 1:
        j = min(i + 1, len(key) - 1)
        chars = list(key)
        chars[i], chars[j] = chars[j], chars[i]
        return "".join(chars) if "".join(chars) != key else key + "s"
    if how == 2:
        return key + rng.choice(("s", "_", "0", "x"))
    return key.upper() if key.upper() != key else key.lower() + "_"


def _paths(node: Any, prefix: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    out = [prefix]
    if isinstance(node, dict):
        for k, v in node.items():
            out += _paths(v, prefix + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            out += _paths(v, prefix + (i,))
    return out


def _get(node: Any, path: tuple[Any, ...]) -> Any:
    for p in path:
        node = node[p]
    return node


def mutate(data: dict[str, Any], rng: random.Random, n: int | None = None) -> dict[str, Any]:
    """A copy of ``data`` with 1..3 hostile edits (values, types, keys, whole tables)."""
    out = json.loads(json.dumps(data))
    for _ in range(n if n is not None else rng.choice((1, 1, 1, 2, 3))):
        paths = [p for p in _paths(out) if p]
        if not paths:
            break
        numeric = [p for p in paths if isinstance(_get(out, p), int | float) and not isinstance(_get(out, p), bool)]
        if numeric and rng.random() < 0.5:  # a number that may pass the reader: the deep paths
            path = rng.choice(numeric)
            parent = _get(out, path[:-1])
            old = parent[path[-1]]
            parent[path[-1]] = _number(rng, old)
            continue
        path = rng.choice(paths)
        parent = _get(out, path[:-1])
        last = path[-1]
        action = rng.randrange(10)
        if action <= 4:
            parent[last] = _hostile(rng, parent[last])
        elif action == 5 and isinstance(parent, dict):
            del parent[last]
        elif action == 6 and isinstance(parent, dict):
            parent[_typo(rng, str(last))] = parent.pop(last)
        elif action == 7 and isinstance(parent, dict):
            parent[rng.choice(("foo", "output", "omega_rmp", "kind", "omega", "omega_rpm", "positions", "phi_deg",
                               "01", "1", "centre", "name", "title", "links", "x y"))] = _hostile(rng, None)
        elif action == 8 and isinstance(parent, list):
            parent.append(json.loads(json.dumps(parent[last])))
        elif action == 8:
            parent[last] = [parent[last]]
        else:
            node = parent[last]
            if isinstance(node, int | float) and not isinstance(node, bool):
                parent[last] = _hostile(rng, node)
            elif isinstance(node, dict) and node:
                node.pop(rng.choice(list(node)))
            elif isinstance(node, list) and node:
                node.pop(rng.randrange(len(node)))
            else:
                parent[last] = _hostile(rng, node)
    return out


def mutate_bytes(text: str, rng: random.Random) -> bytes:
    """Damage at the byte level: not UTF-8, truncated, a stray character."""
    raw = text.encode("utf-8")
    how = rng.randrange(5)
    if how == 4:  # tables nested deeper than any reader walks
        return raw + b"\n[" + b".".join([b"a"] * rng.choice((33, 200, 20000))) + b"]\n"
    i = rng.randrange(len(raw) + 1)
    if how == 0:
        return raw[:i] + rng.choice((b"\xff", b"\xc3", b"\xed\xa0\x80", b"\x00")) + raw[i:]
    if how == 1:
        return raw[:i]
    if how == 2:
        return raw[:i] + rng.choice((b"[", b"]", b"=", b'"', b"\n[links.1]\n", b"\n[[joints]]\n")) + raw[i:]
    return "\ufeff".encode() + raw


