#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The rules of core/'s layout (docs/architecture.md), checked.

    tools/core_rules.py [--objects DIR] [--list]

Each check prints one line "ok: ..." or "FAILED: ..." with the places at
fault, and the run ends with "N passed, N failed". The checks:

  layers     a file includes only headers of its own layer or a lower one
  cycles     no include cycle among core's headers
  calls      an object calls only functions defined in its own layer or a
             lower one (with --objects DIR: the host build's core objects,
             DIR/core/<layer>/*.o, read with nm)
  cpu        no CPU test (FX_SOFT_MUL64, __ARM_ARCH, __riscv, ...) outside
             core/fx, the arithmetic layer
  history    no issue numbers or instruction counts in core's comments:
             figures belong in CHANGELOG.md and the generated docs
  length     no function in core/ over 100 lines; no file over 500
  doc        docs/architecture.md names every file of core/ and no other

--list prints every function's length, longest first.
"""
import os
import re
import subprocess
import sys

LAYERS = ["fx", "scene", "shapes", "parse", "accel", "trace", "frame"]
CORE = "core"
MAX_FUNCTION = 100
MAX_FILE = 500
CPU_WORDS = re.compile(
    r"\b(FX_SOFT_MUL64|FX_SOFT_CLZ|FX_MUL64_CALL|FX_CPU_NAME|"
    r"__ARM_ARCH\w*|__thumb\w*|__riscv\w*|__x86_64__|__i386__|__aarch64__)\b")
# "#17", "(#8:" in a comment; "2,555.7 instructions", "0.6 %", "-> 94".
HISTORY = re.compile(
    r"(?<![\w&])#[0-9]+\b|\b[0-9][0-9,.]*\s+instructions\b|"
    r"\b[0-9]+(\.[0-9]+)?\s?%|\b[0-9][0-9,.]* -> [0-9]")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def core_files():
    out = []
    for layer in LAYERS:
        d = os.path.join(CORE, layer)
        for name in sorted(os.listdir(d)):
            if name.endswith((".c", ".h")):
                out.append((layer, name, os.path.join(d, name)))
    return out


def comments(text):
    """(line number, comment text) for each comment line of C source."""
    out = []
    for m in re.finditer(r"/\*.*?\*/|//[^\n]*", text, re.S):
        first = text.count("\n", 0, m.start()) + 1
        for i, line in enumerate(m.group(0).split("\n")):
            out.append((first + i, line))
    return out


def functions(text):
    """(name, first line, line count) for each function definition whose
    body opens and closes at column 0, as every core file writes them."""
    lines = text.split("\n")
    out = []
    i = 0
    while i < len(lines):
        if lines[i] == "{" or re.match(r"^[A-Za-z_].*\)\s*\{\s*$", lines[i]):
            start = i
            # The signature starts at the last line that begins in column
            # 0 at or above the brace (continuation lines are indented).
            while start > 0 and lines[start] in ("{",) or (
                    start > 0 and not re.match(r"^[A-Za-z_]", lines[start])):
                start -= 1
            head = " ".join(lines[start:i + 1])
            m = re.search(r"(\w+)\s*\(", head)
            end = i + 1
            while end < len(lines) and lines[end] != "}":
                end += 1
            if m and not head.lstrip().startswith(("typedef", "struct",
                                                   "enum", "union")):
                out.append((m.group(1), start + 1, end - start + 1))
            i = end
        i += 1
    return out


class Report:
    def __init__(self):
        self.passed = 0
        self.failed = 0
        self.skipped = 0

    def check(self, name, faults, what):
        if faults:
            self.failed += 1
            print("FAILED: %s: %s" % (name, what))
            for f in faults[:20]:
                print("    " + f)
            if len(faults) > 20:
                print("    ... and %d more" % (len(faults) - 20))
        else:
            self.passed += 1
            print("ok: %s" % name)


def main(argv):
    objects = None
    if "--objects" in argv:
        objects = argv[argv.index("--objects") + 1]
    files = core_files()
    where = {name: layer for layer, name, _ in files}
    rank = {layer: i for i, layer in enumerate(LAYERS)}
    text = {path: open(path, encoding="utf-8").read() for _, _, path in files}

    if "--list" in argv:
        rows = []
        for _, _, path in files:
            for name, line, n in functions(text[path]):
                rows.append((n, "%s:%d %s" % (path, line, name)))
        for n, what in sorted(rows, reverse=True):
            print("%4d %s" % (n, what))
        return 0

    rep = Report()

    faults = []
    graph = {}
    for layer, name, path in files:
        for inc in INCLUDE.findall(text[path]):
            if inc not in where:
                continue  # the user's fixtrace_conf.h
            graph.setdefault(name, []).append(inc)
            if rank[where[inc]] > rank[layer]:
                faults.append("%s includes %s/%s (a higher layer)" %
                              (path, where[inc], inc))
    rep.check("layers", faults, "includes that go upward (" +
              " < ".join(LAYERS) + ")")

    faults = []
    state = {}

    def visit(node, stack):
        state[node] = 1
        for nxt in graph.get(node, []):
            if state.get(nxt) == 1:
                cyc = stack[stack.index(nxt):] + [nxt] if nxt in stack else [
                    node, nxt]
                faults.append(" -> ".join(cyc))
            elif not state.get(nxt):
                visit(nxt, stack + [nxt])
        state[node] = 2

    for _, name, _ in files:
        if not state.get(name):
            visit(name, [name])
    rep.check("cycles", faults, "include cycles")

    if not objects:
        print("SKIPPED: calls: no build given (--objects DIR)")
        rep.skipped += 1
    else:
        faults = []
        defined = {}
        undefined = {}
        for layer in LAYERS:
            d = os.path.join(objects, CORE, layer)
            if not os.path.isdir(d):
                continue
            for obj in sorted(os.listdir(d)):
                if not obj.endswith(".o") or not os.path.exists(
                        os.path.join(CORE, layer, obj[:-2] + ".c")):
                    continue  # not an object of today's sources
                path = os.path.join(d, obj)
                nm = subprocess.run(["nm", path], capture_output=True,
                                    text=True, check=True).stdout
                for line in nm.split("\n"):
                    parts = line.split()
                    if len(parts) == 3 and parts[1] in "TDRB":
                        defined[parts[2]] = layer
                    elif len(parts) == 2 and parts[0] == "U":
                        undefined.setdefault((layer, path), []).append(
                            parts[1])
        if not defined:
            print("SKIPPED: calls: no objects under %s/core" % objects)
            rep.skipped += 1
        for (layer, path), syms in sorted(undefined.items()):
            for sym in syms:
                if sym in defined and rank[defined[sym]] > rank[layer]:
                    faults.append("%s calls %s (defined in %s/)" %
                                  (path, sym, defined[sym]))
        if defined:
            rep.check("calls", faults, "calls into a higher layer")

    faults = []
    for layer, name, path in files:
        if layer == "fx":
            continue
        for i, line in enumerate(text[path].split("\n"), 1):
            if CPU_WORDS.search(line):
                faults.append("%s:%d: %s" % (path, i, line.strip()))
    rep.check("cpu", faults, "CPU tests outside core/fx")

    faults = []
    for _, _, path in files:
        for i, line in comments(text[path]):
            if HISTORY.search(line):
                faults.append("%s:%d: %s" % (path, i, line.strip()))
    rep.check("history", faults,
              "issue numbers or measurements in comments")

    faults = []
    for _, _, path in files:
        n = text[path].count("\n")
        if n > MAX_FILE:
            faults.append("%s: %d lines" % (path, n))
        for name, line, count in functions(text[path]):
            if count > MAX_FUNCTION:
                faults.append("%s:%d: %s is %d lines" %
                              (path, line, name, count))
    rep.check("length", faults, "functions over %d lines or files over %d" %
              (MAX_FUNCTION, MAX_FILE))

    faults = []
    doc = open("docs/architecture.md", encoding="utf-8").read()
    named = set(re.findall(r"`((?:fx|rt|fixtrace)_\w+\.[ch])`", doc))
    for layer, name, path in files:
        if name not in named:
            faults.append("%s is not in docs/architecture.md" % path)
    for name in sorted(named - set(where)):
        faults.append("docs/architecture.md names %s, which is not in core/" %
                      name)
    rep.check("doc", faults, "docs/architecture.md and core/ differ")

    print("%d passed, %d failed%s" % (rep.passed, rep.failed, ", %d skipped" %
                                      rep.skipped if rep.skipped else ""))
    return 1 if rep.failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
