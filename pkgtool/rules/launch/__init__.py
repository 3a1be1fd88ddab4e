"""LCH: launch files and the packages and executables they use."""
