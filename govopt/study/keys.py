"""The keys of a study and of its points.

A study's key is the SHA-256 of its definition (:meth:`govopt.study.definition.Study.
definition`: the spec, the sweeps or tolerances, the combination, samples and seed, the mode
and the analyses left out) as canonical JSON: the same definition, the same key, whatever
process or run computes it. A point's key is its number in the study: the points are a
function of the definition and their number (:meth:`~govopt.study.definition.Study.values`),
and a study holds no point twice (a repeated value is refused when the study is defined), so
the database's primary key is the number and a study's database holds one study.

Which govopt computed a point is not part of its key: a database records the version that
wrote it, and a resume under another version first checks that the new version computes the
stored points alike (:meth:`govopt.study.store.Store.claim`).
"""

from __future__ import annotations

import hashlib

from .definition import canonical


def study_digest(definition: dict) -> str:
    """The key of a study's definition (JSON as :meth:`Study.definition` gives it)."""
    return hashlib.sha256(canonical(definition).encode()).hexdigest()
