"""Generate the rosdistro tables from a ros/rosdistro checkout.

``python -m pkgtool.knowledge.generate_rosdistro``
reads ``<distro>/distribution.yaml`` (humble, jazzy, kilted, rolling) and ``rosdep/base.yaml``
and ``rosdep/python.yaml`` (default: ``../shared/data/rosdistro`` beside the repository) and
writes four tables to ``pkgtool/knowledge/data/``:

- ``ros_packages.txt``: the ROS packages each distribution releases (a release with a version);
- ``rosdep_keys.txt``: every rosdep key, flagged with the distributions on whose Ubuntu release
  (``release_platforms`` of the distribution file) the key resolves;
- ``python_imports.txt``: top-level Python import name (lower case) -> the keys that install it,
  best first, read from the keys' pip packages and Debian/Gentoo package names;
- ``ubuntu_packages.txt``: an Ubuntu package name that is no key -> the one key installing it
  (``libpcap-dev`` -> ``libpcap``), for a package.xml naming the Debian package.

The commit of the checkout is read from its README (``commit <sha>``) or given with ``--commit``.
"""

from __future__ import annotations

import argparse
import re
from collections.abc import Iterator
from pathlib import Path

import yaml

from pkgtool.knowledge.rosdistro import any_stdlib_module
from pkgtool.knowledge.tables import DATA, DISTROS, flags_of, render, write

DEFAULT_SOURCE = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "rosdistro"
INSTALLERS = frozenset({"pip", "apt", "source", "packages"})

DIST_MODULES: dict[str, tuple[str, ...]] = {
    "opencv-python": ("cv2",), "opencv-python-headless": ("cv2",),
    "opencv-contrib-python": ("cv2",), "opencv": ("cv2",), "pillow": ("PIL",), "pil": ("PIL",),
    "pyyaml": ("yaml",), "pyserial": ("serial",), "python-dateutil": ("dateutil",),
    "scikit-learn": ("sklearn",), "scikit-image": ("skimage",), "beautifulsoup4": ("bs4",),
    "gitpython": ("git",), "git-python": ("git",), "pygobject": ("gi",), "pyzmq": ("zmq",),
    "websocket-client": ("websocket",), "pyusb": ("usb",), "pyopengl": ("OpenGL",),
    "opengl": ("OpenGL",), "pycairo": ("cairo",), "dbus-python": ("dbus",),
    "pymongo": ("pymongo", "bson", "gridfs"), "paho-mqtt": ("paho",), "empy": ("em",),
    "pybullet": ("pybullet", "pybullet_data", "pybullet_envs", "pybullet_utils"),
    "grpcio": ("grpc",), "lark-parser": ("lark",), "python-can": ("can",),
    "ruamel-yaml": ("ruamel",), "pytest": ("pytest", "_pytest", "py"),
    "setuptools": ("setuptools", "pkg_resources", "_distutils_hack"),
    "pkg-resources": ("pkg_resources",), "libgpiod": ("gpiod",), "tz": ("pytz",),
    "pykdl": ("PyKDL",), "python-orocos-kdl": ("PyKDL",), "faiss-cpu": ("faiss",),
    "hydra-core": ("hydra",), "python-docx": ("docx",), "py-multicast": ("multicast",),
    "tk": ("tkinter", "turtle", "turtledemo", "idlelib"), "venv": ("ensurepip",),
    "protobuf": ("google.protobuf",), "pycryptodome": ("Crypto",),
    "pycryptodomex": ("Cryptodome",),
    "pyjwt": ("jwt",), "python-xlib": ("Xlib",), "xlib": ("Xlib",), "attrs": ("attr", "attrs"),
    "msgpack-python": ("msgpack",), "netcdf4": ("netCDF4",), "pynacl": ("nacl",),
    "python-magic": ("magic",), "python-slugify": ("slugify",), "wxpython": ("wx",),
    "matplotlib": ("matplotlib", "mpl_toolkits", "pylab"),
    "speechrecognition": ("speech_recognition",), "rpi-gpio": ("RPi",), "jetson-gpio": ("Jetson",),
    "python-vlc": ("vlc",), "jetson-stats": ("jtop",), "sparkfun-ublox-gps": ("ublox_gps",),
    "adafruit-blinka": ("adafruit_blinka", "board", "busio", "digitalio", "microcontroller"),
    "python-socketio": ("socketio",), "python-dotenv": ("dotenv",), "numpy-stl": ("stl",),
    "future": ("future", "past", "libfuturize", "libpasteurize"),
}
"""Distribution names (PyPI, or Debian/Gentoo without ``python3-``) whose modules have other names.

Facts about each distribution's top-level modules (checked against installed wheels where the
test environment has them); an ``adafruit-circuitpython-foo`` library provides ``adafruit_foo``,
any other distribution ``foo-bar`` provides ``foo_bar``.
"""

KEPT_STDLIB = frozenset({"tkinter", "turtle", "turtledemo", "idlelib", "ensurepip"})
"""Standard library modules that Debian and Ubuntu ship in a package of their own
(``python3-tk``: tkinter and what imports it; ``python3-venv``: ensurepip)."""


def _commit(source: Path) -> str:
    readme = source / "README.md"
    found = re.search(r"\b([0-9a-f]{40})\b", readme.read_text()) if readme.is_file() else None
    if not found:
        raise SystemExit(f"No commit in {readme}: give it with --commit.")
    return found.group(1)


def _load(path: Path) -> dict:  # type: ignore[type-arg]
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    with path.open(encoding="utf-8") as stream:
        return yaml.load(stream, Loader=loader) or {}


def released_packages(distribution: dict) -> set[str]:  # type: ignore[type-arg]
    """Names of the packages a distribution file releases (repositories with a version)."""
    names: set[str] = set()
    for repository, entry in (distribution.get("repositories") or {}).items():
        release = (entry or {}).get("release") or {}
        if release.get("version"):
            names.update(release.get("packages") or [repository])
    return names


def resolves(definition: object, os_name: str, codename: str) -> bool:
    """True when a rosdep definition installs something (or nothing, by design) there."""
    if not isinstance(definition, dict):
        return False
    entry = definition.get(os_name, definition.get("*"))
    if entry is None:
        return False
    if not isinstance(entry, dict) or INSTALLERS & entry.keys():
        return True
    if codename in entry:
        return entry[codename] is not None
    return entry.get("*") is not None


def _names(definition: object, os_name: str | None = None) -> Iterator[tuple[str, str]]:
    """(kind, name) pairs of a definition: ``pip`` names and (os, package) names elsewhere."""
    if isinstance(definition, dict):
        for key, value in definition.items():
            if key == "pip":  # `pip: {packages: [...]}`, or the short `pip: [...]`
                names = value.get("packages") or [] if isinstance(value, dict) else \
                    [value] if isinstance(value, str) else value or []
                yield from (("pip", str(n)) for n in names)
            else:
                yield from _names(value, os_name or str(key))
    elif isinstance(definition, list):
        yield from ((os_name or "", str(n)) for n in definition)
    elif isinstance(definition, str):
        yield (os_name or "", definition)


_DEBIAN_NAME = re.compile(r"[a-z0-9][a-z0-9+.-]+")


def _debian_names(definition: object) -> Iterator[str]:
    """The Ubuntu and Debian package names a key's definition installs with apt (any
    release; not pip's, nor a source installer's files)."""
    if not isinstance(definition, dict):
        return
    for os_name in ("ubuntu", "debian"):
        found = definition.get(os_name)
        releases = found.values() if isinstance(found, dict) and not \
            INSTALLERS & found.keys() else [found]
        for release in releases:
            if isinstance(release, dict):
                release = (release.get("apt") or {}).get("packages") \
                    if isinstance(release.get("apt"), dict) else release.get("packages")
            names = [release] if isinstance(release, str) else release or []
            yield from (str(n) for n in names if _DEBIAN_NAME.fullmatch(str(n)))


def distribution_names(definition: object) -> set[str]:
    """Names of the Python distributions a definition installs, normalised (PEP 503)."""
    found = set()
    for kind, name in _names(definition):
        if kind == "pip":
            found.add(name)
        elif kind in ("ubuntu", "debian", "openembedded") and \
                name.startswith("python3-"):
            found.add(name[len("python3-"):].split("@")[0])
        elif kind == "gentoo" and name.startswith("dev-python/"):
            found.add(name[len("dev-python/"):])
    return {re.sub(r"[-_.]+", "-", n.split("[")[0]).lower() for n in found}


def modules_of(distribution: str, stdlib: frozenset[str]) -> set[str]:
    """Top-level import names (lower case) a normalised distribution name provides."""
    circuit = distribution.removeprefix("adafruit-circuitpython-")
    default = f"adafruit_{circuit}" if circuit != distribution else distribution
    modules = DIST_MODULES.get(distribution, (default.replace("-", "_"),))
    tops = {m.split(".")[0].lower() for m in modules}
    return {m for m in tops if m.isidentifier() and (m not in stdlib or m in KEPT_STDLIB)}


def _rank(key: str, name: str, owners: set[str]) -> tuple[int, int, str]:
    """Preference among keys providing one module: apt python3 keys (the module's name, then
    the name of a distribution providing it: ``gridfs`` is pymongo's), -pip keys, others
    (named for Python 3 first), py2."""
    if key.startswith("python-"):
        tier = 6
    elif key.endswith("-pip"):
        tier = 3
    elif key.startswith("python3-"):
        named = key.removeprefix("python3-")
        tier = 0 if named == name.replace("_", "-") else 1 if named in owners else 2
    else:
        tier = 4 if key.endswith("3") else 5  # `ipython3` before `ipython` (Python 2's)
    return (tier, len(key), key)


def tables(source: Path, commit: str) -> dict[str, str]:
    """The text of each table generated from the checkout at ``source``."""
    distributions = {d: _load(source / d / "distribution.yaml") for d in DISTROS}
    rosdep = {**_load(source / "rosdep" / "base.yaml"), **_load(source / "rosdep" / "python.yaml")}
    origin = f"ros/rosdistro {commit}"
    by_package: dict[str, set[str]] = {}
    for distro, distribution in distributions.items():
        for name in released_packages(distribution):
            by_package.setdefault(name, set()).add(distro)
    platforms = {d: (dist.get("release_platforms") or {}).get("ubuntu") or []
                 for d, dist in distributions.items()}
    by_key = {key: {d for d in DISTROS if any(resolves(definition, "ubuntu", c)
                                              for c in platforms[d])}
              for key, definition in rosdep.items()}
    stdlib = any_stdlib_module()
    by_module: dict[str, set[str]] = {}
    owners: dict[str, set[str]] = {}
    older_adafruit = {key for key, definition in rosdep.items()
                      if any(_older_adafruit(d) for d in distribution_names(definition))}
    for key, definition in rosdep.items():
        for distribution in distribution_names(definition):
            for module in modules_of(distribution, stdlib):
                by_module.setdefault(module, set()).add(key)
                owners.setdefault(module, set()).add(distribution)
    ubuntu = ", ".join(f"{d}: {' '.join(platforms[d])}" for d in DISTROS)
    by_ubuntu_name: dict[str, set[str]] = {}
    for key, definition in rosdep.items():
        for name in _debian_names(definition):
            if name not in rosdep:
                by_ubuntu_name.setdefault(name, set()).add(key)
    return {
        "ros_packages": render(
            "ROS packages released per distribution (flags: h=humble j=jazzy k=kilted "
            "r=rolling).\nGenerated by `python -m pkgtool.knowledge.generate_rosdistro`; "
            "do not edit.", origin, _grouped(by_package)),
        "rosdep_keys": render(
            "rosdep keys of base.yaml and python.yaml, flagged with the distributions on whose "
            f"Ubuntu release\n({ubuntu}) they resolve. Generated by "
            "`python -m pkgtool.knowledge.generate_rosdistro`; do not edit.",
            origin, _grouped(by_key)),
        "python_imports": render(
            "Top-level Python import name (lower case) -> the rosdep keys whose pip, Debian or "
            "Gentoo packages\nprovide it, best first. Generated by "
            "`python -m pkgtool.knowledge.generate_rosdistro`; do not edit.", origin,
            [("", [" ".join([m, *sorted(keys, key=lambda k: _rank(k, m, owners[m]))])
                   for m, keys in sorted(by_module.items())]),
             (OLDER_ADAFRUIT, sorted(older_adafruit))]),
        "ubuntu_packages": render(
            "Ubuntu (and Debian) package names that are no rosdep key -> the one key of "
            "base.yaml or python.yaml\ninstalling each (names several keys install are left "
            "out). Generated by\n`python -m pkgtool.knowledge.generate_rosdistro`; do not edit.",
            origin, [("", [f"{name} {next(iter(keys))}" for name, keys in
                           sorted(by_ubuntu_name.items()) if len(keys) == 1])]),
    }


OLDER_ADAFRUIT = "older-adafruit"
"""The flag of python_imports.txt's group of keys installing the older Adafruit_Python
libraries (imported capitalised, ``Adafruit_PCA9685``), not CircuitPython's (``adafruit_pca9685``):
the table's module names are in lower case, which would mix the two families up."""


def _older_adafruit(distribution: str) -> bool:
    """True for a (normalised) distribution of the older Adafruit_Python family."""
    return distribution.startswith("adafruit-") and not distribution.startswith(
        ("adafruit-circuitpython-", "adafruit-blinka", "adafruit-platformdetect",
         "adafruit-pureio"))


def _grouped(flags_by_name: dict[str, set[str]]) -> list[tuple[str, list[str]]]:
    groups: dict[str, list[str]] = {}
    for name in sorted(flags_by_name):
        groups.setdefault(flags_of(flags_by_name[name]), []).append(name)
    return sorted(groups.items(), key=lambda item: (-len(item[1]), item[0]))


def main(argv: list[str] | None = None) -> None:
    """Write the tables."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", type=Path, default=DEFAULT_SOURCE,
                        help="a ros/rosdistro checkout (default: %(default)s)")
    parser.add_argument("--commit", help="the checkout's commit (default: read from README.md)")
    parser.add_argument("--output", type=Path, default=DATA, help="where to write the tables")
    args = parser.parse_args(argv)
    write(tables(args.source, args.commit or _commit(args.source)), args.output)


if __name__ == "__main__":
    main()
