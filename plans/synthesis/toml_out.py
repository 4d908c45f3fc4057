"""A table written as TOML text that reads back to the same table (``tomllib``): tables
near the top as sections, deeper ones inline, keys in the order given."""

from __future__ import annotations

import json
import math
import re
from typing import Any

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def key(k: str) -> str:
    return k if _BARE.match(k) else json.dumps(k, ensure_ascii=False)


def value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if not math.isfinite(v):
            raise ValueError(f"a non-finite number {v!r} cannot be written")
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, list):
        return "[" + ", ".join(value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{key(k)} = {value(x)}" for k, x in v.items()) + " }" if v else "{}"
    raise ValueError(f"cannot write {type(v).__name__} as TOML")


def _is_table_array(v: Any) -> bool:
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)


def dumps(data: dict[str, Any], depth: int = 2) -> str:
    """``data`` as TOML; tables down to ``depth`` levels become sections."""
    out: list[str] = []
    _section(out, data, [], depth)
    return "\n".join(out).strip() + "\n"


def _section(out: list[str], table: dict[str, Any], path: list[str], depth: int) -> None:
    subs = []
    for k, v in table.items():
        if len(path) < depth and (isinstance(v, dict) or _is_table_array(v)):
            subs.append((k, v))
        else:
            out.append(f"{key(k)} = {value(v)}")
    for k, v in subs:
        name = ".".join(key(p) for p in [*path, k])
        if isinstance(v, dict):
            plain = any(not (len(path) + 1 < depth and (isinstance(x, dict) or _is_table_array(x)))
                        for x in v.values())
            if plain or not v:  # a table of tables alone needs no header of its own
                out.append("")
                out.append(f"[{name}]")
            _section(out, v, [*path, k], depth)
        else:
            for item in v:
                out.append("")
                out.append(f"[[{name}]]")
                for kk, vv in item.items():
                    out.append(f"{key(kk)} = {value(vv)}")
