"""Batch trade studies: a spec swept over some of its inputs, one row per point, in SQLite.

A study (:class:`Study`, :func:`load_study`) is a spec plus the inputs to vary: sweeps of
dotted spec keys combined as a grid, zipped or sampled, or manufacturing tolerances sampled
around the spec's design. :func:`run_study` evaluates or designs every point into a database
(:class:`Store`): one row per point, one typed column per input, figure and check, the units
in a ``columns`` table, the study and govopt's version in ``meta`` with a ``format_version``
(docs/reference/study-database.md). A failed point is a row with its reason; a killed study is
resumed without losing or repeating a point. :func:`summary_text`, :func:`export` and the
plots (:mod:`govopt.report.study_plots`) read the database back in the spec's units.

The modules, one job each: :mod:`.definition` (what a study is, the values of its points),
:mod:`.quantities` (numbers as a spec writes them), :mod:`.sampling` and :mod:`.tolerances`
(the samplers and the tolerance model),
:mod:`.keys` (study and point keys), :mod:`.rows` (points into typed rows), :mod:`.store`
(the database), :mod:`.runner` and :mod:`.backends` (running it: this process, a process
pool, Dask), :mod:`.shown` (the spec's units), :mod:`.pareto`, :mod:`.summary` and :mod:`.export`.
"""

from .definition import Study, Sweep, load_study, read_study_file
from .errors import StudyError
from .export import export
from .pareto import OBJECTIVES, feasible, objective_column, pareto_front, pareto_points
from .rows import Column, Rows, run_chunk
from .runner import RunReport, default_chunk, run_study
from .store import FORMAT_VERSION, Store, check_database, is_study_database, remove_database
from .summary import outcome, summary_text, tolerance_summary
from .tolerances import Tolerance, grade_tolerances

__all__ = ["FORMAT_VERSION", "OBJECTIVES", "Column", "Rows", "RunReport", "Store", "Study",
           "StudyError", "Sweep", "Tolerance", "check_database", "default_chunk", "export",
           "feasible", "grade_tolerances", "is_study_database", "load_study",
           "objective_column", "outcome", "pareto_front", "pareto_points", "read_study_file",
           "remove_database", "run_chunk", "run_study", "summary_text", "tolerance_summary"]
