"""setup.py edits: into the literals the evaluator located, refusing computed values."""

from __future__ import annotations

import textwrap

import pytest

from pkgtool.edit import EditError, apply_edits
from pkgtool.edit.setup_py import SetupDoc
from pkgtool.edit.source import Source
from pkgtool.model.setup_eval import read_setup

FILES = ("setup.py", "package.xml", "resource/demo", "demo/__init__.py", "launch/demo.launch.py")


IMPORT = "from setuptools import setup\n"


def _script(text: str, name: str = "b", target: str = "demo.b:main") -> str:
    """``text`` (after a setuptools import) with one more console script."""
    text = IMPORT + textwrap.dedent(text)
    result = apply_edits(text, SetupDoc(Source("setup.py", text), FILES).add_console_script(
        name, target))
    assert result.startswith(IMPORT)
    return result[len(IMPORT):]


def _scripts(text: str) -> list[str]:
    setup = read_setup("setup.py", IMPORT + text, FILES)
    return [e.spec for e in setup.console_scripts]  # type: ignore[union-attr]


@pytest.mark.parametrize(("before", "after"), [
    # one per line, trailing comma, a comment on the last line
    ("setup(\n    entry_points={\n        'console_scripts': [\n            'a = demo.a:main',"
     "  # first\n        ],\n    },\n)\n",
     "setup(\n    entry_points={\n        'console_scripts': [\n            'a = demo.a:main',"
     "  # first\n            'b = demo.b:main',\n        ],\n    },\n)\n"),
    # no trailing comma: one is added after the last item, before its comment
    ("setup(entry_points={'console_scripts': [\n    'a = demo.a:main'  # first\n]})\n",
     "setup(entry_points={'console_scripts': [\n    'a = demo.a:main',  # first\n"
     "    'b = demo.b:main'\n]})\n"),
    # inline list
    ("setup(entry_points={'console_scripts': ['a = demo.a:main']})\n",
     "setup(entry_points={'console_scripts': ['a = demo.a:main', 'b = demo.b:main']})\n"),
    # empty inline list; double quotes are the file's style
    ('setup(name="demo", entry_points={"console_scripts": []})\n',
     'setup(name="demo", entry_points={"console_scripts": ["b = demo.b:main"]})\n'),
    # empty multi-line list, as `pkgtool create` writes it without nodes
    ("setup(\n    entry_points={\n        'console_scripts': [\n        ],\n    },\n)\n",
     "setup(\n    entry_points={\n        'console_scripts': [\n            'b = demo.b:main',\n"
     "        ],\n    },\n)\n"),
    # no console_scripts group yet
    ("setup(\n    entry_points={\n        'other': [],\n    },\n)\n",
     "setup(\n    entry_points={\n        'other': [],\n        'console_scripts': "
     "['b = demo.b:main'],\n    },\n)\n"),
    # no entry_points at all
    ("setup(\n    name='demo',\n)\n",
     "setup(\n    name='demo',\n    entry_points={'console_scripts': ['b = demo.b:main']},\n)\n"),
    # the list is a variable: its literal is edited where it is written
    ("scripts = [\n    'a = demo.a:main',\n]\nsetup(entry_points={'console_scripts': scripts})\n",
     "scripts = [\n    'a = demo.a:main',\n    'b = demo.b:main',\n]\n"
     "setup(entry_points={'console_scripts': scripts})\n"),
])
def test_console_script_goes_into_the_literal_in_its_layout(before: str, after: str) -> None:
    assert _script(before) == after
    assert _scripts(after)[-1] == "b = demo.b:main"
    assert _script(after) == after  # idempotent


def test_a_line_that_would_get_too_long_is_split_one_item_per_line() -> None:
    before = ("setup(entry_points={'console_scripts': ['first_node = demo.first_node:main', "
              "'second = demo.second:main']})\n")
    after = _script(before, "third_node", "demo.third_node:main")
    assert after == ("setup(entry_points={'console_scripts': [\n"
                     "    'first_node = demo.first_node:main',\n"
                     "    'second = demo.second:main',\n"
                     "    'third_node = demo.third_node:main',\n]})\n")


def test_crlf_and_a_bom_free_utf8_file_keep_their_line_breaks() -> None:
    before = ("# é\r\nfrom setuptools import setup\r\nsetup(entry_points={'console_scripts': "
              "[\r\n    'a = demo.a:main',\r\n]})\r\n")
    result = apply_edits(before, SetupDoc(Source("setup.py", before), FILES).add_console_script(
        "b", "demo.b:main"))
    assert result == before.replace("main',\r\n", "main',\r\n    'b = demo.b:main',\r\n")


@pytest.mark.parametrize(("text", "why"), [
    ("scripts = ['a = demo.a:main']\nscripts.append('c = demo.c:main')\n"
     "setup(entry_points={'console_scripts': scripts})\n", "not as one literal"),
    ("setup(entry_points={'console_scripts': ['a = demo.a:main'] + ['c = demo.c:main']})\n",
     "not as one literal"),
    ("setup(entry_points={'console_scripts': [f'{n} = demo.{n}:main' for n in ('a', 'c')]})\n",
     "not as one literal"),
    ("import helper\nsetup(entry_points=helper.scripts())\n", "`import helper` on line 2"),
    ("import helper\nsetup(**helper.options)\n", "does not evaluate"),
    ("base = {'console_scripts': []}\nsetup(entry_points={**base})\n", "not as one literal"),
    ("setup(entry_points='[console_scripts]\\na = demo.a:main\\n')\n", "not as one literal"),
    ("setup(entry_points={'console_scripts': 'a = demo.a:main'})\n", "one string"),
])
def test_computed_values_are_refused_saying_why(text: str, why: str) -> None:
    with pytest.raises(EditError, match=why):
        _script(text)


def test_a_name_taken_by_another_target_is_refused() -> None:
    with pytest.raises(EditError, match="already registers"):
        _script("setup(entry_points={'console_scripts': ['b = demo.other:main']})\n")


def _data(text: str, folder: str = "launch", pattern: str = "launch/*.launch.py") -> str:
    text = textwrap.dedent(text)
    return apply_edits(text, SetupDoc(Source("setup.py", text), FILES).add_data_files(
        folder, pattern, "demo"))


def test_data_files_entry_and_the_imports_it_needs() -> None:
    before = textwrap.dedent('''\
        """Set up demo."""
        from setuptools import setup

        package_name = 'demo'

        setup(
            data_files=[
                ('share/' + package_name, ['package.xml']),
            ],
        )
        ''')
    after = _data(before)
    assert after == before.replace(
        '"""Set up demo."""\n', '"""Set up demo."""\nfrom glob import glob\nimport os\n\n'
    ).replace("['package.xml']),\n", "['package.xml']),\n        (os.path.join('share', "
              "package_name, 'launch'), glob('launch/*.launch.py')),\n")
    entries = read_setup("setup.py", after, FILES).data_files  # type: ignore[union-attr]
    assert entries[-1].destination == "share/demo/launch"
    assert entries[-1].sources[0].matches == ("launch/demo.launch.py",)
    assert _data(after) == after


def test_data_files_use_the_names_setup_py_already_imports() -> None:
    before = ("import glob\nfrom os import path\nfrom setuptools import setup\n\n"
              "setup(data_files=[])\n")
    assert _data(before, "config", "config/*.yaml") == before.replace(
        "data_files=[]", "data_files=[(path.join('share', 'demo', 'config'), "
        "glob.glob('config/*.yaml'))]")


def test_data_files_already_installed_by_another_pattern_change_nothing() -> None:
    before = ("from glob import glob\nfrom setuptools import setup\n\n"
              "setup(data_files=[('share/demo/launch', glob('launch/*.py'))])\n")
    assert _data(before, "launch", "launch/demo.launch.py") == before


def test_a_setup_py_without_setup_call_is_refused() -> None:
    with pytest.raises(EditError, match="no `setup"):
        SetupDoc(Source("setup.py", "print('hi')\n"), FILES)


def test_an_item_too_long_for_the_line_splits_an_inline_list() -> None:
    text = IMPORT + "setup(data_files=[('share/demo', ['package.xml'])])\n"
    result = apply_edits(text, SetupDoc(Source("setup.py", text), FILES).add_data_files(
        "launch", "launch/*.launch.py", "demo"))
    assert result.endswith("setup(data_files=[\n    ('share/demo', ['package.xml']),\n"
                           "    (os.path.join('share', 'demo', 'launch'), "
                           "glob('launch/*.launch.py')),\n])\n")


def test_a_tuple_without_brackets_is_refused() -> None:
    text = IMPORT + ("scripts = 'a = demo.a:main',\n"
                     "setup(entry_points={'console_scripts': scripts})\n")
    with pytest.raises(EditError, match="without brackets"):
        SetupDoc(Source("setup.py", text), FILES).add_console_script("b", "demo.b:main")
