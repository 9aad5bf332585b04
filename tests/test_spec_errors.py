"""Bad specs: one clear line naming file and key, exit code 2, never a traceback."""

import re
from pathlib import Path

import pytest
from clirun import invoke

BASE = Path("specs/hamabe-a.toml").read_text()


def _edit(old: str, new: str) -> str:
    assert old in BASE, old
    return BASE.replace(old, new, 1)


CASES = {
    "missing key": (_edit('a = "18 cm"', ""), r"governor\.a: missing"),
    "unknown key": (_edit('b = "3 cm"', 'b = "3 cm"\nbb = "3 cm"'), r"governor\.bb: unknown key"),
    "stress in cm": (_edit('"4000 kgf/cm^2"', '"4000 cm"'),
                     r"material\.allowable_shear_stress: .*not a stress"),
    "negative length": (_edit('rho = "12 cm"', 'rho = "-12 cm"'),
                        r"governor\.rho: must be positive"),
    "zero length": (_edit('q = "5 cm"', 'q = "0 cm"'), r"governor\.q: must be positive"),
    "angle outside (0, 180)": (_edit('alpha_outer = "80 deg"', 'alpha_outer = "190 deg"'),
                               r"governor\.alpha_outer: must lie in"),
    "zero angle": (_edit('alpha_inner = "50 deg"', 'alpha_inner = "0 deg"'),
                   r"governor\.alpha_inner: must lie in"),
    "malformed TOML": (BASE + "\n[speed\n", r"malformed TOML"),
    "bare number for a length": (_edit('a = "18 cm"', "a = 18"),
                                 r"governor\.a: expected a length with units"),
    "unparsable unit": (_edit('a = "18 cm"', 'a = "18 parsecs per"'),
                        r"governor\.a: cannot parse"),
    "normal outside range": (_edit('alpha_normal = "64 deg + 40 arcmin"',
                                   'alpha_normal = "85 deg"'),
                             r"governor\.alpha_normal: expected alpha_inner < alpha_normal"),
    "unknown governor type": (_edit('type = "shaft"', 'type = "steam"'),
                              r"governor\.type: expected"),
    # every governor type in the sources is modelled now: a type that exists but misses its own
    # keys is told which key it misses (the porter's arm lengths)
    "another type's keys": (_edit('type = "shaft"', 'type = "porter"'),
                            r"governor\.\w+: (missing|unknown key)"),
    "table length mismatch": (_edit('"84 deg", "96 deg"]', '"84 deg"]'),
                              r"valve_gear\.table\.delta: expected 5 values"),
    "list item wrong dimension": (_edit('"58 deg"', '"58 cm"'),
                                  # grammatical ("not an angle")
                                  r"valve_gear\.table\.delta\[1\]: .*not an angle"),
    "irregularity not a number": (_edit("irregularity = 0.12", 'irregularity = "a lot"'),
                                  r"speed\.irregularity: expected a finite number"),
    "both weight and mass": (_edit('pendulum_weight = "12 kgf"',
                                   'pendulum_weight = "12 kgf"\npendulum_mass = "12 kg"'),
                             r"design\.pendulum_weight: give either"),
    "positive torque slope": (_edit('"-300 kgf*m/rad"', '"300 kgf*m/rad"'),
                              r"engine\.torque_slope: expected dT/dalpha < 0"),
    "unknown top-level table": (BASE + '\n[extras]\nx = 1\n', r"extras: unknown key"),
    "bad fidelity choice": (BASE + '\n[analysis]\ngeometry = "approximate"\n',
                            r"analysis\.geometry: expected one of"),
    # inputs pint would silently reinterpret
    "bare number added to an angle": (_edit('alpha_normal = "64 deg + 40 arcmin"',
                                            'alpha_normal = "64 deg + 0.01"'),
                                      r"governor\.alpha_normal: .*0\.01 has no unit"),
    "bare number for an angle": (_edit('alpha_normal = "64 deg + 40 arcmin"',
                                       'alpha_normal = "1.13"'),
                                 r"governor\.alpha_normal: '1\.13' has no unit: expected an angle"),
    "leading operator": (_edit('a = "18 cm"', 'a = "=18 cm"'),
                         r"governor\.a: .*unexpected '='"),
    "number after the unit": (_edit('a = "18 cm"', 'a = "18 cm 3"'),
                              r"governor\.a: .*the number 3 follows 'cm' with no operator"),
    "fractional points": (BASE + "\n[analysis]\npoints = 2.5\n",
                          r"analysis\.points: expected a whole number .*2\.5"),
    "fractional harmonics": (BASE + "\n[analysis]\nharmonics = 12.5\n",
                             r"analysis\.harmonics: expected a whole number .*12\.5"),
    "load change from outside the range": (_edit('from = "57 deg + 20 arcmin"',
                                                 'from = "45 deg"'),
                                           r"load_change\[0\]\.from: expected a configuration "
                                           r"within .*45 deg"),
    "load change to outside the range": (_edit('to = "64 deg + 40 arcmin"', 'to = "85 deg"'),
                                         r"load_change\[0\]\.to: expected a configuration "
                                         r"within .*85 deg"),
    # what an engineer writes for the spec's keys is pointed to them
    "coil diameter for the radius": (_edit('coil_radius = "6 cm"', 'coil_diameter = "12 cm"'),
                                     r"design\.coil_radius: missing .*'coil_diameter': did you "
                                     r"mean 'coil_radius'\? \(the mean coil radius, half"),
    "speed min and max": (_edit('mean = "240 rpm"', 'min = "225 rpm"\nmax = "255 rpm"')
                          .replace("irregularity = 0.12\n", "", 1),
                          r"speed\.(min|max): unknown key \(did you mean 'inner' and 'outer'"),
    # a band past govopt's limit (govopt/limits.py MAX_SPEED_RATIO)
    "band of 240 rpm to 1e7 rpm": (_edit('mean = "240 rpm"', 'inner = "240 rpm"\nouter = "1e7 rpm"')
                                   .replace("irregularity = 0.12\n", "", 1),
                                   r"speed\.outer: expected at most 10 times speed\.inner "
                                   r"\(govopt's limit\), got 4\.167e\+04 times"),
    "irregularity past the band's limit": (_edit("irregularity = 0.12", "irregularity = 1.7"),
                                           r"speed\.irregularity: expected at most 1\.636"),
    # a load change is never dropped without a word: it needs the engine
    "load change without [engine]": (
        re.sub(r"\[engine\][^\[]*", "", BASE, count=1),
        r"load_change: a load change needs \[engine\] .*add \[engine\], or drop the "
        r"\[\[load_change\]\] tables"),
    "torque slope spread without [engine]": (
        re.sub(r"\[engine\][^\[]*", "", re.sub(r"\[\[load_change\]\][^\[]*", "", BASE))
        + "\n[requirements]\nrobust_torque_slope = 0.1\n",
        r"requirements\.robust_torque_slope: spreads the engine's torque slope, and there is "
        r"no \[engine\]"),
}


@pytest.mark.parametrize("case", list(CASES))
def test_bad_spec_exits_2_with_one_line(tmp_path, case):
    text, pattern = CASES[case]
    path = tmp_path / "bad.toml"
    path.write_text(text)
    result = invoke(["evaluate", str(path)])
    assert result.exit_code == 2, result.output
    lines = result.output.strip().splitlines()
    assert len(lines) == 1, result.output
    assert lines[0].startswith(f"error: {path}"), lines[0]
    assert re.search(pattern, lines[0]), lines[0]
    assert "Traceback" not in result.output


def test_missing_file(tmp_path):
    result = invoke(["evaluate", str(tmp_path / "nope.toml")])
    assert result.exit_code == 2
    assert "cannot read spec file" in result.output


def test_r_per_min_is_rpm(tmp_path):
    """'240 r/min' (DIN 1301's symbol for revolutions) reads as 240 rpm, not a misspelt 'yr'."""
    import govopt

    rpm, r_min = (tmp_path / "rpm.toml", tmp_path / "r.toml")
    rpm.write_text(BASE)
    r_min.write_text(_edit('mean = "240 rpm"', 'mean = "240 r/min"'))
    assert govopt.load_spec(r_min).speed == govopt.load_spec(rpm).speed
