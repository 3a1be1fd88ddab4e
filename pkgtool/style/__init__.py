"""ament's style checks (flake8, pydocstyle, copyright headers) run in-process, without ament."""
