"""Byte-for-byte comparison of two gradfric results files, /run excluded.

Every dataset's raw bytes (so NaN payloads and the sign of zero count, unlike h5diff) and every
attribute outside /run must be identical. Exit 0 if so, 1 with the first differences otherwise.
Usage: python3 compare_bytes.py a.h5 b.h5
"""
import sys

import h5py
import numpy as np


def collect(path):
    items = {}

    def visit(name, obj):
        if name == "run" or name.startswith("run/"):
            return
        for key, value in obj.attrs.items():
            items["@" + name + ":" + key] = np.asarray(value).tobytes() if not isinstance(value, str) else value
        if isinstance(obj, h5py.Dataset):
            items[name] = (obj.dtype.str, obj.shape, obj[()].tobytes())

    with h5py.File(path, "r") as f:
        for key, value in f.attrs.items():
            items["@/:" + key] = np.asarray(value).tobytes() if not isinstance(value, str) else value
        f.visititems(visit)
    return items


a, b = collect(sys.argv[1]), collect(sys.argv[2])
differences = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
if differences:
    print("differ:", ", ".join(differences[:10]))
    sys.exit(1)
print("identical bytes:", len(a), "datasets and attributes")
