"""Fixers of interface definitions (``.msg``, ``.srv``, ``.action`` files)."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.edit.core import Edit, EditError, Fix
from pkgtool.edit.changes import read_source
from pkgtool.findings import Finding
from pkgtool.fix.common import manifest_doc, offer
from pkgtool.fix.registry import Refusal, fixer
from pkgtool.model.package import Package
from pkgtool.rules.interfaces._files import built_interface_files
from pkgtool.rules.interfaces.interface_package_not_in_group import GROUP
from pkgtool.rules.interfaces.unknown_field_type import type_problem


@fixer("IFC003", "Write the field type meant", safe=False)
def field_type(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write the type the finding names where it is certain: a basic type in its own letter
    case (`string` for `String`), another language's name (`float64` for `double`),
    `pkg/Name` for `pkg/msg/Name`, a close name of the package written, or the package of a
    bare name (`std_msgs/Header`) when package.xml declares it. Unsafe: the line then says
    another type than it did, though rosidl could not build it before."""
    files = {found.path: found for found in built_interface_files(package)}
    for finding in findings:
        found = files.get(finding.span.path)
        member = next((m for m in found.members if m.line == finding.span.line), None) \
            if found is not None else None
        problem = type_problem(package, member) if member is not None else None
        if member is None or problem is None or problem.meant is None or not problem.fixable:
            continue
        try:
            source = read_source(package.root, found.path)
        except EditError:
            continue
        if source is None:
            continue
        start = source.line_starts[member.line - 1] + member.column - 1
        if source.text[start:start + len(member.type)] == member.type:
            yield Fix(f"Write `{problem.meant}`",
                      (Edit(found.path, start, start + len(member.type), problem.meant),),
                      safe=False)


@fixer("IFC007", "Join the `rosidl_interface_packages` group")
def interface_group(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Add ``<member_of_group>rosidl_interface_packages</member_of_group>`` to a format 3
    package.xml. Safe: rosidl stopped the build without it; a format 2 package.xml is left
    to the user (moving to format 3 changes what other elements mean)."""
    doc = manifest_doc(package)
    if doc is None or not findings:
        return
    yield from offer(f"Add `<member_of_group>{GROUP}</member_of_group>`",
                     lambda: doc.add("member_of_group", GROUP))
