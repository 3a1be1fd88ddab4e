"""The shipped rosdistro tables against the shared ros/rosdistro files, read here independently.

The files are ``shared/data/rosdistro`` beside the checkout, or beside the repository a clean
clone was made from (CI clones the project's repository elsewhere), or ``$PKGTOOL_SHARED_DIR``.
They cannot ship with pkgtool (only tables generated from them do), so where none of those
exists the module is skipped with that reason. The tests read them with plain PyYAML, not with
the generator.
"""

from __future__ import annotations

import importlib.metadata
import os
import re
import subprocess
from functools import cache
from pathlib import Path

import pytest
import yaml

from pkgtool.knowledge import rosdistro
from pkgtool.knowledge.generate_rosdistro import tables
from pkgtool.knowledge.tables import DATA, DISTROS

ROOT = Path(__file__).resolve().parents[2]


def _shared_rosdistro() -> Path | None:
    places = [Path(os.environ["PKGTOOL_SHARED_DIR"])] if "PKGTOOL_SHARED_DIR" in os.environ else []
    places.append(ROOT.parent / "shared")
    origin = subprocess.run(["git", "-C", str(ROOT), "config", "--get", "remote.origin.url"],
                            capture_output=True, text=True, check=False).stdout.strip()
    if origin and Path(origin).is_dir():
        places.append(Path(origin).resolve().parent / "shared")
    return next((p / "data" / "rosdistro" for p in places
                 if (p / "data" / "rosdistro" / "jazzy" / "distribution.yaml").is_file()), None)


SHARED = _shared_rosdistro() or Path("shared-data-not-found")
pytestmark = pytest.mark.skipif(_shared_rosdistro() is None, reason=(
    "no shared/data/rosdistro beside the checkout or its origin, and no $PKGTOOL_SHARED_DIR"))


@cache
def _yaml(relpath: str) -> dict:  # type: ignore[type-arg]
    return yaml.load((SHARED / relpath).read_text(), Loader=yaml.CSafeLoader)


def _rosdep() -> dict:  # type: ignore[type-arg]
    return {**_yaml("rosdep/base.yaml"), **_yaml("rosdep/python.yaml")}


def test_the_shared_files_are_there() -> None:
    assert (SHARED / "jazzy" / "distribution.yaml").is_file(), f"missing {SHARED}"


def test_shipped_tables_are_what_the_generator_makes_from_the_shared_files() -> None:
    commit = re.search(r"[0-9a-f]{40}", (SHARED / "README.md").read_text()).group(0)
    for name, text in tables(SHARED, commit).items():
        assert (DATA / f"{name}.txt").read_text(encoding="utf-8") == text, (
            f"{name}.txt is stale: run python -m pkgtool.knowledge.generate_rosdistro")
    assert rosdistro.source_commit() == commit


@pytest.mark.parametrize("distro", DISTROS)
def test_released_packages_are_the_distribution_files_versioned_releases(distro: str) -> None:
    expected = set()
    for name, repository in _yaml(f"{distro}/distribution.yaml")["repositories"].items():
        release = repository.get("release") or {}
        if "version" in release:
            expected.update(release.get("packages", [name]))
    assert rosdistro.released_packages(distro) == expected
    assert all(rosdistro.is_released_package(name, distro) for name in expected)


def test_released_packages_differ_between_distros() -> None:
    assert rosdistro.is_released_package("rclpy", "humble")
    assert rosdistro.is_released_package("sensor_msgs", "jazzy")
    assert not rosdistro.is_released_package("sensor_msg", "jazzy")
    only_humble = rosdistro.released_packages("humble") - rosdistro.released_packages("jazzy")
    assert only_humble and not any(rosdistro.is_released_package(n) for n in only_humble)
    with pytest.raises(ValueError, match="known: humble"):
        rosdistro.is_released_package("rclpy", "noetic")


def test_rosdep_keys_are_the_top_level_keys_of_both_files() -> None:
    assert rosdistro.rosdep_keys() == set(_rosdep())
    assert rosdistro.is_rosdep_key("python3-numpy") and not rosdistro.is_rosdep_key("numpy")


def test_key_resolution_follows_the_ubuntu_release_of_each_distro() -> None:
    open3d = _yaml("rosdep/python.yaml")["python3-open3d"]["ubuntu"]
    assert open3d["noble"] is None and "jammy" not in open3d  # '*' applies on jammy
    assert rosdistro.key_resolves("python3-open3d", "humble")
    assert not rosdistro.key_resolves("python3-open3d", "jazzy")
    assert "focal" in _yaml("rosdep/python.yaml")["python-numpy"]["ubuntu"]
    assert not any(rosdistro.key_resolves("python-numpy", d) for d in DISTROS)
    assert all(rosdistro.key_resolves("python3-numpy", d) for d in DISTROS)


def _pip_names() -> dict[str, set[str]]:
    """Normalised pip package name -> the keys that install it, read from both files."""
    found: dict[str, set[str]] = {}

    def walk(node: object, key: str) -> None:
        if isinstance(node, dict):
            pip = node.get("pip")
            for name in (pip or {}).get("packages", []) if isinstance(pip, dict) else []:
                found.setdefault(re.sub(r"[-_.]+", "_", name).lower(), set()).add(key)
            for value in node.values():
                walk(value, key)

    for key, definition in _rosdep().items():
        walk(definition, key)
    return found


def test_every_pip_name_that_is_its_import_name_maps_to_its_keys() -> None:
    """rosdep's pip names are the oracle: ``numpy`` installs module numpy, and so on."""
    checked = 0
    for module, keys in _pip_names().items():
        if not module.isidentifier() or module in ("pyyaml", "pillow", "pyserial") or \
                module.startswith("adafruit_"):  # the older Adafruit_Python libraries'
            continue  # distributions provide capitalised modules (Adafruit_PCA9685)
        got = set(rosdistro.keys_for_import(module))
        if got:
            checked += 1
            assert keys <= got, module
    assert checked > 300


@pytest.mark.parametrize(("module", "key"), [
    ("rosdistro", "python3-rosdistro-modules"), ("_pytest", "python3-pytest"),
    ("pyflakes", "pyflakes3"), ("cv2", "python3-opencv"), ("yaml", "python3-yaml"),
    ("PIL", "python3-pil"), ("serial", "python3-serial"), ("numpy", "python3-numpy"),
    ("catkin_pkg", "python3-catkin-pkg"), ("tkinter", "python3-tk"),
    ("speech_recognition", "python-speechrecognition-pip"), ("RPi", "python-rpi.gpio-pip"),
    ("Jetson", "python-jetson-gpio-pip"),
    ("adafruit_mpu6050", "python3-adafruit-circuitpython-mpu6050-pip"), ("vlc", "python-vlc-pip"),
    ("Adafruit_PCA9685", "adafruit-pca9685-pip"),
    ("adafruit_ads1x15", "python3-adafruit-circuitpython-ads1x15-pip"),
    ("IPython", "ipython3"), ("attrs", "python3-attrs"), ("Cython", "cython3"),
])
def test_known_import_keys(module: str, key: str) -> None:
    assert rosdistro.keys_for_import(module)[0] == key
    assert key in _rosdep()


def test_a_circuitpython_import_gets_no_key_of_the_older_adafruit_library() -> None:
    """``adafruit-pca9685-pip`` installs ``Adafruit_PCA9685``; rosdep has no key for the
    CircuitPython ``adafruit_pca9685`` (b150, b155: the old key was offered as the fix)."""
    assert rosdistro.keys_for_import("adafruit_pca9685") == ()


def test_keys_that_resolve_on_the_target_come_first() -> None:
    assert rosdistro.keys_for_import("open3d", "jazzy")[0] == "python3-open3d-pip"
    assert rosdistro.keys_for_import("open3d", "humble")[0] == "python3-open3d"
    assert rosdistro.keys_for_import("no_such_module_anywhere") == ()
    assert rosdistro.keys_for_import("os") == ()  # the standard library needs no key


def test_installed_distributions_top_level_modules_map_to_their_rosdep_key() -> None:
    """For pip packages installed here, their real top-level modules map to their key."""
    pip = _pip_names()
    tops = importlib.metadata.packages_distributions()
    checked = 0
    for module, dists in tops.items():
        if not module.isidentifier() or module.startswith("__"):
            continue
        for dist in dists:
            keys = pip.get(re.sub(r"[-_.]+", "_", dist).lower())
            if keys and rosdistro.keys_for_import(module):
                checked += 1
                assert keys & set(rosdistro.keys_for_import(module)), (module, dist)
    assert checked >= 10


def test_near_misses() -> None:
    assert rosdistro.close_names("sensor_msg") == ["sensor_msgs"]
    assert rosdistro.close_names("python3-numpi") == ["python3-numpy"]
    assert rosdistro.close_names("my_local_pkg_", extra=frozenset({"my_local_pkg"})) == [
        "my_local_pkg"]


def test_stdlib_table_is_what_stdlib_list_says() -> None:
    from stdlib_list import stdlib_list

    from pkgtool.knowledge.generate_stdlib import TEST_SUITE, table

    assert (DATA / "stdlib.txt").read_text(encoding="utf-8") == table(), (
        "stdlib.txt is stale: run python -m pkgtool.knowledge.generate_stdlib")
    for distro, version in rosdistro.PYTHON_VERSIONS.items():
        expected = {m for m in stdlib_list(version) if "." not in m} | set(TEST_SUITE)
        assert rosdistro.stdlib_modules(distro) == expected
    assert rosdistro.stdlib_versions("test") == rosdistro.STDLIB_VERSIONS
    assert "imp" in rosdistro.stdlib_modules("humble")
    assert "imp" not in rosdistro.stdlib_modules("jazzy")
    assert "tomllib" not in rosdistro.stdlib_modules("humble")
    assert rosdistro.stdlib_versions("asyncore") == ("3.6", "3.7", "3.8", "3.9", "3.10", "3.11")


def test_stdlib_table_agrees_with_the_running_interpreter() -> None:
    import sys

    running = f"3.{sys.version_info[1]}"
    listed = {m for m in rosdistro.any_stdlib_module() if running in rosdistro.stdlib_versions(m)}
    public = {m for m in sys.stdlib_module_names if not m.startswith("_")}
    assert public - listed == set()


def test_ubuntu_package_names_map_to_the_key_installing_them() -> None:
    assert rosdistro.key_of_ubuntu_package("libyaml-cpp-dev") == "yaml-cpp"
    assert rosdistro.key_of_ubuntu_package("libpcap-dev") == "libpcap"  # an alias of 0.8-dev
    assert rosdistro.key_of_ubuntu_package("libpcap0.8-dev") == "libpcap"
    assert rosdistro.key_of_ubuntu_package("libopencv-dev") is None  # a key itself
    assert rosdistro.key_of_ubuntu_package("no-such-package-dev") is None


def test_a_dev_name_maps_to_its_bare_key_only_when_that_key_installs_headers() -> None:
    assert rosdistro.key_of_ubuntu_package("libopencv-highgui-dev") is None  # runtime only
    assert rosdistro.key_of_ubuntu_package("libspatialite-dev") is None  # another library
