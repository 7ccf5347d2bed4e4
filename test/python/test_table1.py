"""Tee (1998) Table 1, end to end through the program and its CSV output."""
from decimal import Decimal, ROUND_HALF_EVEN

from conftest import ROOT, read_csv

# Table 1 as printed, with the rho of rows 1-2 swapped back (docs/ERRATA.md)
TABLE1 = [
    # rho, psi, steps, R-bar, s, t
    ("0.2", "1.2", 10, "0.184781963328079", "0.967544327890300", "1.127755808164997"),
    ("0.5", "0.1", 7, "0.252787093630160", "0.505594850833648", "0.914164272619962"),
    ("0.7", "1.8", 7, "0.168913316595188", "1.531621194881120", "1.481218910277573"),
    ("0.9", "0.4", 7, "0.838545794202334", "0.442680075643429", "1.058599268341289"),
    ("1.0", "2.0", 6, "0.057854464393370", "1.947547388961997", "2.221060707125763"),
]


def test_table1_csv_reproduces_every_printed_digit(run, tmp_path):
    out = tmp_path / "table1.csv"
    result = run(ROOT / "data" / "table1.nml", "--csv", out)
    assert result.returncode == 0, result.stderr
    comments, header, rows = read_csv(out)
    assert header == "rho,psi,arch,R,s,t,steps,status"
    assert any("compiler" in c for c in comments)
    assert len(rows) == 5
    for row, (rho, psi, steps, r_bar, s, t) in zip(rows, TABLE1):
        assert abs(Decimal(row["rho"]) - Decimal(rho)) < Decimal("1e-33")
        assert int(row["steps"]) == steps
        assert row["status"] == "ok"
        for key, printed in (("R", r_bar), ("s", s), ("t", t)):
            rounded = Decimal(row[key]).quantize(Decimal("1e-15"), ROUND_HALF_EVEN)
            assert f"{rounded:f}" == printed, (key, row[key], printed)
            # at least 34 significant digits written
            mantissa = row[key].split("e")[0].replace(".", "").lstrip("-0")
            assert len(mantissa) >= 34


def test_table1_stdout_is_a_readable_table(run):
    result = run(ROOT / "data" / "table1.nml")
    assert result.returncode == 0
    assert "R-bar = 1.8478196332807888" in result.stdout
    assert "steps = 10" in result.stdout
