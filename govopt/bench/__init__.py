"""The benchmark runner of ``govopt bench``: speed against error, and the speed targets beside
what was measured.

Run with ``govopt bench [--quick] [--out DIR]`` (or the scripts in ``benchmarks/``). Never used
as timed assertions in the tests. Three modules, one job each:

* :mod:`.suites`: one point (time per evaluation, error) per method and setting over a fixed
  suite with the hard cases, errors against high-precision references (mpmath), and the Pareto
  front of each analysis (:func:`.suites.speed_vs_error`).
* :mod:`.targets`: ``design()`` in process (CPU), whole-process times of ``govopt --help``,
  ``evaluate`` and ``design`` (CPU, user + system, which is what an idle machine's wall time
  is; the wall time beside it, and a bare ``python -c pass`` timed in the same run: the machine
  is shared, so wall times carry its load), the peak RSS of a design over a catalogue of 48
  million combinations, and (:mod:`.bulk`) the designs per
  second of ``evaluate_many`` with and without the load change against a loop of
  ``govopt.evaluate`` timed in the same run (:func:`.targets.targets`).
* :mod:`.report`: ``speed-vs-error.md`` (tables, the Pareto front of each analysis, the
  targets), ``speed-vs-error.csv`` and ``speed-vs-error.png`` (log-log, one panel per analysis),
  and the terminal's summary. :mod:`govopt.fidelity` reads the CSV shipped in ``govopt/data``.
"""
