"""CI is the README's test command on a fresh machine: the line `.ci/run` runs stands verbatim in
the README, and it builds a new virtual environment before installing (so CI fails where a newcomer
would, instead of passing on releases an old environment still holds)."""

from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _ci_command() -> str:
    lines = [ln.strip() for ln in (ROOT / ".ci" / "run").read_text().splitlines()]
    runs = [ln for ln in lines if "pytest" in ln and not ln.startswith("#")]
    assert len(runs) == 1, runs
    return runs[0]


def test_ci_runs_the_readme_test_command():
    assert _ci_command() in (ROOT / "README.md").read_text()


def test_ci_command_makes_a_fresh_venv_before_installing():
    cmd = _ci_command()
    venv, install, test = (cmd.index("python3 -m venv"), cmd.index("-e '.[test]'"),
                           cmd.index("python -m pytest"))
    assert venv < cmd.index('. "$v/bin/activate"') < install < test
    assert "--system-site-packages" not in cmd
    # uv installs into the activated venv (VIRTUAL_ENV), never into a system or user environment
    assert "--system" not in cmd and "--user" not in cmd
