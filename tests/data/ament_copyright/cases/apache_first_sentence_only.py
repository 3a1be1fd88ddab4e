# Copyright 2026 Jane Doe
#
# Licensed under the Apache License, Version 2.0 (the "License");

"""A module."""
