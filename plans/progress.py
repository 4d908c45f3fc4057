"""Progress of long runs on a terminal: one line per step on stderr with the time so far.

Quiet when stderr is not a terminal (piped, redirected, under a test) or when asked
(``--quiet``): the output a script reads never changes.
"""

from __future__ import annotations

import sys
import time
from typing import TextIO


class Progress:
    def __init__(self, quiet: bool = False, stream: TextIO | None = None) -> None:
        self.stream = sys.stderr if stream is None else stream
        isatty = getattr(self.stream, "isatty", None)
        self.on = not quiet and bool(isatty and isatty())
        self.t0 = time.perf_counter()

    def __call__(self, message: str) -> None:
        if self.on:
            print(f"[{time.perf_counter() - self.t0:6.1f} s] {message}", file=self.stream, flush=True)
