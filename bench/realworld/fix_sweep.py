"""Apply every fix (``lint --fix --unsafe-fixes``) to a copy of the corpus and check the edits.

The corpus (``corpus.py build``) is never written: its ament_python packages, and the
packages of their repositories they may use, are copied into a scratch folder first. Then:

- every Python, XML, YAML and setup.cfg file that parsed before the fixes must parse after;
- the findings after the fixes are compared with those before: a finding that only the
  fixed tree has (same rule, file and message) is printed as *introduced*: a fix that made
  something worse, or a finding one fix's edit moved;
- the findings still fixable after the fixes are counted by rule.

    python bench/realworld/fix_sweep.py [--dest ~/.cache/pkgtool-corpus] [--keep DIR]

Exits 1 when a fix left a file unparsable.
"""

from __future__ import annotations

import argparse
import ast
import configparser
import json
import shutil
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

import yaml
from lxml import etree

sys.path.insert(0, str(Path(__file__).resolve().parent))
from corpus import (DEFAULT_DEST, ament_python_packages, context_packages,  # noqa: E402
                    read_corpus)

CHECKED = {".py", ".xml", ".yaml", ".yml", ".cfg"}


def _parses(path: Path) -> bool:
    data = path.read_bytes()
    try:
        if path.suffix == ".py":
            ast.parse(data)
        elif path.suffix == ".xml":
            etree.fromstring(data)
        elif path.suffix in (".yaml", ".yml"):
            list(yaml.safe_load_all(data))
        else:
            configparser.ConfigParser(interpolation=None).read_string(data.decode())
    except Exception:  # noqa: BLE001 - any failure to parse counts
        return False
    return True


def _parsing(root: Path) -> dict[str, bool]:
    return {str(p.relative_to(root)): _parses(p) for p in sorted(root.rglob("*"))
            if p.suffix in CHECKED and p.is_file()}


def _lint(root: Path, packages: list[Path], *fix: str) -> list[dict]:
    command = [sys.executable, "-m", "pkgtool", "lint", "--format", "json", "--exit-zero",
               "--isolated", "--no-cache", *fix, *map(str, packages)]
    done = subprocess.run(command, capture_output=True, text=True, check=False, cwd=root)
    if done.returncode != 0:
        raise SystemExit(f"pkgtool lint failed ({done.returncode}):\n{done.stderr[-2000:]}")
    found = json.loads(done.stdout)["findings"]
    for finding in found:
        finding["path"] = str((root / finding["path"]).resolve().relative_to(root.resolve()))
    return found


def _copy(dest: Path, scratch: Path) -> tuple[list[Path], int]:
    """Copy the packages the sweep lints (ament_python ones, and the packages of their
    repositories they may use, which the workspace needs) into ``scratch``: their new paths,
    and how many are ament_python packages."""
    copied: list[Path] = []
    python = 0
    for repo in read_corpus():
        source = dest / repo.folder
        if not source.is_dir():
            continue
        found = ament_python_packages(source)
        python += len(found)
        for folder in (*found, *context_packages(source, found)):
            target = scratch / folder.relative_to(dest)
            shutil.copytree(folder, target, symlinks=True, dirs_exist_ok=True,
                            ignore=shutil.ignore_patterns(".git"))
            copied.append(target)
    return copied, python


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dest", type=Path, default=DEFAULT_DEST, help="the built corpus")
    parser.add_argument("--keep", type=Path, help="fix a copy here and keep it (default: a "
                        "temporary folder, removed after)")
    args = parser.parse_args(argv)
    scratch = args.keep or Path(tempfile.mkdtemp(prefix="pkgtool-fix-sweep-"))
    try:
        packages, python = _copy(args.dest, scratch)
        before_parse = _parsing(scratch)
        before = _lint(scratch, packages)
        _lint(scratch, packages, "--fix", "--unsafe-fixes")
        after = _lint(scratch, packages)
        after_parse = _parsing(scratch)
    finally:
        if args.keep is None:
            shutil.rmtree(scratch, ignore_errors=True)
    broken = sorted(p for p, ok in before_parse.items() if ok and not after_parse.get(p, True))
    key = lambda f: (f["rule"], f["path"], f["message"])  # noqa: E731
    introduced = Counter(map(key, after)) - Counter(map(key, before))
    fixable = Counter(f["rule"] for f in after if f.get("fixable"))
    print(f"{python} ament_python packages ({len(packages)} with their neighbours); "
          f"findings {len(before)} -> {len(after)}; files left unparsable: {len(broken)}")
    for path in broken:
        print(f"  BROKEN {path}")
    print(f"introduced by the fixes: {sum(introduced.values())}")
    for rule, path, message in sorted(introduced):
        print(f"  {rule} {path}: {message[:160]}")
    print("still fixable: " + (", ".join(f"{r} {n}" for r, n in fixable.most_common()) or "none"))
    return 1 if broken else 0


if __name__ == "__main__":
    raise SystemExit(main())
