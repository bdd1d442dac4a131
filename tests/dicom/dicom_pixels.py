#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Dumps pydicom's view of DICOM pixel data for the C++ corpus test.

usage: dicom_pixels.py OUTDIR FILE...

For each FILE (numbered from 0) writes OUTDIR/<n>.raw with pydicom's pixel
array after the modality LUT (Rescale Slope / Intercept), as little endian
float32, frames x rows x columns, and one line in OUTDIR/manifest.tsv:
  <n> TAB ok TAB frames,rows,columns TAB FILE
  <n> TAB fail TAB <reason> TAB FILE
Exits 0 when it ran (per-file failures are in the manifest), 2 when pydicom or
numpy cannot be imported.
"""
import os
import sys
import warnings

try:
    import numpy as np
    import pydicom
    from pydicom.pixel_data_handlers.util import apply_modality_lut
except Exception as e:  # pragma: no cover - reported to the test
    print("pydicom/numpy unavailable: %s" % e, file=sys.stderr)
    sys.exit(2)


def dump(index, path, outdir):
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ds = pydicom.dcmread(path, force=True)
            if "PixelData" not in ds:
                return "fail\tno pixel data"
            if int(ds.get("SamplesPerPixel", 1)) != 1:
                return "fail\tcolour"
            arr = ds.pixel_array
            arr = apply_modality_lut(arr, ds)
    except Exception as e:
        return "fail\t%s: %s" % (type(e).__name__, str(e).splitlines()[0][:80] if str(e) else "")
    frames = int(ds.get("NumberOfFrames", 1) or 1)
    rows, cols = int(ds.Rows), int(ds.Columns)
    if arr.size != frames * rows * cols:
        return "fail\tunexpected shape %s" % (arr.shape,)
    arr = np.asarray(arr, dtype="<f4").reshape(frames, rows, cols)
    arr.tofile(os.path.join(outdir, "%d.raw" % index))
    return "ok\t%d,%d,%d" % (frames, rows, cols)


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 1
    outdir = sys.argv[1]
    os.makedirs(outdir, exist_ok=True)
    lines = []
    for index, path in enumerate(sys.argv[2:]):
        result = dump(index, path, outdir)
        lines.append("%d\t%s\t%s\n" % (index, result.replace("\n", " "), path))
    with open(os.path.join(outdir, "manifest.tsv"), "w", encoding="utf-8") as f:
        f.writelines(lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
