"""The fit of each part of a sheet raised in turn (drawings.linkage.mixing)."""

from __future__ import annotations

from types import SimpleNamespace

from drawings.linkage.mixing import OWN, ascend, by_phi, swapped
from drawings.paper.sheet import TooBig


def _never(_s) -> bool:
    return False


def test_each_part_rises_to_the_last_fit_that_keeps_the_sheets():
    cap = (2, OWN, 3)  # the longest fit each part's panels still fit the sheets at
    tried = []

    def lay(choice):
        tried.append(choice)
        return choice

    def more(a, b):
        return any(x > m for x, m in zip(b, cap, strict=True))

    def better(a, b):
        return sum(b) > sum(a)

    choice, got = ascend((OWN,) * 3, 4, lay, better, _never, more)
    assert choice == got == cap
    # a part stops at the first fit that overflows: the second part tried once, at fit 0
    assert [c for c in tried if c[0] == 2 and c[2] == OWN] == [(2, OWN, OWN), (2, 0, OWN)]


def test_a_part_refused_as_too_big_keeps_its_fit_and_a_full_layout_stops_the_ascent():
    def lay(choice):
        if choice[0] >= 1:
            raise TooBig("too long")
        return choice

    def better(a, b):
        return sum(b) > sum(a)

    assert ascend((OWN, OWN), 3, lay, better, _never, lambda a, b: False)[0] == (0, 2)
    # full as soon as the second part leaves its own fit: not raised further
    assert ascend((OWN, OWN), 3, lay, better, lambda s: s[1] >= 0, lambda a, b: False)[0] == (0, 0)


def test_a_worse_fit_is_not_taken_but_a_longer_one_still_tried():
    fills = {OWN: 0.5, 0: 0.4, 1: 0.7}

    def lay(choice):
        return fills[choice[0]]

    choice, got = ascend((OWN,), 2, lay, lambda a, b: b > a, _never, lambda a, b: False)
    assert (choice, got) == ((1,), 0.7)


def test_swapped_takes_each_parts_panels_from_its_own_solution():
    def panel(pid, phi):
        return SimpleNamespace(pid=pid, phi=phi, src="own")

    own = [panel("scheme-0", 0.0), panel("lever-0", 0.0), panel("lever-30", 30.0), panel("legend", None)]
    other = {k: {p.pid: SimpleNamespace(pid=p.pid, phi=p.phi, src=k) for p in own} for k in ("a", "b")}
    got = swapped(own, [by_phi(0.0), by_phi(30.0)], ["a", "b"], other.__getitem__)
    assert [(p.pid, p.src) for p in got] == [("scheme-0", "a"), ("lever-0", "a"), ("lever-30", "b"),
                                             ("legend", "own")]
