"""Rebuild the real-world corpus outside the repository and sweep it with ``pkgtool lint``.

The corpus is a list of public repositories pinned to a commit (``corpus.tsv``). Third-party
code never enters our repository: ``build`` writes each repository's tree at its commit to a
folder outside it (default ``~/.cache/pkgtool-corpus``), from a local git directory (a bare
mirror such as ``/work/.mirror/<owner>+<name>/repo``) or, with ``--network``, from a clone of
``https://github.com/<owner>/<name>``.

``sweep`` lints every ament_python package of the corpus in one ``pkgtool lint --format json``
run (with the other packages of its repository it may use, whose findings are not counted:
see :func:`context_packages`), writes the findings to ``<corpus>/sweep.json`` and prints a
count per rule and severity, split by the kind of repository (maintained, course, student).
With ``verdicts.tsv`` (the triage: one line per error on a maintained package) it prints the
false-error rate and every error that has no verdict yet.

    python bench/realworld/corpus.py build [--dest DIR] [--mirror DIR] [--network]
    python bench/realworld/corpus.py sweep [--dest DIR] [--untriaged FILE]
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import os
import re
import subprocess
import sys
import tempfile
from collections import Counter
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
CORPUS = HERE / "corpus.tsv"
VERDICTS = HERE / "verdicts.tsv"
DEFAULT_DEST = Path(os.environ.get("PKGTOOL_CORPUS", Path.home() / ".cache" / "pkgtool-corpus"))
DEFAULT_MIRROR = Path("/work/.mirror")
AMENT_PYTHON = re.compile(rb"<build_type>\s*ament_python\s*</build_type>")
DEPENDENCY = re.compile(rb"<(?:\w+_)?depend\b[^>]*>\s*([^<\s]+)\s*</")
NAME = re.compile(rb"<name>\s*([^<\s]+)\s*</name>")
SKIP_DIRS = {".git", "build", "install", "log", "__pycache__", "node_modules"}


@dataclass(frozen=True)
class Repo:
    """One line of corpus.tsv."""

    name: str  # owner/name
    ref: str
    commit: str
    kind: str  # maintained | course | student

    @property
    def folder(self) -> str:
        return self.name.replace("/", "+")


def read_corpus(path: Path = CORPUS) -> list[Repo]:
    """The repositories of corpus.tsv (``#`` lines are comments)."""
    rows = [line.split("\t") for line in path.read_text().splitlines()
            if line.strip() and not line.startswith("#")]
    return [Repo(row[0], row[1], row[2], row[3]) for row in rows]


def _git_dir(mirror: Path, repo: Repo) -> Path | None:
    base = mirror / repo.folder / "repo"
    for candidate in (base / ".git", base):
        if (candidate / "objects").is_dir():
            return candidate
    return None


MISSING = ".pkgtool-corpus-missing"
"""The file of a checkout listing the files its mirror lacks (one path per line)."""


def _archive(git_dir: Path, commit: str, into: Path) -> None:
    """Write the tree of ``commit`` to ``into``; blobs missing from a mirror are left out and
    listed in :data:`MISSING`.

    Mirrors may lack their largest blobs, so this reads objects with ``git cat-file --batch``
    (which answers ``missing`` instead of failing like ``git archive``). Symbolic links are
    kept only when they stay inside the tree; submodules are skipped.
    """
    git = ["git", f"--git-dir={git_dir}"]
    listing = subprocess.run([*git, "ls-tree", "-r", "-z", commit], check=True,
                             capture_output=True).stdout.split(b"\0")
    entries = []
    for line in filter(None, listing):
        meta, _, path = line.partition(b"\t")
        mode, kind, sha = meta.split()
        if kind == b"blob":
            entries.append((mode, sha, path.decode("utf-8", "surrogateescape")))
    batch = b"".join(sha + b"\n" for _, sha, _ in entries)
    output = io.BytesIO(subprocess.run([*git, "cat-file", "--batch"], input=batch, check=True,
                                       capture_output=True).stdout)
    into.mkdir(parents=True)
    missing = []
    for mode, _, path in entries:
        header = output.readline().split()
        if header[-1] == b"missing":
            missing.append(path)
            continue
        data = output.read(int(header[2]))
        output.read(1)
        _write(into, path, mode, data)
    (into / MISSING).write_text("".join(f"{path}\n" for path in missing))


def _write(root: Path, path: str, mode: bytes, data: bytes) -> None:
    target = root / path
    if ".." in Path(path).parts:
        return
    target.parent.mkdir(parents=True, exist_ok=True)
    if mode == b"120000":
        link = data.decode("utf-8", "surrogateescape")
        inside = os.path.normpath(target.parent / link).startswith(str(root) + os.sep)
        if not os.path.isabs(link) and inside:
            target.symlink_to(link)
        return
    target.write_bytes(data)
    if mode == b"100755":
        target.chmod(0o755)


def _clone(repo: Repo, scratch: Path) -> Path:
    url = f"https://github.com/{repo.name}.git"
    subprocess.run(["git", "clone", "--quiet", "--bare", url, str(scratch)], check=True)
    return scratch


def build(dest: Path, mirror: Path, network: bool) -> int:
    """Write every repository at its commit to ``dest/<owner>+<name>``; return the failures."""
    failures = 0
    for repo in read_corpus():
        into = dest / repo.folder
        stamp = into / ".pkgtool-corpus-commit"
        if stamp.is_file() and stamp.read_text().strip() == repo.commit and \
                (into / MISSING).is_file():
            continue
        subprocess.run(["rm", "-rf", str(into)], check=True)
        git_dir = _git_dir(mirror, repo)
        try:
            if git_dir is not None:
                _archive(git_dir, repo.commit, into)
            elif network:
                with tempfile.TemporaryDirectory() as scratch:
                    _archive(_clone(repo, Path(scratch) / "git"), repo.commit, into)
            else:
                print(f"skipped {repo.name}: no git directory under {mirror} (try --network)",
                      file=sys.stderr)
                failures += 1
                continue
        except subprocess.CalledProcessError as error:
            print(f"failed {repo.name}: {error}", file=sys.stderr)
            failures += 1
            continue
        stamp.write_text(repo.commit + "\n")
    return failures


def _packages(root: Path) -> Iterator[Path]:
    """Folders below ``root`` holding a package.xml (packages do not nest)."""
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("."))
        if "package.xml" in files:
            yield Path(folder)
            dirs[:] = []


def ament_python_packages(root: Path) -> list[Path]:
    """Folders below ``root`` whose package.xml declares the ament_python build type."""
    return [folder for folder in _packages(root)
            if AMENT_PYTHON.search((folder / "package.xml").read_bytes())]


def context_packages(root: Path, python: list[Path]) -> list[Path]:
    """The other packages of the repository at ``root`` that its ament_python packages may use:
    those they declare, and interface packages (whose generated modules they may import).

    Users lint a repository, whose other packages are then part of the workspace pkgtool
    sees; the sweep lints these in the same run for that context only, and counts no finding
    of theirs. Without them, a package of one repository would see another repository's
    package of the same name (the sweep is one run).
    """
    wanted = {name for folder in python
              for name in DEPENDENCY.findall((folder / "package.xml").read_bytes())}
    return [folder for folder in _packages(root) if folder not in python and (
        any((folder / kind).is_dir() for kind in ("msg", "srv", "action"))
        or ((found := NAME.search((folder / "package.xml").read_bytes()))
            and found.group(1) in wanted))]


def _lint(packages: list[Path]) -> list[dict]:
    command = [sys.executable, "-m", "pkgtool", "lint", "--format", "json", "--exit-zero",
               "--isolated", *map(str, packages)]
    done = subprocess.run(command, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise SystemExit(f"pkgtool lint failed ({done.returncode}):\n{done.stderr[-2000:]}")
    return json.loads(done.stdout)["findings"]


def _locate(finding: dict, dest: Path, repos: dict[str, Repo]) -> tuple[Repo, str]:
    relative = Path(finding["path"]).resolve().relative_to(dest.resolve())
    return repos[relative.parts[0]], Path(*relative.parts[1:]).as_posix()


def read_verdicts(path: Path = VERDICTS) -> dict[tuple[str, str, str, int], list[str]]:
    """Triage lines keyed by (repository, rule, file, line)."""
    if not path.is_file():
        return {}
    with path.open(newline="") as handle:
        rows = csv.DictReader((line for line in handle if not line.startswith("#")),
                              delimiter="\t")
        return {(row["repository"], row["rule"], row["file"], int(row["line"])):
                [row["verdict"], row["class"]] for row in rows}


def sweep(dest: Path, untriaged: Path | None) -> None:
    """Lint the corpus, save the findings, print the summary and the triage figures."""
    corpus = read_corpus()
    repos = {repo.folder: repo for repo in corpus}
    packages = {repo.folder: ament_python_packages(dest / repo.folder) for repo in corpus}
    everything = [package for found in packages.values() for package in found]
    context = [other for folder, found in packages.items()
               for other in context_packages(dest / folder, found)]
    counted = tuple(f"{package}{os.sep}" for package in everything)
    findings = [finding for finding in _lint(everything + context)
                if f"{finding['path']}{os.sep}".startswith(counted)]
    (dest / "sweep.json").write_text(json.dumps(findings, indent=1))
    kinds = Counter(repos[folder].kind for folder, found in packages.items() for _ in found)
    print(f"corpus: {len(corpus)} repositories, {len(everything)} ament_python packages "
          f"({', '.join(f'{kind} {n}' for kind, n in sorted(kinds.items()))})")
    table: Counter[tuple[str, str, str]] = Counter()
    errors = []
    absent = {folder: _missing_files(dest / folder) for folder in repos}
    kept = [f for f in findings if not _about_missing(f, dest, absent)]
    if len(kept) < len(findings):
        print(f"left out: {len(findings) - len(kept)} findings about files the mirrors lack")
    for finding in kept:
        repo, file = _locate(finding, dest, repos)
        table[(finding["rule"], finding["severity"], repo.kind)] += 1
        if finding["severity"] == "error" and repo.kind == "maintained":
            errors.append((repo.name, finding["rule"], file, finding["line"] or 0,
                           finding["package"], finding["message"]))
    _print_table(table)
    _print_triage(errors, untriaged)


def _missing_files(checkout: Path) -> tuple[str, ...]:
    listed = checkout / MISSING
    return tuple(filter(None, listed.read_text().splitlines())) if listed.is_file() else ()


def _about_missing(finding: dict, dest: Path, absent: dict[str, tuple[str, ...]]) -> bool:
    """True for a finding naming (in backticks) a file of its package the mirror lacks: the
    real repository has it."""
    path = Path(finding["path"])
    folder = path.relative_to(dest).parts[0] if path.is_relative_to(dest) else ""
    package = dest / folder
    for missing in absent.get(folder, ()):
        inside = (package / missing).relative_to(package)
        parts = inside.parts
        candidates = {"/".join(parts[i:]) for i in range(len(parts))}
        if any(f"`{c}`" in finding["message"] for c in candidates if "/" in c or len(parts) == 1):
            return True
    return False


def _print_table(table: Counter[tuple[str, str, str]]) -> None:
    kinds = ("maintained", "course", "student")
    print(f"\n{'rule':8} {'severity':8} " + " ".join(f"{kind:>10}" for kind in kinds))
    for rule, severity in sorted({(rule, severity) for rule, severity, _ in table}):
        counts = " ".join(f"{table[(rule, severity, kind)]:>10}" for kind in kinds)
        print(f"{rule:8} {severity:8} {counts}")


def _print_triage(errors: list[tuple], untriaged: Path | None) -> None:
    verdicts = read_verdicts()
    verdict_counts = Counter(verdicts.get(error[:4], ["untriaged"])[0] for error in errors)
    total = len(errors)
    false = verdict_counts["false"]
    print(f"\nerrors on maintained packages: {total}; true {verdict_counts['true']}, "
          f"false {false}, untriaged {verdict_counts['untriaged']}")
    if total:
        print(f"false-error rate: {false}/{total} = {false / total:.1%}")
    missing = [error for error in errors if error[:4] not in verdicts]
    if untriaged is not None:
        with untriaged.open("w", newline="") as handle:
            writer = csv.writer(handle, delimiter="\t", lineterminator="\n")
            writer.writerow(["repository", "rule", "file", "line", "package", "message"])
            writer.writerows(missing)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("command", choices=["build", "sweep"])
    parser.add_argument("--dest", type=Path, default=DEFAULT_DEST,
                        help=f"where the corpus lives (default {DEFAULT_DEST}; $PKGTOOL_CORPUS)")
    parser.add_argument("--mirror", type=Path, default=DEFAULT_MIRROR,
                        help="folder of <owner>+<name>/repo git directories")
    parser.add_argument("--network", action="store_true",
                        help="clone repositories that have no local git directory")
    parser.add_argument("--untriaged", type=Path, help="write errors with no verdict here (TSV)")
    args = parser.parse_args(argv)
    if args.command == "build":
        return 1 if build(args.dest, args.mirror, args.network) else 0
    sweep(args.dest, args.untriaged)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
