"""Reading `govopt spring --json`: a figure by its key, whatever the section it is in."""

SECTIONS = ("spring", "material", "lengths_and_energy", "dynamics", "fatigue", "tolerances")


def fig(out: dict, key: str):
    """A figure of `govopt spring --json` by its key, whatever its section."""
    for section in SECTIONS:
        if key in out[section]:
            return out[section][key]
    raise KeyError(key)
