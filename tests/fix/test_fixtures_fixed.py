"""Every failing fixture of a fixable rule: ``--fix`` removes its findings and adds none."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from pkgtool.commands.lint import LintOptions, run
from pkgtool.fix.registry import fixers

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures"
CASES = [(code, case) for code in fixers() for case in sorted((FIXTURES / code / "bad").iterdir())]
PARTLY = {("PYC080", "indexed_messages"), ("PYC046", "methods_not_called"),
          ("LCH028", "misspelt_include_arguments"),
          ("MAN019", "gplv3_and_bsd_3_clause"), ("MAN019", "spdx_case_and_deprecated_ids"),
          ("LCH001", "node_of_another_workspace_package"), ("PYC094", "callbacks_made_in_loops"),
          ("LCH010", "command_as_one_formatted_string"),
          ("LCH001", "executable_of_a_cmake_workspace_package"),
          ("DEP011", "lookups_of_undeclared_packages"),
          ("DEP012", "description_names_undeclared_packages"),
          ("LCH002", "undeclared_packages"), ("LCH002", "xacro_run_by_command"),
          ("MAN018", "cmake_package_keys"),
          ("DAT008", "wrong_shapes"),
          ("LCH005", "foxy_python_arguments"), ("LCH005", "ros1_frontend_attributes"),
          ("PYC016", "missing_methods"), ("PYC016", "print_style_calls"),
          ("PYC025", "literals_of_another_type"),
          ("PYC025", "messages_given_other_values"), ("PYC025", "names_of_another_type"),
          ("DEP008", "interfaces_in_subfolders"), ("DEP008", "misspelled_and_wrong_kind"),
          ("DEP008", "misspelled_modules"), ("DEP008", "workspace_interfaces"),
          ("MAN017", "ros2_pkg_create_defaults"), ("IFC003", "types"),
          ("DEP007", "folder_without_init"),
          ("PYC001", "missing_standard_module"), ("DEP007", "own_package_by_bare_name"),
          ("PYC025", "builtin_results"), ("PYC031", "parameter_texts"),
          *(("PYC019", case) for case in (
              "callback_parameters", "humble_target", "interfaces_without_wheels",
              "misspelled_fields", "workspace_interfaces")),
          ("PYC014", "misspelled_read_after_alias"), ("SET016", "misspelled_keywords"),
          ("PYC063", "misspelled_standard_names"), ("PYC064", "misspelt_methods"),
          ("PYC065", "misspelt_names_and_marks"), ("PYC029", "keywords_no_distribution_takes"),
          ("DEP008", "typos_and_module_reads"), ("PYC066", "misspelt_names"),
          ("PYC014", "misspelled_reads"), ("DAT009", "misspelled_node"),
          ("DAT009", "file_named_in_setup_py"), ("DAT009", "file_named_in_a_test"),
          ("PYC064", "reads_on_self"),
          ("PYC026", "action_and_parameter_callbacks"), ("PYC026", "wrong_value_returned"),
          ("LCH005", "remappings_not_pairs"), ("LCH016", "misspelt_methods"),
          ("LCH010", "arguments_launch_rejects"), ("PYC041", "init_without_super"),
          ("PYC070", "set_wrong_types"), ("LCH010", "command_words_joined"),
          ("PYC082", "messages_compared")}
"""GPLv3 can mean -only or -or-later, `my_robot_description` is no known package, values outside
`ros__parameters` belong to a node only the user knows, a node without its executable names
none, `required="true"` and YAML launch files are left to the user, `exception()` is close to
no rclpy logging method, an int for a bool or string field or a float for an int field has no
one right spelling, a misspelt interface name is renamed nowhere else in the module, `import
pkg.msgs` is used under that name, an email address is the author's, and a standard module's
name used as a value may be a variable never assigned, `import a.b` binds `a`, which the
installed name would not, `len()` for a string field and a parameter's text in an f-string mean
something only the author knows, and a misspelt field, executable, parameter or node block is
renamed only when exactly one name is spelled like it (positional message arguments, a class's
attributes, fields of a message with none, an executable or parameter close to nothing, a node
with a namespace are left; `test_requires` wants a test extra more than `tests_require`,
`collections.Mapping` an import of `collections.abc`, `threads=` is a typo of no parameter
of an executor, and an interface misspelt in a read of its module is the user's to rename;
an action's result and a `SetParametersResult` are the author's to build, where a service
callback's response is the one rclpy passes in; the pairs remappings were meant to be and the
words of an f-string of arguments are the author's to write, and so is the condition a
`condition='true'` was meant to be, the node name a constructor without `super().__init__`
needs, the one message a print-style logging call's arguments were meant to form, and the value
a `Parameter` of a bool or a list was meant to have, where a command's program ends when a
substitution names it, which of too many positional arguments were meant by keyword, and
which program was to read a data file run as a command, whether a package no release
has is built elsewhere, and which field of a message of several a plain value was compared
with): no fix
guesses, the user chooses; the other findings
of the case are fixed."""
MANUAL = {("PYC078", "habits_of_other_languages"), ("LCH001", "nodes_of_released_packages"),
          ("LCH010", "command_words_as_arguments"), ("SET003", "talker_demo"),
          ("DAT006", "helper_module_beside_the_launch_file"),
          ("LCH027", "keyboard_teleop_in_launch_files"), ("DAT025", "sim_time_misspelt"),
          ("SYN008", "parameter_file_nothing_installs"), ("PYC090", "timer_before_first_message"),
          ("PYC091", "service_and_action_types_called"),
          ("LCH002", "dependency_left_out_in_a_comment"),
          ("ENT002", "module_never_written_beside_an_install_command"),
          ("ENT002", "misspelt_module_beside_custom_commands"),
          ("MAN015", "catkin_package_without_cmakelists"), ("PYC079", "unknown_keywords"),
          ("DAT005", "cmake_launch_folder_not_installed"),
          ("IFC007", "format_two_manifest"),
          ("DEP001", "module_of_a_plain_python_project"),
          ("MAN018", "buildtool_depend_ament_python"), ("MAN018", "ros1_packages"),
          ("MAN018", "ament_python_with_a_leftover_cmakelists"), ("PYC050", "call_in_comparison"),
          ("PYC033", "extra_positional"), ("PYC033", "parameter_default_by_position"),
          ("LCH010", "data_file_as_program"), ("DEP001", "interfaces_of_an_unknown_package"),
          ("PYC029", "near_keywords"),
          ("DAT001", "typo_in_path"), ("DAT001", "beside_a_walked_folder"),
          ("LCH001", "cmake_script_installed_with_its_suffix"),
          ("DAT008", "flat_file_for_a_component_and_a_node"),
          ("DAT008", "controllers_file_of_a_moveit_package"),
          ("LCH005", "launch_node_through_alias"),
          ("LCH005", "invalid_names"),
          ("PYC026", "lifecycle_callbacks"),
          ("MAN017", "catkin_create_pkg_license"),
          ("PYC001", "missing_import"), ("PYC001", "setup_and_launch_files"),
          ("PYC001", "undefined_names_in_tests"),
          *(("DEP008", case) for case in (
              "catkin_action_messages", "companion_types_on_humble", "names_no_shim_adds",
              "interfaces_listed_in_an_included_cmake_file", "interfaces_listed_in_cmake",
              "interfaces_without_wheels",
              "misspelled_companion_types", "misspelled_generated_submodules",
              "workspaces_sharing_a_name")),
          *(("ENT002", case) for case in (
              "excluded_by_pattern", "explicit_list_drops_subpackages", "missing_init",
              "module_never_written", "module_of_a_subpackage_never_written",
              "package_named_by_its_path",
              "package_path_with_trailing_slash", "src_layout_without_package_dir",
              "misspelt_prefix_of_a_missing_module",
              "module_of_a_workspace_package_declared_for_tests", "py_module_without_its_file",
              "module_nothing_provides",
              "package_xml_that_does_not_parse")),
          ("PYC019", "kilted_target"), ("PYC019", "reads_in_properties"),
          ("ENT003", "function_named_differently"), ("LCH020", "declaration_assigned_over"),
          ("PYC025", "scalars_for_sequences"),
          ("ENT003", "node_class_as_entry"), ("ENT003", "attribute_of_function"),
          ("ENT003", "star_import_without_main"), ("ENT003", "function_needing_arguments"),
          ("LCH002", "moveit_config_found_by_builder"),
          ("LCH002", "package_named_to_a_lookup_helper"),
          ("PYC014", "read_before_declaring"),
          ("LCH001", "wrong_executable_names"), ("LCH001", "data_files_walked_at_build"),
          ("LCH001", "executables_of_a_loop"), ("LCH001", "cmake_executables_never_installed"),
          ("LCH001", "launch_file_in_a_module_called_example"),
          ("DAT009", "default_name_from_code"), ("DAT009", "renamed_copy_of_a_node"),
          ("DAT009", "xml_and_yaml_launch"), ("LCH003", "gazebo_classic_module"),
          ("DEP007", "cmake_script_without_its_helpers"),
          ("DEP007", "helper_package_copied_in_part")}
"""MAN018 fixes pip and import names only; build types, ROS 1 packages and standard library modules
need the user (a `<build_type>`, a ROS 2 replacement, or nothing). DAT001 fixes a string of
sources and creates the (empty) ament index marker: other missing files have content only their
author knows. DAT008's values at the top level belong to a node only the user knows (here a
component and a node share the file). LCH005 does not choose an executable, the pairs remappings
were meant to be nor a valid node name; PYC016 does not reword print-style logging calls, nor
choose how a message or a number is to be written. DEP008 fixes the module an interface is
imported from, never its name: these cases misspell names (or need a companion type's
attribute); MAN017 has no license in setup.py to copy. PYC001 imports standard modules only:
these cases misspell names or use third-party modules. ENT002 rewrites a script's module only
where the rule names the installed one; these cases need setup.py's packages, an `__init__.py`
or the module itself, which the author chooses. PYC019 renames fields, not positional arguments,
nor a field no field is a typo away from (`linear_acceleration_error`, `frame` for `frame_id`);
ENT003 renames a function only to a close one (`run` is not close to `main`), and a Node class
needs a `main` the author writes; PYC014 renames reads, and moving a declaration is the author's
call; PYC025 does not guess the list a number or a string given to a sequence stands for;
`talker_node` for `talker` (LCH001) and a block `main_talker` for the node `talker` (DAT009) are
more than a typo away: other names, maybe meant, and so is `timeout=` for `timeout_sec=`
(PYC029); a block `movr` beside a block `mover` would merge into it (DAT009). `gazebo_ros`, whose
module a Gazebo Classic launch file imports, has no release after Humble: the fixer declares
only keys that resolve for the target (LCH003). A dropped comparison holding a call (PYC050)
needs the `if` its author meant. An executable a launch file loops over (LCH001) is written in
a list the fixer does not edit, and MoveIt config packages no release has (LCH002) are the
author's to name. DEP007's fixer rewrites Python imports; a script CMake installs
without the modules beside it needs an `install()` only the author places (no CMake fixer), and
so does a catkin package without its CMakeLists.txt (MAN015); a helper package data_files copies
only in part needs the data_files entry its author writes."""

FOLDED = {("DEP001", "pip_name_instead_of_key")}
"""Cases whose findings fold into the finding of their cause when every rule runs: the pip name
declared instead of the key (MAN018) holds the import it leaves undeclared; its fix clears
both."""

REVEALED = {("PYC013", "called_callbacks"): {"PYC026"},
            ("LCH005", "parameters_not_a_list"): {"DAT012"},
            ("PYC032", "joined_without_separator"): {"DAT012"},
            ("PYC019", "misspelled_fields"): {"PYC025"}}
"""Findings a fix may bring to light: once `callback=self.handle()` is `self.handle`, rclpy
calls a service callback that returns no response (PYC026), which the call hid; once a
parameter file reaches the node (in a list, or at a path with its `/`), the launch file reads
a share file the package neither has nor installs (DAT012); once `Duration(secs=1.0)` is
`Duration(sec=1.0)`, the float reaches the int field (PYC025)."""


def _keys(path: Path, code: str, **fix: bool) -> list[tuple[str, str]]:
    options = LintOptions(extend_select=(code,), isolated=True, **fix)
    return [(f.code, f.message) for f in run([str(path)], options=options).findings]


@pytest.mark.parametrize(("code", "case"), CASES, ids=[f"{c}-{p.name}" for c, p in CASES])
def test_fix_clears_the_rule_and_adds_nothing(tmp_path: Path, code: str, case: Path) -> None:
    package = tmp_path / case.name
    shutil.copytree(case, package)
    before = _keys(package, code)
    after = _keys(package, code, fix=True, unsafe_fixes=True)
    mine = [key for key in after if key[0] == code]
    if (code, case.name) not in MANUAL | FOLDED:
        assert len(mine) < len([key for key in before if key[0] == code])
        assert not mine or (code, case.name) in PARTLY, mine
    added = {key for key in set(after) - set(before)
             if key[0] not in REVEALED.get((code, case.name), set())}
    assert not added, added
    assert _keys(package, code, fix=True, unsafe_fixes=True) == after, "not idempotent"


@pytest.mark.parametrize(("code", "case"), CASES, ids=[f"{c}-{p.name}" for c, p in CASES])
def test_a_finding_is_offered_as_fixable_exactly_when_fix_repairs_it(code: str, case: Path
                                                                     ) -> None:
    """Reports mark fixable (``[*]``, JSON ``fixable``) what ``--fix`` repairs: none of a case
    ``--fix`` leaves as it is, all of a case it clears."""
    options = LintOptions(extend_select=(code,), isolated=True)
    mine = [f for f in run([str(case)], options=options).findings if f.code == code]
    offered = [f for f in mine if not f.manual]
    if (code, case.name) in MANUAL:
        assert not offered, [f.message for f in offered]
    elif (code, case.name) not in PARTLY:
        assert offered == mine, [f.message for f in mine if f.manual]
    else:
        assert offered, "a case fixed in part offers some of its findings"
