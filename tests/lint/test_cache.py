"""The lint cache: findings identical in every mode, and never trusted when anything changed."""

from __future__ import annotations

import importlib.util
import json
import re
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from pkgtool.cache.serial import BadEntry, decode, encode
from pkgtool.cache.store import pack_of
from pkgtool.commands.warm_worker import cores
from pkgtool.findings import Severity
from pkgtool.model.span import ParseProblem, Span
from tests.helpers import correct_package_files, make_finding, write_tree
from tests.lint.seeded import CASES, CREATED
from tests.lint.seeded import (  # noqa: F401  (each module registers its cases)
    data_files, dependencies, entry_points, launch, manifest, python, setup_files)

ROOT = Path(__file__).resolve().parents[2]
REFERENCE = ROOT / "reference_packages"
GENERATED = 40
"""Generated packages: with the others more than enough for a worker pool."""


def _lint(cwd: Path, *args: str, jobs: int = 1, env: dict[str, str] | None = None
          ) -> subprocess.CompletedProcess[str]:
    inherited = {k: v for k, v in os.environ.items() if k != "PKGTOOL_CACHE_DIR"}
    environment = {**inherited, "PKGTOOL_LINT_JOBS": str(jobs), **(env or {})}  # 0: default
    done = subprocess.run([sys.executable, "-m", "pkgtool", "lint", "--format", "json", *args],
                          cwd=cwd, capture_output=True, text=True, timeout=600, env=environment)
    assert "Traceback" not in done.stderr and done.returncode in (0, 1), done.stderr
    return done


def _entries(cache: Path) -> dict[str, dict]:
    """The cache's entries by package root."""
    return {root: entry for pack in sorted((cache / "lint").glob("packages-*.json"))
            for root, entry in json.loads(pack.read_text())["entries"].items()}


def _bench_generator():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("bench_lint", ROOT / "bench" / "bench_lint.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.write_package


@pytest.fixture(scope="module")
def corpus(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A workspace: the reference packages, every seeded mistake, generated packages."""
    from pkgtool.commands.create import Request, run

    work = tmp_path_factory.mktemp("cache-corpus")
    created = run(Request("base_pkg", work, maintainer_name="Jane Doe",
                          maintainer_email="jane@example.com",
                          nodes=("talker:publisher", "listener:subscriber", "srv:service"),
                          launch=True, config=True, year=2026)).root
    assert created is not None
    source = work / "ws" / "src"
    for reference in sorted(p for p in REFERENCE.iterdir() if (p / "package.xml").is_file()):
        shutil.copytree(reference, source / reference.name)
    for number, case in enumerate(CASES):
        root = source / f"seeded_{number:03d}"
        shutil.copytree(created if case.base == CREATED else REFERENCE / case.base, root)
        case.mutate(root)
    write_package = _bench_generator()
    for index in range(GENERATED):
        write_package(source / f"gen_{index:03d}", f"gen_{index:03d}")
    return work / "ws"


def test_findings_are_identical_with_and_without_cache_and_workers(corpus: Path) -> None:
    serial = _lint(corpus, "--no-cache", jobs=1).stdout
    pooled = _lint(corpus, "--no-cache", jobs=2).stdout
    cold = _lint(corpus, jobs=2).stdout
    entries = _entries(corpus / ".pkgtool_cache")
    warm = _lint(corpus, jobs=1).stdout
    assert json.loads(serial)["findings"], "the corpus has findings to compare"
    assert len(entries) == len(list((corpus / "src").iterdir()))
    assert pooled == serial
    assert cold == serial
    assert warm == serial
    assert list((corpus / ".pkgtool_cache" / "lint").glob("run-*.json")), "a replay record"
    assert _lint(corpus, jobs=1).stdout == serial  # replayed (tests/lint/test_replay.py)
    for module in ("gen_001/gen_001/node_1.py", "gen_002/setup.py"):
        with open(corpus / "src" / module, "a", encoding="utf-8") as stream:
            stream.write("\nundefined_name\n")
    edited = _lint(corpus, jobs=1).stdout  # only the edited packages are checked again
    assert edited == _lint(corpus, "--no-cache", jobs=1).stdout != serial
    with open(corpus / "src" / "gen_003" / "gen_003" / "node_1.py", "a", encoding="utf-8") as f:
        f.write("\nother_undefined_name\n")
    checked_by_the_warm_worker = _lint(corpus, jobs=0).stdout  # the default: a worker forked
    assert checked_by_the_warm_worker == _lint(corpus, "--no-cache", jobs=1).stdout != edited


SPLIT_PROBE = """
import json, sys
from pathlib import Path
from pkgtool.commands.two_cores import check_on_two_cores
from pkgtool.config import settings_for
from pkgtool.engine import check_package
from pkgtool.model.context import context_for, workspace_index
from pkgtool.model.package import load_package

settings = settings_for([])
roots = sorted(p for p in Path(sys.argv[1]).iterdir() if (p / "package.xml").is_file())
index = workspace_index(roots)
split = differ = 0
for root in roots:
    package = load_package(root, context_for(root, index, settings.rosdistro))
    both = check_on_two_cores(package, settings.codes, root_label=root.name,
                              severities=settings.severities)
    alone = check_package(package, settings.rules, root_label=root.name,
                          severities=settings.severities)
    split += both is not None
    differ += both is not None and both != alone
print(json.dumps([len(roots), split, differ]))
"""


def test_findings_are_identical_when_one_package_is_checked_on_two_cores(corpus: Path) -> None:
    """The split of :mod:`pkgtool.commands.two_cores` (a lint run of one package) changes no
    finding, folded consequences of rules on either side included (a process of its own: a
    pytest worker runs threads, and then no child is forked)."""
    environment = {**os.environ, "PKGTOOL_LINT_JOBS": "0"}
    done = subprocess.run([sys.executable, "-c", SPLIT_PROBE, str(corpus / "src")], check=True,
                          capture_output=True, text=True, timeout=600, env=environment)
    packages, split, differ = json.loads(done.stdout)
    assert packages > 100 and differ == 0
    if cores() > 1:
        assert split == packages


def test_an_edit_a_sibling_or_other_settings_invalidate(tmp_path: Path) -> None:
    talker = correct_package_files("talker")
    listener = correct_package_files("listener")
    listener["listener/use.py"] = "import talker\n"
    files = {**{f"src/talker/{k}": v for k, v in talker.items()},
             **{f"src/listener/{k}": v for k, v in listener.items()}}
    ws = write_tree(tmp_path / "ws", files)
    first = _lint(ws).stdout
    assert _lint(ws).stdout == first  # warm
    shutil.rmtree(ws / "src" / "talker" / "talker")  # the sibling no longer provides `talker`
    assert _lint(ws, "--no-cache").stdout == _lint(ws).stdout != first
    (ws / "src" / "listener" / "listener" / "use.py").write_text("import talker\nx = y\n")
    edited = _lint(ws).stdout
    assert edited == _lint(ws, "--no-cache").stdout
    assert "PYC001" in edited
    assert "PYC001" not in _lint(ws, "--ignore", "PYC001").stdout


def _settle(tree: Path) -> None:
    """Date every file an hour back: trusted by size and time from the next run on."""
    hour_ago = os.stat(tree).st_mtime - 3600
    for file in tree.rglob("*"):
        if file.is_file() and ".pkgtool_cache" not in file.parts:
            os.utime(file, (hour_ago, hour_ago))


def test_the_workspace_index_is_kept_with_settled_packages_and_read_again_on_change(
        tmp_path: Path) -> None:
    beta = correct_package_files("beta")
    beta["beta/use.py"] = "import alpha\n"  # a workspace package's module: DEP001 declare it
    ws = write_tree(tmp_path / "ws", {
        **{f"src/alpha/{k}": v for k, v in correct_package_files("alpha").items()},
        **{f"src/beta/{k}": v for k, v in beta.items()}})
    _settle(ws)
    first = _lint(ws).stdout
    assert "DEP001" in first
    alpha_root = str(ws / "src" / "alpha")
    name, interfaces, modules, messages, folder, setup_digest, depends, executables, own, \
        described = _entries(ws / ".pkgtool_cache")[alpha_root]["index"]
    assert [name, interfaces, modules, messages, folder] == \
        ["alpha", {}, ["alpha"], {}, alpha_root]
    assert "rclpy" in depends  # what it depends on: a cycle a declaration would make
    assert re.fullmatch(r"[0-9a-f]{64}", setup_digest)  # ament_python: its scripts may be read
    assert executables is None  # what CMakeLists.txt installs: for CMake packages alone
    assert own is True  # it has a package.xml: rosdep can resolve a dependency on it
    assert described == []  # no robot description file whose existence a sibling may ask
    assert _lint(ws).stdout == first  # the index of both packages comes from the cache
    pack = ws / ".pkgtool_cache" / "lint" / pack_of(alpha_root)
    whole = json.loads(pack.read_text())
    recorded = whole["entries"][alpha_root]
    for broken in ("garbage", ["alpha", {"msg": "X"}, []], [1, {}, []], None):
        whole["entries"][alpha_root] = {**recorded, "index": broken}
        pack.write_text(json.dumps(whole))
        assert _lint(ws).stdout == first, broken
    # what another pkgtool read (no module `alpha`) is not trusted by this one
    whole["entries"][alpha_root] = {**recorded, "code": "0" * 64, "index": ["alpha", {}, []]}
    pack.write_text(json.dumps(whole))
    assert _lint(ws).stdout == first
    (ws / "src" / "alpha" / "alpha").rename(ws / "src" / "alpha" / "renamed")
    _settle(ws)
    moved = _lint(ws).stdout
    assert moved == _lint(ws, "--no-cache").stdout != first
    assert _lint(ws).stdout == moved


def test_a_sibling_s_changed_console_scripts_are_seen_through_the_cache(tmp_path: Path) -> None:
    """LCH001 reads another workspace package's console scripts: the cache is keyed to them."""
    beta = correct_package_files("beta")
    beta["launch/alpha.launch.py"] = (
        "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([Node(package='alpha', executable='talker')])\n")
    ws = write_tree(tmp_path / "ws", {
        **{f"src/alpha/{k}": v for k, v in correct_package_files("alpha").items()},
        **{f"src/beta/{k}": v for k, v in beta.items()}})
    _settle(ws)
    assert "LCH001" not in _lint(ws).stdout
    setup = ws / "src" / "alpha" / "setup.py"
    setup.write_text(setup.read_text().replace("'talker = ", "'speaker = "))
    changed = _lint(ws).stdout
    assert "LCH001" in changed and "`talker` is not an executable of `alpha`" in changed
    assert changed == _lint(ws, "--no-cache").stdout == _lint(ws).stdout


def test_a_sibling_s_renamed_description_file_is_seen_through_the_cache(
        tmp_path: Path) -> None:
    """DAT012 asks whether another workspace package has the URDF its glob would install."""
    alpha = correct_package_files("alpha")
    alpha["urdf/robot.urdf"] = "<robot name='robot'/>\n"
    alpha["setup.py"] = alpha["setup.py"].replace(
        "glob('launch/*.launch.py')),",
        "glob('launch/*.launch.py')), ('share/alpha/urdf', glob('urdf/*.urdf')),")
    beta = correct_package_files("beta")
    beta["launch/robot.launch.py"] = (
        "import os\n\nfrom ament_index_python.packages import get_package_share_directory\n"
        "from launch import LaunchDescription\n\n\ndef generate_launch_description():\n"
        "    with open(os.path.join(get_package_share_directory('alpha'), 'urdf', "
        "'robot.urdf')) as stream:\n"
        "        stream.read()\n"
        "    return LaunchDescription([])\n")
    ws = write_tree(tmp_path / "ws", {
        **{f"src/alpha/{k}": v for k, v in alpha.items()},
        **{f"src/beta/{k}": v for k, v in beta.items()}})
    _settle(ws)
    assert "DAT012" not in _lint(ws, "--select", "DAT012").stdout
    urdf = ws / "src" / "alpha" / "urdf"
    (urdf / "robot.urdf").rename(urdf / "robot_v2.urdf")
    changed = _lint(ws, "--select", "DAT012").stdout
    assert "DAT012" in changed and "did you mean `urdf/robot_v2.urdf`" in changed
    assert changed == _lint(ws, "--select", "DAT012", "--no-cache").stdout


def test_corrupt_or_foreign_entries_are_ignored_and_rewritten(tmp_path: Path) -> None:
    root = write_tree(tmp_path / "pkg", correct_package_files("demo"))
    (root / "demo" / "bad.py").write_text("x = y\n")
    expected = _lint(root).stdout
    pack = root / ".pkgtool_cache" / "lint" / pack_of(str(root))
    whole = json.loads(pack.read_text())
    good = whole["entries"][str(root)]
    lies = {**good, "findings": []}
    foreign = {**lies, "root": "/elsewhere"}
    evil = {**good, "findings": {"@": "os:system", "value": "touch /tmp/x"}}
    entries = [foreign, {**lies, "key": "0" * 64}, evil, [], "text"]
    texts = ["{not json", "[]", json.dumps({**whole, "schema": "other"}),
             json.dumps({**whole, "entries": []}),
             *(json.dumps({**whole, "entries": {str(root): entry}}) for entry in entries)]
    for text in texts:
        pack.write_text(text)
        for record in pack.parent.glob("run-*.json"):  # a replay would not read the entries
            record.unlink()
        assert _lint(root).stdout == expected
        assert _entries(root / ".pkgtool_cache")[str(root)]["findings"] == good["findings"], text


def test_entries_of_other_runs_are_kept_and_of_removed_packages_dropped(tmp_path: Path) -> None:
    ws = tmp_path / "ws"
    # A removed package's entry goes when the cache file holding it is written again.
    one, two = _sharing_a_cache_file(ws / "src")
    files = {f"src/{name}/{path}": text for name in (one, two)
             for path, text in correct_package_files(name).items()}
    write_tree(ws, files)
    _lint(ws, f"src/{one}")
    _lint(ws, f"src/{two}")
    roots = {str(ws / "src" / one), str(ws / "src" / two)}
    assert set(_entries(ws / ".pkgtool_cache")) == roots
    shutil.rmtree(ws / "src" / one)
    (ws / "src" / two / two / "new.py").write_text('"""New."""\n')
    _lint(ws, f"src/{two}")
    assert set(_entries(ws / ".pkgtool_cache")) == {str(ws / "src" / two)}


def _sharing_a_cache_file(source: Path) -> tuple[str, str]:
    """Two package names whose folders in ``source`` have their entries in one cache file."""
    seen: dict[str, str] = {}
    for number in range(100):
        name = f"pkg_{number}"
        pack = pack_of(str(source / name))
        if pack in seen:
            return seen[pack], name
        seen[pack] = name
    raise AssertionError("16 cache files hold 100 names")


def test_the_cache_folder_is_chosen_by_option_environment_or_project(tmp_path: Path) -> None:
    project = write_tree(tmp_path / "project", {"pyproject.toml": "[project]\nname = 'x'\n"})
    root = write_tree(project / "src" / "demo", correct_package_files("demo"))
    _lint(root)
    assert (project / ".pkgtool_cache" / ".gitignore").read_text().splitlines()[-1] == "*"
    assert not (root / ".pkgtool_cache").exists()
    _lint(root, env={"PKGTOOL_CACHE_DIR": str(tmp_path / "env")})
    _lint(root, "--cache-dir", "here", env={"PKGTOOL_CACHE_DIR": str(tmp_path / "env")})
    assert _entries(tmp_path / "env") and _entries(root / "here")
    _lint(root, "--cache-dir", ".")  # an existing folder: no .gitignore written into it
    assert (root / "lint").is_dir() and not (root / ".gitignore").exists()
    shutil.rmtree(project / ".pkgtool_cache")
    _lint(root, "--no-cache")
    assert not (project / ".pkgtool_cache").exists()


def test_findings_round_trip_whatever_they_carry() -> None:
    finding = make_finding()
    assert decode(json.loads(json.dumps(encode([finding])))) == [finding]
    nested = {"problem": ParseProblem("python-syntax", Span("a.py", 1, 2), "bad"),
              "spans": (Span("b.py"), Span("c.py", 3)), "severity": Severity.INFO}
    assert decode(json.loads(json.dumps(encode(nested)))) == nested
    for data in ({"@": "os.path:join"}, {"@": "pkgtool.findings:Finding", "code": 1},
                 {"@": "tuple", "items": 3}, {"@": "builtins:type"},
                 {"@": "pkgtool.__main__:main"}):
        with pytest.raises(BadEntry):
            decode(data)
    assert "pkgtool.__main__" not in sys.modules  # never imported because an entry said so


def test_a_finding_carrying_a_fix_round_trips_in_a_fresh_process() -> None:
    from pkgtool.records import replace

    from pkgtool.edit.core import Edit, Fix

    finding = replace(make_finding(), fix=Fix("Add the comma", (Edit("setup.py", 3, 3, ","),)))
    data = json.dumps(encode([finding]))
    script = ("import json, sys; from pkgtool.cache.serial import decode; "
              "print(repr(decode(json.loads(sys.stdin.read()))))")
    done = subprocess.run([sys.executable, "-c", script], input=data, capture_output=True,
                          text=True, timeout=120, check=True)
    assert done.stdout.strip() == repr([finding])


@pytest.mark.skipif(sys.platform != "linux", reason="file names are bytes on Linux only")
def test_file_and_folder_names_that_are_not_utf8(tmp_path: Path) -> None:
    ws = write_tree(tmp_path / "ws", {"src/x": ""})
    (ws / "src" / "x").unlink()
    folder = os.fsdecode(os.fsencode(ws / "src") + b"/caf\xe9")
    write_tree(Path(folder), correct_package_files("cafe"))
    with open(os.fsencode(folder) + b"/cafe/bad\xff.py", "wb") as stream:
        stream.write(b"x = y\n")
    expected = _lint(ws, "--no-cache").stdout
    assert "PYC001" in expected
    assert _lint(ws).stdout == expected
    assert _lint(ws).stdout == expected


def test_a_source_tree_stamps_its_files_and_a_release_its_version(tmp_path: Path) -> None:
    """An edited rule in an editable install must not replay an older report; an installed
    release is told apart by its version (its files are not scanned)."""
    from pkgtool.cache.replay import _source_stamp

    source = tmp_path / "src" / "pkgtool"
    source.mkdir(parents=True)
    (source / "rule.py").write_text("A = 1\n")
    before = _source_stamp(source)
    (source / "rule.py").write_text("A = 22\n")
    assert before and _source_stamp(source) != before
    release = tmp_path / "lib" / "site-packages" / "pkgtool"
    release.mkdir(parents=True)
    assert _source_stamp(release) == []
