#!/usr/bin/env python3
"""Draws docs/img/architecture.svg: the time step's phases and the contact pipeline.

Plain SVG written by hand (no plotting package needed). Edit the two lists below when a phase or
a stage changes, then run:  python3 scripts/architecture_svg.py > docs/img/architecture.svg
"""
from html import escape

# (label, owner, exchange point or "") for each phase of Simulation::step(), in order.
STEP = [
    ("plan", "plan_step(): StepPlan", ""),
    ("check the step", "StabilityMonitor", ""),
    ("accelerations", "central_difference.cpp", ""),
    ("constraints", "ties, rigid, supports, Lagrange", ""),
    ("damping", "alpha per node", ""),
    ("velocities", "update_velocities + sums", ""),
    ("tied slaves", "follow_ties", ""),
    ("energy audit", "EnergyLedger", "Exchange::sum_energies"),
    ("check the energy", "StabilityMonitor", ""),
    ("output", "OutputRecorder", ""),
    ("advance", "x, t; reset rigid and ties", ""),
    ("forces", "assemble_forces() -> StepVotes", "Exchange::sum_forces, min_dt"),
]

# (label, detail) for each stage of the contact pipeline, in order: first what is built once
# from the card, then what runs every cycle.
CONTACT = [
    ("deck card", "model::Contact, the reader"),
    ("InterfaceSpec", "sides, offset rule, friction law, stiffness, BT/DT, outputs"),
    ("factory", "make_contact_interface, one per family"),
    ("ContactAlgorithm", "ContactForces, ContactConstraint, KinematicTie"),
]
CONTACT_CYCLE = [
    ("ContactManager", "birth/death, phases in deck order"),
    ("ContactPairs", "broad phase, cadence, tracking, side memory, offsets"),
    ("ContactPoints", "slave, segment, projection, normal, offset"),
    ("enforcement", "penalty, Lagrange, tiebreak"),
    ("force assembly", "f_contact, or multipliers"),
]


def box(x, y, w, h, title, sub, fill):
    return (f'<rect x="{x}" y="{y}" width="{w}" height="{h}" rx="6" fill="{fill}" stroke="#333"/>'
            f'<text x="{x + w / 2}" y="{y + 20}" text-anchor="middle" font-size="13" font-weight="bold">{escape(title)}</text>'
            f'<text x="{x + w / 2}" y="{y + 38}" text-anchor="middle" font-size="10">{escape(sub)}</text>')


def arrow(x1, y1, x2, y2):
    return f'<line x1="{x1}" y1="{y1}" x2="{x2}" y2="{y2}" stroke="#333" marker-end="url(#a)"/>'


def main():
    w, h, gap = 165, 50, 20
    per_row = 6
    out = []
    top = 40
    out.append('<text x="20" y="25" font-size="16" font-weight="bold">One cycle of Simulation::step()</text>')
    for i, (title, owner, exch) in enumerate(STEP):
        row, col = divmod(i, per_row)
        x = 20 + col * (w + gap)
        y = top + row * (h + 50)
        out.append(box(x, y, w, h, title, owner, "#e8f0fe"))
        if exch:
            out.append(f'<text x="{x + w / 2}" y="{y + h + 14}" text-anchor="middle" font-size="10" fill="#b00">{escape(exch)}</text>')
        if i + 1 < len(STEP):
            if col + 1 < per_row:
                out.append(arrow(x + w, y + h / 2, x + w + gap - 2, y + h / 2))
            else:
                out.append(arrow(x + w / 2, y + h, 20 + w / 2, y + h + 48))
    ctop = top + 2 * (h + 50) + 40
    out.append(f'<text x="20" y="{ctop - 15}" font-size="16" font-weight="bold">The contact pipeline (one per interface)</text>')
    cw = 150
    rows = [("built once from the card", CONTACT), ("every cycle, per interface", CONTACT_CYCLE)]
    for r, (caption, stages) in enumerate(rows):
        y = ctop + r * (h + 50)
        out.append(f'<text x="20" y="{y - 4}" font-size="10" fill="#555">{escape(caption)}</text>')
        for i, (title, sub) in enumerate(stages):
            x = 20 + i * (cw + gap)
            out.append(box(x, y, cw, h + 10, title, "", "#e6f4ea"))
            words = sub.split(", ")
            for k, line in enumerate([", ".join(words[j:j + 2]) for j in range(0, len(words), 2)]):
                out.append(f'<text x="{x + cw / 2}" y="{y + 38 + 12 * k}" text-anchor="middle" font-size="9">{escape(line)}</text>')
            if i + 1 < len(stages):
                out.append(arrow(x + cw, y + (h + 10) / 2, x + cw + gap - 2, y + (h + 10) / 2))
    width = max(20 + per_row * (w + gap), 20 + max(len(CONTACT), len(CONTACT_CYCLE)) * (cw + gap))
    height = ctop + 2 * (h + 50) + 10
    print(f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif">')
    print('<defs><marker id="a" markerWidth="8" markerHeight="8" refX="7" refY="4" orient="auto">'
          '<path d="M0,0 L8,4 L0,8 z" fill="#333"/></marker></defs>')
    print(f'<rect width="{width}" height="{height}" fill="white"/>')
    print("\n".join(out))
    print("</svg>")


if __name__ == "__main__":
    main()
