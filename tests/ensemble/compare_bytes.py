"""Byte-for-byte comparison of two gradfric results files, /run excluded.

Every dataset's raw bytes (so NaN payloads and the sign of zero count, unlike h5diff) and every
attribute outside /run must be identical. Exit 0 if so, 1 with the first differences otherwise.
Usage: python3 compare_bytes.py a.h5 b.h5
"""
import sys

import h5py
import numpy as np


def canonical(f, value):
    """Attribute value as comparable bytes; object references (the dimension scales' DIMENSION_LIST
    and REFERENCE_LIST) as the names of the objects they point to."""
    if isinstance(value, str):
        return value
    if isinstance(value, h5py.Reference):
        return f[value].name if value else ""
    array = np.asarray(value)
    if array.dtype.kind == "O" or (array.dtype.names and any(array.dtype[n].kind == "O" for n in array.dtype.names)):
        return repr([canonical(f, v) for v in (array.ravel().tolist() if array.dtype.names else array.ravel())])
    return array.tobytes()


def collect(path):
    items = {}

    def visit(name, obj):
        if name == "run" or name.startswith("run/"):
            return
        for key in obj.attrs.keys():
            if key == "REFERENCE_LIST":  # lists /run's datasets too: compare the others only
                refs = [(f[r].name, int(i)) for r, i in obj.attrs[key].tolist()]
                items["@" + name + ":" + key] = repr([x for x in refs if not x[0].startswith("/run/")])
                continue
            items["@" + name + ":" + key] = canonical(f, obj.attrs[key])
        if isinstance(obj, h5py.Dataset):
            items[name] = (obj.dtype.str, obj.shape, obj[()].tobytes())

    with h5py.File(path, "r") as f:
        for key, value in f.attrs.items():
            items["@/:" + key] = canonical(f, value)
        f.visititems(visit)
    return items


a, b = collect(sys.argv[1]), collect(sys.argv[2])
differences = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
if differences:
    print("differ:", ", ".join(differences[:10]))
    sys.exit(1)
print("identical bytes:", len(a), "datasets and attributes")
