"""Property tests: the same content in random formatting, edited; only the edit's span changes.

Each case draws a package.xml or setup.py with random indentation, quotes, comments, blank
lines, line breaks (LF or CRLF), attribute order and layout, applies an edit, and checks that
(1) the edits only insert or remove their own text, every other byte staying in place,
(2) re-parsing gives exactly the intended model change, and (3) a second run changes nothing.
"""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pkgtool.edit import Edit, apply_edits
from pkgtool.edit.manifest import ManifestDoc
from pkgtool.edit.setup_py import SetupDoc
from pkgtool.edit.source import Source
from pkgtool.model.manifest import parse_manifest
from pkgtool.model.setup_eval import read_setup
from pkgtool.rules.manifest.schema import slot_index

NAMES = st.sampled_from(["rclpy", "std_msgs", "sensor_msgs", "geometry_msgs", "python3-numpy",
                         "ament_index_python", "tf2_ros", "nav_msgs", "action_msgs", "zed"])
DEP_TAGS = st.sampled_from(["depend", "exec_depend", "test_depend", "buildtool_depend",
                            "build_depend", "doc_depend"])
PROFILE = settings(max_examples=150, deadline=None, derandomize=True, database=None,
                   suppress_health_check=[HealthCheck.too_slow])


def _only_inserts(before: str, after: str, edits: list[Edit]) -> None:
    """Every byte outside the edits' spans is kept; inside, only whitespace may go.

    An edit is a pure insertion unless it re-lays a container out one item per line; then the
    text it replaces must survive in the replacement, apart from whitespace.
    """
    assert after == apply_edits(before, edits)
    for edit in edits:
        replaced = "".join(before[edit.start:edit.end].split())
        kept = "".join(edit.replacement.split())
        found = 0
        for char in replaced:  # a subsequence: nothing of the old text is dropped
            found = kept.find(char, found) + 1
            assert found, (replaced, kept)


@st.composite
def manifests(draw: st.DrawFn) -> tuple[str, list[tuple[str, str, dict[str, str]]]]:
    """A format-3 package.xml in a random layout, and its dependencies in document order."""
    newline = draw(st.sampled_from(["\n", "\r\n"]))
    indent = draw(st.sampled_from(["  ", "    ", "\t", " "]))
    quote = draw(st.sampled_from(['"', "'"]))
    deps = draw(st.lists(st.tuples(DEP_TAGS, NAMES), max_size=8, unique=True))
    if draw(st.booleans()):
        deps.sort(key=lambda d: (slot_index(d[0], 3), d[0], d[1]))
    parts = [f"<package format={quote}3{quote}>"]

    def put(element: str) -> None:
        if draw(st.integers(0, 4)) == 0:
            parts.append("")  # a blank line
        if draw(st.integers(0, 5)) == 0:
            parts.append(f"{indent}<!-- note -->")
        trailing = " <!-- why -->" if draw(st.integers(0, 6)) == 0 else ""
        parts.append(f"{indent}{element}{trailing}")

    for element in ("<name>demo</name>", "<version>1.0.0</version>",
                    "<description>Demo.</description>",
                    f"<maintainer email={quote}a@b.org{quote}>A</maintainer>",
                    "<license>MIT</license>"):
        put(element)
    declared = []
    for tag, name in deps:
        attributes = {"version_gte": "1.0"} if draw(st.integers(0, 4)) == 0 else {}
        if attributes and draw(st.booleans()):
            attributes = {"condition": "$ROS_VERSION == 2", **attributes}
        if draw(st.booleans()):
            attributes = dict(reversed(attributes.items()))
        attrs = "".join(f" {k}={quote}{v}{quote}" for k, v in attributes.items())
        put(f"<{tag}{attrs}>{name}</{tag}>")
        declared.append((tag, name, attributes))
    put(f"<export>{newline}{indent * 2}<build_type>ament_python</build_type>{newline}"
        f"{indent}</export>")
    parts.append("</package>")
    head = draw(st.sampled_from(["", '<?xml version="1.0"?>' + newline]))
    return head + newline.join(parts) + newline, declared


def _deps(text: str) -> list[tuple[str, str]]:
    manifest = parse_manifest("package.xml", text)
    return sorted((d.tag, d.name) for d in manifest.dependencies)  # type: ignore[union-attr]


def _order(text: str) -> list[int]:
    manifest = parse_manifest("package.xml", text)
    return [slot_index(c.tag, 3) or 0 for c in manifest.root.children]  # type: ignore[union-attr]


@PROFILE
@given(manifests(), DEP_TAGS, NAMES)
def test_adding_a_dependency_changes_only_its_line(case: tuple, tag: str, name: str) -> None:
    text, declared = case
    edits = ManifestDoc(Source("package.xml", text)).add(tag, name)
    result = apply_edits(text, edits)
    if any(t == tag and n == name and not a for t, n, a in declared):
        assert edits == []
        return
    _only_inserts(text, result, edits)
    assert all(e.replacement.strip() == f"<{tag}>{name}</{tag}>" for e in edits)
    assert _deps(result) == sorted([*_deps(text), (tag, name)])
    if _order(text) == sorted(_order(text)):
        assert _order(result) == sorted(_order(result))
    group = [n for t, n, _ in declared if t == tag]
    if group == sorted(group, key=str.lower):
        manifest = parse_manifest("package.xml", result)
        after = [d.name for d in manifest.dependencies if d.tag == tag]  # type: ignore[union-attr]
        assert after == sorted(after, key=str.lower)
    if "\r\n" in text:
        assert "\n" not in result.replace("\r\n", "")
    assert ManifestDoc(Source("package.xml", result)).add(tag, name) == []


@PROFILE
@given(manifests(), st.data())
def test_removing_a_dependency_removes_only_it(case: tuple, data: st.DataObject) -> None:
    text, declared = case
    if not declared:
        return
    tag, name, _ = data.draw(st.sampled_from(declared))
    doc = ManifestDoc(Source("package.xml", text))
    edit = doc.remove(doc.find(tag, name)[0])
    result = apply_edits(text, [edit])
    assert result == text[:edit.start] + text[edit.end:]
    assert "<" not in text[edit.start:edit.end].replace(f"<{tag}", "", 1).replace(
        f"</{tag}>", "", 1).replace("<!-- why -->", "")
    expected = _deps(text)
    expected.remove((tag, name))
    assert _deps(result) == expected


@st.composite
def setup_files(draw: st.DrawFn) -> tuple[str, list[str]]:
    """A setup.py with random quotes, layout, comments and line breaks; its console scripts."""
    newline = draw(st.sampled_from(["\n", "\r\n"]))
    unit = draw(st.sampled_from(["    ", "  "]))
    q = draw(st.sampled_from(["'", '"']))
    scripts = draw(st.lists(st.sampled_from(["talker", "listener", "beat", "caller"]),
                            max_size=3, unique=True))
    specs = [f"{s} = demo.{s}:main" for s in scripts]
    comment = draw(st.sampled_from(["", "  # a node"]))
    trailing = draw(st.booleans())
    if draw(st.booleans()):  # one per line
        lines = [f"{unit * 3}{q}{spec}{q}," for spec in specs]
        if lines and not trailing:
            lines[-1] = lines[-1][:-1]
        if lines:
            lines[-1] += comment
        listed = f"[{newline}" + "".join(line + newline for line in lines) + f"{unit * 2}]"
    else:
        comma = "," if trailing and specs else ""
        listed = "[" + ", ".join(f"{q}{spec}{q}" for spec in specs) + comma + "]"
    name = draw(st.sampled_from(["package_name", f"{q}demo{q}"]))
    blank = newline * draw(st.integers(1, 2))
    body = [f"{unit}name={name},", f"{unit}version={q}1.0.0{q},",
            f"{unit}packages=[{q}demo{q}],",
            f"{unit}data_files=[({q}share/demo{q}, [{q}package.xml{q}])],",
            f"{unit}entry_points={{{newline}{unit * 2}{q}console_scripts{q}: {listed},"
            f"{newline}{unit}}},"]
    text = (f"# setup of demo{newline}from setuptools import setup{blank}"
            f"package_name = {q}demo{q}{blank}setup({newline}" + newline.join(body)
            + f"{newline}){newline}")
    return text, specs


FILES = ("setup.py", "package.xml", "demo/__init__.py", "config/params.yaml")


def _setup(text: str):  # type: ignore[no-untyped-def]
    return read_setup("setup.py", text, FILES)


@PROFILE
@given(setup_files(), st.sampled_from(["talker", "fresh_node"]))
def test_adding_a_console_script_changes_only_the_list(case: tuple, script: str) -> None:
    text, specs = case
    edits = SetupDoc(Source("setup.py", text), FILES).add_console_script(
        script, f"demo.{script}:main")
    result = apply_edits(text, edits)
    spec = f"{script} = demo.{script}:main"
    if spec in specs:
        assert edits == []
        return
    _only_inserts(text, result, edits)
    assert [e.spec for e in _setup(result).console_scripts] == [*specs, spec]
    before, after = _setup(text), _setup(result)
    assert (after.name, after.version, after.data_files) == \
        (before.name, before.version, before.data_files)
    if "\r\n" in text:
        assert "\n" not in result.replace("\r\n", "")
    assert SetupDoc(Source("setup.py", result), FILES).add_console_script(
        script, f"demo.{script}:main") == []


@PROFILE
@given(setup_files())
def test_adding_data_files_changes_only_the_list_and_imports(case: tuple) -> None:
    text, _ = case
    edits = SetupDoc(Source("setup.py", text), FILES).add_data_files(
        "config", "config/*.yaml", "demo")
    result = apply_edits(text, edits)
    _only_inserts(text, result, edits)
    entries = _setup(result).data_files
    assert [(e.destination, [s.matches for s in e.sources]) for e in entries] == [
        ("share/demo", [("package.xml",)]),
        ("share/demo/config", [("config/params.yaml",)])]
    assert [e.spec for e in _setup(result).console_scripts] == \
        [e.spec for e in _setup(text).console_scripts]
    assert SetupDoc(Source("setup.py", result), FILES).add_data_files(
        "config", "config/*.yaml", "demo") == []
