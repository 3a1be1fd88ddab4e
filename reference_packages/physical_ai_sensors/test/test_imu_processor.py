# Copyright 2026 Physical AI Robotics Team
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.

"""Unit tests of the IMU utilities (the chapter's tests, with its wrong expectation fixed)."""

import math

import numpy as np
from physical_ai_sensors.sensors.imu_processor import (
    estimate_bias, euler_from_quaternion, IMUProcessor, rotation_matrix, validate_imu_message,
    VelocityIntegrator)
import pytest
from sensor_msgs.msg import Imu
from std_msgs.msg import Header


def quaternion_from_euler(roll, pitch, yaw):
    """Return (x, y, z, w) for static-axes roll, pitch, yaw (independent reference formula)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def imu_with_orientation(x, y, z, w):
    msg = Imu()
    msg.orientation.x, msg.orientation.y, msg.orientation.z, msg.orientation.w = x, y, z, w
    return msg


def test_imu_processor_initialization():
    processor = IMUProcessor()
    assert len(processor.bias) == 6  # 3-axis acc + 3-axis gyro
    assert not processor.bias.any()


def test_extract_orientation_from_identity_quaternion():
    roll, pitch, yaw = IMUProcessor().extract_orientation_from_quaternion(
        imu_with_orientation(0.0, 0.0, 0.0, 1.0))
    assert (roll, pitch, yaw) == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)


@pytest.mark.parametrize('angles', [(0.3, -0.2, 1.0), (-1.2, 0.7, -2.5), (math.pi / 2, 0, 0),
                                    (0.0, 0.0, math.pi - 0.01), (0.1, 1.2, 0.4)])
def test_euler_angles_round_trip(angles):
    msg = imu_with_orientation(*quaternion_from_euler(*angles))
    assert IMUProcessor().extract_orientation_from_quaternion(msg) == pytest.approx(angles)


def test_euler_angles_of_a_quarter_turn_about_z():
    half = math.sqrt(0.5)
    assert euler_from_quaternion(0.0, 0.0, half, half) == pytest.approx((0, 0, math.pi / 2))


def test_euler_normalises_and_rejects_a_zero_quaternion():
    assert euler_from_quaternion(0.0, 0.0, 0.0, 2.0) == pytest.approx((0, 0, 0))
    with pytest.raises(ValueError):
        euler_from_quaternion(0.0, 0.0, 0.0, 0.0)


def test_pitch_is_clamped_at_gimbal_lock():
    half = math.sqrt(0.5)
    assert euler_from_quaternion(0.0, half * 1.0000001, 0.0, half)[1] == pytest.approx(
        math.pi / 2)


def test_rotation_matrix_is_orthonormal_and_turns_x_into_y():
    half = math.sqrt(0.5)
    matrix = rotation_matrix(0.0, 0.0, half, half)
    assert matrix @ [1.0, 0.0, 0.0] == pytest.approx([0.0, 1.0, 0.0])
    assert matrix @ matrix.T == pytest.approx(np.eye(3))


def test_compute_velocity_from_acceleration():
    """1 m/s^2 for 0.1 s is 0.1 m/s (the chapter expected 0.01, which is wrong)."""
    processor = IMUProcessor()
    acceleration_data = np.array([[1.0, 0.0, 0.0]] * 10)
    timestamps = np.linspace(0.0, 0.9, 10)
    velocities = processor.compute_velocity_from_acceleration(acceleration_data, timestamps)
    assert velocities[0][0] == pytest.approx(0.0)
    assert velocities[1][0] == pytest.approx(0.1, abs=1e-9)
    assert velocities[:, 0] == pytest.approx(timestamps)
    assert not velocities[:, 1:].any()


def test_compute_velocity_rejects_bad_input():
    processor = IMUProcessor()
    with pytest.raises(ValueError):
        processor.compute_velocity_from_acceleration(np.zeros((3, 3)), np.zeros(2))
    with pytest.raises(ValueError):
        processor.compute_velocity_from_acceleration(np.zeros((3, 3)), np.array([0, 1, 1]))


def test_bias_correction_and_linear_acceleration_without_gravity():
    processor = IMUProcessor()
    processor.set_bias([0.1, -0.2, 0.3], [0.01, 0.02, 0.03])
    raw = np.array([1.0, 1.0, 1.0, 1.0, 1.0, 1.0])
    assert processor.apply_bias_correction(raw) == pytest.approx(
        [0.9, 1.2, 0.7, 0.99, 0.98, 0.97])
    msg = imu_with_orientation(0.0, 0.0, 0.0, 1.0)
    msg.linear_acceleration.x, msg.linear_acceleration.z = 0.6, 9.80665 + 0.3
    assert processor.extract_linear_acceleration(msg) == pytest.approx((0.5, 0.2, 0.0))


def test_gravity_removed_when_imu_is_rolled_ninety_degrees():
    msg = imu_with_orientation(*quaternion_from_euler(math.pi / 2, 0.0, 0.0))
    msg.linear_acceleration.y = 9.80665  # gravity now appears on the sensor's y axis
    assert IMUProcessor().extract_linear_acceleration(msg) == pytest.approx((0, 0, 0), abs=1e-9)


def test_estimate_bias_of_a_level_imu_at_rest():
    samples = np.tile([0.05, -0.02, 9.90665, 0.001, 0.0, -0.002], (50, 1))
    assert estimate_bias(samples) == pytest.approx([0.05, -0.02, 0.1, 0.001, 0.0, -0.002])
    with pytest.raises(ValueError):
        estimate_bias(np.zeros((0, 6)))


def test_velocity_integrator_uses_the_trapezoidal_rule_and_skips_old_samples():
    integrator = VelocityIntegrator()
    assert integrator.update([1.0, 0.0, 0.0], 10.0) is None
    assert integrator.update([3.0, 0.0, 0.0], 10.5) == pytest.approx([1.0, 0.0, 0.0])
    assert integrator.update([100.0, 0.0, 0.0], 10.4) is None
    assert integrator.update([3.0, 0.0, 0.0], 11.0) == pytest.approx([2.5, 0.0, 0.0])


def test_validate_imu_message_valid():
    imu_msg = Imu()
    imu_msg.header = Header()
    imu_msg.header.stamp.sec = 100
    imu_msg.header.stamp.nanosec = 500000000
    imu_msg.orientation.w = 1.0
    assert validate_imu_message(imu_msg)


def test_validate_imu_message_invalid():
    imu_msg = Imu()
    imu_msg.header.stamp.sec = -1
    imu_msg.orientation.w = 1.0
    assert not validate_imu_message(imu_msg)
    imu_msg.header.stamp.sec = 100
    imu_msg.orientation.w = 2.0  # not normalised
    assert not validate_imu_message(imu_msg)
    imu_msg.orientation.w = 1.0
    imu_msg.angular_velocity.x = math.nan
    assert not validate_imu_message(imu_msg)


def test_validate_imu_message_without_orientation_per_rep_145():
    imu_msg = Imu()  # all-zero quaternion, flagged as "no orientation"
    imu_msg.orientation_covariance[0] = -1.0
    assert validate_imu_message(imu_msg)
