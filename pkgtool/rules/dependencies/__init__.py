"""DEP: imports versus the dependencies package.xml declares."""
