# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""robot_status_server answers std_srvs/Trigger calls on /robot_status."""

from my_robot_pkg.robot_status_server import RobotStatusService
from std_srvs.srv import Trigger


def test_status_call_reports_online_and_ready(ros):
    ros.spin_in_background(RobotStatusService(context=ros.context))
    client = ros.node('operator').create_client(Trigger, '/robot_status')
    assert client.wait_for_service(timeout_sec=5.0)
    future = client.call_async(Trigger.Request())
    assert ros.spin_until(future.done)
    assert future.result().success is True
    assert 'Online and ready' in future.result().message


def test_service_name_follows_the_node_namespace(ros):
    server = ros.own(RobotStatusService(context=ros.context, namespace='/robot1'))
    names = dict(server.get_service_names_and_types_by_node(server.get_name(), '/robot1'))
    assert names['/robot1/robot_status'] == ['std_srvs/srv/Trigger']
