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
Image processing utilities for Physical AI systems.

Edges, corners and stereo depth with OpenCV. Conversion from and to ROS messages is done by
:mod:`physical_ai_camera.utils.image_conversion` instead of cv_bridge.
"""

import cv2
import numpy as np
from physical_ai_camera.utils.image_conversion import array_to_image, image_to_bgr
from sensor_msgs.msg import Image


def _gray(image: np.ndarray) -> np.ndarray:
    return image if image.ndim == 2 else cv2.cvtColor(image, cv2.COLOR_BGR2GRAY)


class ImageProcessor:
    """Provides utilities for processing camera images."""

    def __init__(self, focal_length: float = 500.0, baseline: float = 0.2) -> None:
        """Store the stereo camera's focal length (pixels) and baseline (metres)."""
        self.focal_length = focal_length
        self.baseline = baseline

    def ros_image_to_opencv(self, img_msg: Image) -> np.ndarray:
        """Return the image as a BGR numpy array; ValueError for unsupported encodings."""
        return image_to_bgr(img_msg)

    def opencv_to_ros_image(self, cv_image: np.ndarray, encoding: str = 'bgr8',
                            header=None) -> Image:
        """Return a ROS Image message holding ``cv_image``."""
        return array_to_image(cv_image, encoding, header)

    def detect_edges(self, image: np.ndarray) -> np.ndarray:
        """Return a binary edge image (Canny on the blurred grayscale image)."""
        blurred = cv2.GaussianBlur(_gray(image), (5, 5), 0)
        return cv2.Canny(blurred, 50, 150)

    def detect_corners(self, image: np.ndarray, max_corners: int = 100) -> np.ndarray:
        """Return Shi-Tomasi corners as an (N, 2) integer array of (x, y) pixels."""
        corners = cv2.goodFeaturesToTrack(_gray(image), maxCorners=max_corners,
                                          qualityLevel=0.01, minDistance=10)
        if corners is None:
            return np.empty((0, 2), dtype=np.intp)
        # np.int0 was removed in NumPy 2: round explicitly, then convert.
        return np.rint(corners).astype(np.intp).reshape(-1, 2)

    def calculate_disparity(self, left_image: np.ndarray, right_image: np.ndarray,
                            num_disparities: int = 32, block_size: int = 15) -> np.ndarray:
        """Return the disparity in pixels (float32, negative where unknown) of a stereo pair."""
        stereo = cv2.StereoBM_create(numDisparities=num_disparities, blockSize=block_size)
        # StereoBM returns fixed-point disparities with four fractional bits.
        return stereo.compute(_gray(left_image), _gray(right_image)).astype(np.float32) / 16.0

    def calculate_depth_from_disparity(self, left_image: np.ndarray,
                                       right_image: np.ndarray) -> np.ndarray:
        """
        Return the depth map in metres (float32) of a rectified stereo pair.

        depth = focal_length * baseline / disparity; pixels without a valid disparity are 0.
        """
        disparity = self.calculate_disparity(left_image, right_image)
        depth = np.zeros_like(disparity)
        valid = disparity > 0
        depth[valid] = self.focal_length * self.baseline / disparity[valid]
        return depth

    @staticmethod
    def depth_to_display(depth: np.ndarray) -> np.ndarray:
        """Return the depth map scaled to 0-255 (uint8) for visualisation."""
        return cv2.normalize(depth, None, 0, 255, cv2.NORM_MINMAX, dtype=cv2.CV_8U)
