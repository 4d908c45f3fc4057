"""The explanatory note as a Word document: the content built by :mod:`plans.note`, its
formulas as Office Math (``omml``), its figures drawn from the sheets' panels
(``figures``), written with python-docx (``docx_writer``), and ``plans note`` (``cli``)."""
