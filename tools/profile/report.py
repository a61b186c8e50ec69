#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Where a firmware's instructions go: the report of `make profile`.

  report.py --tools PREFIX ELF COUNTS LOG [--inline] [--lines N] [--top N]
            [--inclusive [--depth-fn NAME]]

COUNTS holds "pc count" lines (tools/profile/insncount.c), LOG the
firmware's figures (its "instructions" and "pixels" lines). Prints a
Markdown table of self instructions per pixel: per function, or with
--inline per innermost inlined function ("caller>callee"), and with
--lines N the N hottest source lines. A function's callees are not in
its self count (port/baremetal/README.md).

With --inclusive, COUNTS is a call-context profile
(tools/profile/callstack.c) and the per-function table gives inclusive,
self and calls per pixel, followed by the table by ray depth
(tools/profile/inclusive.py); --inline and --lines work as before.
PREFIX is the cross toolchain's, for its nm and addr2line."""
import argparse
import bisect
import collections
import os
import subprocess
import sys

import inclusive


def fail(msg):
    sys.stderr.write('report.py: %s\n' % msg)
    sys.exit(1)


def read_counts(path):
    counts = collections.Counter()
    with open(path) as f:
        for no, line in enumerate(f, 1):
            p = line.split()
            try:
                counts[int(p[0], 16)] += int(p[1])
            except (IndexError, ValueError):
                fail('%s:%d:1: expected "hexpc count"' % (path, no))
    return counts


def read_log(path):
    figs = {}
    with open(path) as f:
        for line in f:
            p = line.split()
            if len(p) == 2 and p[0] in ('instructions', 'pixels'):
                figs[p[0]] = int(p[1])
    if figs.get('pixels', 0) <= 0:
        fail('%s: no "pixels" line (did the render finish?)' % path)
    return figs


def run(cmd, stdin=None):
    """A binutils tool's output; a missing or failing tool is an error."""
    try:
        return subprocess.run(cmd, input=stdin, capture_output=True,
                              text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError) as e:
        fail('%s: %s' % (cmd[0], getattr(e, 'stderr', None) or e))


def functions(nm, elf):
    out = run([nm, '-S', '--defined-only', elf])
    syms = []
    for line in out.splitlines():
        p = line.split()
        if len(p) == 4 and p[2] in 'tTwW':
            syms.append((int(p[0], 16) & ~1, int(p[1], 16), p[3]))
    syms.sort()
    return syms


def namer(syms):
    """name_of(addr): the function holding addr, or None."""
    starts = [s[0] for s in syms]

    def name_of(addr):
        i = bisect.bisect_right(starts, addr) - 1
        ok = i >= 0 and addr < syms[i][0] + syms[i][1]
        return syms[i][2] if ok else None
    return name_of


def by_function(syms, counts):
    name_of = namer(syms)
    agg = collections.Counter()
    for pc, n in counts.items():
        agg[name_of(pc) or '(no symbol)'] += n
    return agg


def by_source(a2l, elf, counts, inline):
    """Counts per innermost inlined function (inline) or per line."""
    pcs = sorted(counts)
    res = run([a2l, '-a', '-f', '-i', '-e', elf],
              ''.join('%x\n' % pc for pc in pcs))
    agg = collections.Counter()
    frames, pc = [], None

    def flush():
        if pc is None or not frames:
            return
        if inline:
            # frames run innermost first: (function, file:line) pairs
            names = [fn for fn, _ in frames]
            key = names[-1] if len(names) == 1 else \
                names[-1] + '>' + names[0]
        else:
            fl = frames[0][1]
            key = os.path.basename(fl.split(' ')[0])
        agg[key] += counts[pc]

    lines = res.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith('0x'):
            flush()
            pc, frames = int(lines[i], 16), []
            i += 1
        else:
            frames.append((lines[i], lines[i + 1] if i + 1 < len(lines)
                           else '??:0'))
            i += 2
    flush()
    return agg


def table(title, agg, pixels, total, top):
    print('| %s | instr/pixel | share |' % title)
    print('|---|---:|---:|')
    rows = agg.most_common()
    for name, n in rows[:top]:
        print('| %s | %.1f | %.1f%% |' % (name, n / pixels, 100.0 * n / total))
    rest = sum(n for _, n in rows[top:])
    if rest:
        print('| (%d others) | %.1f | %.1f%% |' %
              (len(rows) - top, rest / pixels, 100.0 * rest / total))
    print()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--tools', default='', help='cross toolchain prefix')
    ap.add_argument('--inline', action='store_true')
    ap.add_argument('--lines', type=int, default=0)
    ap.add_argument('--top', type=int, default=30)
    ap.add_argument('--inclusive', action='store_true')
    ap.add_argument('--depth-fn', default='trace')
    ap.add_argument('elf')
    ap.add_argument('counts')
    ap.add_argument('log')
    a = ap.parse_args()
    for p in (a.elf, a.counts, a.log):
        if not os.path.isfile(p):
            fail('%s: no such file' % p)
    if a.inclusive:
        ctxs, ctx_counts = inclusive.read_profile(a.counts)
        counts = collections.Counter()
        for (_, pc), n in ctx_counts.items():
            counts[pc] += n
    else:
        counts = read_counts(a.counts)
    figs = read_log(a.log)
    total = sum(counts.values())
    if total == 0:
        fail('%s: no instructions counted' % a.counts)
    pixels = figs['pixels']
    print('counted %d instructions, %.1f a pixel over %d pixels' %
          (total, total / pixels, pixels))
    if 'instructions' in figs:
        print('the firmware counted %d for the render, %.1f a pixel '
              '(the rest is start-up and reporting)' %
              (figs['instructions'], figs['instructions'] / pixels))
    print()
    if a.inclusive:
        inclusive.tables(*inclusive.analyse(
            ctxs, ctx_counts, namer(functions(a.tools + 'nm', a.elf)),
            a.depth_fn), pixels, total, a.top, a.depth_fn)
    if a.inline:
        table('inlined function', by_source(a.tools + 'addr2line', a.elf,
                                            counts, True),
              pixels, total, a.top)
    elif not a.inclusive:
        table('function', by_function(functions(a.tools + 'nm', a.elf),
                                      counts), pixels, total, a.top)
    if a.lines > 0:
        table('source line', by_source(a.tools + 'addr2line', a.elf,
                                       counts, False),
              pixels, total, a.lines)


if __name__ == '__main__':
    main()
