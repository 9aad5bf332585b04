"""Spring engineering: the checks a spring maker signs off, as pure vectorised functions (SI).

- :mod:`.materials`  spring wire grades (EN 10270-1/-2/-3, ASTM A228, Shigley's fits, custom):
  tensile strength R_m(d), G, E, density, allowable static stresses, fatigue diagrams;
  the data (with their sources) live in ``govopt/data/spring_materials.toml``.
- :mod:`.helical`    helical compression and extension springs: rate, index, Wahl and
  Bergstraesser factors, stresses, solid and minimum lengths, pitch, buckling (EN 13906-1),
  surge frequency and its detuning from excitation harmonics, extension-spring body, initial
  tension and hook stresses (Shigley), mass.
- :mod:`.fatigue`    fatigue: Zimmerli's endurance data with Goodman, Gerber or Sines lines
  (Shigley) and the EN 13906-1 Goodman diagrams (shot-peened or not).
- :mod:`.tolerances` EN 15800 grades 1-3: coil diameter, force and free-length tolerances and the
  resulting spread of the rate from wire and coil tolerances.
- :mod:`.checks`     every check as a :class:`govopt.verdict.Check` (value, limit, margin, source).
- :mod:`.assessment` one spring assessed: every figure and check of ``govopt spring``.
- :mod:`.sheet`      :class:`SpringSheet`, the specification an engineer sends to a spring maker.
- :mod:`.leaf`       leaf springs (width, thickness, length; hinged or clamped) and their table.

Symbols follow EN 13906: wire diameter ``d``, *mean coil diameter* ``D`` (``D = 2 r`` in Hamabe's
notation used by :mod:`govopt.springs.helical`), active coils ``n``, total coils ``n_t``, index
``w = C = D/d``. Every function broadcasts over numpy arrays so an optimiser can screen millions of
candidate springs in one call.
"""
