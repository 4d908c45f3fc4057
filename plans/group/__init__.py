"""A group's course: variants from a table, answer keys, blank forms, every sheet checked,
marks in a gradebook (``plans variants``, ``plans check DIR --xlsx``)."""
