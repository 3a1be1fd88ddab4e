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

"""Colour-based object detection: HSV thresholds, then bounding boxes of the blobs."""

import cv2
import numpy as np

Box = tuple[int, int, int, int]
"""A bounding box: x offset, y offset, width, height, in pixels."""


def color_mask(bgr: np.ndarray, lower_hsv, upper_hsv) -> np.ndarray:
    """
    Return the 0/255 mask of pixels whose HSV values lie within [lower_hsv, upper_hsv].

    OpenCV's hue runs from 0 to 179; a lower hue above the upper hue wraps around 180, which is
    how red (e.g. 170 to 10) is selected.
    """
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
    lower, upper = np.array(lower_hsv, np.uint8), np.array(upper_hsv, np.uint8)
    if lower[0] <= upper[0]:
        return cv2.inRange(hsv, lower, upper)
    high = cv2.inRange(hsv, lower, np.array([179, upper[1], upper[2]], np.uint8))
    low = cv2.inRange(hsv, np.array([0, lower[1], lower[2]], np.uint8), upper)
    return cv2.bitwise_or(high, low)


def detect_color_regions(bgr: np.ndarray, lower_hsv, upper_hsv,
                         min_area: float = 100.0) -> list[Box]:
    """Return boxes of the colour's blobs of at least ``min_area`` pixels, largest first."""
    mask = color_mask(bgr, lower_hsv, upper_hsv)
    mask = cv2.morphologyEx(mask, cv2.MORPH_OPEN, np.ones((3, 3), np.uint8))
    contours = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)[-2]
    blobs = []
    for contour in contours:
        x, y, w, h = cv2.boundingRect(contour)
        area = int(np.count_nonzero(mask[y:y + h, x:x + w]))
        if area >= min_area:
            blobs.append((area, (int(x), int(y), int(w), int(h))))
    return [box for _, box in sorted(blobs, key=lambda blob: -blob[0])]
