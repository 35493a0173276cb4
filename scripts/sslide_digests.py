#!/usr/bin/env python3
"""Writes tests/verification/sslide_digests.txt from a verify run's CSV histories.

The digests are the 64-bit FNV-1a of each problem's CSV history (1 thread) as the library writes
it, shortest round-trip digits, so equal digests mean bitwise-equal histories. They hold for
portable code generation (a -DSLIDELINE_NATIVE=OFF build; the sanitized build of scripts/test.sh
is one): -march=native lets GCC contract a*b+c into FMAs and moves the last bits.

    cmake -S . -B build-portable -DSLIDELINE_NATIVE=OFF && cmake --build build-portable -j2 --target blockcontact
    build-portable/apps/blockcontact/blockcontact verify --all --threads 1 --no-plots -o /tmp/v
    python3 scripts/sslide_digests.py /tmp/v > tests/verification/sslide_digests.txt

Regenerate only for a deliberate physics change, and say in the commit which problems moved and why.
"""
import pathlib
import sys


def fnv1a64(data: bytes) -> int:
    h = 0xCBF29CE484222325
    for byte in data:
        h ^= byte
        h = (h * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    folder = pathlib.Path(sys.argv[1])
    files = sorted(folder.glob("sslide*.csv"))
    if len(files) != 19:
        print(f"error: {folder} holds {len(files)} sslide*.csv files, expected the 19 of verify --all",
              file=sys.stderr)
        return 1
    print("# 64-bit FNV-1a of each problem's 1-thread CSV history, portable code generation")
    print("# (scripts/sslide_digests.py says how to regenerate; tests/verification/test_sslide_suite.cpp checks).")
    for f in files:
        print(f"{f.stem} {fnv1a64(f.read_bytes()):016x}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
