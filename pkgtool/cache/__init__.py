"""Lint's persistent cache: each package's findings, reused while nothing they depend on changed.

See :mod:`pkgtool.cache.store` for the key and the files, :mod:`pkgtool.cache.serial` for how
findings are written (generically, so every field a finding carries survives).
"""
