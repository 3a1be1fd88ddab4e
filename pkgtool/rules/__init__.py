"""Rules: pure functions from a package model to hits, one concern per sub-package.

Every module under this package is imported by the registry; a rule module registers its rules
with the :func:`pkgtool.rules.registry.rule` decorator.
"""
