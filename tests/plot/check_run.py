#!/usr/bin/python3
"""gradfric.run (python/gradfric/_run.py) on a tiny scene, the checkout's package used in place with
the drivers found through GRADFRIC_BIN: the Dataset it returns holds the file's /realisations/mu_s;
options become -name value (a list comma-joined, True a flag); a temporary output is removed when
the Dataset is closed; a bad option raises RunError with exit code 2 and the option's name; the
histories are NaN past /history/length even where a file holds other values there.
Usage: check_run.py <source dir> <folder of the drivers> <work dir>
"""
import os
import shutil
import sys

import h5py
import numpy as np

src, bin_dir, work = (os.path.abspath(a) for a in sys.argv[1:4])
sys.path.insert(0, os.path.join(src, "python"))
os.environ["GRADFRIC_BIN"] = bin_dir
import gradfric  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
out = os.path.join(work, "run.h5")

# (b) A tiny ensemble: 2 points (a list), 2 realisations, 8 x 8 blocks, on 2 ranks.
assert gradfric.find_driver("gradfric") == os.path.join(bin_dir, "gradfric"), gradfric.find_driver("gradfric")
with gradfric.run(ranks=2, output=out, sbm_N=8, grading_profile="linear",
                  ensemble_delta=[0, 0.2], ensemble_realisations=2) as ds:
    with h5py.File(out, "r") as f:
        mu_s = f["realisations/mu_s"][()]
        lengths = f["history/length"][()]
    assert ds["mu_s"].dims == ("point", "realisation") and ds["mu_s"].shape == (2, 2), ds["mu_s"].shape
    assert np.array_equal(ds["mu_s"].values, mu_s) and np.isfinite(mu_s).all(), (ds["mu_s"].values, mu_s)
    assert np.allclose(ds["delta"].values, [0, 0.2]) and ds.attrs["sbm_N"] == "8", (ds["delta"].values, ds.attrs["sbm_N"])
    assert "-ensemble_delta 0,0.2" in ds.attrs["command_line"], ds.attrs["command_line"]
    # Histories: finite up to each task's length, NaN after it.
    for p in range(2):
        for r in range(2):
            n = int(lengths[p, r])
            mu = ds["mu"].isel(point=p, realisation=r).values
            assert 0 < n <= mu.size and np.isfinite(mu[:n]).all() and np.isnan(mu[n:]).all(), (p, r, n)
    # open() cuts the sample axis at the longest history.
    assert ds.sizes["sample"] == lengths.max(), (ds.sizes["sample"], lengths)
# The same run again onto the same file: refused (exit 2) without -output_overwrite, done with the flag.
try:
    gradfric.run(ranks=2, output=out, sbm_N=8)
except gradfric.RunError as e:
    assert e.returncode == 2 and "output" in e.message, (e.returncode, e.message)
else:
    raise SystemExit("FAIL: an existing output was overwritten without -output_overwrite")
with gradfric.run(ranks=2, output=out, sbm_N=8, output_overwrite=True) as ds:
    assert ds.sizes["point"] == 1 and "-output_overwrite" in ds.attrs["command_line"].split()

# A temporary output (output=None): readable, removed with the Dataset's close().
ds = gradfric.run(ranks=1, sbm_N=8)
temporary = ds.attrs["output"]
assert os.path.isfile(temporary) and np.isfinite(ds["mu_s"].values).all()
ds.close()
assert not os.path.exists(os.path.dirname(temporary)), f"{temporary} left after close()"

# (c) Bad input: RunError with the driver's one line, exit code 2, the option's name.
for options, name in (({"sbm_bogus": 3}, "-sbm_bogus"), ({"sbm_N": "abc"}, "-sbm_N")):
    try:
        gradfric.run(ranks=2, output=os.path.join(work, "bad.h5"), **dict({"sbm_N": 8}, **options))
    except gradfric.RunError as e:
        assert e.returncode == 2, (options, e.returncode, e.message)
        assert e.message.startswith("gradfric: error: ") and "\n" not in e.message and name in e.message, e.message
        assert name in str(e) and "exit code 2" in str(e), str(e)
        print(f"{options}: {e}")
    else:
        raise SystemExit(f"FAIL: {options} did not raise")
    assert not os.path.exists(os.path.join(work, "bad.h5"))
try:
    gradfric.run(driver="gradfric-nonexistent")
except ValueError:
    pass
else:
    raise SystemExit("FAIL: an unknown driver was accepted")
os.environ["GRADFRIC_BIN"] = work  # a folder without drivers: not found, whatever else exists
try:
    gradfric.find_driver("gradfric")
except FileNotFoundError as e:
    assert work in str(e), str(e)
else:
    raise SystemExit("FAIL: a driver was found outside GRADFRIC_BIN")
os.environ["GRADFRIC_BIN"] = bin_dir

# Histories past their length: masked by open() whatever the file holds there (zeros here).
shutil.copy(out, os.path.join(work, "zeros.h5"))
with h5py.File(os.path.join(work, "zeros.h5"), "r+") as f:
    n = int(f["history/length"][0, 0])
    for name in ("mu", "time", "force_x"):
        f[f"history/{name}"][0, 0, n:] = 0.0
with gradfric.open(os.path.join(work, "zeros.h5")) as ds:
    for name in ("mu", "time", "force_x"):
        values = ds[name].isel(point=0, realisation=0).values
        assert np.isfinite(values[:n]).all() and np.isnan(values[n:]).all(), name
    assert ds["mu"].isel(point=0, realisation=0).dropna("sample").size == n
print("gradfric.run checks passed")
