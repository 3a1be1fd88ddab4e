"""The names the package-level modules of ``launch``, ``launch_ros`` and
``ament_index_python`` define, and the substitutions launch's XML and YAML front ends know.

Each module's top-level bindings and submodules (what ``from <module> import <name>`` can
import), public names only, read from the ros2/launch and ros2/launch_ros sources of Foxy,
Galactic, Humble, Iron, Jazzy and Rolling (December 2024): the union, so a name any of them has
is known; ament_index_python's public names from its Jazzy wheel (1.8), which Humble's match. A
name missing here may still be newer than this table.
"""

from __future__ import annotations

MODULE_NAMES: dict[str, frozenset[str]] = {
    "launch": frozenset("""
    Action Condition Event EventHandler InvalidLaunchFileError LaunchContext
    LaunchDescription LaunchDescriptionEntity LaunchDescriptionSource LaunchIntrospector
    LaunchService SomeActionsType SomeActionsType_types_tuple SomeEntitiesType
    SomeEntitiesType_types_tuple SomeSubstitutionsType SomeSubstitutionsType_types_tuple
    Substitution action actions condition conditions descriptions event event_handler
    event_handlers events frontend invalid_launch_file_error launch_context
    launch_description launch_description_entity launch_description_source
    launch_description_sources launch_introspector launch_service logging some_actions_type
    some_entities_type some_substitutions_type substitution substitutions utilities
    """.split()),
    "launch.actions": frozenset("""
    AppendEnvironmentVariable DeclareLaunchArgument EmitEvent ExecuteLocal ExecuteProcess
    GroupAction IncludeLaunchDescription LogInfo OpaqueCoroutine OpaqueFunction
    PopEnvironment PopLaunchConfigurations PushEnvironment PushLaunchConfigurations
    RegisterEventHandler ResetEnvironment ResetLaunchConfigurations SetEnvironmentVariable
    SetLaunchConfiguration Shutdown TimerAction UnregisterEventHandler
    UnsetEnvironmentVariable UnsetLaunchConfiguration append_environment_variable conftest
    declare_launch_argument emit_event execute_local execute_process group_action
    include_launch_description log_info opaque_coroutine opaque_function pop_environment
    pop_launch_configurations push_environment push_launch_configurations
    register_event_handler reset_environment reset_launch_configurations
    set_environment_variable set_launch_configuration shutdown_action timer_action
    unregister_event_handler unset_environment_variable unset_launch_configuration
    """.split()),
    "launch.conditions": frozenset("""
    IfCondition InvalidConditionExpressionError LaunchConfigurationEquals
    LaunchConfigurationNotEquals UnlessCondition evaluate_condition_expression
    evaluate_condition_expression_impl if_condition invalid_condition_expression_error
    launch_configuration_equals launch_configuration_not_equals unless_condition
    """.split()),
    "launch.event_handlers": frozenset("""
    OnExecutionComplete OnIncludeLaunchDescription OnProcessExit OnProcessIO OnProcessStart
    OnShutdown event_named on_action_event_base on_execution_complete
    on_include_launch_description on_process_exit on_process_io on_process_start
    on_shutdown
    """.split()),
    "launch.events": frozenset("""
    ExecutionComplete IncludeLaunchDescription Shutdown TimerEvent execution_complete
    include_launch_description matchers matches_action process shutdown timer_event
    """.split()),
    "launch.launch_description_sources": frozenset("""
    AnyLaunchDescriptionSource FrontendLaunchDescriptionSource
    InvalidFrontendLaunchFileError InvalidLaunchFileError InvalidPythonLaunchFileError
    PythonLaunchDescriptionSource any_launch_description_source any_launch_file_utilities
    frontend_launch_description_source frontend_launch_file_utilities
    get_launch_description_from_any_launch_file
    get_launch_description_from_frontend_launch_file
    get_launch_description_from_python_launch_file load_python_launch_file_as_module
    python_launch_description_source python_launch_file_utilities
    """.split()),
    "launch.substitutions": frozenset("""
    AllSubstitution AndSubstitution AnonName AnySubstitution Command EnvironmentVariable
    EqualsSubstitution FileContent FindExecutable IfElseSubstitution LaunchConfiguration
    LaunchLogDir LocalSubstitution NotEqualsSubstitution NotSubstitution OrSubstitution
    PathJoinSubstitution PythonExpression SubstitutionFailure TextSubstitution
    ThisLaunchFile ThisLaunchFileDir anon_name boolean_substitution command
    environment_variable equals_substitution file_content find_executable
    if_else_substitution launch_configuration launch_log_dir local_substitution
    not_equals_substitution path_join_substitution python_expression substitution_failure
    text_substitution this_launch_file this_launch_file_dir
    """.split()),
    "launch_ros": frozenset("""
    actions descriptions event_handlers events parameter_descriptions parameters_type
    remap_rule_type ros_adapters substitutions utilities
    """.split()),
    "launch_ros.actions": frozenset("""
    ComposableNodeContainer LifecycleNode LifecycleTransition LoadComposableNodes Node
    PushROSNamespace PushRosNamespace ROSTimer RosTimer SetParameter SetParametersFromFile
    SetROSLogDir SetRemap SetUseSimTime composable_node_container lifecycle_node
    lifecycle_transition load_composable_nodes node push_ros_namespace ros_timer
    set_parameter set_parameters_from_file set_remap set_ros_log_dir set_use_sim_time
    """.split()),
    "launch_ros.descriptions": frozenset("""
    ComposableNode Parameter ParameterFile ParameterValue composable_node
    """.split()),
    "launch_ros.event_handlers": frozenset("""
    OnStateTransition on_state_transition
    """.split()),
    "launch_ros.substitutions": frozenset("""
    ExecutableInPackage FindPackage FindPackagePrefix FindPackageShare Parameter
    executable_in_package find_package parameter
    """.split()),
    "ament_index_python": frozenset("""
    InvalidResourceNameError InvalidResourceTypeNameError PackageNotFoundError
    RESOURCE_INDEX_SUBFOLDER cli constants get_package_prefix get_package_share_directory
    get_package_share_path get_packages_with_prefixes get_resource get_resource_types
    get_resources get_search_paths has_resource packages resources search_paths
    """.split()),
    "ament_index_python.constants": frozenset("""
    AMENT_PREFIX_PATH_ENV_VAR RESOURCE_INDEX_SUBFOLDER
    """.split()),
    "ament_index_python.packages": frozenset("""
    PackageNotFoundError get_package_prefix get_package_share_directory get_package_share_path
    get_packages_with_prefixes get_resource get_resources get_search_paths
    """.split()),
    "ament_index_python.resources": frozenset("""
    InvalidResourceNameError InvalidResourceTypeNameError RESOURCE_INDEX_SUBFOLDER
    get_resource get_resource_types get_resources get_search_paths has_resource
    """.split()),
    "ament_index_python.search_paths": frozenset("""
    AMENT_PREFIX_PATH_ENV_VAR get_search_paths
    """.split()),
}


FRONTEND_SUBSTITUTIONS = frozenset("""
    all and anon any command dirname env equals eval exec-in-pkg file-content filename
    find-exec find-pkg-prefix find-pkg-share if launch_log_dir log_dir not not-equals or param
    var
    """.split())
"""The substitutions XML and YAML launch files can write as ``$(name ...)``: those
ros2/launch (3.7.1, December 2024) and ros2/launch_ros (Rolling, November 2024) expose with
``@expose_substitution``, the names of Humble and Jazzy included (``test`` left out: the test
suites' own)."""
ROS1_SUBSTITUTIONS = {"find": "find-pkg-share", "arg": "var", "optenv": "env"}
"""ROS 1 roslaunch substitutions that ROS 2 launch does not have, and the ROS 2 one to write
instead (``$(find pkg)``: ``$(find-pkg-share pkg)``; ``$(optenv X)``: ``$(env X '')``)."""


LAUNCH_DESCRIPTION_ATTRIBUTES = frozenset("""
    add_action add_entity deprecated deprecated_reason describe describe_conditional_sub_entities
    describe_sub_entities entities get_asyncio_future get_launch_arguments
    get_launch_arguments_with_include_launch_description_actions visit
    """.split())
"""The public attributes of ``launch.LaunchDescription`` (ros2/launch 3.7.1, its base
``LaunchDescriptionEntity`` included; Humble's have no other)."""


def homes(name: str) -> tuple[str, ...]:
    """The modules of the table that define ``name``, sorted."""
    return tuple(sorted(module for module, names in MODULE_NAMES.items() if name in names))
