"""The bundled example specs, installed as the package ``govopt.specs`` (pyproject.toml maps it
to this folder): ``govopt examples`` lists them, ``govopt init NAME`` copies one."""
