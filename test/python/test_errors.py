"""Every input error ends with exit code 1, a message naming what is wrong, and no
output file; unsolvable endpoints give exit code 2 and a complete table."""
import pytest

from conftest import read_csv

CASES = [
    # (file contents, fragments the message must contain)
    ("", ["&endpoints", "no namelist group"]),
    ("&other x = 1 /\n", ["&endpoints"]),
    ("&endpoints rho = 0.5, psi = 1 /\n", ["variable n", "is missing"]),
    ("&endpoints n = 2, rho = 0.5, psi = 1, 1 /\n", ["variable rho", "has 1 values but n = 2"]),
    ("&endpoints n = 1, rho = 0.5, 0.7, psi = 1 /\n", ["variable rho", "more than n = 1"]),
    ("&endpoints n = 2, rho = 0.5, NaN, psi = 1, 1 /\n", ["rho(2)", "not a finite number"]),
    ("&endpoints n = 1, rho = 1.5, psi = 1 /\n", ["rho(1)", "0 < rho <= 1"]),
    ("&endpoints n = 1, rho = 0, psi = 1 /\n", ["rho(1)", "0 < rho <= 1"]),
    ("&endpoints n = 1, rho = 1e999, psi = 1 /\n", ["rho(1)", "0 < rho <= 1"]),
    ("&endpoints n = 1, rho = 0.5, psi = -0.2 /\n", ["psi(1)", "0 <= psi <= pi"]),
    ("&endpoints n = 1, rho = 0.5, psi = Inf /\n", ["psi(1)", "not a finite number"]),
    ("&endpoints n = 1, rho = 0.5, psi = 1, r0 = 0.3 /\n", ["r1(1)", "give both r0 and r1"]),
    ("&endpoints n = 1, rho = 0.5, psi = 1, speed = 2 /\n", ['unknown variable "speed"']),
    ("&endpoints n = 2\n rho = 0.5, 0.6\n psi = 1, abc /\n",
     [":3:", "variable psi", '"abc" is not a valid value']),
    ("&endpoints n = 1, rho = 0.5, psi = 1\n", ["is not closed", "/"]),
    ("&endpoints n = 1.5, rho = 0.5, psi = 1 /\n", ["variable n", "whole number"]),
    ("&endpoints n = 1, rho = 0.5, psi = 1 = 2 /\n", ['"="']),
    ("&endpoints n = 3, rho = 3*0.5, psi = 0.1, 0.2, 4.0 /\n", ["psi(3)", "0 <= psi <= pi"]),
    ("&endpoints n = 20000000, rho = 0.5, psi = 1 /\n", ["variable n", "out of range"]),
    ("&endpoints n = two, rho = 0.5, psi = 1 /\n", ["variable n", "whole number"]),
    ("! only a comment\n", ["no namelist group &endpoints"]),
    ("&endpoints n = 1, rho = 0.5, psi = 1, curve_points = 1 /\n",
     ["variable curve_points = 1", "2 <= curve_points <= 100000"]),
    ("&endpoints n = 1, rho = 0.5, psi = 1, curve_points = many /\n",
     ["variable curve_points", "whole number"]),
]


@pytest.mark.parametrize("contents,fragments", CASES)
def test_bad_input_exit_1_message_and_no_output(run, tmp_path, contents, fragments):
    nml = tmp_path / "bad.nml"
    nml.write_text(contents)
    out = tmp_path / "out.csv"
    result = run(nml, "--csv", out)
    assert result.returncode == 1, result.stderr
    assert str(nml) in result.stderr
    for fragment in fragments:
        assert fragment in result.stderr, result.stderr
    assert not out.exists()
    assert list(tmp_path.iterdir()) == [nml]        # no temporary file left either
    assert result.stdout == ""


def test_all_problems_of_a_file_are_reported(run, tmp_path):
    nml = tmp_path / "bad.nml"
    nml.write_text("&endpoints\n n = 3\n rho = 0.5, 2.0, -1\n psi = 1, 9, 1\n/\n")
    result = run(nml)
    assert result.returncode == 1
    for fragment in ("rho(2)", "rho(3)", "psi(2)", ":3:", ":4:"):
        assert fragment in result.stderr


def test_rows_are_traced_to_their_lines(run, tmp_path):
    nml = tmp_path / "long.nml"
    nml.write_text("&endpoints\n n = 4\n rho = 0.5,\n       0.6,\n       0.7,\n"
                   "       1.7\n psi = 4*0.1 /\n")
    result = run(nml)
    assert result.returncode == 1
    assert f"{nml}:6: group &endpoints, variable rho(4) = 1.7" in result.stderr


def test_repeat_counts_and_null_values_are_accepted(run, tmp_path):
    nml = tmp_path / "ok.nml"
    nml.write_text("&endpoints n = 3, rho = 3*0.5, psi = 2*0.1, 0.2,\n"
                   " r0 = , 0.4, , r1 = , 0.2, /\n")
    result = run(nml)
    assert result.returncode == 0, result.stderr


def test_missing_file(run, tmp_path):
    result = run(tmp_path / "nowhere.nml")
    assert result.returncode == 1
    assert "nowhere.nml" in result.stderr and "cannot read" in result.stderr


def test_usage_errors(run, tmp_path):
    assert run().returncode == 1
    assert run("--bogus", "x.nml").returncode == 1
    help_ = run("--help")
    assert help_.returncode == 0 and "usage:" in help_.stdout


def test_existing_output_is_kept_without_force(run, tmp_path):
    nml = tmp_path / "ok.nml"
    nml.write_text("&endpoints n = 1, rho = 0.5, psi = 0.1 /\n")
    out = tmp_path / "out.csv"
    out.write_text("precious\n")
    result = run(nml, "--csv", out)
    assert result.returncode == 1 and "--force" in result.stderr
    assert out.read_text() == "precious\n"
    assert run(nml, "--csv", out, "--force").returncode == 0
    assert out.read_text().startswith("#")


def test_unsolvable_endpoints_exit_2_with_full_table(run, tmp_path):
    nml = tmp_path / "mixed.nml"
    nml.write_text("&endpoints n = 3, rho = 0.5, 0.5, 0.9,\n"
                   " psi = 0.1, 2.5, 0.4\n"
                   " r0 = , , 0.1  r1 = , , 0.01 /\n")   # row 3: secant from poor estimates
    out = tmp_path / "out.csv"
    result = run(nml, "--csv", out)
    assert result.returncode == 2, result.stderr
    _, header, rows = read_csv(out)
    assert len(rows) == 3
    assert rows[0]["status"] == "ok"
    assert rows[1]["arch"] == "inaccessible" and rows[1]["status"] == "inaccessible"
    assert rows[1]["R"] == "" and rows[1]["s"] == "" and rows[1]["t"] != ""
    assert "nan" not in out.read_text().lower()
