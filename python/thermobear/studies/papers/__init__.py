"""Data of the seed papers: their quoted numbers (``seed_a_quotes.csv``,
``seed_b_quotes.csv``, read by ``thermobear.studies.paper_numbers``) and
the calibrated models pinned from them (JSON, with provenance)."""
