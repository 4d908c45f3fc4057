"""The locale a test runs under, for the outputs whose default language is the locale's."""

from __future__ import annotations

import functools
import os
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any


@contextmanager
def locale(value: str) -> Iterator[None]:
    """``LC_ALL`` set to ``value`` inside the block (it outranks ``LC_MESSAGES`` and ``LANG``)."""
    old = os.environ.get("LC_ALL")
    os.environ["LC_ALL"] = value
    try:
        yield
    finally:
        if old is None:
            del os.environ["LC_ALL"]
        else:
            os.environ["LC_ALL"] = old


def in_russian(draw: Callable[..., Any]) -> Callable[..., Any]:
    """``draw`` under a Russian locale: a sheet without ``[sheet] language`` or ``language=`` is
    Russian, as the sheets these tests measure were drawn (the default follows the locale); a
    file's or a call's own language still wins."""

    @functools.wraps(draw)
    def drawn(*args: Any, **kw: Any) -> Any:
        with locale("ru_RU.UTF-8"):
            return draw(*args, **kw)

    return drawn
