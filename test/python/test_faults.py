"""Fault injection: a result file is complete and correct under its name, or absent.

Full disks (a 200 KiB tmpfs, root only), /dev/full and closed pipes on stdout, links
planted at the target and at the temporary file, outputs that are the same file or the
input, missing and read-only directories, signals during a long run, and two runs
writing the same name (issue 9). Each case asserts the exit code, the message and that
no output or temporary file is left where none should be.
"""
import os
import re
import signal
import stat
import subprocess
import time

import pytest

from conftest import read_csv

TEMPORARY = re.compile(r"^\.(.+)\.[A-Za-z0-9]{6}\.(tmp|old)$")   # .NAME.XXXXXX.tmp


def write_input(path, n, force=None, curve_points=0, seed=3):
    """An &endpoints file of n rows (inverse-square unless `force` names another field)."""
    import random
    rng = random.Random(seed)
    rho = ", ".join(f"{rng.uniform(0.05, 1.0):.6f}" for _ in range(n))
    psi = ", ".join(f"{rng.uniform(0.01, 1.5):.6f}" for _ in range(n))
    extra = f" force = '{force}'\n exponent = 3\n" if force else ""
    if curve_points:
        extra += f" curve_points = {curve_points}\n"
    path.write_text(f"&endpoints\n n = {n}\n{extra} rho = {rho}\n psi = {psi}\n/\n")
    return path


def leftovers(directory):
    """Temporary files of the program left in a directory."""
    return [name for name in os.listdir(directory) if TEMPORARY.match(name)]


def mount_tmpfs(options, directory):
    """mount -t tmpfs; a CompletedProcess, also when there is no mount command."""
    try:
        return subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", str(directory)],
                              capture_output=True, text=True)
    except OSError as error:
        return subprocess.CompletedProcess([], 1, "", str(error))


@pytest.fixture
def small_disk(tmp_path):
    """A 200 KiB tmpfs: a full disk. Needs root and a working mount; skipped otherwise."""
    if os.geteuid() != 0:
        pytest.skip("full-disk cases need root to mount a small tmpfs (not root here)")
    disk = tmp_path / "disk"
    disk.mkdir()
    mounted = mount_tmpfs("size=200k", disk)
    if mounted.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {mounted.stderr.strip()}")
    yield disk
    subprocess.run(["umount", str(disk)], check=False)


@pytest.fixture
def read_only_dir(tmp_path):
    """A read-only directory that root cannot write either: a read-only tmpfs mount."""
    if os.geteuid() != 0:
        directory = tmp_path / "ro"
        directory.mkdir()
        directory.chmod(0o555)
        yield directory
        directory.chmod(0o755)
        return
    directory = tmp_path / "ro"
    directory.mkdir()
    mounted = mount_tmpfs("size=20k,ro", directory)
    if mounted.returncode != 0:
        pytest.skip(f"root ignores permissions and a read-only mount failed: "
                    f"{mounted.stderr.strip()}")
    yield directory
    subprocess.run(["umount", str(directory)], check=False)


# --- full disk, /dev/full, closed pipe ------------------------------------------------

@pytest.mark.parametrize("option", ["--csv", "--nml", "--table", "--curves"])
def test_full_disk_exit_3_and_nothing_left(run, tmp_path, small_disk, option):
    nml = write_input(tmp_path / "in.nml", 2000, curve_points=5)
    out = small_disk / "out"
    result = run(nml, option, out, "--no-table", "--quiet")
    assert result.returncode == 3, result.stderr
    assert f"cannot write {out}: No space left on device" in result.stderr
    assert os.listdir(small_disk) == []


def test_full_disk_second_output_removes_the_first(run, tmp_path, small_disk):
    nml = write_input(tmp_path / "in.nml", 2000)
    elsewhere = tmp_path / "fits.csv"                 # on a disk with room
    result = run(nml, "--csv", elsewhere, "--nml", small_disk / "out.nml", "--no-table",
                 "--quiet")
    assert result.returncode == 3 and "No space left on device" in result.stderr
    assert not elsewhere.exists() and leftovers(tmp_path) == []
    assert os.listdir(small_disk) == []


def test_stdout_to_full_disk_file(app, tmp_path, small_disk):
    nml = write_input(tmp_path / "in.nml", 2000)
    with open(small_disk / "stdout.csv", "w") as sink:
        result = subprocess.run([str(app), str(nml), "--csv", "-", "--quiet"], stdout=sink,
                                stderr=subprocess.PIPE, text=True, timeout=120)
    assert result.returncode == 3
    assert "cannot write to standard output: No space left on device" in result.stderr


def test_stdout_to_dev_full(app, tmp_path):
    nml = write_input(tmp_path / "in.nml", 20)
    out = tmp_path / "out.csv"
    with open("/dev/full", "w") as sink:
        result = subprocess.run([str(app), str(nml), "--csv", str(out)], stdout=sink,
                                stderr=subprocess.PIPE, text=True, timeout=120)
    assert result.returncode == 3
    assert "standard output: No space left on device" in result.stderr
    assert not out.exists() and leftovers(tmp_path) == []       # all or none
    with open("/dev/full", "w") as sink:                         # the --check verdict too
        result = subprocess.run([str(app), "--check", str(nml)], stdout=sink,
                                stderr=subprocess.PIPE, text=True, timeout=120)
    assert result.returncode == 3 and "No space left on device" in result.stderr


@pytest.mark.parametrize("ignore_sigpipe", [False, True])
def test_closed_pipe_exits_quietly_141(app, tmp_path, ignore_sigpipe):
    nml = write_input(tmp_path / "in.nml", 2000)
    out = tmp_path / "out.csv"
    # restore_signals=False: the child inherits Python's SIG_IGN for SIGPIPE (EPIPE path)
    child = subprocess.Popen([str(app), str(nml), "--quiet", "--csv", str(out)],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             restore_signals=not ignore_sigpipe)
    child.stdout.read(100)
    child.stdout.close()
    assert child.wait(timeout=120) == 141
    assert child.stderr.read() == b""
    assert not out.exists() and leftovers(tmp_path) == []


# --- links planted at the target and at the temporary file ---------------------------

def test_dangling_symlink_at_target_is_kept_without_force(run, tmp_path):
    nml = write_input(tmp_path / "in.nml", 2)
    link = tmp_path / "out.csv"
    link.symlink_to(tmp_path / "nowhere")
    result = run(nml, "--csv", link, "--no-table")
    assert result.returncode == 1 and "exists; use --force" in result.stderr
    assert os.readlink(link) == str(tmp_path / "nowhere")
    assert not (tmp_path / "nowhere").exists() and leftovers(tmp_path) == []


@pytest.mark.parametrize("kind", ["symlink", "hardlink"])
def test_force_replaces_the_link_never_the_victim(run, tmp_path, kind):
    nml = write_input(tmp_path / "in.nml", 2)
    victim = tmp_path / "victim.txt"
    victim.write_text("precious\n")
    out = tmp_path / "out.csv"
    if kind == "symlink":
        out.symlink_to(victim)
    else:
        os.link(victim, out)
    result = run(nml, "--csv", out, "--no-table", "--force")
    assert result.returncode == 0, result.stderr
    assert victim.read_text() == "precious\n"
    assert not out.is_symlink() and out.read_text().startswith("# brachistochrone")
    assert os.stat(victim).st_nlink == 1 and leftovers(tmp_path) == []


def test_force_refuses_directory_fifo_and_device(run, tmp_path):
    nml = write_input(tmp_path / "in.nml", 2)
    directory = tmp_path / "dir.csv"
    directory.mkdir()
    fifo = tmp_path / "fifo.csv"
    os.mkfifo(fifo)
    for target, word in [(directory, "a directory"), (fifo, "a FIFO"),
                         ("/dev/null", "a character device")]:
        result = run(nml, "--csv", target, "--no-table", "--force")
        assert result.returncode == 1, result.stderr
        assert f"is {word}; --force replaces only regular files" in result.stderr
    assert directory.is_dir() and stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)
    assert leftovers(tmp_path) == []


def blocked_run(app, nml, *args):
    """A run stopped before its commit: its table fills a pipe nobody reads yet."""
    child = subprocess.Popen([str(app), str(nml), "--quiet", *map(str, args)],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    return child


def wait_for(condition, timeout=60.0):
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, "timed out"
        time.sleep(0.02)


def test_temporary_file_is_fresh_and_unguessable(app, tmp_path):
    nml = write_input(tmp_path / "in.nml", 2000)      # table > 64 KiB: blocks on the pipe
    child = blocked_run(app, nml, "--csv", tmp_path / "out.csv")
    wait_for(lambda: leftovers(tmp_path))
    (name,) = leftovers(tmp_path)
    assert TEMPORARY.match(name).group(1) == "out.csv"
    info = os.lstat(tmp_path / name)
    assert stat.S_ISREG(info.st_mode) and info.st_nlink == 1
    child.stdout.read()
    assert child.wait(timeout=120) == 0
    assert leftovers(tmp_path) == [] and (tmp_path / "out.csv").exists()


def test_link_swapped_in_at_temporary_name_is_not_committed(app, tmp_path):
    nml = write_input(tmp_path / "in.nml", 2000)
    victim = tmp_path / "victim.txt"
    victim.write_text("precious\n")
    child = blocked_run(app, nml, "--csv", tmp_path / "out.csv")
    wait_for(lambda: leftovers(tmp_path))
    (name,) = leftovers(tmp_path)
    planted = tmp_path / "planted"
    planted.symlink_to(victim)
    os.replace(planted, tmp_path / name)              # an attacker swaps in a link
    child.stdout.read()
    assert child.wait(timeout=120) == 3
    assert "removed or replaced by another process" in child.stderr.read().decode()
    assert victim.read_text() == "precious\n"
    assert not (tmp_path / "out.csv").exists() and leftovers(tmp_path) == []


def test_links_planted_for_the_next_pids_are_never_written_through(app, tmp_path):
    # the attack of issue 9 on the old OUT.tmp<pid> names: links for the next 300 pids
    nml = write_input(tmp_path / "in.nml", 3)
    victim = tmp_path / "victim.txt"
    victim.write_text("precious\n")
    out = tmp_path / "out.csv"
    if not os.path.exists("/proc/sys/kernel/ns_last_pid"):
        pytest.skip("no /proc/sys/kernel/ns_last_pid to predict the next pids")
    next_pid = int(open("/proc/sys/kernel/ns_last_pid").read()) + 1
    for pid in range(next_pid, next_pid + 300):
        os.symlink(victim, f"{out}.tmp{pid}")
    result = subprocess.run([str(app), str(nml), "--csv", str(out), "--no-table"],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    assert victim.read_text() == "precious\n"
    assert not out.is_symlink() and out.read_text().startswith("# brachistochrone")
    assert leftovers(tmp_path) == []


# --- same outputs, output = input, directories ---------------------------------------

def test_same_path_outputs_are_refused_before_work(run, tmp_path):
    nml = write_input(tmp_path / "in.nml", 2, curve_points=3)
    sub = tmp_path / "sub"
    sub.mkdir()
    (tmp_path / "kept.csv").write_text("precious\n")
    cases = [("--csv", sub / "x", "--nml", sub / "x"),
             ("--csv", sub / "x", "--table", tmp_path / "sub" / ".." / "sub" / "x"),
             ("--nml", tmp_path / "kept.csv", "--curves", f"{tmp_path}//kept.csv")]
    for a, pa, b, pb in cases:
        for force in ([], ["--force"]):
            result = run(nml, a, pa, b, pb, "--no-table", *force)
            assert result.returncode == 1, result.stderr
            assert "are the same file" in result.stderr
    assert os.listdir(sub) == []
    assert (tmp_path / "kept.csv").read_text() == "precious\n"


def test_output_equal_to_input_is_refused(run, tmp_path):
    nml = write_input(tmp_path / "in.nml", 2)
    before = nml.read_text()
    link = tmp_path / "link.csv"
    link.symlink_to(nml)
    for out in (nml, tmp_path / "." / "in.nml", link):
        result = run(nml, "--csv", out, "--force", "--no-table")
        assert result.returncode == 1 and "is the input file" in result.stderr
    assert nml.read_text() == before and leftovers(tmp_path) == []


def test_missing_directory_found_before_solving(run, tmp_path):
    # 20,000 endpoints of the slow general engine: solving first would take minutes
    nml = write_input(tmp_path / "in.nml", 20000, force="power")
    started = time.monotonic()
    result = run(nml, "--csv", tmp_path / "fine.csv", "--nml", tmp_path / "no" / "out.nml",
                 "--threads", "1", "--no-table")
    assert result.returncode == 3
    assert f"cannot write {tmp_path / 'no' / 'out.nml'}" in result.stderr
    assert "No such file or directory" in result.stderr
    assert time.monotonic() - started < 20
    assert sorted(os.listdir(tmp_path)) == ["in.nml"]


def test_read_only_directory_found_before_solving(run, tmp_path, read_only_dir):
    nml = write_input(tmp_path / "in.nml", 20000, force="power")
    started = time.monotonic()
    result = run(nml, "--csv", read_only_dir / "out.csv", "--threads", "1", "--no-table")
    assert result.returncode == 3, result.stderr
    assert re.search(r"(Read-only file system|Permission denied)", result.stderr)
    assert time.monotonic() - started < 20
    assert os.listdir(read_only_dir) == []


# --- signals ------------------------------------------------------------------------

@pytest.mark.parametrize("signal_number", [signal.SIGTERM, signal.SIGINT, signal.SIGHUP])
def test_signal_removes_temporary_files(app, tmp_path, signal_number):
    nml = write_input(tmp_path / "in.nml", 20000, force="power")
    child = subprocess.Popen([str(app), str(nml), "--csv", str(tmp_path / "out.csv"),
                              "--nml", str(tmp_path / "out.nml"), "--threads", "1",
                              "--quiet"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    wait_for(lambda: len(leftovers(tmp_path)) == 2)
    time.sleep(0.2)                                   # now solving
    child.send_signal(signal_number)
    assert child.wait(timeout=30) == 128 + signal_number
    assert sorted(os.listdir(tmp_path)) == ["in.nml"]


# --- two runs, one name -------------------------------------------------------------

def test_two_concurrent_runs_one_wins(app, tmp_path):
    nml = write_input(tmp_path / "in.nml", 3000)
    out = tmp_path / "same.csv"
    runs = [subprocess.Popen([str(app), str(nml), "--csv", str(out), "--no-table", "--quiet"],
                             stderr=subprocess.PIPE, text=True) for _ in range(2)]
    codes = sorted(r.wait(timeout=300) for r in runs)
    assert codes == [0, 1]
    loser = [r.stderr.read() for r in runs if r.returncode == 1][0]
    assert str(out) in loser and "--force" in loser
    _, _, rows = read_csv(out)
    assert len(rows) == 3000 and leftovers(tmp_path) == []


def test_target_appearing_during_the_run_is_kept_and_nothing_committed(app, run, tmp_path):
    nml = write_input(tmp_path / "in.nml", 2000)
    slow = blocked_run(app, nml, "--csv", tmp_path / "a.csv", "--nml", tmp_path / "b.nml")
    wait_for(lambda: len(leftovers(tmp_path)) == 2)
    other = run(nml, "--nml", tmp_path / "b.nml", "--no-table")   # the other run wins b
    assert other.returncode == 0
    winner = (tmp_path / "b.nml").read_bytes()
    slow.stdout.read()
    assert slow.wait(timeout=120) == 1
    assert "appeared during the run" in slow.stderr.read().decode()
    assert (tmp_path / "b.nml").read_bytes() == winner
    assert not (tmp_path / "a.csv").exists()          # all or none: a.csv was undone
    assert leftovers(tmp_path) == []


def test_force_commit_failure_restores_the_replaced_file(app, tmp_path):
    nml = write_input(tmp_path / "in.nml", 2000)
    old = tmp_path / "a.csv"
    old.write_text("previous results\n")
    slow = blocked_run(app, nml, "--csv", old, "--nml", tmp_path / "b.nml", "--force")
    wait_for(lambda: len(leftovers(tmp_path)) == 2)
    (tmp_path / "b.nml").mkdir()                      # the second target turns into a dir
    slow.stdout.read()
    assert slow.wait(timeout=120) == 1
    assert "is a directory" in slow.stderr.read().decode()
    assert old.read_text() == "previous results\n"    # a.csv was committed, then restored
    assert os.stat(old).st_nlink == 1 and leftovers(tmp_path) == []


def test_full_disk_with_force_keeps_the_old_file(run, tmp_path, small_disk):
    nml = write_input(tmp_path / "in.nml", 2000)
    out = small_disk / "out.csv"
    out.write_text("previous results\n")
    result = run(nml, "--csv", out, "--force", "--no-table", "--quiet")
    assert result.returncode == 3 and "No space left on device" in result.stderr
    assert out.read_text() == "previous results\n"
    assert os.listdir(small_disk) == ["out.csv"]


# --- command line and resources -----------------------------------------------------

def test_out_of_memory_for_the_solutions_exit_1_and_nothing_left(app, tmp_path):
    import resource
    nml = tmp_path / "many.nml"       # 2,000,000 rows in 70 bytes: table ~100 MB,
    nml.write_text("&endpoints\n n = 2000000\n rho = 2000000*0.5\n psi = 2000000*0.1\n/\n")
    out = tmp_path / "out.csv"        # solutions ~250 MB: more than the 280 MB limit allows

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (280 << 20, 280 << 20))
    try:
        result = subprocess.run([str(app), str(nml), "--csv", str(out), "--threads", "1",
                                 "--quiet"], capture_output=True, text=True, timeout=60,
                                preexec_fn=limit)
    except subprocess.TimeoutExpired:
        pytest.fail("the solutions fitted under 280 MB; the test needs a larger table")
    assert result.returncode == 1, result.stderr
    assert "out of memory for the solutions of 2000000 endpoints" in result.stderr
    assert "--first/--last" in result.stderr and "Error termination" not in result.stderr
    assert sorted(os.listdir(tmp_path)) == ["many.nml"]


def test_command_line_values(run, tmp_path):
    nml = write_input(tmp_path / "in.nml", 2)
    result = run(nml, "--csv", "--force", "--no-table")
    assert result.returncode == 1 and 'got the option "--force"' in result.stderr
    assert not (tmp_path / "--force").exists()
    result = run(nml, "--csv", tmp_path / "no\ndir" / "x.csv", "--no-table")
    assert result.returncode == 3 and "no\\ndir" in result.stderr       # escaped: one line
    assert len(result.stderr.splitlines()) == 1
    result = run(nml, "--threads", "2000")
    assert result.returncode == 1 and "from 1 to 1024" in result.stderr
    result = run(nml, "--csv", "-", "--nml", "-")
    assert result.returncode == 1 and "only one output can be standard output" in result.stderr
    out = tmp_path / "eq.csv"
    assert run(nml, f"--csv={out}", "--no-table").returncode == 0 and out.exists()
    piped = run(nml, "--csv", "-", "--threads=1")
    assert piped.returncode == 0
    assert piped.stdout.startswith("# brachistochrone") and "R-bar" not in piped.stdout
    assert piped.stdout.splitlines()[-3] == "rho,psi,arch,R,s,t,steps,status"
