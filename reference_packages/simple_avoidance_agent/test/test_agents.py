# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Both agents driven through ROS: LaserScan on /scan in, Twist on /cmd_vel out."""

import math
import random

from geometry_msgs.msg import Twist
import pytest
from rclpy.parameter import Parameter
from scans import LAYOUTS, make_scan
from sensor_msgs.msg import LaserScan
from simple_avoidance_agent.advanced_avoidance_agent import AdvancedAvoidanceAgent
from simple_avoidance_agent.avoidance_agent import AvoidanceAgent


def _command_for(ros, agent, scan: LaserScan) -> Twist:
    ros.add(agent)
    driver = ros.node('driver')
    publisher = driver.create_publisher(LaserScan, '/scan', 10)
    received = []
    driver.create_subscription(Twist, '/cmd_vel', received.append, 10)
    assert ros.spin_until(lambda: received, tick=lambda: publisher.publish(scan))
    return received[0]


@pytest.mark.parametrize(('name', 'angle_min', 'increment', 'count'), LAYOUTS)
def test_obstacle_ahead_makes_the_agent_turn(ros, name, angle_min, increment, count):
    scan = make_scan(angle_min, increment, count, obstacles=((0.0, 4.0, 0.4),))
    twist = _command_for(ros, AvoidanceAgent(context=ros.context), scan)
    assert twist.linear.x == 0.0 and twist.angular.z == -0.5, name


@pytest.mark.parametrize(('name', 'angle_min', 'increment', 'count'), LAYOUTS)
def test_clear_path_makes_the_agent_drive(ros, name, angle_min, increment, count):
    scan = make_scan(angle_min, increment, count, obstacles=((90.0, 10.0, 0.3),))
    twist = _command_for(ros, AvoidanceAgent(context=ros.context), scan)
    assert twist.linear.x == 0.2 and twist.angular.z == 0.0, name


@pytest.mark.parametrize(('name', 'angle_min', 'increment', 'count'), LAYOUTS)
def test_advanced_agent_turns_away_from_a_left_obstacle(ros, name, angle_min, increment, count):
    scan = make_scan(angle_min, increment, count, obstacles=((30.0, 10.0, 0.5),))
    twist = _command_for(ros, AdvancedAvoidanceAgent(context=ros.context), scan)
    assert twist.linear.x == 0.0 and twist.angular.z == -0.5, name


@pytest.mark.parametrize(('name', 'angle_min', 'increment', 'count'), LAYOUTS)
def test_advanced_agent_turns_away_from_a_right_obstacle(ros, name, angle_min, increment, count):
    scan = make_scan(angle_min, increment, count, obstacles=((-30.0, 10.0, 0.5),))
    twist = _command_for(ros, AdvancedAvoidanceAgent(context=ros.context), scan)
    assert twist.linear.x == 0.0 and twist.angular.z == 0.5, name


def test_advanced_agent_stops_and_turns_when_blocked_ahead(ros):
    scan = make_scan(-180.0, 0.5, 720, obstacles=((0.0, 6.0, 0.3),))
    agent = AdvancedAvoidanceAgent(rng=random.Random(3), context=ros.context)
    twist = _command_for(ros, agent, scan)
    assert twist.linear.x == 0.0 and abs(twist.angular.z) == 0.5


def test_parameters_set_speeds_and_threshold(ros):
    overrides = [Parameter('threshold_distance', value=1.5), Parameter('angular_speed', value=1.2)]
    scan = make_scan(0.0, 1.0, 360, obstacles=((0.0, 4.0, 1.0),))
    twist = _command_for(ros, AvoidanceAgent(context=ros.context, parameter_overrides=overrides),
                         scan)
    assert twist.angular.z == -1.2


def test_empty_scan_publishes_nothing(ros):
    ros.add(AvoidanceAgent(context=ros.context))
    driver = ros.node('driver')
    publisher = driver.create_publisher(LaserScan, '/scan', 10)
    received = []
    driver.create_subscription(Twist, '/cmd_vel', received.append, 10)
    assert not ros.spin_until(lambda: received, timeout_sec=0.5,
                              tick=lambda: publisher.publish(LaserScan()))


def test_seed_mistake_fixed_indices_no_longer_used(ros):
    # The lesson checked indices 0-14 and 345-359 as "front". On a -90..90 degree scanner
    # index 0 is the far right: the seed saw danger there and missed the obstacle ahead.
    side_only = make_scan(-90.0, 1.0, 181, obstacles=((-85.0, 10.0, 0.3),))
    assert _command_for(ros, AvoidanceAgent(context=ros.context), side_only).linear.x == 0.2


def test_seed_mistake_obstacle_ahead_on_a_half_scanner_is_seen(ros):
    ahead = make_scan(-90.0, 1.0, 181, obstacles=((0.0, 4.0, 0.3),))
    assert _command_for(ros, AvoidanceAgent(context=ros.context), ahead).angular.z == -0.5


def test_seed_mistake_left_and_right_are_not_swapped(ros):
    # The exercise called indices 315-359 "front left"; with 0 = ahead and angles growing
    # counter-clockwise (REP 103) those beams are on the right.
    right_side = make_scan(0.0, 1.0, 360, obstacles=((-30.0, 10.0, 0.5),))
    twist = _command_for(ros, AdvancedAvoidanceAgent(context=ros.context), right_side)
    assert twist.angular.z > 0.0, 'an obstacle on the right must make the robot turn left'


@pytest.mark.parametrize('reading', [math.nan, math.inf, -math.inf, 0.01, 99.0])
def test_seed_mistake_invalid_readings_ahead_are_not_obstacles(ros, reading):
    scan = make_scan(0.0, 1.0, 360, obstacles=((0.0, 30.0, reading),))
    assert _command_for(ros, AvoidanceAgent(context=ros.context), scan).linear.x == 0.2
