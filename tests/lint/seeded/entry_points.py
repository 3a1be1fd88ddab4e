"""Seeded console_scripts mistakes (ENT)."""

from __future__ import annotations

from pathlib import Path

from tests.lint.seeded import case, edit, move, remove, write

SETUP = "setup.py"


@case("ENT002", SETUP, "base_pkg.talkr:main")
def module_name_typo(root: Path) -> None:
    edit(root, SETUP, "base_pkg.talker:main", "base_pkg.talkr:main")


@case("ENT003", SETUP, "base_pkg.talker:mian")
def function_name_typo(root: Path) -> None:
    edit(root, SETUP, "base_pkg.talker:main", "base_pkg.talker:mian")


@case("ENT001", SETUP, "'talker = base_pkg.talker'")
def function_left_out(root: Path) -> None:
    edit(root, SETUP, "base_pkg.talker:main", "base_pkg.talker")


@case("ENT001", SETUP, "base_pkg.talker.main")
def dot_instead_of_colon(root: Path) -> None:
    edit(root, SETUP, "base_pkg.talker:main", "base_pkg.talker.main")


@case("ENT001", SETUP, "base_pkg/talker.py:main")
def file_path_instead_of_module(root: Path) -> None:
    edit(root, SETUP, "base_pkg.talker:main", "base_pkg/talker.py:main")


@case("ENT001", SETUP, "'talker base_pkg.talker:main'")
def equals_sign_left_out(root: Path) -> None:
    edit(root, SETUP, "talker = base_pkg.talker:main", "talker base_pkg.talker:main")


@case("ENT002", SETUP, "base_pkg.talker:main")
def package_prefix_left_out(root: Path) -> None:
    edit(root, SETUP, "base_pkg.talker:main", "talker:main")
    edit(root, SETUP, "'talker = talker:main'", "'talker = talker:main',  # base_pkg.talker:main")


@case("ENT002", SETUP, "base_pkg.nodes.talker:main")
def module_in_subpackage_without_init(root: Path) -> None:
    move(root, "base_pkg/talker.py", "base_pkg/nodes/talker.py")
    edit(root, SETUP, "base_pkg.talker:main", "base_pkg.nodes.talker:main")


@case("ENT002", SETUP, "base_pkg.nodes.talker:main")
def flat_packages_list_drops_subpackage(root: Path) -> None:
    move(root, "base_pkg/talker.py", "base_pkg/nodes/talker.py")
    write(root, "base_pkg/nodes/__init__.py", "")
    edit(root, SETUP, "base_pkg.talker:main", "base_pkg.nodes.talker:main")
    edit(root, SETUP, "find_packages(exclude=['test'])", "[package_name]")


@case("ENT002", SETUP, "base_pkg.talker:main")
def package_init_missing(root: Path) -> None:
    remove(root, "base_pkg/__init__.py")


@case("ENT004", SETUP, "'talker = base_pkg.listener:main'")
def console_script_name_copy_pasted(root: Path) -> None:
    edit(root, SETUP, "'listener = base_pkg.listener:main'", "'talker = base_pkg.listener:main'")


@case("ENT003", SETUP, "base_pkg.talker:main")
def main_indented_into_class(root: Path) -> None:
    path = root / "base_pkg/talker.py"
    head, rest = path.read_text().split("\n\ndef main(args=None):")
    body, tail = rest.split("\n\n\nif __name__")
    indented = "\n".join(f"    {line}" if line else line for line in body.splitlines())
    path.write_text(f"{head}\n    def main(args=None):{indented}\n\n\nif __name__{tail}")


@case("ENT003", SETUP, "base_pkg.listener:main")
def main_renamed(root: Path) -> None:
    edit(root, "base_pkg/listener.py", "def main(args=None):", "def run(args=None):")
    edit(root, "base_pkg/listener.py", "    main()", "    run()")


@case("ENT001", SETUP, "base_pkg.talker-node:main")
def module_file_named_with_dash(root: Path) -> None:
    move(root, "base_pkg/talker.py", "base_pkg/talker-node.py")
    edit(root, SETUP, "base_pkg.talker:main", "base_pkg.talker-node:main")


@case("ENT005", SETUP, "'talker = base_pkg.talker:main'")
def console_scripts_group_capitalised(root: Path) -> None:
    edit(root, SETUP, "'console_scripts'", "'Console_Scripts'")


@case("ENT002", SETUP, "base_pkgs.talker:main")
def package_name_misspelled_in_entry(root: Path) -> None:
    edit(root, SETUP, "base_pkg.talker:main", "base_pkgs.talker:main")


@case("ENT002", SETUP, "my_robot.listener:main")
def entry_copied_from_another_package(root: Path) -> None:
    edit(root, SETUP, "base_pkg.listener:main", "my_robot.listener:main")


@case("ENT003", SETUP, "base_pkg.talker:Talker")
def entry_point_names_the_node_class(root: Path) -> None:
    edit(root, SETUP, "base_pkg.talker:main", "base_pkg.talker:Talker")
