"""Allow ``python -m pkgtool``."""

from pkgtool.cli_fast import main

main()
