"""``lint --fix``: rule codes mapped to fixers that turn findings into edits, and the loop.

A fixer is a pure function of the package model and its findings of one code; it returns
:class:`pkgtool.edit.core.Fix` values (data). :mod:`pkgtool.fix.apply` applies them through the
edit engine and re-lints until nothing changes.
"""
