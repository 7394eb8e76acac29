#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""docs/ARCHITECTURE.md's topic and parameter tables against the code (issue #21).

Topics: every Topic of `struct Blackboard` (modules/topics.hpp) has one row, whose writer cell
names its owner module and whose readers cell names exactly the modules that take a reader of it
(`bb.<topic>.reader()` under modules/<module>/; a helper's readers — a `MotionClaim`'s `authority`,
a `ptu::ScanView`'s scan, pan-tilt status and posture — are its holder's; the firmware's
composition hands the motion requests and the known structure's readers to the emergency module).
Parameters: every section of `for_each_param_section` (kernel/config.hpp) has one row naming the
header that declares its table. Blackboard::for_each_topic names every topic member. Namespaces: a header under modules/<m>/ opens only robuter or
robuter::<m>. And no code outside tests/ includes tests/support/test_writer.hpp.

  architecture_check.py --check [--doc FILE]   exit 1 and say why when they disagree
  architecture_check.py --readers              print the readers found in the code
  architecture_check.py --self-test            the checker catches a reader, a row and a section
                                               left out of the real document
"""
import argparse
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
OWNERS = {  # owner class -> module name as the tables write it
    "HeartbeatModule": "heartbeat", "SerialModule": "serial", "UltrasonicModule": "us",
    "EmergencyModule": "emergency", "ExecutorModule": "executor", "PlannerModule": "planner",
    "PtuModule": "ptu", "GateModule": "gate", "DoorsModule": "doors", "DemoModule": "demo",
    "LocaliseModule": "localise"}
MODULES = set(OWNERS.values()) | {"firmware"}


def topics():
    text = (ROOT / "modules/topics.hpp").read_text()
    body = text[text.index("struct Blackboard {"):]
    return {m.group(2): OWNERS[m.group(1)] for m in re.finditer(r"Topic<\w+, (\w+)> (\w+);", body)}


# Helpers whose readers are their holders': a module's header that holds one (a member), or
# derives from a frame that holds one for it, reads what the helper reads.
HELPERS = {  # the helper's file stem: how a holder names it
    "motion_claim": r"\bMotionClaim\s+\w+_;|\bModeProcess<|\bScanMode<",
    "scan_view": r"\bScanView\s+\w+_;|\bScanMode<",
}
FRAMES = {"mode_process", "scan_mode"}  # the frames (their helpers are their derived modules')


def code_readers():
    found = {}
    helper_reads = {h: set() for h in HELPERS}
    holders = []
    for path in sorted((ROOT / "modules").glob("*/**/*.[ch]pp")):
        module = path.relative_to(ROOT / "modules").parts[0]
        if module not in MODULES:
            continue
        text = path.read_text()
        for line in text.splitlines():
            for m in re.finditer(r"\bbb_?\.(\w+)\.reader\(\)", line):
                if path.stem in HELPERS:
                    helper_reads[path.stem].add(m.group(1))
                    continue
                who = module
                if module == "firmware" and ("add_motion_source" in line or "PriorMapStructure" in line):
                    who = "emergency"  # composition: the emergency module is given these readers
                found.setdefault(m.group(1), set()).add(who)
        if path.suffix == ".hpp" and path.stem not in HELPERS and path.stem not in FRAMES:
            holders += [(module, h) for h, pattern in HELPERS.items() if re.search(pattern, text)]
    for module, h in holders:
        for topic in helper_reads[h]:
            found.setdefault(topic, set()).add(module)
    return found


def doc_table(lines, first_header):
    """Rows of the Markdown table whose header starts with `first_header`: (line number, cells)."""
    rows, inside = [], False
    for n, line in enumerate(lines, 1):
        if line.startswith("| " + first_header + " |"):
            inside = True
            continue
        if inside:
            if not line.startswith("|"):
                break
            if line.startswith("|---"):
                continue
            rows.append((n, [c.strip() for c in line.strip().strip("|").split("|")]))
    return rows


def names(cell):
    """Module names of a writer or readers cell: each comma-separated entry's first word,
    parentheticals removed."""
    while True:
        stripped = re.sub(r"\([^()]*\)", "", cell)
        if stripped == cell:
            break
        cell = stripped
    return {m.group(1) for m in re.finditer(r"(?:^|[,;])\s*([a-z]+)", cell)}


def check(doc, text=None):
    lines = (doc.read_text() if text is None else text).splitlines()
    problems = []
    want = topics()
    readers = code_readers()
    rows = doc_table(lines, "topic")
    seen = set()
    for n, cells in rows:
        if len(cells) < 4:
            problems.append(f"{doc.name}:{n}: a topic row needs 4 cells")
            continue
        keys = re.findall(r"`(\w+)`", cells[0])
        if len(keys) != 1:
            problems.append(f"{doc.name}:{n}: one topic per row, found {keys}")
            continue
        t = keys[0]
        seen.add(t)
        if t not in want:
            problems.append(f"{doc.name}:{n}: `{t}` is not a topic of struct Blackboard")
            continue
        writer = names(cells[2])
        if writer != {want[t]}:
            problems.append(f"{doc.name}:{n}: `{t}`'s writer is {want[t]}, the table says {sorted(writer)}")
        got = names(cells[3]) - {"tests"}
        code = readers.get(t, set())
        if got != code:
            problems.append(f"{doc.name}:{n}: `{t}`'s readers are {sorted(code)} in the code, the table says "
                            f"{sorted(got)}")
    for t in sorted(set(want) - seen):
        problems.append(f"{doc.name}: no row for the topic `{t}`")
    # Blackboard::for_each_topic (the start-up claim check walks it) names every member, in order.
    header = (ROOT / "modules/topics.hpp").read_text()
    walked = re.findall(r'f\("(\w+)", bb\.(\w+)\);', header)
    if [n for n, _ in walked] != list(want) or any(n != m for n, m in walked):
        problems.append("modules/topics.hpp: for_each_topic does not name every topic of struct Blackboard, in order")
    # Parameters: section -> the header declaring its table.
    config = (ROOT / "kernel/config.hpp").read_text()
    sections = dict(re.findall(r'f\(std::string_view\("([\w.]+)"\), (\w+)\(\)', config))
    declared = {}
    for path in list(ROOT.glob("modules/*/*_params.hpp")) + list(ROOT.glob("hal/**/*_params.hpp")) + \
            list(ROOT.glob("kernel/*_params.hpp")) + list(ROOT.glob("robot/*_params.hpp")):
        for table in re.findall(r"std::span<const param::Param<\w+>> (\w+)\(\);", path.read_text()):
            declared[table] = str(path.relative_to(ROOT))
    prows = doc_table(lines, "section")
    pseen = set()
    for n, cells in prows:
        keys = re.findall(r"`\[([\w.]+)\]`", cells[0])
        for s in keys:
            pseen.add(s)
            if s not in sections:
                problems.append(f"{doc.name}:{n}: [{s}] is not a section of for_each_param_section")
                continue
            header = declared.get(sections[s], "?")
            if f"`{header}`" not in cells[1] or f"`{sections[s]}()`" not in cells[1]:
                problems.append(f"{doc.name}:{n}: [{s}]'s table {sections[s]} is declared in {header}")
    for s in sorted(set(sections) - pseen):
        problems.append(f"{doc.name}: no row for the section [{s}]")
    # Namespaces are their folders: modules/<m>/ opens robuter or robuter::<m> (lib/ keeps its own;
    # modules/firmware composes everything and forward-declares other namespaces' types).
    for path in sorted((ROOT / "modules").glob("*/*.hpp")):
        module = path.parent.name
        if module == "firmware":
            continue
        for ns in re.findall(r"^namespace (robuter(?:::[a-z_:]+)?) \{", path.read_text(), re.M):
            if ns not in ("robuter", f"robuter::{module}"):
                problems.append(f"{path.relative_to(ROOT)}: namespace {ns} is not its folder's (robuter::{module})")
    # The tests' writer access stays in the tests (kernel/blackboard.hpp only declares it).
    for folder in ("modules", "kernel", "hal", "protocol", "robot", "tools", "cli", "picture"):
        for path in sorted((ROOT / folder).glob("**/*.[ch]pp")):
            if '#include "tests/support/test_writer.hpp"' in path.read_text():
                problems.append(f"{path.relative_to(ROOT)}: includes the tests' writer access")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--readers", action="store_true")
    ap.add_argument("--self-test", action="store_true")
    ap.add_argument("--doc", type=pathlib.Path, default=ROOT / "docs/ARCHITECTURE.md")
    a = ap.parse_args()
    if a.readers:
        for t, owner in topics().items():
            print(f"{t}: writer {owner}; readers {', '.join(sorted(code_readers().get(t, [])))}")
        return 0
    if a.self_test:
        text = a.doc.read_text()
        cases = [  # (what is broken, the message the check must give)
            (re.sub(r"(\| `us_timing` \|[^\n]*\| us \|)[^\n]*\|", r"\1 |", text),
             "`us_timing`'s readers are ['serial'] in the code, the table says []"),
            (re.sub(r"\| `heartbeat` \|[^\n]*\n", "", text), "no row for the topic `heartbeat`"),
            (re.sub(r"\| `\[demo\]` \|[^\n]*\n", "", text), "no row for the section [demo]"),
            (text.replace("| `go_to_motion` | as `link_motion` | executor", "| `go_to_motion` | as `link_motion` | serial"),
             "`go_to_motion`'s writer is executor, the table says ['serial']")]
        failed = 0
        for broken, message in cases:
            found = check(a.doc, broken)
            if broken == text or not any(message in p for p in found):
                print(f"self-test: not caught: {message}")
                failed += 1
        if check(a.doc, text):
            print("self-test: the real document does not pass")
            failed += 1
        print(f"self-test: {max(0, len(cases) - failed)} of {len(cases)} cases caught")
        return 1 if failed else 0
    problems = check(a.doc)
    for p in problems:
        print(p)
    if not problems:
        print(f"{a.doc.name}: the topic and parameter tables agree with the code")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
