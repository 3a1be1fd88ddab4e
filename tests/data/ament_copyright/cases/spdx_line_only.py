# Copyright 2026 Jane Doe
# SPDX-License-Identifier: Apache-2.0

"""A module."""
