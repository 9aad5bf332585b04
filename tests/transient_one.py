"""One design through :func:`govopt.analysis.transient_events.analyse_many` (the one transient
analysis; :func:`govopt.evaluate` calls it so), its figures as Python scalars for the tests."""

from dataclasses import fields
from types import SimpleNamespace

import numpy as np

from govopt.analysis.transient_events import analyse_many


def analyse_one(*args, **kw) -> SimpleNamespace:
    s = analyse_many(*args, **kw)
    out = {}
    for f in fields(s):
        v = getattr(s, f.name)
        if v is None:
            out[f.name] = None
        elif f.name == "roots":
            out[f.name] = tuple(complex(r) for r in np.asarray(v).reshape(3))
        else:
            out[f.name] = np.asarray(v).reshape(()).item()
    return SimpleNamespace(**out)
