"""``pkgtool doctor``: call :mod:`pkgtool.commands.doctor` and print one line per check."""

from __future__ import annotations

import typer

from pkgtool.cli import examples


def doctor() -> None:
    """Say what works on this machine and what does not, with the command that fixes each.

    Checks Python and pkgtool's extras, rclpy (imported and initialised with discovery off),
    the rmw, colcon, the ament linters, the ROS discovery settings of this shell and the
    sandbox `pkgtool grade` would use. Nothing is installed or changed. Exit code 0.
    """
    from pkgtool.commands.doctor import run

    result = run()
    width = max(len(check.name) for check in result.checks)
    for check in result.checks:
        typer.echo(f"{'ok' if check.ok else 'missing':<8} {check.name:<{width}}  {check.detail}")
        if check.fix:
            typer.echo(f"{'':<8} {'':<{width}}  fix: {check.fix}")
    typer.echo(f"{len(result.checks) - result.missing} ok, {result.missing} missing.")
    raise typer.Exit(int(result.exit_code))


def register(app: typer.Typer) -> None:
    """Attach ``doctor`` to the root app."""
    app.command("doctor", epilog=examples("pkgtool doctor",
                                          "pkgtool doctor | grep missing"))(doctor)
