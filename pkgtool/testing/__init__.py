"""Test support shared by pkgtool's own tests and the packages it generates."""
