"""The study's one error type: what went wrong as fields, the one line composed from them."""

from __future__ import annotations

from ..errors import GovoptError


class StudyError(GovoptError):
    """A study that cannot run, or a database that cannot be used, in one line.

    The reason is data, not text to be read back: ``reason`` (what is wrong), ``file`` (the
    spec or database it concerns, named first), ``where`` (the key, option or table), ``advice``
    (what to do) and ``kind`` (a word code reads: ``"damaged"``, ``"format"``, ``"version"``,
    ``"other study"``, ``"rows"``, ``"busy"``, ``"foreign"``, ...; ``""`` for a plain error).

    >>> str(StudyError("expected at least 1", where="study.samples", file="s.toml"))
    's.toml: study.samples: expected at least 1'
    >>> e = StudyError("damaged", kind="damaged", advice="--force starts it afresh").at("d.db")
    >>> str(e), e.kind
    ('d.db: damaged; --force starts it afresh', 'damaged')
    """

    def __init__(self, reason: str, *, file=None, where: str | None = None,
                 advice: str | None = None, kind: str = ""):
        self.reason, self.file, self.where, self.advice, self.kind = (
            reason, None if file is None else str(file), where, advice, kind)
        super().__init__(self._line())

    def _line(self) -> str:
        parts = [p for p in (self.file, self.where) if p]
        text = ": ".join([*parts, self.reason])
        return f"{text}; {self.advice}" if self.advice else text

    def __str__(self) -> str:
        return self._line()

    def at(self, file) -> StudyError:
        """This error naming ``file`` first (unless it names a file already)."""
        if self.file is not None:
            return self
        return StudyError(self.reason, file=file, where=self.where, advice=self.advice,
                          kind=self.kind)

    def within(self, prefix: str) -> StudyError:
        """This error inside ``prefix`` (``study``: ``study: sweep x: ...``)."""
        where = f"{prefix}: {self.where}" if self.where else prefix
        return StudyError(self.reason, file=self.file, where=where, advice=self.advice,
                          kind=self.kind)
