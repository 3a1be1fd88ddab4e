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

"""
IMU processing utilities for Physical AI systems.

Orientation comes from the message's quaternion with plain math (no tf_transformations, which
is not a dependency of this package), so the module works wherever numpy does.
"""

import math

import numpy as np
from physical_ai_sensors.utils.data_validation import validate_imu_message
from sensor_msgs.msg import Imu

__all__ = [
    'IMUProcessor', 'STANDARD_GRAVITY', 'VelocityIntegrator', 'estimate_bias',
    'euler_from_quaternion', 'rotation_matrix', 'validate_imu_message',
]

STANDARD_GRAVITY = 9.80665
"""Standard gravity in m/s^2."""


def _normalised(x: float, y: float, z: float, w: float) -> tuple[float, float, float, float]:
    norm = math.sqrt(x * x + y * y + z * z + w * w)
    if norm == 0.0 or not math.isfinite(norm):
        raise ValueError('quaternion must have a finite, non-zero length')
    return x / norm, y / norm, z / norm, w / norm


def euler_from_quaternion(x: float, y: float, z: float, w: float) -> tuple[float, float, float]:
    """Return (roll, pitch, yaw) in radians; ROS order (x, y, z, w), static axes X-Y-Z."""
    x, y, z, w = _normalised(x, y, z, w)
    roll = math.atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2.0 * (w * y - z * x))))
    yaw = math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
    return roll, pitch, yaw


def rotation_matrix(x: float, y: float, z: float, w: float) -> np.ndarray:
    """Return the 3x3 matrix turning sensor-frame vectors into reference-frame vectors."""
    x, y, z, w = _normalised(x, y, z, w)
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])


def estimate_bias(samples: np.ndarray, gravity: float = STANDARD_GRAVITY) -> np.ndarray:
    """
    Estimate the 6-dof bias from readings of an IMU lying still and level.

    ``samples`` has shape (N, 6): acc_x, acc_y, acc_z, gyro_x, gyro_y, gyro_z. A level IMU at
    rest measures +gravity on its z axis and no rotation; the mean difference is the bias.
    """
    data = np.asarray(samples, dtype=float)
    if data.ndim != 2 or data.shape[1] != 6 or len(data) == 0:
        raise ValueError('samples must have shape (N, 6) with N >= 1')
    return data.mean(axis=0) - np.array([0.0, 0.0, gravity, 0.0, 0.0, 0.0])


class IMUProcessor:
    """Provides utilities for processing IMU data."""

    def __init__(self, covariance_params: dict | None = None,
                 gravity: float = STANDARD_GRAVITY) -> None:
        """Start with zero bias; ``covariance_params`` is kept for noise modelling."""
        self.covariance_params = dict(covariance_params or {})
        self.bias = np.zeros(6)  # 3-axis accelerometer then 3-axis gyroscope
        self.gravity = gravity

    def set_bias(self, accel_bias, gyro_bias) -> None:
        """Set the accelerometer and gyroscope biases (three values each)."""
        bias = np.concatenate([np.asarray(accel_bias, float), np.asarray(gyro_bias, float)])
        if bias.shape != (6,):
            raise ValueError('accel_bias and gyro_bias need three values each')
        self.bias = bias

    def extract_orientation_from_quaternion(self, imu_msg: Imu) -> tuple[float, float, float]:
        """Return (roll, pitch, yaw) in radians from the message's orientation."""
        q = imu_msg.orientation
        return euler_from_quaternion(q.x, q.y, q.z, q.w)

    def extract_linear_acceleration(self, imu_msg: Imu,
                                    remove_gravity: bool = True) -> tuple[float, float, float]:
        """
        Return the bias-corrected acceleration in the sensor frame, in m/s^2.

        With ``remove_gravity`` the gravity vector, rotated into the sensor frame using the
        message's orientation, is subtracted, leaving the acceleration due to motion.
        """
        acc = imu_msg.linear_acceleration
        linear = np.array([acc.x, acc.y, acc.z]) - self.bias[:3]
        if remove_gravity:
            q = imu_msg.orientation
            linear = linear - rotation_matrix(q.x, q.y, q.z, q.w).T @ [0.0, 0.0, self.gravity]
        return float(linear[0]), float(linear[1]), float(linear[2])

    def compute_velocity_from_acceleration(self, acceleration_data: np.ndarray,
                                           timestamps: np.ndarray) -> np.ndarray:
        """
        Integrate acceleration (N x 3, m/s^2) over timestamps (N, seconds) into velocity.

        The trapezoidal rule is used and the initial velocity is zero: 1 m/s^2 held for 0.1 s
        gives 0.1 m/s.
        """
        acc = np.asarray(acceleration_data, dtype=float)
        times = np.asarray(timestamps, dtype=float)
        if acc.ndim != 2 or acc.shape[1] != 3 or len(acc) != len(times) or len(times) < 2:
            raise ValueError('need N >= 2 samples of 3-axis acceleration and N timestamps')
        dt = np.diff(times)
        if np.any(dt <= 0):
            raise ValueError('timestamps must be strictly increasing')
        velocity = np.zeros_like(acc)
        velocity[1:] = np.cumsum((acc[:-1] + acc[1:]) / 2.0 * dt[:, np.newaxis], axis=0)
        return velocity

    def apply_bias_correction(self, raw_data: np.ndarray) -> np.ndarray:
        """Subtract the bias from 6-dof readings, shape (6,) or (N, 6)."""
        return np.asarray(raw_data, dtype=float) - self.bias


class VelocityIntegrator:
    """Integrates a stream of acceleration samples into a velocity (trapezoidal rule)."""

    def __init__(self) -> None:
        """Start at rest with no previous sample."""
        self.velocity = np.zeros(3)
        self._last: tuple[float, np.ndarray] | None = None

    def update(self, acceleration, stamp: float) -> np.ndarray | None:
        """Add one sample at time ``stamp`` (seconds); None until two samples were seen."""
        acc = np.asarray(acceleration, dtype=float)
        last, self._last = self._last, (stamp, acc)
        if last is None:
            return None
        dt = stamp - last[0]
        if dt <= 0.0:
            self._last = last  # out-of-order or repeated stamp: ignore the sample
            return None
        self.velocity = self.velocity + (last[1] + acc) / 2.0 * dt
        return self.velocity.copy()
