#!/usr/bin/env python3
"""Plots of `blockcontact verify` runs, in the style of the spec's figures.

usage: python3 scripts/plot_sslide.py DIR

Reads DIR/sslide_plots.json (written by `blockcontact verify`: per problem its HDF5 file, the
channels of each pairing, the monitored slave node with its relative displacement as the criteria
measure it, and the closed-form expected curves) and writes, per problem:
  DIR/<problem>_forces.png    F_x, F_y, R_x, R_y against time, every pairing, expected dashed
  DIR/<problem>_relative.png  relative x and y displacement of the monitored slave node against
                              the master surface point under it (negative y = interpenetration)
Needs python3-matplotlib and python3-h5py (scripts/setup.sh installs them).
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# The spec's figures: solid-on-solid solid, shell-on-solid dashed, shell-on-shell dotted.
STYLES = ["-", "--", ":", "-."]


def read(f, path):
    """A dataset as an (n, 3) array, or None when the run did not record it."""
    return f[path][:] if path in f else None


def legend(fig, axes):
    """One legend for the figure: every pairing's line style once, and the expected curve."""
    seen = {}
    for ax in axes:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            seen.setdefault(label, handle)
    fig.legend(list(seen.values()), list(seen.keys()), loc="lower center", ncol=len(seen), fontsize=8)


def relative_displacement(f, pairing):
    # `blockcontact verify` writes the series the criteria measure: the slave node re-projected
    # onto the current master surface at every output. Older manifests: the t = 0 segment.
    if pairing.get("relative_x"):
        return np.stack([np.asarray(pairing["relative_x"]), np.asarray(pairing["relative_y"])], axis=1)
    slave = read(f, "/nodes/%d/displacement" % pairing["slave_node"])
    masters = [read(f, "/nodes/%d/displacement" % n) for n in pairing["master_nodes"]]
    if slave is None or any(m is None for m in masters):
        return None
    under = sum(w * m for w, m in zip(pairing["weights"], masters))
    return slave - under


def plot_problem(directory, problem):
    path = os.path.join(directory, problem["h5"])
    if not os.path.exists(path):
        print("plot_sslide: %s: no %s, skipped" % (problem["name"], path), file=sys.stderr)
        return
    expected = problem["expected"]
    with h5py.File(path, "r") as f:
        t = f["/time"][:]
        fig, axes = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
        panels = [("F_x", 0, "force"), ("F_y", 1, "force"), ("R_x", 0, "reaction"), ("R_y", 1, "reaction")]
        for ax, (label, comp, kind) in zip(axes.flat, panels):
            for k, p in enumerate(problem["pairings"]):
                if kind == "force":
                    series = read(f, p["force"])
                else:
                    bottom, right = read(f, p["bottom"]), read(f, p["right"])
                    series = None if bottom is None or right is None else bottom + right
                if series is not None:
                    ax.plot(t, series[:, comp], STYLES[k % len(STYLES)], label=p["name"].replace("_", "-"))
            ax.plot(expected["time"], expected[label], color="0.6", linewidth=3.0, alpha=0.5, zorder=0,
                    label="expected (closed form)")
            ax.set_title(label)
            ax.set_xlabel("time")
            ax.grid(True, alpha=0.3)
        legend(fig, axes.flat)
        fig.suptitle("%s: %s" % (problem["name"], problem["description"]), fontsize=10)
        fig.tight_layout(rect=(0, 0.05, 1, 1))
        fig.savefig(os.path.join(directory, problem["name"] + "_forces.png"), dpi=110)
        plt.close(fig)

        fig, axes = plt.subplots(1, 2, figsize=(10, 3.8), sharex=True)
        for k, p in enumerate(problem["pairings"]):
            rel = relative_displacement(f, p)
            if rel is None:
                continue
            for comp, ax in enumerate(axes):
                ax.plot(t, rel[:, comp], STYLES[k % len(STYLES)], label=p["name"].replace("_", "-"))
        for comp, ax in enumerate(axes):
            ax.axhline(0.0, color="0.6", linewidth=3.0, alpha=0.5, zorder=0, label="expected (closed form)")
            ax.set_title("relative %s-displacement" % "xy"[comp])
            ax.set_xlabel("time")
            ax.grid(True, alpha=0.3)
            ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 3))
        legend(fig, axes)
        fig.suptitle("%s: slave node - master surface point under it" % problem["name"], fontsize=10)
        fig.tight_layout(rect=(0, 0.08, 1, 1))
        fig.savefig(os.path.join(directory, problem["name"] + "_relative.png"), dpi=110)
        plt.close(fig)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    directory = sys.argv[1]
    manifest = os.path.join(directory, "sslide_plots.json")
    with open(manifest) as fh:
        problems = json.load(fh)["problems"]
    for problem in problems:
        plot_problem(directory, problem)
    print("plot_sslide: %d problem(s) plotted in %s" % (len(problems), directory))
    return 0


if __name__ == "__main__":
    sys.exit(main())
