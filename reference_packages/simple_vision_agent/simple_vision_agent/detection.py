# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Find objects of one colour in a BGR image with an HSV threshold (OpenCV, no ROS)."""

from dataclasses import dataclass
from typing import Sequence

import cv2
import numpy as np


@dataclass(frozen=True)
class Detection:
    """An axis-aligned bounding box in pixels and the area of the blob inside it."""

    x: int
    y: int
    width: int
    height: int
    area: float


def color_mask(bgr: np.ndarray, lower_hsv: Sequence[int], upper_hsv: Sequence[int]
               ) -> np.ndarray:
    """Return a uint8 mask, 255 where the pixel's HSV lies within [lower_hsv, upper_hsv]."""
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
    return cv2.inRange(hsv, np.array(lower_hsv, dtype=np.uint8),
                       np.array(upper_hsv, dtype=np.uint8))


def find_blobs(mask: np.ndarray, min_area: float) -> list[Detection]:
    """Return the blobs of ``mask`` larger than ``min_area`` pixels, largest first."""
    contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
    detections = []
    for contour in contours:
        area = cv2.contourArea(contour)
        if area > min_area:
            x, y, width, height = cv2.boundingRect(contour)
            detections.append(Detection(x, y, width, height, area))
    return sorted(detections, key=lambda d: d.area, reverse=True)


def segment(bgr: np.ndarray, mask: np.ndarray, detections: Sequence[Detection]) -> np.ndarray:
    """Keep only the masked pixels and outline each detection with a green rectangle."""
    segmented = cv2.bitwise_and(bgr, bgr, mask=mask)
    for d in detections:
        cv2.rectangle(segmented, (d.x, d.y), (d.x + d.width - 1, d.y + d.height - 1),
                      (0, 255, 0), 2)
    return segmented
