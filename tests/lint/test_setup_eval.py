"""The setup.py evaluator: every construct it must compute, and what it must refuse to guess."""

from __future__ import annotations

import textwrap

import pytest

from pkgtool.model.setup_eval import read_setup
from pkgtool.model.setup_py import SetupPy
from pkgtool.model.span import ParseProblem

FILES = ("setup.py", "package.xml", "resource/demo", "demo/__init__.py", "demo/talker.py",
         "demo/nodes/__init__.py", "demo/nodes/listener.py", "demo/utils/helpers.py",
         "launch/a.launch.py", "launch/b_launch.py", "launch/sub/c.launch.py",
         "config/params.yaml", "config/.secret.yaml", "test/__init__.py", "test/test_x.py",
         "src/other/__init__.py", "src/other/mod.py", "tool.py")


def evaluate(body: str, files: tuple[str, ...] = FILES) -> SetupPy:
    """Evaluate a setup.py whose text is ``body`` (dedented)."""
    result = read_setup("setup.py", textwrap.dedent(body).lstrip("\n"), files)
    assert isinstance(result, SetupPy), result
    return result


def data(setup: SetupPy) -> dict[str, tuple[str, ...]]:
    """data_files as destination -> all matched sources."""
    assert setup.data_files is not None, setup.unresolved
    return {f.destination: tuple(m for s in f.sources for m in s.matches)
            for f in setup.data_files}


def test_string_operations() -> None:
    setup = evaluate("""
        from setuptools import setup
        base = 'de'
        name = base + 'mo'
        version = '%s.%d.%s' % ('1', 2, '3')
        setup(name=name, version=version, description=f'{name!r} v{version:>6}',
              license='{}-{}'.format('Apache', '2.0'), maintainer=' '.join(['A', 'B']).upper())
    """)
    assert setup.name and setup.name.value == "demo"
    assert setup.version and setup.version.value == "1.2.3"
    assert setup.description and setup.description.value == "'demo' v 1.2.3"
    assert setup.license and setup.license.value == "Apache-2.0"
    assert setup.maintainer and setup.maintainer.value == "A B"
    assert setup.unresolved == ()


def test_module_level_mutations_loops_and_comprehensions() -> None:
    setup = evaluate("""
        import os
        from glob import glob
        from setuptools import setup
        package_name = 'demo'
        data_files = [('share/' + package_name, ['package.xml'])]
        data_files += [('share/ament_index/resource_index/packages', ['resource/demo'])]
        for folder in ['launch', 'config']:
            data_files.append((os.path.join('share', package_name, folder),
                               glob(folder + '/*.*')))
        extra = []
        extra.extend([f for f in glob('launch/**/*.py', recursive=True) if 'sub' in f])
        data_files.append(('share/demo/sub', extra))
        setup(name=package_name, data_files=data_files)
    """)
    assert data(setup) == {
        "share/demo": ("package.xml",),
        "share/ament_index/resource_index/packages": ("resource/demo",),
        "share/demo/launch": ("launch/a.launch.py", "launch/b_launch.py"),
        "share/demo/config": ("config/params.yaml",),
        "share/demo/sub": ("launch/sub/c.launch.py",),
    }


def test_setup_inside_main_function_and_static_kwargs() -> None:
    setup = evaluate("""
        import setuptools
        KW = {'name': 'demo', 'version': '0.1.0'}
        def main():
            setuptools.setup(packages=['demo'], **KW)
        if __name__ == '__main__':
            main()
    """)
    assert setup.name and setup.name.value == "demo"
    assert setup.packages and setup.packages.names == ("demo",)
    assert setup.setup_span and setup.setup_span.line == 4


def test_helper_function_with_arguments_and_return() -> None:
    setup = evaluate("""
        from glob import glob
        from setuptools import setup
        def share(folder, pattern='*'):
            return ('share/demo/' + folder, sorted(glob(f'{folder}/{pattern}')))
        setup(data_files=[share('launch', pattern='*.py'), share('config')])
    """)
    assert data(setup) == {"share/demo/launch": ("launch/a.launch.py", "launch/b_launch.py"),
                           "share/demo/config": ("config/params.yaml",)}


def test_an_early_return_under_a_test_not_evaluated_leaves_the_result_unknown() -> None:
    setup = evaluate("""
        import os
        from setuptools import setup
        def files(folder):
            found = []
            if not os.path.isdir(os.path.join(os.path.dirname(__file__), folder)):
                return found  # may or may not happen: the result is not `[]`
            for name in os.listdir(folder):
                found.append(os.path.join(folder, name))
            return found
        def first(names):
            for name in names:
                if name.endswith(os.environ['SUFFIX']):
                    break  # may or may not happen: `kept` is not all of `names`
                kept.append(name)
            return kept
        kept = []
        setup(data_files=[('share/demo/launch', files('launch'))],
              packages=first(['demo', 'other']))
    """)
    assert setup.data_files is None and setup.packages is None
    assert setup.unresolved


def test_globs_match_like_the_glob_module() -> None:
    setup = evaluate("""
        from glob import glob
        import glob as g
        from setuptools import setup
        setup(data_files=[('a', glob('launch/*')), ('b', g.glob('launch/**', recursive=True)),
                          ('c', glob('config/*')), ('d', glob('nothing/*.py'))])
    """)
    assert setup.data_files is not None
    sources = {f.destination: f.sources[0] for f in setup.data_files}
    assert sources["a"].matches == ("launch/a.launch.py", "launch/b_launch.py", "launch/sub")
    assert "launch/sub/c.launch.py" in sources["b"].matches
    assert sources["c"].matches == ("config/params.yaml",)  # hidden files are not matched
    assert sources["d"].is_glob and sources["d"].pattern == "nothing/*.py"
    assert sources["d"].matches == ()


def test_globs_keep_the_spelling_glob_returns() -> None:
    """``glob`` keeps the literal folders as written and a trailing slash (the oracle's finds)."""
    setup = evaluate("""
        import os
        from glob import glob
        from setuptools import setup
        setup(description=' '.join(glob('./launch/*.py') + glob(os.path.join('.', 'config', '*'))),
              maintainer=' '.join(glob('launch//*/') + glob('launch/**/', recursive=True)))
    """)
    assert setup.description and setup.description.value == \
        "./launch/a.launch.py ./launch/b_launch.py ./config/params.yaml"
    assert setup.maintainer and setup.maintainer.value == "launch/sub/ launch/ launch/sub/"


@pytest.mark.parametrize("call", ["glob('missing/**', recursive=True)", "glob('launch/*/./x')",
                                  "glob('tool.py/**', recursive=True)"])
def test_globs_glob_answers_oddly_are_unresolved(call: str) -> None:
    """``glob('missing/**', recursive=True)`` is ``['missing/']`` in CPython: not guessed."""
    setup = evaluate(f"from glob import glob\nfrom setuptools import setup\n"
                     f"setup(data_files=[('share/demo', {call})])")
    assert setup.is_unresolved("data_files")


def test_pathlib_globbing_and_str_of_paths() -> None:
    setup = evaluate("""
        from pathlib import Path
        from setuptools import setup
        launch = Path('launch')
        setup(data_files=[
            ('share/demo/launch', [str(p) for p in sorted(launch.glob('*.launch.py'))]),
            ('share/demo/all', [p.as_posix() for p in Path('.').rglob('*.yaml')]),
            ('share/demo', [str(Path('package.xml'))]),
            ('share/demo/none', [str(p) for p in launch.glob('*.xml')]),
        ])
    """)
    assert data(setup) == {"share/demo/launch": ("launch/a.launch.py",),
                           "share/demo/all": ("config/.secret.yaml", "config/params.yaml"),
                           "share/demo": ("package.xml",), "share/demo/none": ()}
    assert setup.data_files is not None
    assert setup.data_files[3].sources[0].pattern == "launch/*.xml"


@pytest.mark.parametrize(("call", "names"), [
    ("find_packages()", ("demo", "demo.nodes", "test")),
    ("find_packages(exclude=['test'])", ("demo", "demo.nodes")),
    ("find_packages(exclude=('test', 'demo.*'))", ("demo",)),
    ("find_packages(include=['demo*'])", ("demo", "demo.nodes")),
    ("find_packages(where='src')", ("other",)),
    ("find_namespace_packages(include=['demo', 'demo.*'])",
     ("demo", "demo.nodes", "demo.utils")),
])
def test_package_finders(call: str, names: tuple[str, ...]) -> None:
    setup = evaluate(f"""
        from setuptools import find_namespace_packages, find_packages, setup
        setup(packages={call})
    """)
    assert setup.packages is not None
    assert setup.packages.names == names
    assert setup.packages.kind == call.split("(")[0]


def test_src_layout_and_py_modules() -> None:
    setup = evaluate("""
        from setuptools import find_packages, setup
        setup(packages=find_packages('src'), package_dir={'': 'src/'}, py_modules=['tool'])
    """)
    assert setup.packages and setup.packages.where == "src"
    assert setup.package_dir == {"": "src"}
    assert setup.py_modules == ("tool",)


def test_entry_points_as_lists_strings_and_ini() -> None:
    setup = evaluate('''
        from setuptools import setup
        setup(entry_points={
            'console_scripts': ['talker = demo.talker:main', 'bad'],
            'other': """
                x = demo.x:run
            """,
        })
    ''')
    points = {(e.group, e.name): e for e in setup.entry_points or ()}
    assert points[("console_scripts", "talker")].module == "demo.talker"
    assert points[("console_scripts", "talker")].span.line == 3
    assert not points[("console_scripts", "bad")].valid
    assert points[("other", "x")].attr == "run" and points[("other", "x")].span.line == 5
    ini = evaluate('''
        from setuptools import setup
        setup(entry_points="""
        [console_scripts]
        talker = demo.talker:main [extra]
        """)
    ''')
    assert [(e.name, e.attr, e.span.line) for e in ini.console_scripts] == [("talker", "main", 4)]


@pytest.mark.parametrize(("body", "keyword", "source"), [
    ("setup(long_description=open('README.md').read())", "long_description", "open("),
    ("import os\nsetup(version=os.environ['V'])", "version", "os.environ"),
    ("from demo import __version__\nsetup(version=__version__)", "version", "from demo"),
    ("setup(packages=unknown())", "packages", "unknown()"),
    ("import os\nsetup(data_files=[('x', os.listdir('config'))])", "data_files", "os.listdir"),
    ("import os\nsetup(name=os.path.abspath('.'))", "name", "os.path.abspath"),
    ("files = []\nfor f in open('list.txt'):\n    files.append(f)\nsetup(data_files=files)",
     "data_files", "open("),
    ("x = []\nwith open('a') as f:\n    x = f.read()\nsetup(name=x)", "name", "open("),
])
def test_dynamic_code_is_unresolved_never_guessed(body: str, keyword: str, source: str) -> None:
    setup = evaluate("from setuptools import setup\n" + body)
    assert setup.is_unresolved(keyword)
    assert getattr(setup, keyword, None) is None
    reason = dict(setup.unresolved)[keyword]
    assert source in reason.source and reason.span.line >= 2


def test_other_keywords_survive_an_unresolved_one() -> None:
    setup = evaluate("""
        from setuptools import setup
        setup(name='demo', long_description=open('README.md').read(), version='1.0.0')
    """)
    assert setup.name and setup.version and setup.is_unresolved("long_description")


def test_unknown_branch_makes_changed_names_unresolved() -> None:
    setup = evaluate("""
        import sys
        from setuptools import setup
        files = ['package.xml']
        if sys.platform == 'win32':
            files.append('win.txt')
        setup(name='demo', data_files=[('share/demo', files)])
    """)
    assert setup.name and setup.is_unresolved("data_files")


def test_ros_version_branches_are_decided_for_ros2() -> None:
    setup = evaluate("""
        import os
        ROS_VERSION = int(os.environ['ROS_VERSION'])
        if ROS_VERSION == 1:
            from catkin_pkg.python_setup import generate_distutils_setup
            from distutils.core import setup
            d = generate_distutils_setup(packages=['demo'])
            setup(**d)
        elif ROS_VERSION == 2:
            from setuptools import setup
            setup(name='demo', packages=['demo'])
    """)
    assert setup.name and setup.name.value == "demo"
    assert setup.setup_span and setup.setup_span.line == 10
    assert not setup.is_unresolved("**") and not setup.is_unresolved("packages")


def test_setup_call_forms() -> None:
    assert evaluate("print('no setup here')").setup_span is None
    wrapped = evaluate("from helpers import setup\nsetup(name='demo')")
    assert wrapped.setup_span and wrapped.is_unresolved("**")
    unreached = evaluate("from setuptools import setup\ndef build():\n    setup(name='x')\n")
    assert unreached.setup_span and unreached.setup_span.line == 3
    assert unreached.is_unresolved("**")


@pytest.mark.parametrize("text", ["from setuptools import setup\nsetup(name='x'\n",
                                  "x = " + "(" * 5000 + ")" * 5000,
                                  "x = " + "'a' + " * 50_000 + "'a'"])
def test_syntax_errors_and_unparsable_nesting_are_parse_problems(text: str) -> None:
    result = read_setup("setup.py", text, FILES)
    assert isinstance(result, ParseProblem)
    assert result.kind == "python-syntax" and result.span.path == "setup.py"


@pytest.mark.parametrize("body", [
    "x = 'a' * 10**9\nsetup(name=x)",
    "x = []\nfor i in range(10**5):\n    for j in range(10**5):\n        x.append(j)\n"
    "setup(name='a', data_files=x)",
    "x = 'a'\nwhile True:\n    x += x\nsetup(name=x)",
    "setup(name=" + "'a' + " * 900 + "'a')",
])
def test_runaway_code_is_bounded(body: str) -> None:
    setup = evaluate("from setuptools import setup\n" + body)
    assert setup.setup_span is not None
    assert setup.name is None or setup.name.value == "a"


def test_data_files_string_sources_and_bare_files() -> None:
    setup = evaluate("""
        from setuptools import setup
        setup(data_files=[('share/demo', 'package.xml'), 'tool.py', ('share/x', ['missing'])])
    """)
    assert setup.data_files is not None
    text_entry, bare, missing = setup.data_files
    assert text_entry.sources_is_text
    assert bare.destination == "" and bare.sources[0].matches == ("tool.py",)
    assert missing.sources[0].matches == () and not missing.sources[0].is_glob


def test_setup_py_without_setup_call_is_complete() -> None:
    setup = evaluate("")
    assert setup.setup_span is None and setup.unresolved == () and setup.keywords == ()
    assert not setup.is_unresolved("name") and setup.console_scripts == ()


def test_try_runs_the_body_and_distrusts_handlers() -> None:
    setup = evaluate("""
        try:
            from setuptools import setup
        except ImportError:
            from distutils.core import setup
        files = ['package.xml']
        try:
            import yaml
        except ImportError:
            files = []
        setup(name='demo', data_files=[('share/demo', files)])
    """)
    assert setup.name and setup.is_unresolved("data_files") and not setup.is_unresolved("**")


def test_a_failed_statement_only_taints_what_it_can_change() -> None:
    setup = evaluate("""
        import os
        from setuptools import setup
        name = 'demo'
        files = ['package.xml']
        other = []
        walked = [os.path.join(name, r) for r, _, fs in os.walk('models')]
        unknown_helper(files, name)
        setup(name=name, version=os.path.join('1', '0'), data_files=[('share', files)],
              py_modules=other)
    """)
    assert setup.name and setup.version and setup.py_modules == ()
    assert setup.is_unresolved("data_files")
