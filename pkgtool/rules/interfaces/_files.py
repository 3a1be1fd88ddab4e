"""The interface definitions of a ROS 2 package, split once for the IFC rules."""

from __future__ import annotations


from pkgtool.model.cmake_interfaces import ListedInterfaces, listed_interfaces, rebuilds_list
from pkgtool.model.context import interface_file
from pkgtool.model.installed import cmake_text, is_ament_python
from pkgtool.model.interface_file import InterfaceFile, read_interface
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package, is_interface_definition
from pkgtool.lazy_regex import lazy_pattern

PRIMITIVES = frozenset({"bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16",
                        "uint16", "int32", "uint32", "int64", "uint64", "string", "wstring",
                        "duration", "time"})
"""The basic types of ``.msg`` files rosidl knows (``duration`` and ``time`` kept from ROS 1)."""
LOWER_NAME = lazy_pattern(r"(?!.*__)(?!.*_$)[a-z][a-z0-9_]*")
"""What rosidl accepts for a package or field name."""
MESSAGE_NAME = lazy_pattern(r"[A-Z][A-Za-z0-9]*")
"""What rosidl accepts for a message name."""


@per_package
def interface_files(package: Package) -> tuple[InterfaceFile, ...]:
    """The ``.msg``, ``.srv`` and ``.action`` files of a ROS 2 package that could be read, in
    path order (a ROS 1 package's follow ROS 1's rules: none)."""
    if package.manifest is None or package.manifest.is_ros1:
        return ()
    found = []
    for path in sorted(package.files):
        text = package.texts.get(path) if is_interface_definition(path) else None
        kind_and_name = interface_file(path)
        if text is not None and kind_and_name is not None:
            found.append(read_interface(path, *kind_and_name, text))
    return tuple(found)


def split_type(written: str) -> tuple[str, str]:
    """The type of a field without its array part, and that part (``int32[<=3]`` gives
    ``int32`` and ``[<=3]``)."""
    if written.endswith("]") and "[" in written:
        at = written.rindex("[")
        return written[:at], written[at:]
    return written, ""


def type_base(written: str) -> str:
    """The type ``written`` names without array and string bounds (``string<=5[3]`` gives
    ``string``)."""
    return split_type(written)[0].split("<=", 1)[0]


@per_package
def built_interface_files(package: Package) -> tuple[InterfaceFile, ...]:
    """The interface files rosidl reads when the package builds: those its CMakeLists.txt
    passes to ``rosidl_generate_interfaces`` (literally, through variables it sets, or by
    its globs). None of an ament_python package (IFC004's business) nor of one whose listing
    cannot be read: a file left out of the list is never parsed (a course's template)."""
    cmake = cmake_text(package)
    if cmake is None:
        return ()
    listed = listed_interfaces(cmake, package.files).files
    return tuple(found for found in interface_files(package) if found.path in listed)


def read_listing(package: Package) -> ListedInterfaces | None:
    """The interface files a CMake package's ``rosidl_generate_interfaces`` lists (with the
    CMake files it includes), when it calls it and no loop or ``list()`` rebuilds its lists
    (names given folders later, not read here); None otherwise."""
    cmake = package.texts.get("CMakeLists.txt")
    if cmake is None or "rosidl_generate_interfaces" not in cmake or is_ament_python(package):
        return None
    text = cmake_text(package) or ""
    return None if rebuilds_list(text) else listed_interfaces(text, package.files)
