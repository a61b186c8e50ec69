# SPDX-License-Identifier: MIT
"""Inclusive counts for `make profile PROFILE=--inclusive`: report.py's
tables from a call-context profile (tools/profile/callstack.c).

A function's inclusive count is every instruction that ran while it was
on the call stack, or in its own code: itself and all it called. A
block counts once to each function, however often a recursive function
is on the stack. Self counts a function's own code; calls are the calls
the plugin saw (BL, BLX to a function entry).

"By ray depth" splits the count by the number of frames of one function
(--depth-fn, default trace) on the stack, and names, per depth, the top
callees: the functions active above the innermost such frame, each with
its inclusive count at that depth (at depth 0, every active function)."""
import collections
import re
import sys


def fail(path, no, col, msg):
    # report.py's message form; report.py imports this module
    sys.stderr.write('report.py: %s:%d:%d: %s\n' % (path, no, col, msg))
    sys.exit(1)


def read_profile(path):
    """Contexts {id: (parent, entry, calls)}, with 0 the root, and the
    counts {(ctx, pc): instructions} of callstack.c's output."""
    ctxs = {0: (None, None, 0)}
    counts = collections.Counter()
    with open(path) as f:
        for no, line in enumerate(f, 1):
            cols = [m.start() + 1 for m in re.finditer(r'\S+', line)]
            p = line.split()
            k = 0  # the field being read, for the error's column
            try:
                if p[0] == 'C' and len(p) == 5:
                    k = 1
                    cid = int(p[1])
                    if cid in ctxs:
                        raise ValueError
                    k = 2
                    parent = int(p[2])
                    if parent not in ctxs:
                        raise ValueError
                    k = 3
                    entry = int(p[3], 16)
                    k = 4
                    ctxs[cid] = (parent, entry, int(p[4]))
                elif p[0] == 'B' and len(p) >= 6:
                    k = 1
                    ctx = int(p[1])
                    if ctx not in ctxs:
                        raise ValueError
                    k = 3
                    runs = int(p[3])
                    k = 4
                    if int(p[4]) != len(p) - 5:
                        raise ValueError
                    pcs = []
                    for k in range(5, len(p)):
                        pcs.append(int(p[k], 16))
                    k = 2
                    if int(p[2], 16) != pcs[0]:
                        raise ValueError
                    for pc in pcs:
                        counts[(ctx, pc)] += runs
                else:
                    raise ValueError
            except (IndexError, ValueError):
                col = cols[k] if k < len(cols) else len(line.rstrip('\n')) + 1
                fail(path, no, col,
                     'expected "C id parent entry calls" or '
                     '"B ctx pc runs n pc..." (tools/profile/callstack.c)')
    return ctxs, counts


def analyse(ctxs, counts, name_of, depth_fn):
    """Per function (inclusive, self, calls); per depth the instructions
    and the callees' counts. name_of(addr): the function holding addr,
    or None."""
    incl, self_, calls = (collections.Counter() for _ in range(3))
    chain, depth, above = {}, {}, {}
    for cid in sorted(ctxs):  # parents come first
        parent, entry, n = ctxs[cid]
        if parent is None:
            chain[cid], depth[cid], above[cid] = frozenset(), 0, frozenset()
            continue
        fn = name_of(entry) or '0x%x' % entry
        calls[fn] += n
        chain[cid] = chain[parent] | {fn}
        if fn == depth_fn:
            depth[cid], above[cid] = depth[parent] + 1, frozenset()
        else:
            depth[cid], above[cid] = depth[parent], above[parent] | {fn}
    # (ctx, function of the pc) first: far fewer keys than (ctx, pc)
    per = collections.Counter()
    for (ctx, pc), n in counts.items():
        per[(ctx, name_of(pc) or '(no symbol)')] += n
    by_depth = collections.Counter()
    callees = collections.defaultdict(collections.Counter)
    for (ctx, fn), n in per.items():
        self_[fn] += n
        for f in chain[ctx] | {fn}:
            incl[f] += n
        d = depth[ctx]
        by_depth[d] += n
        for f in above[ctx] | ({fn} if fn != depth_fn else set()):
            callees[d][f] += n
    return incl, self_, calls, by_depth, callees


def tables(incl, self_, calls, by_depth, callees, pixels, total, top,
           depth_fn):
    print('| function | inclusive/pixel | share | self/pixel | '
          'calls/pixel |')
    print('|---|---:|---:|---:|---:|')
    rows = sorted(incl.items(), key=lambda kv: (-kv[1], kv[0]))
    for fn, n in rows[:top]:
        print('| %s | %.1f | %.1f%% | %.1f | %.2f |' %
              (fn, n / pixels, 100.0 * n / total, self_[fn] / pixels,
               calls[fn] / pixels))
    rest = rows[top:]
    if rest:
        print('| (%d others) | | | %.1f | |' %
              (len(rest), sum(self_[fn] for fn, _ in rest) / pixels))
    print()
    print('By ray depth (frames of %s on the stack):' % depth_fn)
    print()
    print('| depth | instr/pixel | share |')
    print('|---:|---:|---:|')
    for d in sorted(by_depth):
        n = by_depth[d]
        print('| %d | %.1f | %.1f%% |' % (d, n / pixels, 100.0 * n / total))
    print()
    for d in sorted(by_depth):
        print('| depth %d callee | instr/pixel |' % d)
        print('|---|---:|')
        for fn, n in sorted(callees[d].items(),
                            key=lambda kv: (-kv[1], kv[0]))[:8]:
            print('| %s | %.1f |' % (fn, n / pixels))
        print()
