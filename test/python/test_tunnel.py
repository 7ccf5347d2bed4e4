"""`brachistochrone tunnel` against an independent double-precision computation:
haversine central angle, then Saitoh's closed forms (10) and the hypocycloid."""
import math
import pathlib
import subprocess

from conftest import ROOT, FPM


def tunnel(*args):
    subprocess.run([str(FPM), "build", "--profile", "release"], cwd=ROOT, check=True,
                   capture_output=True)
    exe = subprocess.run([str(FPM), "run", "--profile", "release", "--runner", "echo",
                          "brachistochrone"], cwd=ROOT, check=True, capture_output=True,
                         text=True).stdout.strip().splitlines()[-1]
    return subprocess.run([str(ROOT / exe), "tunnel", *map(str, args)], capture_output=True,
                          text=True)


def oracle(lat1, lon1, lat2, lon2, radius=6371.0, g=9.81):
    p1, p2, dl = math.radians(lat1), math.radians(lat2), math.radians(lon2 - lon1)
    h = math.sin((p2 - p1) / 2) ** 2 + math.cos(p1) * math.cos(p2) * math.sin(dl / 2) ** 2
    angle = 2 * math.asin(math.sqrt(h))
    rho_m = 1 - angle / math.pi                      # Saitoh: surface angle pi (1 - rho_m)
    minutes = math.pi * math.sqrt(1 - rho_m ** 2) * math.sqrt(radius * 1e3 / g) / 60
    return radius * (1 - rho_m), minutes


def number_after(text, label):
    """The first number after `label` on its line (the program prints 3 decimals)."""
    line = next(l for l in text.splitlines() if l.startswith(label))
    return float(line[len(label):].replace(":", " ").split()[0])


def test_new_york_to_los_angeles():
    result = tunnel(40.7128, -74.0060, 34.0522, -118.2437)
    assert result.returncode == 0, result.stderr
    depth, minutes = oracle(40.7128, -74.0060, 34.0522, -118.2437)
    assert abs(number_after(result.stdout, "deepest point") - depth) < 1e-3
    line = next(l for l in result.stdout.splitlines() if l.startswith("travel time"))
    assert abs(float(line.split("=")[1].split()[0]) - minutes) < 1e-3


def test_antipodes_take_pi_sqrt_r_over_g():
    result = tunnel(0, 0, 0, 180)
    assert result.returncode == 0
    expected = math.pi * math.sqrt(6371e3 / 9.81) / 60          # 42.196 min, not 41
    assert f"{expected:.3f} min" in result.stdout


def test_bad_input():
    assert tunnel(91, 0, 0, 0).returncode == 1
    assert tunnel(1, 2, 3).returncode == 1
    assert tunnel("x", 0, 0, 0).returncode == 1
