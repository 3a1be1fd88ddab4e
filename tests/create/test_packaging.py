"""An installed (non-editable) pkgtool finds its templates: build, install the wheel, create.

``python -m build`` (as the README tells users) builds the sdist from a copy of the source (the
checkout is never written to), then the wheel from that sdist, so a file missing from the sdist
fails here. The wheel is installed into a fresh venv whose only other path is this venv's
site-packages (for jinja2 and typer); the command runs outside any checkout, so only the
packaged templates can be found.
"""

from __future__ import annotations

import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest

from tests.create.conftest import ALL_KINDS
from tests.helpers import copy_project_sources

pytestmark = pytest.mark.slow
UV = str(Path(sys.executable).parent / "uv")  # the project's installer (scripts/bootstrap.sh)
DIST = "pkgtool_ros"  # the distribution `pkgtool-ros`, normalised as in file names


def _run(*args: str, cwd: Path) -> str:
    done = subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=300,
                          check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def test_the_built_wheel_carries_the_templates_and_create_uses_them(tmp_path: Path) -> None:
    source = copy_project_sources(tmp_path / "src")
    _run(sys.executable, "-m", "build", "--installer", "uv", "-o", str(tmp_path / "dist"),
         str(source), cwd=tmp_path)
    assert len(list((tmp_path / "dist").glob(f"{DIST}-*.tar.gz"))) == 1
    wheel = next((tmp_path / "dist").glob(f"{DIST}-*-py3-none-any.whl"))
    names = zipfile.ZipFile(wheel).namelist()
    assert "pkgtool/_resources/templates/package.xml.jinja" in names
    assert "pkgtool/_resources/templates/licenses/Apache-2.0.txt" in names
    metadata = next(n for n in names if n.endswith(".dist-info/METADATA"))
    assert "Name: pkgtool-ros" in zipfile.ZipFile(wheel).read(metadata).decode()

    venv = tmp_path / "venv"
    _run(sys.executable, "-m", "venv", "--without-pip", str(venv), cwd=tmp_path)
    python = venv / "bin" / "python"
    _run(UV, "pip", "install", "--python", str(python), "--no-deps", "-q", str(wheel),
         cwd=tmp_path)
    purelib = "import sysconfig; print(sysconfig.get_paths()['purelib'])"
    site = Path(_run(str(python), "-c", purelib, cwd=tmp_path).strip())
    (site / "zz_project_deps.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")

    where = _run(str(python), "-c", "import pkgtool.resources as r; "
                 "print(r.resource_dir('templates'))", cwd=tmp_path).strip()
    assert where == str(site / "pkgtool" / "_resources" / "templates")
    out = tmp_path / "out"
    args = [str(python), "-m", "pkgtool", "create", "demo_pkg", "--destination-directory",
            str(out), "--maintainer-name", "Jane Doe", "--maintainer-email", "jane@example.com",
            "--license", "MIT", "--launch", "--config"]
    for spec in ALL_KINDS:
        args += ["--node", spec]
    _run(*args, cwd=tmp_path)
    assert (out / "demo_pkg" / "demo_pkg" / "fib_client.py").is_file()
    assert (out / "demo_pkg" / "LICENSE").read_text().startswith("MIT License")
