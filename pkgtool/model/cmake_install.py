"""What a CMakeLists.txt installs, as far as its text says: the sources of its ``install()``
calls, the Python packages and extension modules it builds, the programs and executables it
puts into ``lib/<package>``, and the sources it copes with missing."""

from __future__ import annotations

import posixpath
from collections.abc import Iterable

from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.cmake_text import (DEPTH, VARIABLE, commands, expand, set_variables)

_PYTHON_MODULE_COMMANDS = frozenset({"ament_python_install_package", "pybind11_add_module",
                                     "nanobind_add_module"})
"""Commands whose first argument is a name Python imports: the package
``ament_python_install_package`` installs, the extension module pybind11 or nanobind builds
(the target's name is the module's: ``PYBIND11_MODULE(name, m)`` must repeat it)."""


def installed_python_packages(text: str) -> frozenset[str]:
    """The Python packages and extension modules ``text`` builds (:data:`_PYTHON_MODULE_COMMANDS`).

    The first argument names the package as Python imports it, wherever ``PACKAGE_DIR`` puts
    its source (``ament_python_install_package(tb_tools PACKAGE_DIR python/tb_tools)``), or
    the extension module (``pybind11_add_module(planner_bindings src/bindings.cpp)``).
    """
    calls = commands(text)
    variables = set_variables(calls, frozenset())
    return frozenset(value for name, args in calls
                     if name in _PYTHON_MODULE_COMMANDS and args
                     for value in expand(args[0], variables, DEPTH)
                     if value and value.isidentifier())


_INSTALL_SOURCES = frozenset({"DIRECTORY", "PROGRAMS", "FILES"})


_INSTALL_OPTIONS = frozenset({"DESTINATION", "TYPE", "PERMISSIONS", "CONFIGURATIONS",
                              "COMPONENT", "OPTIONAL", "USE_SOURCE_PERMISSIONS",
                              "FILES_MATCHING", "PATTERN", "REGEX", "EXCLUDE", "RENAME",
                              "MESSAGE_NEVER", "FILE_PERMISSIONS", "DIRECTORY_PERMISSIONS",
                              "EXCLUDE_FROM_ALL"})
"""``install()`` keywords: the sources of ``install(DIRECTORY|PROGRAMS|FILES ...)`` end at one."""


_OPAQUE = frozenset({"add_subdirectory", "function", "macro",
                     "catkin_python_setup", "catkin_install_python"})
"""Commands after which what the file installs is no longer known from its own text."""


_BUILD_TREE = lazy_pattern(r"\$\{(?:CMAKE_|CMAKE_CURRENT_|PROJECT_|\w+_)?BINARY_DIR\}")
"""A path in the build folder (``${CMAKE_BINARY_DIR}``, ``${PROJECT_BINARY_DIR}``,
``${<project>_BINARY_DIR}``): what the build writes there (generated, or copied from the
package's files by ``configure_file`` or ``file(COPY)``)."""
_DATA_DESTINATIONS = ("share", "include")


def _into_data_folders(args: list[str]) -> bool:
    """True for an ``install()`` whose ``DESTINATION`` is below ``share/`` or ``include/``:
    what it copies from the build folder is neither code nor a script's neighbour."""
    if "DESTINATION" not in args[:-1]:
        return False
    destination = args[args.index("DESTINATION") + 1].lstrip("/")
    return destination.split("/")[0] in _DATA_DESTINATIONS


def installed_sources(text: str, files: Iterable[str] = ()) -> frozenset[str] | None:
    """The package-relative files and folders ``text`` (a CMakeLists.txt with the files it
    includes) installs: the sources of ``install(DIRECTORY|PROGRAMS|FILES ...)``, the
    folders ``ament_python_install_package`` reads and the file of
    ``ament_python_install_module``, and what ``ament_auto_package(INSTALL_TO_SHARE ...)``
    copies; globs match ``files``.

    None when that is not known statically: a source built from a variable the file does not
    set, a generator expression, or a subdirectory, function or macro that may install more.
    """
    calls = commands(text)
    if any(name in _OPAQUE for name, _ in calls):
        return None
    variables = set_variables(calls, frozenset(files))
    found: set[str] = set()
    for name, args in calls:
        for arg in _install_args(name, args):
            if _BUILD_TREE.match(arg) and _into_data_folders(args):
                continue  # a file the build writes into share/ (``${CMAKE_BINARY_DIR}/x.yaml``)
            values = expand(arg, variables, DEPTH)
            if "$<" in arg or not values or None in values:
                return None
            found.update(posixpath.normpath(v.lstrip("/")) for v in values if v)
    return frozenset(found)


_EXISTENCE_TESTS = frozenset({"EXISTS", "IS_DIRECTORY"})
"""``if()`` operators asking whether a path exists."""


def tolerated_missing_sources(text: str) -> frozenset[str]:
    """The install sources ``text`` copes with missing: those of an ``install(... OPTIONAL)``
    and the paths an ``if(EXISTS ...)`` or ``if(IS_DIRECTORY ...)`` asks about (a source
    installed only when it is there), as package-relative paths."""
    calls = commands(text)
    variables = set_variables(calls, frozenset())
    found: set[str] = set()
    for name, args in calls:
        if name in ("if", "elseif"):
            paths = [args[i + 1] for i, arg in enumerate(args[:-1]) if arg in _EXISTENCE_TESTS]
        else:
            paths = _install_args(name, args) if "OPTIONAL" in args else []
        for path in paths:
            found.update(posixpath.normpath(value.lstrip("/"))
                         for value in expand(path, variables, DEPTH) if value)
    return frozenset(found)


def installed_programs(text: str) -> frozenset[str]:
    """The names under which ``install(PROGRAMS ...)`` calls of ``text`` install files into
    ``lib/<package>``, where ``ros2 run`` and launch look executables up (a file keeps its
    name, ``.py`` and all, unless ``RENAME`` gives another); sources that are not static are
    left out."""
    return frozenset(installed_as for _, installed_as in program_sources(text))


def program_sources(text: str) -> list[tuple[str, str]]:
    """Each static source of the ``install(PROGRAMS ... DESTINATION lib...)`` calls of
    ``text`` (package-relative) with the name it is installed under."""
    calls = commands(text)
    variables = set_variables(calls, frozenset())
    found: list[tuple[str, str]] = []
    for name, args in calls:
        destination = args[args.index("DESTINATION") + 1] if "DESTINATION" in args[:-1] else ""
        if name != "install" or args[:1] != ["PROGRAMS"] or not destination.startswith("lib"):
            continue
        renamed = args[args.index("RENAME") + 1] if "RENAME" in args[:-1] else None
        for arg in _install_args(name, args):
            for value in expand(arg, variables, DEPTH):
                if value and "${" not in value:
                    found.append((posixpath.normpath(value.lstrip("/")),
                                  renamed or posixpath.basename(value)))
    return found


_PLAIN_COMMANDS = frozenset("""
    cmake_minimum_required project find_package if elseif else endif set unset list string math
    message option add_compile_options add_compile_definitions add_definitions
    remove_definitions include_directories link_directories link_libraries add_executable
    add_library target_link_libraries target_include_directories target_compile_definitions
    target_compile_features target_compile_options target_link_options target_sources
    set_target_properties set_property get_target_property get_property get_filename_component
    add_dependencies cmake_policy find_path find_library find_file find_program
    pkg_check_modules pkg_search_module enable_testing add_test set_tests_properties
    enable_language check_cxx_compiler_flag check_language mark_as_advanced
    set_source_files_properties set_directory_properties add_link_options processorcount
    get_cmake_property separate_arguments cmake_dependent_option generate_export_header
    add_custom_target add_custom_command include install
    ament_package ament_lint_auto_find_test_dependencies ament_target_dependencies
    ament_export_dependencies ament_export_include_directories ament_export_libraries
    ament_export_targets ament_export_interfaces ament_export_link_flags ament_environment_hooks
    ament_index_register_resource ament_index_get_resource ament_add_gtest ament_add_gmock
    ament_add_pytest_test ament_add_test ament_add_gtest_executable ament_add_gmock_executable
    ament_add_gtest_test ament_add_gmock_test ament_add_ros_isolated_gtest ament_add_test_label
    ament_add_google_benchmark ament_find_gtest ament_lint_cmake ament_xmllint ament_cppcheck
    ament_pep257 ament_copyright ament_flake8 ament_uncrustify ament_cpplint ament_clang_format
    ament_python_install_package ament_python_install_module ament_get_python_install_dir
    ament_package_xml ament_auto_find_build_dependencies ament_auto_package
    ament_auto_add_library ament_auto_add_executable ament_auto_add_gtest
    rosidl_generate_interfaces rosidl_get_typesupport_target rosidl_target_interfaces
    rclcpp_components_register_nodes rclcpp_components_register_node
    pluginlib_export_plugin_description_file generate_parameter_library add_launch_test
    add_ros_isolated_launch_test add_ros_test
""".split())
"""CMake's and ament's commands whose effect on what a file installs into ``lib/`` is known:
any other (a project's own function, a loop, a subdirectory) may install executables."""


_STANDARD_MODULES = frozenset({"GNUInstallDirs", "CTest", "CheckCXXCompilerFlag",
                               "CMakePackageConfigHelpers", "CMakeParseArguments",
                               "GenerateExportHeader", "ProcessorCount", "CheckIncludeFile",
                               "CheckIncludeFileCXX", "CheckLanguage"})
"""CMake's modules an ``include()`` of which defines nothing that installs executables."""


_TARGET_KINDS = frozenset({"ARCHIVE", "LIBRARY", "RUNTIME", "OBJECTS", "FRAMEWORK", "BUNDLE",
                           "PUBLIC_HEADER", "PRIVATE_HEADER", "RESOURCE", "FILE_SET",
                           "INCLUDES", "CXX_MODULES_BMI"})
"""The kinds of artifact an ``install(TARGETS ...)`` gives destinations for."""


def _runs_install_code(calls: list[tuple[str, list[str]]]) -> bool:
    """True when ``calls`` hold an ``install(CODE|SCRIPT ...)``: CMake code run at install
    time, which may link or copy files anywhere (``ln -s node.py node``)."""
    return any(name == "install" and args[:1] in (["CODE"], ["SCRIPT"]) for name, args in calls)


def runs_install_code(text: str) -> bool:
    """:func:`_runs_install_code` of a CMakeLists.txt's text."""
    return _runs_install_code(commands(text))


def installed_executables(text: str) -> frozenset[str] | None:
    """The executables ``text`` (a CMakeLists.txt with the files it includes) installs into
    ``lib/<project>``, where ``ros2 run`` and launch look them up: targets ``install(TARGETS
    ...)`` puts there (under their ``OUTPUT_NAME``), files of ``install(PROGRAMS|FILES ...)``
    (or their ``RENAME``), ``ament_auto_add_executable`` targets of a file ending in
    ``ament_auto_package()``, and components' ``EXECUTABLE``. None when that is not certain:
    a command other than :data:`_PLAIN_COMMANDS` (a loop doing more than configure targets,
    a function of the project, a subdirectory), an included file other than a ``.cmake``
    file of the package or a CMake module, a folder installed into ``lib/``, a name or
    destination built from what the file does not set, the console scripts of a Python
    package's setup.cfg (``ament_python_install_package(... SCRIPTS_DESTINATION ...)``), an
    ``install(CODE|SCRIPT ...)`` (CMake code run at install time may link or copy files
    there: ``ln -s node.py node``)."""
    calls = _without_configuring_loops(commands(text))
    if not _known_commands(calls) or _runs_install_code(calls) or any(
            name == "ament_python_install_package" and "SCRIPTS_DESTINATION" in args
            for name, args in calls):
        return None  # what it installs is not known from the text (a setup.cfg's scripts)
    variables = set_variables(calls, frozenset())
    project = _static("${PROJECT_NAME}", variables)
    if project is None:
        return None
    lib = f"lib/{project}"
    renamed = {args[0]: args[args.index("OUTPUT_NAME") + 1] for name, args in calls
               if name == "set_target_properties" and "OUTPUT_NAME" in args[1:-1]}
    automatic = any(name == "ament_auto_package" for name, _ in calls)
    found: set[str | None] = set()
    for name, args in calls:
        if name == "install" and args[:1] == ["TARGETS"]:
            runtime = _runtime_destination(args, variables)
            if runtime is None or any(d is None for d in _destinations(args, variables)):
                return None
            if runtime == lib:
                found.update(_static(renamed.get(target, target), variables)
                             for target in _until_keyword(args[1:]))
        elif name == "install" and args[:1] in (["PROGRAMS"], ["FILES"], ["DIRECTORY"]):
            destinations = _destinations(args, variables)
            if None in destinations:
                return None
            if lib not in destinations:
                continue
            if args[0] == "DIRECTORY":
                return None  # every file of a folder: not known from the text
            rename = args[args.index("RENAME") + 1] if "RENAME" in args[:-1] else None
            found.update(_static(rename, variables) if rename else
                         (posixpath.basename(value) if value else None)
                         for value in (_static(a, variables) for a in _install_args(name, args)))
        elif name == "ament_auto_add_executable" and args and automatic:
            found.add(_static(renamed.get(args[0], args[0]), variables))
        elif name == "rclcpp_components_register_node" and "EXECUTABLE" in args[:-1]:
            found.add(_static(args[args.index("EXECUTABLE") + 1], variables))
    return None if None in found else frozenset(n for n in found if n)


def installed_into_share(text: str, files: Iterable[str]) -> frozenset[str] | None:
    """The package-relative files and folders ``text`` (a CMakeLists.txt with the files it
    includes) installs under ``share/<project>``, where ``ros2 launch`` looks launch files up:
    the sources of ``install(DIRECTORY|FILES|PROGRAMS ...)`` with such a destination and the
    folders of ``ament_auto_package(INSTALL_TO_SHARE ...)``. None when that is not certain, as
    for :func:`installed_executables` (a command it does not know, a source or destination
    built from what the file does not set, an included file that is not one of the package's
    ``files``, which ``text`` then lacks)."""
    calls = commands(text)
    if not _known_commands(calls, frozenset(files)):
        return None
    variables = set_variables(calls, frozenset())
    project = _static("${PROJECT_NAME}", variables)
    if project is None:
        return None
    share = f"share/{project}"
    found: set[str | None] = set()
    for name, args in calls:
        destinations = _destinations(args, variables) if name == "install" else \
            [share] if name == "ament_auto_package" else []
        if None in destinations:
            return None
        if any(d == share or str(d).startswith(share + "/") for d in destinations):
            found.update(_static(arg, variables) for arg in _install_args(name, args))
    if None in found:
        return None
    return frozenset(posixpath.normpath(n) for n in found if n)  # type: ignore[arg-type]


def _package_path(path: str) -> str:
    """``path`` relative to the package root (``${CMAKE_CURRENT_SOURCE_DIR}/cmake/x.cmake``:
    ``cmake/x.cmake``); a path leaving the package keeps its ``..``."""
    for prefix in ("${CMAKE_CURRENT_SOURCE_DIR}/", "${PROJECT_SOURCE_DIR}/"):
        path = path.removeprefix(prefix)
    return posixpath.normpath(path)


_CONFIGURING = frozenset("""
    ament_target_dependencies target_link_libraries target_include_directories
    target_compile_options target_compile_definitions target_compile_features
    target_link_options add_dependencies message rosidl_target_interfaces
""".split())
"""Commands that only configure existing targets: a loop of them installs nothing."""


def _without_configuring_loops(calls: list[tuple[str, list[str]]]
                               ) -> list[tuple[str, list[str]]]:
    """``calls`` without the ``foreach`` loops whose body only configures targets
    (:data:`_CONFIGURING`: ``foreach(t ${NODES}) ament_target_dependencies(${t} rclcpp)``),
    which change nothing the file installs; any other loop is kept (and makes what the file
    installs unknown)."""
    kept: list[tuple[str, list[str]]] = []
    loop: list[tuple[str, list[str]]] = []
    for call in calls:
        if loop or call[0] == "foreach":
            loop.append(call)
            if call[0] == "endforeach":
                body = loop[1:-1]
                if not all(name in _CONFIGURING for name, _ in body):
                    kept.extend(loop)
                loop = []
        else:
            kept.append(call)
    return kept + loop


def _known_commands(calls: list[tuple[str, list[str]]], files: frozenset[str] | None = None
                    ) -> bool:
    """True when every command of ``calls`` is one of :data:`_PLAIN_COMMANDS`, and every
    included file a CMake module or a ``.cmake`` file (with ``files``, one of these files of
    the package: a file outside it is not in the text read)."""
    return not any(name not in _PLAIN_COMMANDS or name == "include" and args[:1] and
                   args[0] not in _STANDARD_MODULES and (
                       not args[0].endswith(".cmake") or
                       files is not None and _package_path(args[0]) not in files)
                   for name, args in calls)


def _static(arg: str, variables: dict[str, list[str] | None]) -> str | None:
    """``arg`` with each ``${VAR}`` replaced by the one literal value the file sets it to;
    None when a variable has no such value (or ``arg`` holds a generator expression)."""
    for _ in range(DEPTH):
        names = VARIABLE.findall(arg)
        if not names:
            return None if "$<" in arg else arg.rstrip("/")
        values = variables.get(names[0])
        if not values or len(values) != 1 or values[0] is None:
            return None
        arg = arg.replace(f"${{{names[0]}}}", values[0])
    return None


def _destinations(args: list[str], variables: dict[str, list[str] | None]) -> list[str | None]:
    """Every ``DESTINATION`` of an ``install()`` call, made static (None: not static)."""
    return [_static(args[i + 1], variables) for i, arg in enumerate(args[:-1])
            if arg == "DESTINATION"]


def _runtime_destination(args: list[str], variables: dict[str, list[str] | None]
                         ) -> str | None:
    """Where ``install(TARGETS ...)`` puts executables: the last ``DESTINATION`` given after
    ``RUNTIME`` (CMake keeps the last), else the last given for all kinds; ``""`` when none
    applies, None when it is not static."""
    kind, runtime, common = "", None, None
    for i, arg in enumerate(args[:-1]):
        if arg in _TARGET_KINDS and args[i - 1] != "EXPORT":
            kind = arg
        elif arg == "DESTINATION" and args[i - 1] != "EXPORT" and kind in ("", "RUNTIME"):
            if kind:
                runtime = args[i + 1]
            else:
                common = args[i + 1]
    chosen = runtime if runtime is not None else common
    return "" if chosen is None else _static(chosen, variables)


_TARGETS_KEYWORDS = _TARGET_KINDS | _INSTALL_OPTIONS | {
    "EXPORT", "RUNTIME_DEPENDENCIES", "RUNTIME_DEPENDENCY_SET", "NAMELINK_ONLY", "NAMELINK_SKIP",
    "NAMELINK_COMPONENT"}
"""The keywords that end the targets of ``install(TARGETS ...)`` (a target may be named in
capitals: ``EMERGENCY_NODE_LISTENER``)."""
_AUTO_PACKAGE_KEYWORDS = frozenset({"INSTALL_TO_SHARE", "INSTALL_TO_PATH",
                                    "USE_SCOPED_HEADER_INSTALL_DIR"})
"""The keywords of ``ament_auto_package()``."""


def _until_keyword(args: list[str]) -> list[str]:
    """The leading arguments before the first keyword of ``install(TARGETS ...)``."""
    found = []
    for arg in args:
        if arg in _TARGETS_KEYWORDS:
            break
        found.append(arg)
    return found


def _install_args(name: str, args: list[str]) -> list[str]:
    """The source arguments of one installing command (none for other commands)."""
    if name == "install" and args[:1] and args[0] in _INSTALL_SOURCES:
        sources: list[str] = []
        for arg in args[1:]:
            if arg in _INSTALL_OPTIONS:
                break
            sources.append(arg)
        return sources
    if name == "ament_python_install_package" and args:
        folder = args.index("PACKAGE_DIR") + 1 if "PACKAGE_DIR" in args[:-1] else 0
        return [args[folder]]
    if name == "ament_python_install_module" and args:
        return [args[0]]
    if name == "ament_auto_package" and "INSTALL_TO_SHARE" in args:
        folders: list[str] = []
        for arg in args[args.index("INSTALL_TO_SHARE") + 1:]:
            if arg in _AUTO_PACKAGE_KEYWORDS:  # the next keyword
                break
            folders.append(arg)
        return folders
    return []
