# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""HSV colour thresholding and blob extraction."""

import numpy as np
from simple_vision_agent.detection import color_mask, Detection, find_blobs, segment

GREEN_HSV = ([40, 40, 40], [80, 255, 255])
GREEN_BGR, BLUE_BGR = (0, 200, 0), (200, 0, 0)


def _image_with(*squares) -> np.ndarray:
    image = np.zeros((120, 160, 3), dtype=np.uint8)
    for x, y, size, colour in squares:
        image[y:y + size, x:x + size] = colour
    return image


def test_green_square_is_found_with_its_bounding_box():
    image = _image_with((50, 40, 60, GREEN_BGR))
    detections = find_blobs(color_mask(image, *GREEN_HSV), min_area=500.0)
    assert [(d.x, d.y, d.width, d.height) for d in detections] == [(50, 40, 60, 60)]


def test_other_colours_and_small_blobs_are_ignored():
    image = _image_with((10, 10, 40, BLUE_BGR), (100, 80, 15, GREEN_BGR))
    assert find_blobs(color_mask(image, *GREEN_HSV), min_area=500.0) == []


def test_largest_blob_comes_first():
    image = _image_with((5, 5, 30, GREEN_BGR), (60, 40, 70, GREEN_BGR))
    detections = find_blobs(color_mask(image, *GREEN_HSV), min_area=500.0)
    assert [(d.x, d.width) for d in detections] == [(60, 70), (5, 30)]


def test_segment_keeps_only_the_object_and_outlines_it():
    image = _image_with((50, 40, 60, GREEN_BGR), (0, 0, 20, BLUE_BGR))
    mask = color_mask(image, *GREEN_HSV)
    segmented = segment(image, mask, [Detection(50, 40, 60, 60, 3481.0)])
    assert not segmented[:20, :20].any(), 'the blue square is masked out'
    assert segmented[70, 80].tolist() == list(GREEN_BGR)
    assert segmented[40, 50].tolist() == [0, 255, 0]
