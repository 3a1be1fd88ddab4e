# Copyright 2026 Jane Doe

"""A module."""
