"""The explanatory note (расчётно-пояснительная записка) as plain data.

``source`` reads the project's files through the engine (the one place that knows the
engine's API), ``build`` turns what was solved into sections, paragraphs, equations (a
small formula tree, :mod:`plans.note.model`), tables and references to figures, in the
course's order and in one language.  Writing it as a Word document and drawing its
figures belongs to ``drawings.note``: this package imports no renderer and no python-docx.
"""
