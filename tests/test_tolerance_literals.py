"""No bare tolerance literal in the engine or the drawings: a number like 1e-9 or 1e-12 written
in plans/ or drawings/ outside plans/tolerances.py is either one of the reviewed ones in
tests/tolerance_literals.txt (with why it is not a shared tolerance) or a new one, which fails
here.  The drawings' own slack on paper is ``drawings.paper.panel_frame.SLACK_MM``."""

from __future__ import annotations

import io
import re
import tokenize
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ALLOWED = Path(__file__).with_name("tolerance_literals.txt")
#: A literal written with a negative exponent: how the code writes a tolerance.
SMALL = re.compile(r"^[0-9_.]*[eE]-[0-9]+$")


def small_literals(source: str) -> list[str]:
    """The negative-exponent number literals of a module's code (not its comments or strings)."""
    return [t.string for t in tokenize.generate_tokens(io.StringIO(source).readline)
            if t.type == tokenize.NUMBER and SMALL.match(t.string)]


def found() -> Counter[tuple[str, str]]:
    got: Counter[tuple[str, str]] = Counter()
    for path in sorted([*(ROOT / "plans").rglob("*.py"), *(ROOT / "drawings").rglob("*.py")]):
        rel = path.relative_to(ROOT).as_posix()
        if rel == "plans/tolerances.py":
            continue
        for lit in small_literals(path.read_text(encoding="utf-8")):
            got[(rel, lit)] += 1
    return got


def allowed() -> tuple[Counter[tuple[str, str]], dict[tuple[str, str], str]]:
    counts: Counter[tuple[str, str]] = Counter()
    why: dict[tuple[str, str], str] = {}
    for line in ALLOWED.read_text(encoding="utf-8").splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        path, lit, n, reason = (part.strip() for part in line.split("|", 3))
        counts[(path, lit)] += int(n)
        why[(path, lit)] = reason
    return counts, why


def test_the_scan_finds_literals_in_code_only():
    src = "x = 1e-9 * y  # 1e-12 in a comment\ns = '1e-6'\nz = 2.5e-3 + 1e3 + 0.001\n"
    assert small_literals(src) == ["1e-9", "2.5e-3"]


def test_no_new_bare_tolerance_literal_in_plans():
    got = found()
    counts, _ = allowed()
    new = sorted(f"{p}: {lit} ×{n - counts[(p, lit)]}" for (p, lit), n in got.items() if n > counts[(p, lit)])
    assert not new, ("a tolerance literal not reviewed: name it in plans/tolerances.py (with why that "
                     "value) or use a name there; if it is not a tolerance (a unit, a floor, a number "
                     "format), list it in tests/tolerance_literals.txt with why: " + "; ".join(new))


def test_the_allow_list_is_current_and_says_why():
    got = found()
    counts, why = allowed()
    stale = sorted(f"{p}: {lit}" for (p, lit), n in counts.items() if got[(p, lit)] < n)
    assert not stale, "listed in tests/tolerance_literals.txt but no longer in the code: " + "; ".join(stale)
    assert all(len(reason) > 10 for reason in why.values())


def test_every_named_tolerance_says_why():
    """Each name in plans/tolerances.py has a ``#:`` comment right above it."""
    lines = (ROOT / "plans" / "tolerances.py").read_text(encoding="utf-8").splitlines()
    names = [i for i, line in enumerate(lines) if re.match(r"^[A-Z][A-Z_0-9]* = ", line)]
    assert names
    for i in names:
        assert lines[i - 1].startswith("#:"), lines[i]
