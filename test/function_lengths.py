#!/usr/bin/env python3
"""Functions longer than a limit, counted in code lines (not blank, not a
`//` comment), found with Universal Ctags (Debian: universal-ctags).

    test/function_lengths.py include 80     # the library: none over 80
    test/function_lengths.py tools 120      # the tool: none over 120

Prints one line per function over the limit (lines, file, name, first line)
and exits 1 when there is one.
"""
import json
import subprocess
import sys

root, limit = sys.argv[1], int(sys.argv[2])
tags = subprocess.run(["ctags", "-R", "--output-format=json", "--fields=+ne", "--kinds-c++=f",
                       "--languages=C++", "-f", "-", root], capture_output=True, text=True, check=True).stdout
over = []
for line in tags.splitlines():
    t = json.loads(line)
    if t.get("kind") != "function" or "end" not in t:
        continue
    with open(t["path"], encoding="utf-8") as f:
        body = f.read().splitlines()[t["line"] - 1:t["end"]]
    n = sum(1 for l in body if l.strip() and not l.strip().startswith("//"))
    if n > limit:
        over.append((n, t["path"], t["name"], t["line"]))
for n, path, name, first in sorted(over, reverse=True):
    print(f"{n} {path}:{first} {name}")
sys.exit(1 if over else 0)
