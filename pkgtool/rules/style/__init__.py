"""STY and CPY: ament's flake8, pep257 and copyright checks (opt-in with ``--style``)."""
