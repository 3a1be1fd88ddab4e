"""The curated tables are facts: checked against real NumPy and real rclpy, not assumed."""

from __future__ import annotations

import importlib
import pkgutil
import sys
import warnings

import pytest

from pkgtool.knowledge import rosdistro
from pkgtool.knowledge.numpy_removed import REMOVED
from pkgtool.knowledge.rclpy_classes import attributes_of, classes
from pkgtool.knowledge.rclpy_missing import entries, missing_attribute, owners
from pkgtool.knowledge.rclpy_names import close_name, defined_on, defines
from pkgtool.knowledge.ros_names import looks_like_ros
from pkgtool.knowledge.rosdep import (CMAKE_NAMES, NOT_ROSDEP_KEYS, accepted_keys,
                                      key_for_python_module, package_for_ros_module,
                                      stdlib_modules, suggested_key)


def test_suggested_keys_are_rosdep_keys_that_resolve_on_every_distro() -> None:
    """Each key offered instead of a name is a rosdep key, or a ROS package (`rclpy` for
    `rclpy_lifecycle`), of every distribution."""
    for key in (*NOT_ROSDEP_KEYS.values(), *CMAKE_NAMES.values()):
        assert all(rosdistro.key_resolves(key, distro) or
                   rosdistro.is_released_package(key, distro)
                   for distro in rosdistro.DISTROS), key


def test_public_lookups() -> None:
    assert key_for_python_module("cv2") == "python3-opencv"
    assert key_for_python_module("no_such_module_anywhere") is None
    assert suggested_key("python-opencv") == "python3-opencv"
    assert suggested_key("opencv-python") == "python3-opencv"
    assert suggested_key("yaml") is None  # a real rosdep key (libyaml)
    assert package_for_ros_module("tf2_ros") == "tf2_ros_py"
    assert package_for_ros_module("sensor_msgs") == "sensor_msgs"
    assert accepted_keys("PyKDL", "python3-pykdl") == ("python3-pykdl",
                                                       "python_orocos_kdl_vendor")
    assert "os" in stdlib_modules() and "numpy" not in stdlib_modules()


@pytest.mark.parametrize("name", ["sensor_msgs", "std_srvs", "my_robot_interfaces", "rclpy",
                                  "rcl_interfaces", "tf2_geometry_msgs", "launch_ros",
                                  "cv_bridge", "ament_index_python", "nav2_simple_commander"])
def test_ros_names(name: str) -> None:
    assert looks_like_ros(name)


@pytest.mark.parametrize("name", ["numpy", "launchpadlib", "rospy_helpers_x", "messages",
                                  "mylib"])
def test_not_ros_names(name: str) -> None:
    assert not looks_like_ros(name)


def test_numpy_names_are_really_gone_from_numpy_2() -> None:
    import numpy

    assert int(numpy.__version__.split(".")[0]) >= 2
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        present = [name for name, removed in REMOVED.items()
                   if "back in 2.0" not in removed.removed_in and hasattr(numpy, name)]
        back = [name for name, removed in REMOVED.items()
                if "back in 2.0" in removed.removed_in and not hasattr(numpy, name)]
    assert present == [] and back == []


def test_numpy_2_expired_names_with_replacements_are_covered() -> None:
    from numpy._expired_attrs_2_0 import __expired_attributes__ as expired

    common = {"float_", "complex_", "string_", "unicode_", "Inf", "NaN", "PINF", "NINF",
              "alltrue", "sometrue", "round_", "cfloat", "longfloat", "asfarray", "mat"}
    assert common <= set(expired) and common <= set(REMOVED)


def _import_all_of_rclpy() -> None:
    rclpy = importlib.import_module("rclpy")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # deprecated modules such as rclpy.qos_event
        for info in pkgutil.walk_packages(rclpy.__path__, "rclpy."):
            try:
                importlib.import_module(info.name)
            except Exception:  # optional submodules that need other packages
                continue


def _resolve(dotted: str) -> object:
    module, _, name = dotted.rpartition(".")
    try:
        return importlib.import_module(dotted)
    except ImportError:
        return getattr(importlib.import_module(module), name)


@pytest.mark.ros
def test_rclpy_attributes_in_the_table_do_not_exist() -> None:
    _import_all_of_rclpy()
    existing = [(owner, attr) for owner, attr in entries() if hasattr(_resolve(owner), attr)]
    assert existing == []


@pytest.mark.ros
def test_rclpy_class_aliases_are_the_same_classes() -> None:
    for canonical, aliases in owners().items():
        assert all(_resolve(alias) is _resolve(canonical) for alias in aliases)
    assert missing_attribute("rclpy.action.client.ActionClient", "GoalStatus")
    assert missing_attribute("rclpy.action.ActionClient", "send_goal_async") is None


@pytest.mark.ros
def test_rclpy_names_table_knows_every_name_of_the_installed_rclpy() -> None:
    """No false error: whatever the installed (Jazzy) rclpy defines, PYC004 accepts."""
    _import_all_of_rclpy()
    rclpy = importlib.import_module("rclpy")
    modules = ["rclpy", *(info.name for info in pkgutil.walk_packages(rclpy.__path__, "rclpy."))]
    unknown = [f"{name}.{attr}" for name in modules if name in sys.modules
               for attr in dir(sys.modules[name]) if not defines(name, attr, "jazzy")]
    assert unknown == []
    assert not defines("rclpy", "excutors") and not defines("rclpy.qos", "QoSProfil")
    assert defines("rclpy.qos_event", "SubscriptionEventCallbacks")  # Humble's and Jazzy's
    assert close_name("rclpy.executors", "SingleThreadExecutor") == "SingleThreadedExecutor"
    assert not defines("rclpy", "event_handler", "humble") and defines("rclpy", "event_handler")
    assert defined_on("rclpy.time", "CONVERSION_CONSTANT") == ["humble"]
    assert defines("rclpy.time", "CONVERSION_CONSTANT", "kilted")  # no table: any distro


@pytest.mark.ros
def test_rclpy_classes_table_knows_every_attribute_of_real_objects() -> None:
    """No false error: every public attribute of the objects a real (Jazzy) node makes, its
    clock, times, durations, futures and parameters, of the executors, action clients, their
    goal handles and servers, and of rclpy's enums, is in PYC004's table (PYC004 never
    reports a name starting with ``_``)."""
    import rclpy
    from rclpy.duration import Duration
    from rclpy.action import ActionClient, ActionServer, CancelResponse, GoalResponse
    from rclpy.action.client import ClientGoalHandle
    from unique_identifier_msgs.msg import UUID
    from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor
    from rclpy.node import Node
    from rclpy.qos import DurabilityPolicy, HistoryPolicy, LivelinessPolicy, ReliabilityPolicy
    from std_msgs.msg import String
    from std_srvs.srv import Trigger
    from test_msgs.action import Fibonacci

    context = rclpy.Context()
    rclpy.init(context=context)
    try:
        node = Node("probe", context=context)
        now = node.get_clock().now()
        made = {"rclpy.publisher.Publisher": node.create_publisher(String, "probe", 1),
                "rclpy.subscription.Subscription": node.create_subscription(
                    String, "probe", print, 1),
                "rclpy.timer.Timer": node.create_timer(10.0, print),
                "rclpy.timer.Rate": node.create_rate(1.0),
                "rclpy.client.Client": node.create_client(Trigger, "probe"),
                "rclpy.service.Service": node.create_service(Trigger, "probe", print),
                "rclpy.clock.ROSClock": node.get_clock(), "rclpy.time.Time": now,
                "rclpy.duration.Duration": now - now,
                "rclpy.task.Future": node.create_client(Trigger, "other").call_async(
                    Trigger.Request()),
                "rclpy.executors.SingleThreadedExecutor": SingleThreadedExecutor(context=context),
                "rclpy.executors.MultiThreadedExecutor": MultiThreadedExecutor(context=context),
                "rclpy.action.client.ActionClient": ActionClient(node, Fibonacci, "probe"),
                "rclpy.action.server.ActionServer": ActionServer(node, Fibonacci, "probe",
                                                                 execute_callback=print),
                "rclpy.parameter.Parameter": node.declare_parameter("probe", 1.0)}
        made["rclpy.action.client.ClientGoalHandle"] = ClientGoalHandle(
            made["rclpy.action.client.ActionClient"], UUID(),
            Fibonacci.Impl.SendGoalService.Response())
        made.update({f"rclpy.qos.{enum.__name__}": enum for enum in
                     (ReliabilityPolicy, HistoryPolicy, DurabilityPolicy, LivelinessPolicy)})
        made.update({f"rclpy.action.server.{enum.__name__}": enum for enum in
                     (GoalResponse, CancelResponse)})
        assert isinstance(made["rclpy.duration.Duration"], Duration)
        unknown = {cls: sorted(a for a in dir(obj) if not a.startswith("_") and
                               a not in (attributes_of(cls) or ()))
                   for cls, obj in made.items()}
        for action in (made[f"rclpy.action.{kind.lower()}.Action{kind}"] for kind in
                       ("Client", "Server")):
            action.destroy()
        node.destroy_node()
        for executor in (made[f"rclpy.executors.{kind}Executor"] for kind in
                         ("SingleThreaded", "MultiThreaded")):
            executor.shutdown()
    finally:
        rclpy.shutdown(context=context)
    assert {cls: names for cls, names in unknown.items() if names} == {}
    assert sorted(made) == sorted(classes())


@pytest.mark.ros
def test_rclpy_signatures_table_knows_every_parameter_of_the_installed_rclpy() -> None:
    """No false error: every parameter the installed (Jazzy) rclpy's functions, methods and
    constructors take is in PYC029's table, and a function taking ``**kwargs`` says so."""
    import importlib
    import inspect

    from pkgtool.knowledge.generate_rclpy_signatures import FUNCTIONS, METHODS
    from pkgtool.knowledge.rclpy_signatures import parameters_of

    wanted = {name: f"{cls}.{name}" for cls, names in METHODS.items() for name in names}
    wanted.update(FUNCTIONS)
    missing = {}
    for call, where in wanted.items():
        module_name, *attributes = where.split(".")
        found: object = importlib.import_module(module_name)
        for attribute in attributes:
            try:
                found = getattr(found, attribute)
            except AttributeError:
                found = importlib.import_module(f"{found.__name__}.{attribute}")  # type: ignore
        parameters = inspect.signature(found).parameters.values()  # type: ignore[arg-type]
        names = {p.name if p.kind is not p.VAR_KEYWORD else "**" for p in parameters
                 if p.kind is not p.VAR_POSITIONAL} - {"self"}
        if names - (parameters_of(call) or set()):
            missing[call] = sorted(names - (parameters_of(call) or set()))
    assert missing == {}


@pytest.mark.ros
def test_node_tables_know_every_attribute_of_the_installed_rclpy_nodes() -> None:
    """No false PYC023: what the installed (Jazzy) Node and LifecycleNode classes define, the
    tables know (name-mangled privates aside); each lifecycle name is the lifecycle node's."""
    import rclpy.lifecycle
    import rclpy.node

    from pkgtool.knowledge.rclpy_node import (LIFECYCLE_NODE_ATTRIBUTES, LIFECYCLE_NODES,
                                              NODE_ATTRIBUTES)

    lifecycle = rclpy.lifecycle.LifecycleNode
    public = {name for name in dir(lifecycle) if not name.startswith(("__", "_Lifecycle"))}
    assert public - LIFECYCLE_NODE_ATTRIBUTES == set()
    assert {n for n in dir(rclpy.node.Node) if not n.startswith("__")} - NODE_ATTRIBUTES == set()
    assert all(_resolve(name) is lifecycle for name in LIFECYCLE_NODES)
