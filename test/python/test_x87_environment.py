"""The program refuses to run where the x87 arithmetic is not at its defaults.

The quad-precision primitives (fast_exp, fast_sqrt, the engines' pairs of x87 numbers)
assume the x87 precision control at 64 bits and rounding to nearest; at 53 bits their
results are wrong by up to 1e22 ulp. A shared object loaded before the program (a
constructor that sets the precision control to 53 bits, as gfortran's -mpc64 or a
library calling fldcw would) must make the program stop with exit code 1, a message
that names the cause, and no output file.
"""
import os
import pathlib
import shutil
import subprocess

ROOT = pathlib.Path(__file__).resolve().parents[2]

SHIM = r"""
#include <fpu_control.h>
__attribute__((constructor)) static void precision_53(void) {
    fpu_control_t cw;
    _FPU_GETCW(cw);
    cw = (cw & ~_FPU_EXTENDED) | _FPU_DOUBLE;
    _FPU_SETCW(cw);
}
"""


def build_shim(tmp_path):
    source = tmp_path / "pc53.c"
    source.write_text(SHIM)
    shim = tmp_path / "pc53.so"
    compiler = shutil.which("gcc") or shutil.which("cc")
    assert compiler, "a C compiler is needed (gcc comes with gfortran)"
    subprocess.run([compiler, "-shared", "-fPIC", "-o", str(shim), str(source)], check=True)
    return shim


def test_precision_53_is_refused(app, tmp_path):
    shim = build_shim(tmp_path)
    namelist = tmp_path / "table1.nml"
    shutil.copy(ROOT / "data" / "table1.nml", namelist)
    env = dict(os.environ, LD_PRELOAD=str(shim))
    done = subprocess.run([str(app), str(namelist)], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 1, done.stderr
    assert "x87 arithmetic is not at its defaults" in done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pc53.c", "pc53.so", "table1.nml"]


def test_defaults_run(app, tmp_path):
    """The same run without the shim solves Table 1 (the check passes by default)."""
    namelist = tmp_path / "table1.nml"
    shutil.copy(ROOT / "data" / "table1.nml", namelist)
    done = subprocess.run([str(app), str(namelist)], cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
