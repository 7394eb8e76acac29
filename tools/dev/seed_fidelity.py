#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every "(seed NNN ...)" mention in docs/ has a row in a fidelity table (ctest docs.seed_fidelity).

  tools/dev/seed_fidelity.py          lists every mention with the row it cites
  tools/dev/seed_fidelity.py --check  the same, and exits 1 when a mention cites no row, a row
                                      has no verdict, or a module doc has no fidelity table
  --docs DIR                          another folder of docs (the test's own cases)

A fidelity table is a Markdown table under a heading "Fidelity to the seeds", with the columns
| row | seed | the seed | ours | verdict |; a row's id is a word and a number (`SAF-3`). A mention is
a parenthesis that opens with "seed" and a seed report (000, 002, 003, 004, or a seed file such as
`emerg.c`); it names the row it stands for: "(seed 000, PL-2)". Random seeds of runs ("seed 7")
are not mentions.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
# The docs of modules (each holds one fidelity table).
MODULE_DOCS = ["SAFETY.md", "DOORS.md", "PLANNER.md", "PLACES.md", "PROTOCOL.md", "ROBOT.md"]
MENTION = re.compile(r"\(seed (?:00[0-4]|`)[^)]*\)?")
ROW_ID = re.compile(r"\b([A-Z]{2,4}-\d+)\b")
VERDICT = re.compile(r"^(same\b.*|adopted\b.*|kept\b.*)$", re.IGNORECASE)


def scan(path):
    """One doc in one pass: its fidelity rows [(line, id, cells)], its number of fidelity tables,
    and its mentions [(line, text)] outside those tables."""
    rows, mentions, count, inside = [], [], 0, False
    for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if line.startswith("#"):
            inside = "fidelity to the seeds" in line.lower()
            count += 1 if inside else 0
        if inside and line.startswith("|"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if ROW_ID.fullmatch(cells[0]):
                rows.append((n, cells[0], cells))
            continue  # the tables' own cells are not mentions
        mentions += [(n, m.group(0)) for m in MENTION.finditer(line)]
    return rows, count, mentions


def main(argv):
    check = "--check" in argv
    docs = pathlib.Path(argv[argv.index("--docs") + 1]) if "--docs" in argv else DOCS
    errors, rows, mentions = [], {}, []
    for path in sorted(docs.glob("*.md")):
        found, count, said = scan(path)
        mentions += [(f"{path.name}:{n}", text) for n, text in said]
        for n, rid, cells in found:
            where = f"{path.name}:{n}"
            if rid in rows:
                errors.append(f"{where}: row {rid} also in {rows[rid]}")
            rows[rid] = where
            if len(cells) != 5 or not all(cells):
                errors.append(f"{where}: row {rid} needs five non-empty cells (row, seed, the seed, ours, verdict)")
            elif not (VERDICT.match(cells[4]) or re.search(r"\d", cells[4])):
                errors.append(f"{where}: row {rid}'s verdict is neither 'same', 'adopted ...', 'kept ...' nor a measurement")
        if path.name in MODULE_DOCS and count != 1:
            errors.append(f"{path.name}: {count} fidelity tables (a module doc holds one)")
    for where, text in mentions:
        ids = [i for i in ROW_ID.findall(text) if i in rows]
        if not ids:
            errors.append(f"{where}: {text!r} cites no fidelity row")
        for i in ids:
            print(f"{where}: {text} -> {i} ({rows[i]})")
    print(f"{len(mentions)} seed mentions, {len(rows)} fidelity rows, {len(errors)} errors")
    for e in errors:
        print("error: " + e, file=sys.stderr)
    return 1 if (check and errors) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
