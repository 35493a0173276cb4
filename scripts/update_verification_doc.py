#!/usr/bin/env python3
"""Puts the table of a `blockcontact verify --all -o DIR` run into docs/verification.md.

usage: python3 scripts/update_verification_doc.py DIR [docs/verification.md]

Copies the per-problem status table and the criteria table (our figure, the bound, DYNA3D's
figure, pass/FAIL) from DIR/report.md between the markers
  <!-- verify-table begin -->  and  <!-- verify-table end -->
of the document, replacing what was there, so the committed table is always one the suite wrote.
"""
import os
import sys

BEGIN, END = "<!-- verify-table begin -->", "<!-- verify-table end -->"


def tables(report):
    """The Markdown table lines of report.md up to its figures."""
    out = []
    for line in report.split("\n"):
        if line.startswith("## Figures"):
            break
        if line.startswith("|") or line.startswith("## ") or (line.startswith("(") and out):
            out.append(line)
        elif out and out[-1] != "":
            out.append("")
    return "\n".join(out).strip() + "\n"


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    here = os.path.dirname(os.path.abspath(__file__))
    doc = sys.argv[2] if len(sys.argv) == 3 else os.path.join(here, "..", "docs", "verification.md")
    with open(os.path.join(sys.argv[1], "report.md")) as fh:
        body = tables(fh.read()).replace("## ", "#### ")
    with open(doc) as fh:
        text = fh.read()
    if BEGIN not in text or END not in text:
        print("update_verification_doc: %s has no %s ... %s markers" % (doc, BEGIN, END), file=sys.stderr)
        return 1
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    with open(doc, "w") as fh:
        fh.write(head + BEGIN + "\n" + body + END + tail)
    print("update_verification_doc: %s updated from %s" % (doc, os.path.join(sys.argv[1], "report.md")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
