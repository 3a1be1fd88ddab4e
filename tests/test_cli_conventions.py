"""What every pkgtool command does alike: -h, metavars, examples, completion, Ctrl-C."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest
import typer
from typer.testing import CliRunner

from pkgtool.cli import _register, app

_register()
PKGTOOL = str(Path(sys.executable).parent / "pkgtool")
TYPER_DEFAULT_METAVARS = ("<str>", "<int range>", "<float range>", "<path>", "<file>", "<int>",
                          "<float>", " INTEGER", " FLOAT", "{path}", "[submissions]")


def _commands(group: object, path: tuple[str, ...] = ()) -> list[tuple[str, ...]]:
    found = [path]
    for name, command in getattr(group, "commands", {}).items():
        found += _commands(command, (*path, name))
    return found


COMMANDS = _commands(typer.main.get_command(app))


def test_every_verb_is_found() -> None:
    assert {c[0] for c in COMMANDS if c} == {"lint", "create", "add", "test", "grade",
                                             "reference", "doctor"}
    assert ("reference", "test") in COMMANDS


@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: " ".join(c) or "pkgtool")
def test_h_is_help_with_examples_and_named_metavars(command: tuple[str, ...]) -> None:
    short = CliRunner().invoke(app, [*command, "-h"])
    assert short.exit_code == 0, short.output
    assert short.output == CliRunner().invoke(app, [*command, "--help"]).output
    assert "Examples:" in short.output
    assert not [m for m in TYPER_DEFAULT_METAVARS if m in short.output], short.output


def test_grade_shows_the_rubric_as_required() -> None:
    usage = CliRunner().invoke(app, ["grade", "-h"]).output.splitlines()[0]
    assert usage == "Usage: pkgtool grade --rubric FILE [OPTIONS] [SUBMISSION...]"


def test_shell_completion_is_offered_and_completes_verbs() -> None:
    assert "--install-completion" in CliRunner().invoke(app, ["-h"]).output
    env = dict(os.environ, _PKGTOOL_COMPLETE="complete_bash", COMP_WORDS="pkgtool cre",
               COMP_CWORD="1")
    done = subprocess.run([PKGTOOL], env=env, capture_output=True, text=True, timeout=60)
    assert done.stdout.split() == ["create"], done.stdout + done.stderr


def test_a_run_attaches_its_verb_only_and_a_typo_still_gets_suggestions() -> None:
    count = ("import sys; from pkgtool import cli; cli._register(sys.argv[1:]); "
             "print(len(cli.app.registered_commands) + len(cli.app.registered_groups))")
    attached = [subprocess.run([sys.executable, "-c", count, *arguments], capture_output=True,
                               text=True, timeout=60, check=True).stdout.strip()
                for arguments in (["lint", "."], ["reference", "list"], ["lnt"], [])]
    assert attached[:2] == ["1", "1"] and attached[2] == attached[3] != "1"
    done = subprocess.run([PKGTOOL, "lnt"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 2 and "lint" in done.stderr, done.stderr


def test_completing_a_verbs_options_sees_every_verb() -> None:
    env = dict(os.environ, _PKGTOOL_COMPLETE="complete_bash", COMP_WORDS="pkgtool lint --no-c",
               COMP_CWORD="2")
    done = subprocess.run([PKGTOOL, "lint"], env=env, capture_output=True, text=True,
                          timeout=60)
    assert done.stdout.split() == ["--no-cache"], done.stdout + done.stderr


def _interrupted(command: list[str], ready: str, env: dict[str, str]) -> tuple[int, str]:
    """Start ``command`` as a shell does, press Ctrl-C once ``ready`` is printed."""
    process = subprocess.Popen(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, start_new_session=True,
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    assert process.stdout is not None and process.stderr is not None
    for line in process.stdout:
        if ready in line:
            break
    os.killpg(process.pid, signal.SIGINT)  # Ctrl-C reaches the whole foreground group
    process.stdout.read()
    return process.wait(timeout=120), process.stderr.read()


SELF_INTERRUPT = """
import os, signal, sys, time
from pkgtool import cli

@cli.app.command('sleepy')
def sleepy():
    print('ready', flush=True)
    time.sleep(60)

sys.argv = ['pkgtool', 'sleepy']
cli.main()
"""


def test_ctrl_c_prints_one_line_and_exits_130(tmp_path: Path) -> None:
    code, err = _interrupted([sys.executable, "-c", SELF_INTERRUPT], "ready", dict(os.environ))
    assert (code, err) == (130, "Interrupted: nothing was written\n")


FAST_LINT_INTERRUPT = """
import sys, time
from pkgtool import cli_fast, cli_lint_run

def sleepy(**call):
    print('ready', flush=True)
    time.sleep(60)

cli_lint_run.lint_call = sleepy
sys.argv = ['pkgtool', 'lint', '--no-cache', '.']
cli_fast.main()
"""


def test_ctrl_c_in_the_fast_start_of_lint_prints_one_line_and_exits_130() -> None:
    code, err = _interrupted([sys.executable, "-c", FAST_LINT_INTERRUPT], "ready",
                             dict(os.environ))
    assert (code, err) == (130, "Interrupted: nothing was written\n")


@pytest.mark.slow
@pytest.mark.colcon
def test_ctrl_c_during_a_build_leaves_nothing_behind(tmp_path: Path) -> None:
    temp = tmp_path / "temp"
    temp.mkdir()
    env = dict(os.environ, TMPDIR=str(temp))
    code, err = _interrupted([PKGTOOL, "reference", "test", "robot_monitor"],
                             "robot_monitor: building", env)
    assert code == 130 and err.splitlines()[-1] == "Interrupted: nothing was written", err
    assert "Traceback" not in err
    assert list(temp.iterdir()) == []


@pytest.mark.parametrize("arguments", [("lint", "--explain", "PYC"), ("lint", "--list-rules"),
                                       ("create", "--help")])
def test_a_reader_closing_the_pipe_early_ends_the_run_quietly(arguments: tuple[str, ...]) -> None:
    """``pkgtool lint --explain PYC | head -1``: no traceback, no "Internal error"."""
    reader, writer = os.pipe()
    os.close(reader)  # the reader is gone before anything is written
    done = subprocess.run([PKGTOOL, *arguments], stdout=writer, stderr=subprocess.PIPE,
                          text=True, timeout=60)
    os.close(writer)
    assert "Traceback" not in done.stderr and "Internal error" not in done.stderr
    assert done.returncode in (0, 1, 141)  # click ends its own help with 1
