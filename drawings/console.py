"""The ``plans`` console script.  The command's modules are imported inside :func:`main`,
so Ctrl-C while they are still loading stops as quietly (status 130) as Ctrl-C during the
work itself; only the interpreter's own start-up, before any of our code runs, is outside
our reach."""

from __future__ import annotations


def main() -> int:
    try:
        from drawings.cli import main as run
    except KeyboardInterrupt:
        return 130
    return run()
