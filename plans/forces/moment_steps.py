"""A moment equation as the draftsman writes it: each known force's moment about the point,
with its arm on the scheme (mm at μl) and in metres, each couple, their sum, and what the
equation gives; the arms kept to be drawn."""

from __future__ import annotations

from plans.kinematics.plan import Step
from plans.lines import cross
from plans.phrases import Phrase, phrase
from plans.records import frozen
from plans.tolerances import EXACT_ZERO_REL


@frozen
class Arm:
    """A known force's arm in a moment equation, on the scheme (m): the perpendicular from the
    point the moments are taken about (``about``) to the force's line, met at ``foot``; the
    force acts at ``at``."""

    label: str
    about: complex
    foot: complex
    at: complex


def moment_terms(forces, moments, P: complex, k: int, mu_l: float) -> tuple[list[Phrase], float, list[Arm]]:
    """Signed moments of known forces (arms in mm on the scheme and in m) and couples about
    P, and each force's arm where it has one."""
    terms, total, arms = [], 0.0, []
    for f in forces:
        F = complex(f.F[k])
        if abs(F) == 0:
            continue
        r = complex(f.r[k])
        m = cross(r - P, F)
        h = abs(m) / abs(F)
        if h <= EXACT_ZERO_REL * max(abs(r - P), 1e-300):  # passes through P up to round-off
            m, h = 0.0, 0.0
        else:
            d = F / abs(F)
            arms.append(Arm(f.label, P, r + d * ((P - r) * d.conjugate()).real, r))
        terms.append(phrase("m_term_force", sign="+" if m >= 0 else "−", label=f.label, F=abs(F), mm=h * mu_l, h=h,
                            M=abs(F) * h))
        total += m
    for mo in moments:
        M = float(mo.M[k])
        if M == 0:
            continue
        terms.append(phrase("m_term_couple", sign="+" if M >= 0 else "−", label=mo.label, M=abs(M)))
        total += M
    return terms, total, arms


def moment_equation(op: str, inputs: tuple[str, ...], output: str, name: str,
              known: tuple[list[Phrase], float, list[Arm]], unknown: Phrase) -> tuple[Step, tuple[Arm, ...]]:
    """The step of one moment equation (the known moments and what they give), with the
    known forces' arms."""
    terms, total, arms = known
    return Step.of(op, inputs, output, phrase("m_equation", name=name, known=terms or phrase("m_zero"),
                                              total=total, unknown=unknown)), tuple(arms)
