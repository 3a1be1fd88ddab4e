"""ament_lint's checks reproduced in-process, without ROS.

flake8 and pydocstyle with ament's settings, and copyright headers read as ament_copyright reads
them. The STY and CPY rules call these; :mod:`pkgtool.style.api` gives the rules' verdicts to the
linter tests of generated packages.
"""
