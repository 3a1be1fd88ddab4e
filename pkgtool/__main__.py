"""Allow ``python -m pkgtool``."""

from pkgtool.cli import main

main()
