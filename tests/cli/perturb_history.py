#!/usr/bin/env python3
"""Scales one component of one history channel of a run's HDF5 file over a time window, in place:
a perturbed history for `blockcontact verify --histories` (tests/cli/verify_exit_code.cmake).

    perturb_history.py FILE DATASET COMPONENT FACTOR T0 T1
"""
import sys

import h5py


def main(argv):
    path, dataset, component, factor, t0, t1 = argv[1:7]
    component, factor, t0, t1 = int(component), float(factor), float(t0), float(t1)
    with h5py.File(path, "r+") as f:
        time = f["/time"][:]
        data = f[dataset][:]
        rows = (time >= t0 - 1e-9) & (time <= t1 + 1e-9)
        if not rows.any():
            sys.exit(f"no record of {path} in [{t0}, {t1}]")
        data[rows, component] *= factor
        f[dataset][...] = data
    print(f"perturb_history: {dataset}[{component}] x {factor} on {int(rows.sum())} records")


if __name__ == "__main__":
    main(sys.argv)
