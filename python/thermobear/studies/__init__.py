"""The seed studies: each reproduces figures and tables of a seed paper
(seed A: bearing, thermal network, gear dynamics; seed B: bearing, motorized
spindle, rotor vibration, and the diagnosis on its measurements) and writes
them into a folder. ``thermobear.studies.demo`` runs them all (``thermobear demo``)."""
