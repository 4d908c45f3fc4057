"""The note as a Word document (python-docx, loaded only here): A4, the GOST 7.32 layout
(margins 30/15/20/20 mm, Times New Roman 14 pt at 1.5 lines, 1.25 cm indent, numbered
sections, "Рисунок N – …" under a figure, "Таблица N – …" over a table, a contents field,
page numbers from the second page), the title page, native Office Math equations, figures
and Word tables.  The same note gives the same bytes: fixed core properties and zip
entries' dates."""

from __future__ import annotations

import io
import re
import zipfile
from collections.abc import Callable, Iterator
from datetime import UTC, datetime
from typing import Any
from xml.sax.saxutils import escape

from plans.note.model import Equation, Figure, Note, Para, Section, Table

from .omml import omath, omath_para

#: The fixed date of every document (core properties and zip entries).
FIXED = datetime(2000, 1, 1, tzinfo=UTC)
_REF = re.compile(r"\{(fig|tab):([^}]+)\}")
TEXT_WIDTH_MM = 165.0  # A4 less the 30 and 15 mm margins


def _words(lang: str) -> tuple[str, str]:
    return ("Рисунок", "Таблица") if lang == "ru" else ("Figure", "Table")


def _walk(sections: list[Section], prefix: str = "") -> Iterator[tuple[str, Section]]:
    for n, s in enumerate(sections, 1):
        number = f"{prefix}{n}"
        yield number, s
        yield from _walk(s.children, number + ".")


def numbers(note: Note) -> dict[str, int]:
    """Figures and tables numbered in the order they appear ("fig:KEY" / "tab:KEY" -> N)."""
    out: dict[str, int] = {}
    nf = nt = 0
    for _, s in _walk(note.sections):
        for b in s.blocks:
            if isinstance(b, Figure):
                nf += 1
                out[f"fig:{b.key}"] = nf
            elif isinstance(b, Table):
                nt += 1
                out[f"tab:{b.key}"] = nt
    return out


def write_docx(note: Note, figure: Callable[[Figure], tuple[bytes, float]]) -> bytes:
    """The document's bytes; ``figure(f)`` gives a figure's PNG and its width in mm."""
    import docx
    from docx.enum.section import WD_SECTION  # noqa: F401  (python-docx's enums load with it)
    from docx.enum.table import WD_TABLE_ALIGNMENT
    from docx.enum.text import WD_ALIGN_PARAGRAPH, WD_BREAK
    from docx.oxml import parse_xml
    from docx.oxml.ns import qn
    from docx.shared import Mm, Pt

    doc = docx.Document()
    nums = numbers(note)
    fig_word, tab_word = _words(note.lang)
    _page(doc, Mm)
    _styles(doc, Pt, Mm, qn, note.lang == "ru")

    def ref(text: str) -> str:
        def one(m: re.Match) -> str:
            key = f"{m.group(1)}:{m.group(2)}"
            if key not in nums:
                raise KeyError(f"the note refers to {key}, which it does not hold")
            return str(nums[key])
        return _REF.sub(one, text)

    def plain_para(text: str, align=None, bold: bool = False, indent: bool = True, size: float | None = None,
                   style: str | None = None):
        p = doc.add_paragraph(style=style)
        if text:
            r = p.add_run(text)
            r.bold = bold or None
            if size:
                r.font.size = Pt(size)
        if align is not None:
            p.alignment = align
        if not indent:
            p.paragraph_format.first_line_indent = Mm(0)
        return p

    # ---- the title page
    tp = note.title
    C = WD_ALIGN_PARAGRAPH.CENTER
    for line in (tp.organization, tp.department):
        if line:
            plain_para(line, C, indent=False)
    for _ in range(6):
        plain_para("", indent=False)
    plain_para(tp.kind, C, bold=True, indent=False, size=16)
    plain_para(tp.subtitle, C, indent=False)
    plain_para(tp.title, C, bold=True, indent=False)
    if tp.designation:
        plain_para(tp.designation, C, indent=False)
    for _ in range(6):
        plain_para("", indent=False)
    ru = note.lang == "ru"
    for label, value in ((("Выполнил" if ru else "Done by"), tp.author), (("Группа" if ru else "Group"), tp.group),
                         (("Проверил" if ru else "Checked by"), tp.checked_by)):
        if value:
            plain_para(f"{label}: {value}", WD_ALIGN_PARAGRAPH.RIGHT, indent=False)
    if tp.date:
        plain_para(tp.date, C, indent=False)
    doc.paragraphs[-1].add_run().add_break(WD_BREAK.PAGE)

    # ---- the contents: a TOC field Word updates, its entries written in already
    plain_para(note.contents, C, bold=True, indent=False)
    entries = [(num, s.title, s.level if s.level else num.count(".") + 1) for num, s in _walk(note.sections)]
    _toc(doc, entries, parse_xml, Mm)
    doc.paragraphs[-1].add_run().add_break(WD_BREAK.PAGE)

    # ---- the sections
    pictures = [0]  # the drawings' ids (python-docx's own search of the document costs a scan per picture)
    first = True
    for number, s in _walk(note.sections):
        level = number.count(".") + 1
        h = doc.add_paragraph(f"{number} {s.title}", style=f"Heading {min(level, 3)}")
        if level == 1 and not first:
            h.paragraph_format.page_break_before = True
        first = False
        for b in s.blocks:
            if isinstance(b, Para):
                p = doc.add_paragraph()
                for part in b.parts:
                    if isinstance(part, str):
                        p.add_run(ref(part))
                    else:
                        p._p.append(parse_xml(omath(part)))
            elif isinstance(b, Equation):
                p = doc.add_paragraph()
                p.paragraph_format.first_line_indent = Mm(0)
                p.alignment = C
                p._p.append(parse_xml(omath_para(b.formula)))
            elif isinstance(b, Figure):
                png, width = figure(b)
                p = doc.add_paragraph()
                p.alignment = C
                p.paragraph_format.first_line_indent = Mm(0)
                p.paragraph_format.keep_with_next = True
                p.add_run()._r.add_drawing(_inline(doc, png, Mm(min(width, TEXT_WIDTH_MM)), pictures))
                plain_para(f"{fig_word} {nums['fig:' + b.key]} – {b.caption}", C, indent=False)
            elif isinstance(b, Table):
                cap = plain_para(f"{tab_word} {nums['tab:' + b.key]} – {b.caption}", WD_ALIGN_PARAGRAPH.LEFT,
                                 indent=False)
                cap.paragraph_format.keep_with_next = True
                _table(doc, b, Pt, Mm, qn, WD_TABLE_ALIGNMENT, C)
    _fix_core(doc, note)
    return package_bytes(doc)


def _inline(doc: Any, png: bytes, width: Any, counter: list[int]) -> Any:
    """A picture's ``wp:inline`` (as ``Run.add_picture`` makes it, with its own ids)."""
    from docx.oxml.shape import CT_Inline

    rId, image = doc.part.get_or_add_image(io.BytesIO(png))
    cx, cy = image.scaled_dimensions(width, None)
    counter[0] += 1
    return CT_Inline.new_pic_inline(1000 + counter[0], rId, image.filename, cx, cy)


def package_bytes(doc: Any) -> bytes:
    """The document's package written as python-docx writes it (content types, the
    package's relationships, every part and its relationships, in that order), every
    entry dated 1980-01-01, the pictures stored as they are (PNG is compressed already)."""
    from docx.opc.packuri import CONTENT_TYPES_URI, PACKAGE_URI
    from docx.opc.pkgwriter import _ContentTypesItem

    pkg = doc.part.package
    parts = list(pkg.parts)
    for part in parts:
        part.before_marshal()
    entries = [(CONTENT_TYPES_URI, _ContentTypesItem.from_parts(parts).blob), (PACKAGE_URI.rels_uri, pkg.rels.xml)]
    for part in parts:
        entries.append((part.partname, part.blob))
        if len(part.rels):
            entries.append((part.partname.rels_uri, part.rels.xml))
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w") as z:
        for uri, blob in entries:
            _entry(z, uri.membername, blob)
    return out.getvalue()


def _entry(z: zipfile.ZipFile, name: str, blob: bytes) -> None:
    zi = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
    zi.compress_type = zipfile.ZIP_STORED if name.endswith((".png", ".jpeg", ".jpg")) else zipfile.ZIP_DEFLATED
    zi.external_attr = 0o644 << 16
    zi.create_system = 0
    z.writestr(zi, blob)


def _page(doc: Any, Mm: Any) -> None:
    sec = doc.sections[0]
    sec.page_width, sec.page_height = Mm(210), Mm(297)
    sec.left_margin, sec.right_margin = Mm(30), Mm(15)
    sec.top_margin, sec.bottom_margin = Mm(20), Mm(20)
    sec.header_distance, sec.footer_distance = Mm(10), Mm(10)
    sec.different_first_page_header_footer = True  # no number on the title page
    from docx.enum.text import WD_ALIGN_PARAGRAPH
    from docx.oxml import parse_xml

    p = sec.footer.paragraphs[0]
    p.alignment = WD_ALIGN_PARAGRAPH.CENTER
    W = 'xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main"'
    for x in (f'<w:r {W}><w:fldChar w:fldCharType="begin"/></w:r>',
              f'<w:r {W}><w:instrText xml:space="preserve"> PAGE </w:instrText></w:r>',
              f'<w:r {W}><w:fldChar w:fldCharType="separate"/></w:r>', f'<w:r {W}><w:t>2</w:t></w:r>',
              f'<w:r {W}><w:fldChar w:fldCharType="end"/></w:r>'):
        p._p.append(parse_xml(x))
    # Word recomputes the fields (contents, pages) when the document opens
    settings = doc.settings.element
    upd = parse_xml(f'<w:updateFields {W} w:val="true"/>')
    later = next((c for c in settings if c.tag.rsplit("}", 1)[-1] in _AFTER_UPDATE_FIELDS), None)
    if later is not None:  # the schema's order: Word refuses a settings part out of it
        later.addprevious(upd)
    else:
        settings.append(upd)


#: The elements of w:settings that come after w:updateFields in the schema's sequence.
_AFTER_UPDATE_FIELDS = {"hdrShapeDefaults", "footnotePr", "endnotePr", "compat", "docVars", "rsids", "mathPr",
                        "attachedSchema", "themeFontLang", "clrSchemeMapping", "doNotIncludeSubdocsInStats",
                        "doNotAutoCompressPictures", "forceUpgrade", "captions", "readModeInkLockDown",
                        "smartTagType", "schemaLibrary", "shapeDefaults", "doNotEmbedSmartTags", "decimalSymbol",
                        "listSeparator"}


def _styles(doc: Any, Pt: Any, Mm: Any, qn: Any, ru: bool) -> None:
    from docx.enum.text import WD_ALIGN_PARAGRAPH, WD_LINE_SPACING
    from docx.shared import RGBColor

    st = doc.styles["Normal"]
    st.font.name = "Times New Roman"
    st.font.size = Pt(14)
    rpr = st.element.get_or_add_rPr()
    fonts = rpr.get_or_add_rFonts()
    for a in ("w:asciiTheme", "w:hAnsiTheme", "w:cstheme", "w:eastAsiaTheme"):
        if fonts.get(qn(a)) is not None:
            del fonts.attrib[qn(a)]
    for a in ("w:ascii", "w:hAnsi", "w:cs", "w:eastAsia"):
        fonts.set(qn(a), "Times New Roman")
    lang = rpr.find(qn("w:lang"))
    if lang is None:
        from docx.oxml import OxmlElement

        lang = OxmlElement("w:lang")
        rpr.append(lang)
    lang.set(qn("w:val"), "ru-RU" if ru else "en-GB")
    pf = st.paragraph_format
    pf.first_line_indent = Mm(12.5)
    pf.line_spacing_rule = WD_LINE_SPACING.ONE_POINT_FIVE
    pf.space_before = pf.space_after = Pt(0)
    pf.alignment = WD_ALIGN_PARAGRAPH.JUSTIFY
    pf.widow_control = True
    for level in (1, 2, 3):
        h = doc.styles[f"Heading {level}"]
        h.font.name = "Times New Roman"
        h.font.size = Pt(14)
        h.font.bold = True
        h.font.italic = False
        h.font.color.rgb = RGBColor(0, 0, 0)
        hr = h.element.get_or_add_rPr().get_or_add_rFonts()
        for a in ("w:asciiTheme", "w:hAnsiTheme", "w:cstheme", "w:eastAsiaTheme"):
            if hr.get(qn(a)) is not None:
                del hr.attrib[qn(a)]
        for a in ("w:ascii", "w:hAnsi", "w:cs", "w:eastAsia"):
            hr.set(qn(a), "Times New Roman")
        hf = h.paragraph_format
        hf.first_line_indent = Mm(12.5)
        hf.alignment = WD_ALIGN_PARAGRAPH.LEFT
        hf.space_before = Pt(12)
        hf.space_after = Pt(12)
        hf.keep_with_next = True
        hf.line_spacing_rule = WD_LINE_SPACING.ONE_POINT_FIVE


def _toc(doc: Any, entries: list[tuple[str, str, int]], parse_xml: Any, Mm: Any) -> None:
    W = 'xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main"'
    for i, (number, title, level) in enumerate(entries):
        p = doc.add_paragraph()
        p.paragraph_format.first_line_indent = Mm(0)
        p.paragraph_format.left_indent = Mm(5 * (level - 1))
        if i == 0:
            for x in (f'<w:r {W}><w:fldChar w:fldCharType="begin"/></w:r>',
                      f'<w:r {W}><w:instrText xml:space="preserve"> TOC \\o "1-3" \\h \\z \\u </w:instrText></w:r>',
                      f'<w:r {W}><w:fldChar w:fldCharType="separate"/></w:r>'):
                p._p.append(parse_xml(x))
        p.add_run(f"{number} {title}")
        if i == len(entries) - 1:
            p._p.append(parse_xml(f'<w:r {W}><w:fldChar w:fldCharType="end"/></w:r>'))


def _table(doc: Any, t: Table, Pt: Any, Mm: Any, qn: Any, TA: Any, C: Any) -> None:
    """A Word table written as its XML at once (python-docx's cell by cell access costs a
    second on a table over twelve positions): a grid style, the header repeated on every
    page, a smaller font for wide tables."""
    from docx.oxml import parse_xml

    ncol = len(t.header)
    width = int(TEXT_WIDTH_MM / 25.4 * 1440) // ncol  # twips: equal columns Word then fits to their text
    half_points = 24 if ncol <= 6 else (20 if ncol <= 9 else 16)
    style = doc.styles["Table Grid"].style_id
    ppr = '<w:pPr><w:spacing w:line="240" w:lineRule="auto"/><w:ind w:firstLine="0"/>{jc}</w:pPr>'
    rows = []
    for r, cells in enumerate((t.header, *t.rows)):
        tcs = []
        for c, text in enumerate(cells):
            jc = '<w:jc w:val="center"/>' if c else '<w:jc w:val="left"/>'
            bold = "<w:b/>" if r == 0 else ""
            tcs.append(f'<w:tc><w:tcPr><w:tcW w:w="{width}" w:type="dxa"/></w:tcPr><w:p>{ppr.format(jc=jc)}'
                       f'<w:r><w:rPr>{bold}<w:sz w:val="{half_points}"/><w:szCs w:val="{half_points}"/></w:rPr>'
                       f'<w:t xml:space="preserve">{escape(text)}</w:t></w:r></w:p></w:tc>')
        trpr = "<w:trPr><w:tblHeader/></w:trPr>" if r == 0 else "<w:trPr><w:cantSplit/></w:trPr>"
        rows.append(f"<w:tr>{trpr}{''.join(tcs)}</w:tr>")
    grid = "".join(f'<w:gridCol w:w="{width}"/>' for _ in range(ncol))
    xml = (f'<w:tbl {_W}><w:tblPr><w:tblStyle w:val="{style}"/><w:tblW w:w="0" w:type="auto"/>'
           f'<w:jc w:val="center"/><w:tblLook w:val="04A0" w:firstRow="1" w:lastRow="0" w:firstColumn="1" '
           f'w:lastColumn="0" w:noHBand="0" w:noVBand="1"/></w:tblPr><w:tblGrid>{grid}</w:tblGrid>'
           f"{''.join(rows)}</w:tbl>")
    body = doc.element.body
    body.insert(len(body) - 1, parse_xml(xml))  # before the section's properties
    doc.add_paragraph().paragraph_format.first_line_indent = Mm(0)


_W = 'xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main"'


def _fix_core(doc: Any, note: Note) -> None:
    cp = doc.core_properties
    cp.author = note.title.author or "plans"
    cp.last_modified_by = "plans"
    cp.title = note.title.title
    cp.subject = note.title.kind
    cp.created = cp.modified = cp.last_printed = FIXED.replace(tzinfo=None)
    cp.revision = 1
    cp.comments = ""
    cp.keywords = ""
    cp.category = ""
    cp.language = "ru-RU" if note.lang == "ru" else "en-GB"
