"""setup.cfg read with configparser (interpolation off)."""

from __future__ import annotations

from pkgtool.model.span import ParseProblem, Span
from pkgtool.records import record


@record
class CfgOption:
    """One ``key = value`` with its section and position (key as written, dashes kept)."""

    section: str
    key: str
    value: str
    span: Span


@record
class SetupCfg:
    """All options of setup.cfg in file order."""

    path: str
    options: tuple[CfgOption, ...]

    def get(self, section: str, key: str) -> CfgOption | None:
        """The option whose key matches with dashes and underscores treated alike."""
        wanted = key.replace("-", "_")
        for option in self.options:
            if option.section == section and option.key.replace("-", "_") == wanted:
                return option
        return None


def parse_setup_cfg(path: str, text: str) -> SetupCfg | ParseProblem:
    """Parse setup.cfg; a syntax error gives a ParseProblem at its line."""
    import configparser

    parser = configparser.ConfigParser(interpolation=None, strict=False)
    parser.optionxform = str  # type: ignore[assignment,method-assign]
    try:
        parser.read_string(text, source=path)
    except configparser.Error as error:
        line = getattr(error, "lineno", 1) or 1
        return ParseProblem("cfg-syntax", Span(path, line, 1), str(error).splitlines()[0])
    lines = text.splitlines()
    options: list[CfgOption] = []
    for section in parser.sections():
        header = _line_of(lines, lambda s: s.strip() == f"[{section}]", 0)
        for key, value in parser.items(section, raw=True):
            line = _line_of(lines, lambda s: s.split("=", 1)[0].split(":", 1)[0].strip() == key,
                            header)
            options.append(CfgOption(section, key, value.strip(), Span(path, line, 1)))
    return SetupCfg(path, tuple(options))


def _line_of(lines: list[str], match: object, start: int) -> int:
    for number, line in enumerate(lines[start:], start + 1):
        if callable(match) and match(line):
            return number
    return start or 1
