"""`brachistochrone merge`: the CSVs of the slices of a run (a job array) joined into one.

End to end with the built program: a random 500-row input solved whole and in 7 slices,
the slices merged in shuffled order must give the whole run's rows byte for byte; and
every way a set of slices can be wrong is refused with exit 1, nothing written.
"""
import hashlib
import random

import pytest

from test_batch import write_table

ROWS = 500
SLICES = 7
HEADER = b"rho,psi,arch,R,s,t,steps,status"


@pytest.fixture
def env_fixed_date(monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")


def check_checksum(csv, nml):
    """The slice's `# input sha256:` line must be the input's SHA-256 and size (computed
    here with hashlib)."""
    data = nml.read_bytes()
    line = b"# input sha256: %s, %d bytes\n" % (hashlib.sha256(data).hexdigest().encode(),
                                               len(data))
    lines = csv.read_bytes().splitlines(keepends=True)
    present = [x for x in lines if x.startswith(b"# input sha256: ")]
    assert present == [line]


def bounds(n, parts):
    """Rows (first, last) of `parts` nearly equal slices of 1..n, computed here."""
    cuts = [k * n // parts for k in range(parts + 1)]
    return [(cuts[k] + 1, cuts[k + 1]) for k in range(parts)]


def solve(run, nml, out, *args):
    result = run(nml, "--csv", out, "--no-table", "--quiet", *args)
    assert result.returncode in (0, 2), result.stderr
    check_checksum(out, nml)
    return out


def split(data):
    """(comment lines, header, data rows) of a CSV's bytes."""
    lines = data.split(b"\n")
    assert lines[-1] == b""
    comments = [x for x in lines[:-1] if x.startswith(b"#")]
    rest = lines[len(comments):-1]
    return comments, rest[0], rest[1:]


@pytest.fixture
def job(run, tmp_path, env_fixed_date):
    """A 500-row input, its whole run, and its 7 slices (paths in row order)."""
    nml = tmp_path / "in.nml"
    write_table(nml, ROWS, seed=2026, estimates=True)
    whole = solve(run, nml, tmp_path / "whole.csv")
    parts = [solve(run, nml, tmp_path / f"part{k}.csv", "--first", first, "--last", last)
             for k, (first, last) in enumerate(bounds(ROWS, SLICES))]
    for part, (first, last) in zip(parts, bounds(ROWS, SLICES)):
        assert b", rows %d to %d of %d\n" % (first, last, ROWS) in part.read_bytes()
    return nml, whole, parts


def refused(run, tmp_path, args, *words):
    """Exit 1, nothing written, and every word in the messages."""
    out = tmp_path / "merged.csv"
    result = run("merge", out, *args)
    assert result.returncode == 1, result.stderr
    assert not out.exists()
    assert not list(tmp_path.glob(".merged.csv.*"))
    for word in words:
        assert word in result.stderr, (word, result.stderr)
    return result.stderr


def test_slices_merge_to_the_whole_run(run, tmp_path, job):
    nml, whole, parts = job
    shuffled = parts[:]
    random.Random(5).shuffle(shuffled)
    out = tmp_path / "merged.csv"
    result = run("merge", out, *shuffled)
    assert result.returncode == 0, result.stderr
    comments, header, rows = split(out.read_bytes())
    whole_comments, whole_header, whole_rows = split(whole.read_bytes())
    assert header == whole_header == HEADER
    assert rows == whole_rows and len(rows) == ROWS
    # the provenance is the whole run's (fixed date), with the merge's two lines instead
    # of the echo of the effective input
    input_line = b"# input: %s, rows 1 to %d of %d" % (str(nml).encode(), ROWS, ROWS)
    assert input_line in comments and input_line in whole_comments
    merged_from = [x for x in comments if x.startswith(b"# merged from ")]
    assert merged_from == [b"# merged from 7 slices: " + b", ".join(
        b"%s (rows %d to %d)" % (str(p).encode(), f, l)
        for p, (f, l) in zip(parts, bounds(ROWS, SLICES)))]
    echo = whole_comments.index(b"# effective input:")
    note = [x for x in comments if x.startswith(b"# effective input:")]
    assert len(note) == 1 and b"not repeated" in note[0]
    assert [x for x in comments if x not in merged_from + note] == whole_comments[:echo]
    # standard output gives the same bytes
    result = run("merge", "-", *parts)
    assert result.returncode == 0 and result.stdout.encode() == out.read_bytes()


def test_a_missing_slice_is_a_gap(run, tmp_path, job):
    _, _, parts = job
    (f2, l2), (f5, l5) = bounds(ROWS, SLICES)[2], bounds(ROWS, SLICES)[5]
    refused(run, tmp_path, parts[:2] + parts[3:5] + parts[6:],
            f"rows {f2} to {l2} of {ROWS} in no slice", f"rows {f5} to {l5} of {ROWS}")


def test_overlapping_slices(run, tmp_path, job):
    nml, _, parts = job
    extra = solve(run, nml, tmp_path / "extra.csv", "--first", 100, "--last", 150)
    message = refused(run, tmp_path, parts + [extra], "rows 100 to 142 in two slices",
                      "rows 143 to 150 in two slices")
    refused(run, tmp_path, parts + [parts[3]], "in two slices")
    assert "extra.csv" in message


def test_a_slice_of_another_input(run, tmp_path, job):
    _, _, parts = job
    other = tmp_path / "other.nml"
    write_table(other, ROWS, seed=99)
    first, last = bounds(ROWS, SLICES)[4]
    stranger = solve(run, other, tmp_path / "stranger.csv", "--first", first, "--last", last)
    refused(run, tmp_path, parts[:4] + [stranger] + parts[5:], "stranger.csv line",
            hashlib.sha256(other.read_bytes()).hexdigest(), "different inputs")


def test_a_truncated_slice(run, tmp_path, job):
    _, _, parts = job
    data = parts[3].read_bytes()
    parts[3].write_bytes(data[:-100])          # the last row cut in the middle
    first, last = bounds(ROWS, SLICES)[3]
    refused(run, tmp_path, parts, "part3.csv line", "no end of line")
    lines = data.split(b"\n")
    parts[3].write_bytes(b"\n".join(lines[:-6] + [b""]))   # five whole rows missing
    refused(run, tmp_path, parts, f"part3.csv: {last - first + 1 - 5} data rows",
            f"says rows {first} to {last} ({last - first + 1} rows)")


def test_out_exists_without_force(run, tmp_path, job):
    _, whole, parts = job
    out = tmp_path / "merged.csv"
    out.write_text("keep me\n")
    result = run("merge", out, *parts)
    assert result.returncode == 1 and "--force" in result.stderr
    assert out.read_text() == "keep me\n"
    result = run("merge", "--force", out, *parts)
    assert result.returncode == 0, result.stderr
    assert split(out.read_bytes())[2] == split(whole.read_bytes())[2]
    result = run("merge", "--force", parts[0], *parts)       # OUT is one of the slices
    assert result.returncode == 1 and "is the slice" in result.stderr


def test_files_that_are_not_slices(run, tmp_path, job):
    nml, _, parts = job
    alien = tmp_path / "alien.csv"
    alien.write_text("a,b\n1,2\n")
    renamed = tmp_path / "renamed.csv"
    renamed.write_bytes(parts[1].read_bytes().replace(HEADER, b"x,y,z"))
    refused(run, tmp_path, [parts[0], alien, renamed, nml, tmp_path / "absent.csv"] +
            parts[2:], "alien.csv: not a CSV written by brachistochrone",
            "renamed.csv line", 'header "x,y,z"', "in.nml: not a CSV",
            "absent.csv: cannot read", "4 problem(s); nothing written")


def test_usage(run, tmp_path):
    result = run("merge", "--help")
    assert result.returncode == 0 and "usage: brachistochrone merge" in result.stdout
    result = run("merge", "--version")
    assert result.returncode == 0 and result.stdout.startswith("brachistochrone merge ")
    for args in ((), (tmp_path / "out.csv",), ("--bogus", "a", "b")):
        result = run("merge", *args)
        assert result.returncode == 1 and result.stderr, args
    assert not (tmp_path / "out.csv").exists()


def test_an_input_named_like_rows_and_an_io_error(run, tmp_path, env_fixed_date):
    nml = tmp_path / "in, rows 1 to 2 of 3.nml"       # the rows are the LAST ", rows "
    write_table(nml, 9)
    parts = [solve(run, nml, tmp_path / f"p{k}.csv", "--first", f, "--last", l)
             for k, (f, l) in enumerate(((1, 4), (5, 9)))]
    out = tmp_path / "merged.csv"
    result = run("merge", out, parts[1], parts[0])
    assert result.returncode == 0, result.stderr
    assert b"# input: %s, rows 1 to 9 of 9\n" % str(nml).encode() in out.read_bytes()
    result = run("merge", tmp_path / "no such directory" / "m.csv", *parts)
    assert result.returncode == 3 and "cannot write" in result.stderr


def test_slice_option_gives_the_same_slices(run, tmp_path, job):
    """`--slice K/7` (no arithmetic in the job script) gives the slices computed here."""
    nml, whole, parts = job
    sliced = [solve(run, nml, tmp_path / f"slice{k}.csv", "--slice", f"{k}/{SLICES}")
              for k in range(1, SLICES + 1)]
    for mine, theirs in zip(parts, sliced):
        assert split(mine.read_bytes())[2] == split(theirs.read_bytes())[2]
    out = tmp_path / "merged.csv"
    result = run("merge", out, *reversed(sliced))
    assert result.returncode == 0, result.stderr
    assert split(out.read_bytes())[2] == split(whole.read_bytes())[2]
