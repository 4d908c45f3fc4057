"""Numbers of teeth of a 2K-H planetary train (sun 1, planets 2, ring 3 held, carrier H).

For a ratio i_1H = 1 + z3/z1 the course's conditions, all unshifted gears:

- coaxiality: z1 + 2 z2 = z3;
- assembly: (z1 + z3)/k a whole number (k planets, equally spaced);
- neighbourhood: the planets' tip circles do not touch, sin(π/k) > (z2 + 2h_a*)/(z1 + z2);
- every wheel with at least z_min teeth.

Among the sets within the tolerance the smallest train (least z3) is chosen, then the
nearest ratio, then the most planets.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from plans.errors import InputError, Said

from .model import SynthesisSpec


@dataclass(frozen=True)
class TeethSet:
    z1: int
    z2: int
    z3: int
    planets: int
    ratio: float  # i_1H achieved

    def conditions(self, ha: float) -> dict[str, bool]:
        k = self.planets
        return {
            "coaxiality": self.z1 + 2 * self.z2 == self.z3,
            "assembly": (self.z1 + self.z3) % k == 0,
            "neighbourhood": math.sin(math.pi / k) > (self.z2 + 2.0 * ha) / (self.z1 + self.z2),
        }


def candidates(spec: SynthesisSpec, ha: float, z3_max: int = 400) -> list[TeethSet]:
    """Every admissible set up to ``z3_max`` teeth on the ring."""
    out = []
    for z1 in range(spec.z_min, z3_max):
        # z3/z1 = i − 1 within the tolerance: z3 in a small window
        lo = math.ceil(z1 * (spec.ratio * (1 - spec.tolerance) - 1))
        hi = math.floor(z1 * (spec.ratio * (1 + spec.tolerance) - 1))
        for z3 in range(max(lo, z1 + 2 * spec.z_min), min(hi, z3_max) + 1):
            if (z3 - z1) % 2:
                continue
            z2 = (z3 - z1) // 2
            if z2 < spec.z_min:
                continue
            for k in spec.planets:
                t = TeethSet(z1, z2, z3, k, 1.0 + z3 / z1)
                if all(t.conditions(ha).values()):
                    out.append(t)
    return out


def synthesise(spec: SynthesisSpec, ha: float, file: str | None = None) -> TeethSet:
    found = candidates(spec, ha)
    if not found:
        raise InputError(Said("gy_train_up_ring", ratio=spec.ratio, tolerance=spec.tolerance, v=list(spec.planets)), file=file, field="synthesis")
    return min(found, key=lambda t: (t.z3, abs(t.ratio - spec.ratio), -t.planets))
