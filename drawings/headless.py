"""Headless Chromium through Playwright, where both are installed: ``plans bench`` times the
demonstration page and the workbench in it, and the page tests open their pages in it."""

from __future__ import annotations

import shutil
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

#: The names Chromium is installed under, in the order they are looked for.
BROWSERS = ("chromium", "chromium-browser", "google-chrome")


def executable() -> str | None:
    """The first of ``BROWSERS`` on the PATH."""
    return next((path for path in map(shutil.which, BROWSERS) if path), None)


@contextmanager
def chromium() -> Iterator[Any]:
    """A launched headless Chromium (Playwright's ``Browser``), closed on leaving; None where
    Chromium or Playwright is missing."""
    exe = executable()
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        exe = None
    if exe is None:
        yield None
        return
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=exe, args=["--no-sandbox"])
        try:
            yield browser
        finally:
            browser.close()
