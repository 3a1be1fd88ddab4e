"""Fixers of setup.cfg: the script folders ``ros2 run`` needs, and underscored option names."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.edit.core import Edit, Fix
from pkgtool.edit.setup_cfg import has_section, remove_option, rename_option, rename_section, \
    set_option
from pkgtool.edit.source import Source
from pkgtool.findings import Finding
from pkgtool.fix.common import cfg_source
from pkgtool.fix.registry import fixer
from pkgtool.model.package import Package
from pkgtool.model.setup_cfg import CfgOption, SetupCfg
from pkgtool.rules.setup.wrong_script_dir import SCRIPT_OPTIONS, near_miss


def _lines(findings: list[Finding]) -> set[int]:
    return {f.span.line for f in findings if f.span.path == "setup.cfg"}


def _script_dir(package: Package) -> str:
    return f"$base/lib/{package.name}"


@fixer("SET008", "Write setup.cfg with the `lib/<package>` script folders")
def missing_setup_cfg(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Create setup.cfg as ``ros2 pkg create`` writes it. Safe: the rule fires only when the
    package's own launch files, README or nodes say its scripts are started by ``ros2 run``,
    which cannot find them in ``bin/``."""
    if cfg_source(package) is not None or package.has_file("setup.cfg"):
        return
    folder = _script_dir(package)
    text = f"[develop]\nscript_dir={folder}\n[install]\ninstall_scripts={folder}\n"
    yield Fix("Write `setup.cfg`", (Edit("setup.cfg", 0, 0, text, create=True),))


@fixer("SET009", "Set `script_dir` and `install_scripts` to `$base/lib/<package>`")
def wrong_script_dir(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write a wrong folder over, rename a misspelt key or section, add a missing option.
    Safe for the same reason as SET008: nothing but ``ros2 run`` and launch files, which need
    ``lib/<package>``, starts the scripts of such a package."""
    source, cfg = cfg_source(package), package.setup_cfg
    if source is None or cfg is None:
        return
    lines = _lines(findings)
    for section, key in SCRIPT_OPTIONS:
        option = cfg.get(section, key)
        near = near_miss(cfg.options, section, key) if option is None else None
        title = f"Set `[{section}] {key}={_script_dir(package)}`"
        if near is not None and near.span.line in lines:
            title = f"Write `[{near.section}] {near.key}` as `[{section}] {key}`"
            edits = _rename(source, near, section, key)
        elif option is not None and option.span.line in lines or \
                option is None and near is None and 1 in lines:
            edits = set_option(source, section, key, _script_dir(package))
        else:
            continue
        if edits:
            yield Fix(title, tuple(edits))


def _rename(source: Source, near: CfgOption, section: str, key: str) -> list[Edit]:
    """Edits turning the near miss ``near`` into ``[section] key`` (its value kept)."""
    if near.section == section:
        return rename_option(source, section, near.key, key)
    if not has_section(source, section):
        return rename_section(source, near.section, section)
    return remove_option(source, near.section, near.key) + \
        set_option(source, section, key, near.value)


@fixer("SET010", "Write the option with underscores")
def dash_separated(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename ``script-dir`` to ``script_dir``: setuptools reads both alike, so it is safe.
    A section that also has the underscored option is left to the user (which one wins
    depends on the setuptools version)."""
    source, cfg = cfg_source(package), package.setup_cfg
    if source is None or cfg is None:
        return
    lines = _lines(findings)
    for option in cfg.options:
        new_key = option.key.replace("-", "_")
        if option.span.line in lines and "-" in option.key and \
                not _has_exact(cfg, option.section, new_key):
            yield Fix(f"Rename `{option.key}` to `{new_key}`",
                      tuple(rename_option(source, option.section, option.key, new_key)))


def _has_exact(cfg: SetupCfg, section: str, key: str) -> bool:
    return any(o.section == section and o.key == key for o in cfg.options)
