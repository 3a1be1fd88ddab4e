"""SET/ENT/DAT rules on whole packages: templates and unusual but valid forms stay clean."""

from __future__ import annotations

from pathlib import Path

import pytest

from pkgtool.findings import Severity
from pkgtool.model.package import load_package
from pkgtool.rules.registry import load_all
from tests.helpers import MINIMAL_MANIFEST, findings, make_package

FAMILIES = ("SET", "ENT", "DAT")
NODE = '"""A node."""\n\n\ndef main():\n    """Run."""\n'
LAUNCH = ("from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n"
          "def generate_launch_description():\n    return LaunchDescription([Node(package='{0}',"
          " executable='talker')])\n")
CFG = "[develop]\nscript_dir=$base/lib/{0}\n[install]\ninstall_scripts=$base/lib/{0}\n"


def problems(root: Path, files: dict[str, str | bytes]) -> list[str]:
    """Errors and warnings of the SET, ENT and DAT rules, as ``CODE path:line message``."""
    codes = [c for c in load_all() if c.startswith(FAMILIES)]
    return [f"{f.code} {f.span.path}:{f.span.line} {f.message}"
            for f in findings(make_package(root, files), *codes)
            if f.severity in (Severity.ERROR, Severity.WARNING)]


def ros2_pkg_create(name: str, setup_packages: str) -> dict[str, str | bytes]:
    """The tree `ros2 pkg create --build-type ament_python --node-name my_node` writes."""
    manifest = MINIMAL_MANIFEST.format(name=name).replace(
        "<license>Apache-2.0</license>", "<license>TODO: License declaration</license>")
    setup = f"""from setuptools import find_packages, setup

package_name = '{name}'

setup(
    name=package_name,
    version='0.1.0',
    packages={setup_packages},
    data_files=[
        ('share/ament_index/resource_index/packages',
            ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Dev',
    maintainer_email='dev@example.com',
    description='TODO: Package description',
    license='TODO: License declaration',
    tests_require=['pytest'],
    entry_points={{
        'console_scripts': [
            'my_node = {name}.my_node:main'
        ],
    }},
)
"""
    return {"package.xml": manifest, "setup.py": setup, "setup.cfg": CFG.format(name),
            f"resource/{name}": "", f"{name}/__init__.py": "", f"{name}/my_node.py": NODE,
            "test/test_flake8.py": "def test_flake8():\n    pass\n",
            "test/test_pep257.py": "def test_pep257():\n    pass\n"}


@pytest.mark.parametrize("packages", ["find_packages(exclude=['test'])", "[package_name]"])
def test_ros2_pkg_create_output_is_clean(tmp_path: Path, packages: str) -> None:
    assert problems(tmp_path / "my_pkg", ros2_pkg_create("my_pkg", packages)) == []


UNUSUAL = {
    "src_layout": {
        "setup.py": """
            from setuptools import find_packages, setup
            package_name = 'demo'
            setup(
                name=package_name, version='0.1.0', license='Apache-2.0',
                packages=find_packages(where='src', exclude=['test']),
                package_dir={'': 'src'},
                data_files=[('share/ament_index/resource_index/packages', ['resource/demo']),
                            ('share/demo', ['package.xml'])],
                entry_points={'console_scripts': ['talker = demo.nodes.talker:main']},
            )
        """,
        "src/demo/__init__.py": "", "src/demo/nodes/__init__.py": "",
        "src/demo/nodes/talker.py": NODE,
    },
    "loops_and_f_strings": {
        "setup.py": """
            import os
            from glob import glob
            from setuptools import setup
            package_name = 'demo'
            data_files = [(f'share/{package_name}', ['package.xml']),
                          ('share/ament_index/resource_index/packages',
                           [f'resource/{package_name}'])]
            for folder in ('launch', 'config', 'urdf'):
                files = [f for f in glob(f'{folder}/**/*', recursive=True) if os.path.isfile(f)]
                for path in files:
                    data_files.append((os.path.join('share', package_name,
                                                    os.path.dirname(path)), [path]))
            setup(name=package_name, version='0.1.0', packages=[package_name],
                  long_description=open('README.md').read(), data_files=data_files,
                  entry_points={'console_scripts': [f'talker = {package_name}.talker:main']})
        """,
        "demo/__init__.py": "", "demo/talker.py": NODE, "launch/robot.launch.py": LAUNCH,
        "launch/sim/world_launch.py": LAUNCH, "config/params.yaml": "a: 1\n",
        "config/maps/map.yaml": "image: map.pgm\n", "README.md": "# demo\n",
    },
    "launch_flat_in_share": {
        "setup.py": """
            from pathlib import Path
            from setuptools import setup
            package_name = 'demo'
            launch = [str(p) for p in Path('launch').glob('*_launch.py')]
            setup(name=package_name, version='0.1.0', packages=[package_name],
                  data_files=[('share/ament_index/resource_index/packages',
                               ['resource/' + package_name]),
                              ('share/' + package_name, ['package.xml', *launch])],
                  entry_points={'console_scripts': ['talker = demo.talker:main']})
        """,
        "demo/__init__.py": "", "demo/talker.py": NODE, "launch/robot_launch.py": LAUNCH,
    },
    "folder_name_differs": {
        "setup.py": """
            from setuptools import setup
            setup(name='demo', version='0.1.0', packages=['monitor', 'monitor.nodes'],
                  data_files=[('share/ament_index/resource_index/packages', ['resource/demo']),
                              ('share/demo', ['package.xml'])],
                  entry_points={'console_scripts': ['talker = monitor.nodes.talker:main',
                                                    'tool = monitor:main']})
        """,
        "monitor/__init__.py": NODE, "monitor/nodes/__init__.py": "",
        "monitor/nodes/talker.py": NODE,
    },
    "declarative_setup_cfg": {
        "setup.py": "from setuptools import setup\n\nsetup()\n",
        "setup.cfg": (CFG.format("demo") + "[options]\npackages = find:\n"
                      "[options.data_files]\nshare/demo = package.xml\n"
                      "[options.entry_points]\nconsole_scripts =\n"
                      "    talker = demo.talker:main\n"),
        "demo/__init__.py": "", "demo/talker.py": NODE,
    },
    "helper_function_and_static_kwargs": {
        "setup.py": """
            import glob
            import setuptools
            NAME = 'demo'

            def share(*parts):
                return '/'.join(('share', NAME) + parts)

            KWARGS = dict(name=NAME, version='0.1.0', packages=[NAME, NAME + '.nodes'])
            if __name__ == '__main__':
                setuptools.setup(
                    data_files=[('share/ament_index/resource_index/packages',
                                 ['resource/' + NAME]),
                                (share(), ['package.xml']),
                                (share('launch'), glob.glob('launch/*.launch.xml'))],
                    entry_points={'console_scripts': '''
                        talker = demo.nodes.talker:main
                    '''},
                    **KWARGS)
        """,
        "demo/__init__.py": "", "demo/nodes/__init__.py": "", "demo/nodes/talker.py": NODE,
        "launch/robot.launch.xml": "<launch>\n  <node pkg='demo' exec='talker'/>\n</launch>\n",
    },
}


@pytest.mark.parametrize("case", sorted(UNUSUAL))
def test_unusual_but_valid_packages_are_clean(tmp_path: Path, case: str) -> None:
    files: dict[str, str | bytes] = {"package.xml": MINIMAL_MANIFEST.format(name="demo"),
                                     "setup.cfg": CFG.format("demo"), "resource/demo": ""}
    files.update(UNUSUAL[case])
    assert problems(tmp_path / "checkout-of-demo", files) == []


def test_lint_never_runs_setup_py(tmp_path: Path) -> None:
    sentinel = tmp_path / "SENTINEL"
    setup = (f"import os\nopen({str(sentinel)!r}, 'w').write('ran')\n"
             f"os.system('touch {sentinel}')\n"
             "from setuptools import setup\nsetup(name=__import__('os').getcwd())\n")
    package = make_package(tmp_path / "demo", {
        "package.xml": MINIMAL_MANIFEST.format(name="demo"), "setup.py": setup})
    codes = [c for c in load_all() if c.startswith(FAMILIES)]
    found = {f.code for f in findings(package, *codes)}
    assert not sentinel.exists()
    assert package.setup_py is not None and package.setup_py.is_unresolved("name")
    assert "SET003" not in found


@pytest.mark.parametrize("content", [b"", b"\x00\x01binary", "x = (".encode(),
                                     b"# -*- coding: latin-1 -*-\nname = '\xe9'\n"])
def test_bad_setup_py_never_raises(tmp_path: Path, content: bytes) -> None:
    root = tmp_path / "demo"
    make_package(root, {"package.xml": MINIMAL_MANIFEST.format(name="demo"), "setup.py": content})
    codes = [c for c in load_all() if c.startswith(FAMILIES)]
    for finding in findings(load_package(root), *codes):
        assert finding.span.path in ("setup.py", "package.xml")


@pytest.mark.parametrize(("finder", "init", "hides"), [
    ("find_packages(exclude=['test'])", True, True),
    ("find_namespace_packages(exclude=['test'])", False, False),
])
def test_a_launch_folder_hides_launch_only_as_a_regular_package(
        tmp_path: Path, finder: str, init: bool, hides: bool) -> None:
    """A `launch/` folder installed as a package: with `__init__.py` it is a regular package
    that comes before ROS 2's `launch`; without, a namespace package, which hides nothing."""
    files = ros2_pkg_create("my_pkg", finder)
    files["setup.py"] = str(files["setup.py"]).replace(
        "from setuptools import find_packages, setup",
        "from setuptools import find_namespace_packages, find_packages, setup")
    files["launch/demo.launch.py"] = LAUNCH.format("my_pkg")
    if init:
        files["launch/__init__.py"] = ""
    found = [p for p in problems(tmp_path / "my_pkg", files)
             if p.startswith("SET014") and "the folder `launch`" in p]
    assert len(found) == 1 and ("hides the real `launch` module" in found[0]) == hides, found
