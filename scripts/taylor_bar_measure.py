#!/usr/bin/env python3
"""Reads a Taylor bar deck (scripts/taylor_bar_deck.py) and the CSV histories of its run
(`blockcontact run deck.k --csv`) and prints, at the last record: the final length (largest z of
the free end; the wall is z = 0), the mushroom radius (largest distance from the axis of the impact
face's rim), the largest effective plastic strain, the energies (plastic work, hourglass, bulk
viscosity, kinetic; as fractions of the initial kinetic energy) and the balance error.

    taylor_bar_measure.py deck.k run/deck.csv
"""
import csv
import math
import sys


def read_deck(path):
    coords, hist, lines = {}, [], open(path).read().splitlines()
    kw = None
    for ln in lines:
        if ln.startswith('*'):
            kw = ln.strip()
            continue
        if ln.startswith('$') or not ln.strip():
            continue
        if kw == '*NODE':
            coords[int(ln[0:8])] = (float(ln[8:24]), float(ln[24:40]), float(ln[40:56]))
        elif kw == '*DATABASE_HISTORY_NODE':
            hist += [int(ln[s:s + 10]) for s in range(0, len(ln), 10) if ln[s:s + 10].strip()]
    return coords, hist


def main():
    deck, csv_path = sys.argv[1], sys.argv[2]
    coords, hist = read_deck(deck)
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    first, last = rows[0], rows[-1]
    zmax0 = max(c[2] for c in coords.values())
    top = [n for n in hist if coords[n][2] == zmax0]
    zmin0 = min(c[2] for c in coords.values())
    rim = [n for n in hist if coords[n][2] == zmin0]

    def pos(n):
        c = coords[n]
        return tuple(c[a] + float(last[f'nodes/{n}/displacement_{x}']) for a, x in enumerate('xyz'))

    length = max(pos(n)[2] for n in top)
    radius = max(math.hypot(*pos(n)[:2]) for n in rim)
    # on the symmetry plane y = 0 (the O-grid's rim node at 0 degrees) and the rim's largest lift
    radius0 = max(math.hypot(*pos(n)[:2]) for n in rim if coords[n][1] == 0.0)
    lift = max(pos(n)[2] for n in rim) - min(coords[n][2] for n in rim)
    ke0 = float(first['energy/kinetic'])
    eps = float(last['parts/1/max_plastic_strain'])
    e = {k: float(last[f'energy/{k}']) / ke0 for k in
         ('kinetic', 'internal', 'hourglass', 'bulk_viscosity', 'external', 'balance_error')}
    wp = float(last['parts/1/plastic_work']) / ke0
    print(f'{deck}: t = {float(last["time"]) * 1e6:.1f} us, final length {length * 1e3:.3f} mm, '
          f'mushroom radius {radius * 1e3:.3f} mm (on y = 0: {radius0 * 1e3:.3f} mm; rim lifted '
          f'{lift * 1e3:.3f} mm), max eff. plastic strain {eps:.3f}')
    print(f'  energies / KE0 (KE0 = {ke0:.3f} J, quarter bar): plastic work {wp:.4f}, internal {e["internal"]:.4f}, '
          f'kinetic {e["kinetic"]:.4f}, hourglass {e["hourglass"]:.4f}, bulk viscosity {e["bulk_viscosity"]:.4f}, '
          f'wall (external) {e["external"]:.4f}, balance error {e["balance_error"]:.2e}')


if __name__ == '__main__':
    main()
