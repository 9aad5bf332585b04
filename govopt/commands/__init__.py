"""The command line's commands, one module each (:mod:`govopt.cli` imports a command's module
when that command runs or shows its help): ``evaluate`` (evaluate and design), ``spring``,
``bench``, ``study`` (run, export, show) and ``examples`` (examples and init); :mod:`.common`
holds the conventions every command keeps (one-line errors, exit codes, held warnings) and the
typer command class that parses options without pydantic."""
