"""The workbench page's words: a quantity's key, a table's title and a plan's label as the
page writes them in its language (the textbook's symbols, the notation's acceleration pole)."""

from __future__ import annotations

from plans.language import GREEK, TERMS, quantity_name, symbols


def textbook_symbol(name: str, lang: str, pole: str) -> str:
    """A quantity's or a plan point's key as a page writes it: ω1, ε2 in either language,
    the textbook's Russian letters (p, F_ур, M_Φ2) in Russian, the acceleration pole
    ``pole`` (π or p_a, :func:`plans.scene.notation.resolve`)."""
    if name == "p_a":
        return pole
    if lang == "ru":
        return quantity_name(name, "ru")
    head, _, rest = name.partition("_")
    return GREEK[head] + rest.replace("_", "") if head in ("omega", "eps") and rest else name


def again(text: str, keys: tuple[str, ...], lang: str) -> str:
    """A line written in English from one of the :data:`TERMS` ``keys`` (a title kept in
    English in a JSON), written again in ``lang``: its values as written, with a decimal
    comma in Russian; a line none of them wrote, unchanged."""
    if lang == "en":
        return text
    import re

    field = re.compile(r"\{(\w+)(?::[^{}]*)?\}")
    for key in keys:
        en, ru = TERMS[key]
        parts = field.split(en)  # literal, name, literal, ...
        pattern = "".join(re.escape(p) if i % 2 == 0 else f"(?P<{p}>.+?)" for i, p in enumerate(parts))
        m = re.fullmatch(pattern, text)
        if m is not None:
            values = {k: v.replace(".", ",") if re.fullmatch(r"-?[\d.e+-]+", v) else v for k, v in m.groupdict().items()}
            return field.sub(lambda x, v=values: v[x.group(1)], ru)  # type: ignore[misc]
    return text


def page_label(text: str, lang: str, pole: str) -> str:
    """A label of a drawing (a force polygon's ``Phi2``, ``F_bal``, ``F21^τ``) as a page in
    ``lang`` writes it: the Greek letters in either language, the textbook's Russian
    symbols (F_ур, p) in Russian, the acceleration pole ``pole``."""
    import re

    text = re.sub(r"\bp_a(?![A-Z_])", pole, text)
    if lang == "ru":
        return symbols(text, lang)
    for pattern, greek in ((r"(?<![A-Za-z])Phi(?=\w)", "Φ"), (r"\bomega_?(?=\d)", "ω"), (r"\beps_?(?=\d)", "ε")):
        text = re.sub(pattern, greek, text)
    return text
