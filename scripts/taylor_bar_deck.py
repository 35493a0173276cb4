#!/usr/bin/env python3
"""Writes the Taylor bar deck of issue 21 (docs/verification.md, "Taylor bar").

A copper bar, L0 = 32.4 mm, R0 = 3.2 mm, strikes a frictionless rigid wall (*RIGIDWALL_PLANAR,
the plane z = 0) at 227 m/s; E = 117 GPa, nu = 0.35, rho = 8930 kg/m^3, bilinear isotropic
hardening SIGY = 400 MPa, ETAN = 100 MPa (*MAT_PLASTIC_KINEMATIC, BETA = 1); 80 us. SI units.
A quarter bar (x, y >= 0) of one-point hexahedra on the symmetry planes x = 0 and y = 0
(*BOUNDARY_SPC_SET), its impact face GAP = 0.01 mm above the wall at t = 0 (it lands after
0.044 us, a few cycles; the run ends 80 us after that).

Cross-section: an O-grid ("butterfly") of the quarter disc: an inner square [0, a]^2 (a = R0 / 2)
of k x k cells and two outer blocks of k x r cells between the square's sides and the arc (the arc
split at 45 degrees, each side point joined to its arc point by a straight line), so that no cell
has a corner on the arc with a 180-degree angle; k + r cells across the radius, 2 (k + r) across
the diameter. Along the axis m cells. The history nodes (*DATABASE_HISTORY_NODE) are the impact
face's rim (its mushroom radius) and the free end's nodes (the final length).

    taylor_bar_deck.py K R M [--ihq N] [--qm Q] [--q1 Q1 --q2 Q2] [--tssfac F] > deck.k
"""
import argparse
import math
import sys

L0, R0, V0, GAP = 32.4e-3, 3.2e-3, 227.0, 1e-5
END = 80e-6 + GAP / V0  # 80 us after the impact


def section(k, r):
    """2-D nodes of the quarter disc (list of (x, y)), quads (4 node indices, counter-clockwise),
    the rim node indices and the node indices on x = 0 and on y = 0."""
    a = 0.5 * R0
    index = {}
    pts = []

    def node(key, p):
        if key not in index:
            index[key] = len(pts)
            pts.append(p)
        return index[key]

    # Inner square: key ('s', i, j).
    def sq(i, j):
        return node(('s', i, j), (a * i / k, a * j / k))

    # Outer block A (between x = a and the arc from 0 to 45 degrees): along j (0..k), radial l (0..r).
    def blk_a(j, l):
        if l == 0:
            return sq(k, j)
        if j == k:
            return blk_b(k, l)
        s = (a, a * j / k)
        t = 0.25 * math.pi * j / k
        c = (R0 * math.cos(t), R0 * math.sin(t))
        f = l / r
        return node(('a', j, l), (s[0] + f * (c[0] - s[0]), s[1] + f * (c[1] - s[1])))

    # Outer block B (between y = a and the arc from 90 down to 45 degrees): along i (0..k), radial l.
    def blk_b(i, l):
        if l == 0:
            return sq(i, k)
        s = (a * i / k, a)
        t = 0.5 * math.pi - 0.25 * math.pi * i / k
        c = (R0 * math.cos(t), R0 * math.sin(t)) if i else (0.0, R0)  # cos(pi/2) is not 0 in floating point
        f = l / r
        return node(('b', i, l), (s[0] + f * (c[0] - s[0]), s[1] + f * (c[1] - s[1])))

    quads = []
    for j in range(k):
        for i in range(k):
            quads.append((sq(i, j), sq(i + 1, j), sq(i + 1, j + 1), sq(i, j + 1)))
    for j in range(k):
        for l in range(r):
            quads.append((blk_a(j, l), blk_a(j, l + 1), blk_a(j + 1, l + 1), blk_a(j + 1, l)))
    for i in range(k):
        for l in range(r):
            # counter-clockwise seen from +z: radial outwards is +y here, i runs along +x
            quads.append((blk_b(i, l), blk_b(i + 1, l), blk_b(i + 1, l + 1), blk_b(i, l + 1)))
    rim = sorted({blk_a(j, r) for j in range(k + 1)} | {blk_b(i, r) for i in range(k + 1)})
    assert all(p[0] >= 0.0 and p[1] >= 0.0 for p in pts)
    on_x0 = [n for n, p in enumerate(pts) if p[0] == 0.0]
    on_y0 = [n for n, p in enumerate(pts) if p[1] == 0.0]
    assert len(on_x0) == len(on_y0) == k + r + 1
    return pts, quads, rim, on_x0, on_y0


def signed_area(pts, q):
    s = 0.0
    for t in range(4):
        x0, y0 = pts[q[t]]
        x1, y1 = pts[q[(t + 1) % 4]]
        s += x0 * y1 - x1 * y0
    return 0.5 * s


def id_cards(ids, width=10, per=8):
    lines = []
    for s in range(0, len(ids), per):
        lines.append(''.join(f'{i:{width}d}' for i in ids[s:s + per]))
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('k', type=int, help='cells along each side of the inner square')
    ap.add_argument('r', type=int, help='radial cells of the outer blocks')
    ap.add_argument('m', type=int, help='cells along the axis')
    ap.add_argument('--ihq', type=int, default=0, help='*CONTROL_HOURGLASS IHQ (0: the default, 1)')
    ap.add_argument('--qm', type=float, default=0.0, help='*CONTROL_HOURGLASS QH (0: the default, 0.1)')
    ap.add_argument('--q1', type=float, default=0.0, help='*CONTROL_BULK_VISCOSITY Q1 (0: 1.5)')
    ap.add_argument('--q2', type=float, default=0.0, help='*CONTROL_BULK_VISCOSITY Q2 (0: 0.06)')
    ap.add_argument('--face-spc', action='store_true',
                    help='instead of the wall, the impact face held in z from the start (as Simo 1992 and '
                         'the Abaqus benchmark: nodes that reach the wall stay on it), no gap')
    ap.add_argument('--elform', type=int, default=1, help='*SECTION_SOLID ELFORM (1 one-point, 2 selective-reduced)')
    ap.add_argument('--tssfac', type=float, default=0.0, help='*CONTROL_TIMESTEP TSSFAC (0: 0.9)')
    args = ap.parse_args()
    k, r, m = args.k, args.r, args.m
    gap = 0.0 if args.face_spc else GAP
    end = 80e-6 if args.face_spc else END
    pts, quads, rim, on_x0, on_y0 = section(k, r)
    for q in quads:
        assert signed_area(pts, q) > 0.0, q
    nn = len(pts)

    def nid(p, layer):
        return 1 + p + nn * layer

    out = []
    w = out.append
    w('*KEYWORD')
    w('*TITLE')
    w(f'Taylor bar: copper quarter bar, O-grid {k}+{r} cells across the radius, {m} along, 227 m/s')
    w('$ Written by scripts/taylor_bar_deck.py ' + ' '.join(sys.argv[1:]) + '; docs/verification.md,')
    w('$ "Taylor bar" (issue 21). SI units (m, kg, s, Pa).')
    w('*CONTROL_TERMINATION')
    w('$#  ENDTIM')
    w(f'{end:10.4e}')
    if args.tssfac:
        w('*CONTROL_TIMESTEP')
        w('$#  DTINIT    TSSFAC')
        w(f'{0.0:10.1f}{args.tssfac:10.3f}')
    if args.ihq or args.qm:
        w('*CONTROL_HOURGLASS')
        w('$#     IHQ        QH')
        w(f'{args.ihq:10d}{args.qm:10.4f}')
    if args.q1 or args.q2:
        w('*CONTROL_BULK_VISCOSITY')
        w('$#      Q1        Q2')
        w(f'{args.q1:10.3e}{args.q2:10.3e}')
    w('*DATABASE_GLSTAT')
    w(f'{1e-6:10.1e}')
    w('*DATABASE_NODOUT')
    w(f'{1e-6:10.1e}')
    w('*DATABASE_HISTORY_NODE')
    w('$ the impact face rim, then the free end (ids 8 per card)')
    hist = [nid(p, 0) for p in rim] + [nid(p, m) for p in range(nn)]
    out.extend(id_cards(hist))
    w('*PART')
    w('copper bar')
    w('$#     PID     SECID       MID')
    w(f'{1:10d}{1:10d}{1:10d}')
    w('*SECTION_SOLID')
    w('$#   SECID    ELFORM')
    w(f'{1:10d}{args.elform:10d}')
    w('*MAT_PLASTIC_KINEMATIC')
    w('$#     MID        RO         E        PR      SIGY      ETAN      BETA')
    w(f'{1:10d}{8930.0:10.1f}{117e9:10.3e}{0.35:10.2f}{400e6:10.3e}{100e6:10.3e}{1.0:10.1f}')
    w('$#     SRC       SRP        FS        VP')
    w(f'{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}')
    w('*SET_NODE_LIST_TITLE')
    w('symmetry plane x = 0')
    w(f'{1:10d}')
    out.extend(id_cards([nid(p, l) for l in range(m + 1) for p in on_x0]))
    w('*SET_NODE_LIST_TITLE')
    w('symmetry plane y = 0')
    w(f'{2:10d}')
    out.extend(id_cards([nid(p, l) for l in range(m + 1) for p in on_y0]))
    w('*BOUNDARY_SPC_SET')
    w('$#    NSID       CID      DOFX      DOFY      DOFZ     DOFRX     DOFRY     DOFRZ')
    w(f'{1:10d}{0:10d}{1:10d}{0:10d}{0:10d}{0:10d}{0:10d}{0:10d}')
    w(f'{2:10d}{0:10d}{0:10d}{1:10d}{0:10d}{0:10d}{0:10d}{0:10d}')
    if args.face_spc:
        w('*SET_NODE_LIST_TITLE')
        w('impact face')
        w(f'{3:10d}')
        out.extend(id_cards([nid(p, 0) for p in range(nn)]))
        w('*BOUNDARY_SPC_SET')
        w(f'{3:10d}{0:10d}{0:10d}{0:10d}{1:10d}{0:10d}{0:10d}{0:10d}')
    else:
        w('*RIGIDWALL_PLANAR_ID')
        w(f'{1:10d}wall')
        w('$#    NSID    NSIDEX     BOXID')
        w(f'{0:10d}{0:10d}{0:10d}')
        w('$#      XT        YT        ZT        XH        YH        ZH      FRIC')
        w(f'{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{0.0:10.1f}{1.0:10.1f}{0.0:10.1f}')
    w('*INITIAL_VELOCITY')
    w('$#    NSID    NSIDEX     BOXID')
    w(f'{0:10d}{0:10d}{0:10d}')
    w('$#      VX        VY        VZ')
    w(f'{0.0:10.1f}{0.0:10.1f}{-V0:10.1f}')
    w('*NODE')
    for l in range(m + 1):
        z = gap + L0 * l / m
        for p, (x, y) in enumerate(pts):
            w(f'{nid(p, l):8d}{x:16.9e}{y:16.9e}{z:16.9e}')
    w('*ELEMENT_SOLID')
    e = 1
    for l in range(m):
        for q in quads:
            ids = [nid(p, l) for p in q] + [nid(p, l + 1) for p in q]
            w(f'{e:8d}{1:8d}' + ''.join(f'{i:8d}' for i in ids))
            e += 1
    w('*END')
    sys.stdout.write('\n'.join(out) + '\n')
    sys.stderr.write(f'{nn * (m + 1)} nodes, {len(quads) * m} hexahedra ({len(quads)} per layer), '
                     f'{len(rim)} rim nodes\n')


if __name__ == '__main__':
    main()
