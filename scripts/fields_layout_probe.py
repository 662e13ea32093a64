#!/usr/bin/env python3
"""What a stacked layout of the element fields would cost to write (doc/performance.md, "Not done",
issue 27): reads the per-case groups of a result file written with ``&output fields = 'all'``
and writes the same tables stacked over the patches of all cases (one dataset per table, one
deflate-4 chunk per row), then without compression, then times zlib alone on the same bytes.

    python3 scripts/fields_layout_probe.py RESULT.h5 [SCRATCH_DIR]     # needs numpy, h5py

Prints the three times and the bytes. A probe for the design, not a writer of shcontact files.
"""
import os
import sys
import tempfile
import time
import zlib

import h5py
import numpy as np

TANGENTIAL = ["pn", "px", "py", "slip", "state", "x", "xy"]
NORMAL = ["y", "a", "k", "p0", "strip_load", "m", "n", "eps_a", "gamma", "delta_r", "r_wheel"]


def rows_of(path):
    rows = []
    with h5py.File(path, "r") as f:
        for case in sorted(f["cases"]):
            for patch in sorted(f["cases"][case]):
                g = f["cases"][case][patch]
                row = {k: g["tangential"][k][()] for k in TANGENTIAL}
                row.update({"normal_" + k: g["normal"][k][()] for k in NORMAL})
                rows.append(row)
    return rows


def write_stacked(rows, name, compress):
    start = time.perf_counter()
    with h5py.File(name, "w") as f:
        for key, first in rows[0].items():
            opts = dict(compression="gzip", compression_opts=4) if compress else {}
            d = f.create_dataset("fields/" + key, shape=(len(rows),) + first.shape,
                                 dtype=first.dtype, chunks=(1,) + first.shape, **opts)
            d.attrs["units"] = "1"
            for i, row in enumerate(rows):
                d[i] = row[key]
    return time.perf_counter() - start


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    scratch = sys.argv[2] if len(sys.argv) > 2 else tempfile.mkdtemp()
    rows = rows_of(sys.argv[1])
    t_deflate = write_stacked(rows, os.path.join(scratch, "stacked4.h5"), True)
    t_raw = write_stacked(rows, os.path.join(scratch, "stacked0.h5"), False)
    start = time.perf_counter()
    raw = packed = 0
    for row in rows:
        for value in row.values():
            data = np.ascontiguousarray(value).tobytes()
            raw += len(data)
            packed += len(zlib.compress(data, 4))
    t_zlib = time.perf_counter() - start
    n = len(rows)
    print(f"{n} rows (patches), {raw / n / 1024:.0f} KiB per row, deflate 4 -> {packed / n / 1024:.0f} KiB")
    print(f"stacked, deflate 4: {t_deflate:.2f} s ({1e3 * t_deflate / n:.1f} ms per row)")
    print(f"stacked, raw:       {t_raw:.2f} s ({1e3 * t_raw / n:.1f} ms per row)")
    print(f"zlib alone:         {t_zlib:.2f} s ({1e3 * t_zlib / n:.1f} ms per row)")


if __name__ == "__main__":
    main()
