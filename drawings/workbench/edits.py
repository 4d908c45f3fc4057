"""The form's edits of a TOML text, made with tomlkit: the comments, the order and the layout
of everything else stay as the file had them.

An edit is a list of operations, applied in this order:

- ``set``: ``[key path, value]``, the key path existing up to its last key (a figure of the
  form: a length, a position, a sense);
- ``put``: ``[key path, value]``, the tables on the way made as needed (a new link
  ``["links", "5"]`` as a table, a fixed pivot ``["points", "C"]``, a group's branch);
- ``append``: ``[key path, table]``, a table added to the array of tables there (made as
  needed): a joint ``["joints"]``, a load ``["loads", "force"]``;
- ``delete``: a key path, the key or the array's element removed (an array of tables left
  empty goes too).

A key path is a list of keys, an array's element named by its index.
"""

from __future__ import annotations

import threading
from typing import Any

from plans.errors import Said


class EditError(Exception):
    """An edit that cannot be made: a status, one line, and the key path it names."""

    def __init__(self, status: int, message: str | Said, field: str | None = None) -> None:
        super().__init__(str(message))
        self.status, self.message, self.field = status, message, field


#: tomlkit documents by the text they print: the next edit of a page starts from the text the
#: last one answered, and parsing it again would be most of the edit's time.
_DOCS: dict[str, Any] = {}
_DOCS_LOCK = threading.Lock()
_OPS = ("set", "put", "append", "delete")


def _name(keys: list) -> str:
    return ".".join(map(str, keys))


def _document(text: str) -> Any:
    import tomlkit

    with _DOCS_LOCK:
        doc = _DOCS.pop(text, None)  # the text the last edit answered: its document, parsed
    if doc is None:
        try:
            doc = tomlkit.parse(text)
        except Exception as exc:  # tomlkit's parse errors have no common public base
            raise EditError(422, Said("we_toml", v=' '.join(str(exc).split()))) from None
    return doc


def _keep(text: str, doc: Any) -> None:
    with _DOCS_LOCK:
        _DOCS[text] = doc
        while len(_DOCS) > 16:  # a few tabs' documents; the oldest goes first
            _DOCS.pop(next(iter(_DOCS)))


def _check_value(value: Any, keys: list, tables: bool) -> Any:
    ok = (str, int, float, bool, list, dict) if tables else (str, int, float, bool, list)
    if not isinstance(value, ok):
        what = Said("we_value_tables") if tables else Said("we_value")
        raise EditError(400, Said("we_what", v=_name(keys), what=what))
    if isinstance(value, float) and value.is_integer():
        return int(value)  # 120, not 120.0, as a person writes it
    return value


def _item(value: Any, top: bool = False) -> Any:
    """A JSON value as tomlkit writes it: a table at the top of a new section (its nested
    tables inline, ``guide = { link = 4, ... }`` as the samples write it)."""
    import tomlkit

    if isinstance(value, float) and value.is_integer():
        return int(value)
    if isinstance(value, dict):
        t = tomlkit.table() if top else tomlkit.inline_table()
        for k, v in value.items():
            t.append(str(k), _item(v))
        return t
    if isinstance(value, list):
        return [_item(v) for v in value]
    return value


def _walk(doc: Any, keys: list, make: bool) -> Any:
    """The container the key path's last key is in (tables made on the way when ``make``)."""
    import tomlkit

    node: Any = doc
    for k in keys[:-1]:
        try:
            if isinstance(node, dict):
                if str(k) not in node:
                    if not make:
                        raise KeyError(k)
                    node[str(k)] = tomlkit.table(is_super_table=True)
                node = node[str(k)]
            else:
                node = node[int(k)]
        except (KeyError, IndexError, ValueError, TypeError):
            raise EditError(422, Said("we_such_key_file", v=_name(keys)), _name(keys)) from None
    return node


def _set(doc: Any, keys: list, value: Any, make: bool) -> None:
    node = _walk(doc, keys, make)
    last = keys[-1]
    try:
        if isinstance(node, dict):
            old = node.get(str(last))
            if isinstance(old, list) and isinstance(value, list) and len(old) == len(value) \
                    and not any(isinstance(v, dict) for v in value):
                for i, v in enumerate(value):  # in place: an inline array keeps its layout
                    old[i] = v
            else:
                # a new section ([links.5], [driver]); a table deeper in is written inline
                top = isinstance(value, dict) and not _is_inline(node) and len(keys) <= 2
                new = _item(value, top)
                if str(last) in node:
                    node[str(last)] = new
                else:
                    if top:
                        _blank_after(_last_table(node.values()), new)
                    container: Any = node  # a tomlkit table: it appends after its last key
                    container.append(str(last), new)
        else:
            node[int(last)] = _item(value)
    except (IndexError, ValueError, TypeError):
        raise EditError(422, Said("we_such_key_file", v=_name(keys)), _name(keys)) from None


def _is_inline(node: Any) -> bool:
    import tomlkit.items

    return isinstance(node, tomlkit.items.InlineTable)


def _append(doc: Any, keys: list, value: Any) -> None:
    import tomlkit

    if not isinstance(value, dict):
        raise EditError(400, Said("we_table_add", v=_name(keys)))
    node = _walk(doc, keys, True)
    last = str(keys[-1])
    if not isinstance(node, dict):
        raise EditError(422, Said("we_such_key_file", v=_name(keys)), _name(keys))
    if last not in node:
        table: Any = node
        table.append(last, tomlkit.aot())
    arr = node[last]
    if not isinstance(arr, list):
        raise EditError(422, Said("we_list_tables_file", v=_name(keys)), _name(keys))
    new = _item(value, top=isinstance(arr, tomlkit.items.AoT))
    if len(arr) and isinstance(new, tomlkit.items.Table):
        _blank_after(arr[-1], new)
    arr.append(new)


def _last_table(values: Any) -> Any:
    tables = [v for v in values if hasattr(v, "value") and hasattr(v.value, "body")]
    return tables[-1] if tables else None


def _blank_after(prev: Any, new: Any) -> None:
    """The new section set apart as the one before it: the blank line that closes that one
    closes the new one too (it stood before the next section), or one comes before it."""
    import tomlkit.items

    body = getattr(getattr(prev, "value", None), "body", None)
    if body and body[-1][0] is None and isinstance(body[-1][1], tomlkit.items.Whitespace):
        new.value.body.append((None, tomlkit.items.Whitespace(body[-1][1].s)))
    elif body:
        new.trivia.indent = "\n"  # a blank line before it, none being after the one before


def _delete(doc: Any, keys: list) -> None:
    import tomlkit.items

    node = _walk(doc, keys, False)
    last = keys[-1]
    try:
        if isinstance(node, dict):
            del node[str(last)]
        else:
            del node[int(last)]
    except (KeyError, IndexError, ValueError, TypeError):
        raise EditError(422, Said("we_such_key_file", v=_name(keys)), _name(keys)) from None
    if isinstance(node, tomlkit.items.AoT | list) and len(node) == 0 and len(keys) >= 2:
        _delete(doc, keys[:-1])  # an array left empty: its key goes too ([[loads.force]])


def edit(text: str, ops: dict[str, list]) -> str:
    """The TOML ``text`` with the operations (``{"set": [...], "put": [...], "append": [...],
    "delete": [...]}``) made; every other line as it was."""
    import tomlkit

    for op in _OPS:
        if not isinstance(ops.get(op, []), list):
            raise EditError(400, Said("we_op_list", op=op))
    doc = _document(text)
    for op in _OPS:
        for item in ops.get(op) or []:
            if op == "delete":
                keys = item
                if not (isinstance(keys, list) and keys and all(isinstance(k, str | int) for k in keys)):
                    raise EditError(400, Said("we_each_deletion_key"))
                _delete(doc, keys)
                continue
            if not (isinstance(item, list) and len(item) == 2 and isinstance(item[0], list) and item[0]
                    and all(isinstance(k, str | int) and not isinstance(k, bool) for k in item[0])):
                raise EditError(400, Said("we_each_op_key", op=op))
            keys, value = item
            value = _check_value(value, keys, op != "set")
            if op == "append":
                _append(doc, keys, value)
            else:
                _set(doc, keys, value, make=op == "put")
    new = tomlkit.dumps(doc)
    _keep(new, doc)
    return new
