"""PYC: Python code that fails at run time, found without running it."""
