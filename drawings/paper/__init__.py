"""The paper toolkit: sheets, frames, title blocks, packing, text, backends (SVG, DXF) and
export (PDF, PNG). It knows millimetres, lines and words, and no mechanism: no room of the
engine is imported here."""
