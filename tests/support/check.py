# SPDX-License-Identifier: GPL-3.0-or-later
"""The verdicts of the Python process tests: one line per check, the failures counted, the exit status."""
import sys


class Checks:
    """check(name, ok, detail) prints `ok   name` or `FAIL name: detail`; exit() ends the test."""

    def __init__(self):
        self.failed = 0  # checks that failed so far

    def __call__(self, name, ok, detail=""):
        print(("ok   " if ok else "FAIL ") + name + (f": {detail}" if detail else ""), flush=True)
        self.failed += 0 if ok else 1

    def exit(self):
        print(f"{self.failed} failed")
        sys.exit(1 if self.failed else 0)
