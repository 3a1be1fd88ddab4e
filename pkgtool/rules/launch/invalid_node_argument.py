"""LCH005: a launch node action without its executable, or with arguments ROS 2 rejects."""

from __future__ import annotations

from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.launch import NodeRef
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.ros_name_checks import node_name_problem, topic_name_problem

PYTHON_ACTIONS = frozenset({"Node", "LifecycleNode", "ComposableNodeContainer"})
"""Python node actions; each needs ``executable=``."""
FRONTEND_TAGS = frozenset({"node", "lifecycle_node", "node_container"})
"""XML/YAML node tags; each needs ``exec``."""
REMOVED_KEYWORDS = {"node_executable": "executable", "node_name": "name",
                    "node_namespace": "namespace"}
"""Python keywords of ROS 2 Dashing to Foxy that Galactic removed, and their names now."""


def removed_message(action: str, name: str) -> str:
    """LCH005's message on a keyword of :data:`REMOVED_KEYWORDS` (its fixer matches it)."""
    return f"`{action}()` has no `{name}` argument since ROS 2 Galactic (Foxy deprecated it)"


WRONG_ATTRIBUTES = {"type": "`exec` (`type` is ROS 1)", "executable": "`exec`",
                    "package": "`pkg`", "ns": "`namespace` (`ns` is ROS 1)",
                    "node_name": "`name`", "node_executable": "`exec`",
                    "node_namespace": "`namespace`", "machine": "nothing (ROS 1 only)",
                    "required": "`on_exit=\"shutdown\"`", "clear_params": "nothing (ROS 1 only)"}
"""XML/YAML attributes of ``<node>`` that ROS 2's launch rejects, and what to write instead."""
_PROCESS_KEYWORDS = frozenset("""
    prefix cwd env additional_env shell sigterm_timeout sigkill_timeout emulate_tty output
    output_format cached_output log_cmd on_exit respawn respawn_delay respawn_max_retries
    condition""".split())
"""What a node action passes on to ``ExecuteProcess``, ``ExecuteLocal`` and ``Action``
(launch, Foxy to Rolling: the union); any other keyword raises TypeError."""
KEYWORDS = {
    "Node": frozenset("""executable package name namespace exec_name parameters remappings
                      ros_arguments arguments""".split()) | _PROCESS_KEYWORDS,
}
KEYWORDS["LifecycleNode"] = KEYWORDS["Node"] | {"autostart"}
KEYWORDS["ComposableNodeContainer"] = KEYWORDS["Node"] | {"composable_node_descriptions"}
"""The keywords each Python node action of launch_ros takes (Foxy to Rolling: the union,
read from the ros2/launch_ros and ros2/launch sources), besides :data:`REMOVED_KEYWORDS`.
``LifecycleNode(autostart=...)`` came with ros2/launch_ros#430 (Rolling, and Jazzy from
launch_ros 0.26.7)."""
OUTPUTS = frozenset({"screen", "log", "both", "own_log", "full"})
"""The ``output`` configurations launch knows (launch.logging, Humble to Rolling)."""


_SHARE_LOOKUP = lazy_pattern(r"\$\(\s*find-pkg-(?:share|prefix)\b")
"""A substitution giving a package's folder, not its name."""
_ROS1_PARAM = "; `file=` is ROS 1's `<rosparam file=>`"


def _names(node: NodeRef) -> Iterator[tuple[str, str, Span]]:
    """(message, fix, where) for a static node name or namespace that rcl rejects."""
    problem = node_name_problem(node.name) if node.name else None
    if problem:
        yield (f"`{node.name}` is not a valid node name: {problem}",
               "Use only letters, digits and underscores", node.span)
    namespace = (node.namespace or "").rstrip("/")  # launch_ros strips trailing slashes
    problem = topic_name_problem(namespace) if namespace else None  # none, or the root
    if problem:
        yield (f"`{node.namespace}` is not a valid namespace: {problem}",
               "Use only letters, digits and underscores, and `/` between parts", node.span)


def _output(node: NodeRef) -> Iterator[tuple[str, str, Span]]:
    """(message, fix, where) for a static ``output`` launch has no configuration for."""
    if node.output is not None and node.output not in OUTPUTS:
        close = get_close_matches(node.output, sorted(OUTPUTS), n=1)
        yield (f"`output` of `{node.action}` is `{node.output}`, which launch does not know "
               f"({', '.join(f'`{o}`' for o in sorted(OUTPUTS))}): it raises ValueError when "
               "it starts the node", f"Write `{close[0]}`" if close else "Write `screen`",
               node.span)


def _problems(node: NodeRef) -> Iterator[tuple[str, str, Span]]:
    """(message, fix, where) for each argument problem of one node action."""
    yield from _names(node)
    yield from _output(node)
    given = set(node.arguments)
    if node.not_text:
        where, keyword = node.not_text
        yield (f"`{keyword}=` of `{node.action}()` holds a number or bool, not text: launch "
               "takes text and substitutions only and raises TypeError",
               "Quote it: `'2'`", where)
    if node.text_not_list:
        where, keyword = node.text_not_list
        effect = "launch passes each character as an argument" if keyword == "arguments" \
            else "launch raises TypeError (a list plus a str)"
        yield (f"`{keyword}=` of `{node.action}()` is one string, not a list: {effect}",
               f"Split it into a list: `{keyword}=['--log-level', 'debug']`", where)
    if node.joined_words:
        where, keyword, text = node.joined_words
        yield (f"`'{text}'` in `{keyword}=` of `{node.action}()` is one command-line argument "
               "holding several words: the node gets it as one word and cannot parse it (an "
               "option with its value, or a word and an option, are separate list items)",
               _split_words(text, keyword), where)
    if node.remappings_not_pairs:
        yield (f"`remappings=` of `{node.action}()` is not a list of (from, to) tuples",
               "Put each remapping in a tuple of two, in a list: "
               "`remappings=[('/chatter', '/talk')]`", node.remappings_not_pairs)
    if node.action in PYTHON_ACTIONS:
        removed = set() if node.other_distros else given & REMOVED_KEYWORDS.keys()
        for name in sorted(removed):
            where = node.executable_span if name == "node_executable" else None
            yield (removed_message(node.action, name),
                   f"Write `{REMOVED_KEYWORDS[name]}=`", where or node.span)
        for name in sorted(given - KEYWORDS[node.action] - REMOVED_KEYWORDS.keys() - {"*", "**"}):
            close = get_close_matches(name, sorted(KEYWORDS[node.action]), n=1)
            yield (f"`{node.action}()` has no `{name}` argument: launch raises TypeError",
                   f"Write `{close[0]}=`" if close else "Remove it", node.span)
        if not given & {"executable", "node_executable", "**"}:
            yield (f"`{node.action}()` has no `executable`",
                   "Add `executable='<console script>'`", node.span)
        if node.parameters_not_list:
            yield (f"`parameters=` of `{node.action}()` is not a list",
                   "Put the file paths and dicts in a list: `parameters=[params]`",
                   node.parameters_not_list)
    elif node.action in FRONTEND_TAGS:
        for name in sorted(given & WRONG_ATTRIBUTES.keys()):
            yield (f"`<{node.action}>` has no `{name}` attribute in ROS 2",
                   f"Write {WRONG_ATTRIBUTES[name]} instead", node.span)
        if "exec" not in given and not given & {"type", "executable", "node_executable"}:
            yield (f"`<{node.action}>` has no `exec` attribute", "Add `exec=\"<executable>\"`",
                   node.span)
        if node.package_written and _SHARE_LOOKUP.search(node.package_written):
            yield (f"`pkg` of `<{node.action}>` is `{node.package_written}`, a folder of the "
                   "package, not its name: launch cannot find the package (PackageNotFoundError)",
                   "Write the package's name: `pkg=\"my_pkg\"`", node.span)
        for where, attributes in node.params_without_source:
            ros1 = _ROS1_PARAM if "file" in attributes else ""
            yield ("`<param>` has neither `name` nor `from`: launch raises ValueError (param "
                   f"Entity should have name or from attribute){ros1}",
                   "Write `from=` for a parameter file, or `name=` and `value=`", where)


_ROS_OPTIONS = frozenset({"-r", "--remap", "-p", "--param", "--params-file", "-e",
                          "--enclave", "--log-level", "--log-config-file", "--disable-rosout-logs",
                          "--disable-stdout-logs", "--disable-external-lib-logs"})
"""Options of ROS's own arguments, which come after ``--ros-args``."""


def _ros_option(words: list[str]) -> bool:
    """True for words that are ROS's own arguments: a long option of ROS's
    (``--log-level``), or ``-r``/``-p`` given ROS's ``name:=value``."""
    first = words[0]
    if first.startswith("--"):
        return first in _ROS_OPTIONS
    return first in _ROS_OPTIONS and len(words) > 1 and ":=" in words[1]


def _split_words(text: str, keyword: str) -> str:
    """The fix of an item holding several words: each word its own item, as a shell splits
    them (quoted text kept together), after ``'--ros-args'`` for ROS's own options."""
    import shlex

    try:
        words = shlex.split(text)
    except ValueError:
        words = text.split()
    shown = ", ".join(repr(word) for word in words)
    if keyword == "arguments" and words and _ros_option(words):
        return (f"Write each word as an item, after `'--ros-args'`: {shown} (or give them "
                "as `ros_arguments=`)")
    return f"Write each word as an item: {shown}"


@rule("LCH005", "invalid-launch-node-argument", Severity.ERROR,
      fix="Name the executable with `executable=` (Python) or `exec` (XML, YAML)")
def invalid_launch_node_argument(package: Package) -> Iterator[Hit]:
    """A launch node has no executable, or an argument ROS 2's launch rejects.

    ## What it does
    Checks the node actions of launch files: Python `Node`, `LifecycleNode` and
    `ComposableNodeContainer` calls need `executable=`, must not use `node_executable`,
    `node_name` or `node_namespace` (deprecated in Foxy, gone since Galactic) nor a keyword none of
    Foxy to Rolling takes (`nam=`, `parameter=`, `args=`), and their `parameters=`
    must be a list (not a path, a string, a tuple or a dict); their `remappings=` (and
    those of a `ComposableNode`) must be a list of tuples of two (not a single pair
    `('/a', '/b')`, a string, a dict, nor a list holding a string `[('/a')]`, a list or a
    tuple of another length); only displays and literals are judged. XML and YAML `node`,
    `lifecycle_node` and `node_container` need `exec` and must not use ROS 1 or Python
    attribute names (`type`, `ns`, `executable`, `package`, `required`, ...); an XML node's
    `pkg` must not be a package's folder (`$(find-pkg-share x)`), and each of its `<param>`
    needs `name` or `from` (`<param file=...>` is ROS 1's rosparam). Calls that pass
    `**kwargs` are not checked, nor the removed keywords of calls in either branch of a test
    on the ROS distribution (`if os.environ['ROS_DISTRO'] <= 'eloquent':`, also through a
    variable assigned from `os.environ.get('ROS_DISTRO')`, `os.getenv('ROS_DISTRO')` or a
    command's output, `subprocess.Popen('echo $ROS_DISTRO', ...)`): that code is written for
    older distributions on purpose. Nodes that are never started (left
    out of the LaunchDescription) are checked too: the call that makes them raises. In every
    kind of launch file, a node name or namespace written literally (`name='talker node'`,
    `namespace="my robot"`, a `__node:=` remapping) must be one rcl accepts: letters,
    digits and underscores (and `/` between the parts of a namespace, which may also end
    with `/`: launch strips it), no part starting
    with a digit, and a literal `output` must be one launch knows (`screen`, `log`, `both`,
    `own_log`, `full`); a Python `arguments=`, `ros_arguments=` or `remappings=` display must
    hold text (`arguments=['--rate', 2]` is refused), and `arguments=` or `ros_arguments=` must
    be a list, not one string (`arguments='--ros-args --log-level debug'` passes each
    character as an argument; `ros_arguments='...'` raises TypeError), whose items are one
    word each (`'-r in:=/image_raw'` or `'serial --dev /dev/ttyACM0'` reach the node as one
    word, which its parser rejects).

    ## Why is this bad?
    `ros2 launch` stops before starting anything: Python raises `TypeError: unexpected keyword
    argument` (or, for `parameters=`, launch_ros's "expected 'parameters' to be one of
    [list]"), and the XML and YAML front ends reject unknown attributes ("Unexpected
    attribute(s) found in `node`") and a node without `exec`. A node name or namespace
    rcl rejects makes the node exit at start-up (`InvalidNodeNameException`,
    `InvalidNamespaceException`, or rcl failing to parse the `__node:=` remapping).

    ## Example
    ```xml
    <node pkg="my_pkg" type="talker" name="talker" ns="robot1"/>
    ```

    ## Use instead
    ```xml
    <node pkg="my_pkg" exec="talker" name="talker" namespace="robot1"/>
    ```
    """
    for launch in package.launch_files:
        for node in launch.nodes:
            for message, fix, where in _problems(node):
                yield Hit(where, message, fix)
