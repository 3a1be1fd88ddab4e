"""SPDX license expressions (``MIT``, ``GPL-2.0-or-later WITH Classpath-exception-2.0``).

A small parser of the SPDX expression grammar (SPDX 2.3, annex D) over the identifiers vendored
in ``templates/licenses/spdx-ids.json``. It answers one question for ``pkgtool create``: is this
``--license`` an SPDX expression, and how is it spelt canonically? Identifiers match without
regard to case (as the specification says) and come out as the list spells them.
"""

from __future__ import annotations

import functools
import json
from pkgtool.lazy_regex import lazy_pattern

_TOKEN = lazy_pattern(r"\(|\)|[^\s()]+")
_REF = lazy_pattern(r"^(DocumentRef-[A-Za-z0-9.-]+:)?LicenseRef-[A-Za-z0-9.-]+$")


@functools.cache
def _ids() -> tuple[dict[str, str], dict[str, str]]:
    """(licenses, exceptions): lower-case identifier -> the list's spelling."""
    from pkgtool.create.licenses import IDS_FILE, licenses_dir

    data = json.loads((licenses_dir() / IDS_FILE).read_text(encoding="utf-8"))
    return ({i.lower(): i for i in data["licenses"]}, {i.lower(): i for i in data["exceptions"]})


class _Parser:
    """Recursive descent over the tokens; ``out`` collects them canonically spelt."""

    def __init__(self, tokens: list[str]) -> None:
        self.tokens = tokens
        self.at = 0
        self.out: list[str] = []

    def peek(self) -> str:
        return self.tokens[self.at] if self.at < len(self.tokens) else ""

    def take(self) -> str:
        self.at += 1
        return self.tokens[self.at - 1]

    def expression(self) -> None:
        """An or-expression: and-expression {OR and-expression}."""
        self.and_expression()
        while self.peek().upper() == "OR":
            self.out.append(self.take().upper())
            self.and_expression()

    def and_expression(self) -> None:
        """term {AND term}."""
        self.term()
        while self.peek().upper() == "AND":
            self.out.append(self.take().upper())
            self.term()

    def term(self) -> None:
        if self.peek() == "(":
            self.out.append(self.take())
            self.expression()
            if self.peek() != ")":
                raise ValueError("unbalanced parentheses")
            self.out.append(self.take())
            return
        licenses, exceptions = _ids()
        word = self.take() if self.peek() else ""
        plus = word.endswith("+") and len(word) > 1
        name = licenses.get(word[:-1].lower() if plus else word.lower())
        if name is None and not (_REF.match(word) and not plus):
            raise ValueError(f"unknown license id {word!r}")
        self.out.append((name + "+" if plus else name) if name else word)
        if self.peek().upper() == "WITH":
            self.out.append(self.take().upper())
            exception = exceptions.get(self.take().lower() if self.peek() else "")
            if exception is None:
                raise ValueError("unknown exception id")
            self.out.append(exception)


def canonical(text: str) -> str | None:
    """``text`` in canonical spelling when it is an SPDX license expression, else None."""
    parser = _Parser(_TOKEN.findall(text))
    try:
        parser.expression()
    except ValueError:
        return None
    if parser.at != len(parser.tokens) or not parser.out:
        return None
    return " ".join(parser.out).replace("( ", "(").replace(" )", ")")
