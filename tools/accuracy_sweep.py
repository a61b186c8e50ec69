#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""accuracy_sweep: decision flips and PSNR over many image sizes.

Every scene in scenes/ is rendered at many sizes and at 1, 4 and 16
samples a pixel by the fixed-point core (fixtrace), by the float32 build
of the reference (fixtrace --reference-float) and by the double reference
(fixtrace --reference); the first two are compared with the third
(fixtrace compare). A flip is a pixel off by more than 64/255 in some
channel (compare's outliers): a decision that went the other way.

  accuracy_sweep.py measure [-j N]   the sweep: writes docs/accuracy-sweep.tsv
                                     and tests/accuracy_ceilings.txt
  accuracy_sweep.py report           the section of docs/accuracy.md made
                                     from docs/accuracy-sweep.tsv (stdout)
  accuracy_sweep.py check [-j N]     the short set (make test): fails when a
                                     scene's fixed render has more flips
                                     than tests/accuracy_ceilings.txt allows
  accuracy_sweep.py classify [-j N]  the short set's flips by the depth
                                     where each first appears

FIXTRACE names the binary (default build/posix/fixtrace). Plain python3:
no numpy.
"""
import math
import os
import resource
import subprocess
import sys
import tempfile
import textwrap
import time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), '..'))
TSV = os.path.join(ROOT, 'docs', 'accuracy-sweep.tsv')
DEPTHS = os.path.join(ROOT, 'docs', 'accuracy-sweep-depths.tsv')
CEILINGS = os.path.join(ROOT, 'tests', 'accuracy_ceilings.txt')
SEED = 39
N_SIZES = 20
FIXED_SIZES = [(320, 240), (640, 480)]  # the floors' size and make run's
SPP_SIZES = {1: N_SIZES, 4: 8, 16: 3}   # generated sizes used at each spp
SHORT = [1, 2, 3]                       # generated sizes the short set uses
PSNR_SLACK = 1.0                        # dB the short set may lose


def xorshift32(state):
    """One step of Marsaglia's xorshift32: the next state, never 0."""
    state ^= (state << 13) & 0xFFFFFFFF
    state ^= state >> 17
    state ^= (state << 5) & 0xFFFFFFFF
    return state


def generated_sizes(n=N_SIZES, seed=SEED):
    """n sizes: widths log-uniform in 97..801, aspect ratios (width over
    height) log-uniform in 1:2..2:1, from xorshift32 seeded with seed, so
    odd sizes and unusual shapes come up and the list never changes."""
    s = seed
    out = []
    while len(out) < n:
        s = xorshift32(s)
        u = s / 2.0**32
        s = xorshift32(s)
        v = s / 2.0**32
        w = int(round(math.exp(math.log(97) + u * math.log(801 / 97))))
        a = math.exp(math.log(0.5) + v * math.log(4.0))
        h = max(16, int(round(w / a)))
        if (w, h) not in out and (w, h) not in FIXED_SIZES:
            out.append((w, h))
    return out


def scenes():
    d = os.path.join(ROOT, 'scenes')
    return sorted(f[:-6] for f in os.listdir(d) if f.endswith('.scene'))


def jobs(short):
    """(scene, width, height, spp) to measure, the costliest first."""
    gen = generated_sizes()
    out = []
    for sc in scenes():
        if short:
            for i in SHORT:
                out.append((sc, gen[i][0], gen[i][1], 1))
            continue
        for spp, n in SPP_SIZES.items():
            sizes = FIXED_SIZES[:1 if spp > 1 else 2] + gen[:n]
            for w, h in sizes:
                out.append((sc, w, h, spp))
    out.sort(key=lambda j: -j[1] * j[2] * j[3])
    return out


def fixtrace():
    return os.environ.get('FIXTRACE',
                          os.path.join(ROOT, 'build', 'posix', 'fixtrace'))


def compare(ft, a, b):
    """(PSNR in dB, flips) of image a against b."""
    out = subprocess.run([ft, 'compare', a, b], check=True,
                         capture_output=True, text=True).stdout
    psnr = flips = None
    for line in out.splitlines():
        f = line.split()
        if line.startswith('PSNR:'):
            psnr = math.inf if f[1] == 'inf' else float(f[1])
        elif line.startswith('outliers'):
            flips = int(f[3])
    if psnr is None or flips is None:
        raise RuntimeError('fixtrace compare said: ' + out)
    return psnr, flips


def measure_one(job, tmp):
    sc, w, h, spp = job
    ft = fixtrace()
    scene = os.path.join(ROOT, 'scenes', sc + '.scene')
    base = os.path.join(tmp, '%s-%dx%d-%d' % job)
    paths = {}
    for mode, flag in (('fixed', []), ('f32', ['--reference-float']),
                       ('dbl', ['--reference'])):
        paths[mode] = '%s-%s.ppm' % (base, mode)
        subprocess.run([ft, '-q'] + flag + ['-W', str(w), '-H', str(h),
                        '-s', str(spp), '-o', paths[mode], scene],
                       check=True)
    pf, ff = compare(ft, paths['fixed'], paths['dbl'])
    p3, f3 = compare(ft, paths['f32'], paths['dbl'])
    for p in paths.values():
        os.remove(p)
    return (sc, w, h, spp, pf, ff, p3, f3)


def run(short, n_jobs):
    todo = jobs(short)
    with tempfile.TemporaryDirectory() as tmp:
        with ThreadPoolExecutor(max_workers=n_jobs) as ex:
            rows = list(ex.map(lambda j: measure_one(j, tmp), todo))
    rows.sort(key=lambda r: (r[0], r[3], r[1] * r[2], r[1]))
    return rows


def fmt_psnr(p):
    return 'inf' if p == math.inf else '%.2f' % p


def short_summary(rows):
    """Per scene: fixed flips, worst fixed PSNR, float32 flips, over the
    rows of the short set."""
    gen = generated_sizes()
    keep = {(gen[i][0], gen[i][1]) for i in SHORT}
    out = {}
    for sc, w, h, spp, pf, ff, p3, f3 in rows:
        if spp != 1 or (w, h) not in keep:
            continue
        a = out.setdefault(sc, [0, math.inf, 0])
        a[0] += ff
        a[1] = min(a[1], pf)
        a[2] += f3
    return out


def write_ceilings(rows):
    gen = generated_sizes()
    sizes = ', '.join('%dx%d' % gen[i] for i in SHORT)
    with open(CEILINGS, 'w') as f:
        f.write('# Written by `make accuracy-sweep` (tools/accuracy_sweep.py)'
                ': per scene, over\n# the short set (%s, 1 spp), the fixed-'
                'point render\'s flips\n# against the double reference '
                '(pixels off by more than 64/255), its\n# worst PSNR (dB) '
                'and, for comparison, the float32 reference\'s flips.\n'
                '# tests/suite_sweep.sh fails when a scene has more flips '
                'than here or\n# its worst PSNR falls more than %.1f dB '
                'below.\n# scene flips_fixed worst_psnr_fixed flips_float32'
                '\n' % (sizes, PSNR_SLACK))
        for sc, (ff, pf, f3) in sorted(short_summary(rows).items()):
            f.write('%s %d %s %d\n' % (sc, ff, fmt_psnr(pf), f3))


def measure(n_jobs):
    t0 = time.time()
    c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    rows = run(False, n_jobs)
    secs = time.time() - t0
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = c1.ru_utime + c1.ru_stime - c0.ru_utime - c0.ru_stime
    with open(TSV, 'w') as f:
        f.write('# seconds %d jobs %d cpu %d (tools/accuracy_sweep.py '
                'measure; columns: scene width height spp psnr_fixed '
                'flips_fixed psnr_float32 flips_float32)\n' %
                (round(secs), n_jobs, round(cpu)))
        for r in rows:
            f.write('%s\t%d\t%d\t%d\t%s\t%d\t%s\t%d\n' %
                    (r[0], r[1], r[2], r[3], fmt_psnr(r[4]), r[5],
                     fmt_psnr(r[6]), r[7]))
    write_ceilings(rows)
    print('wrote %s and %s (%d renders of 3 each, %.0f s)' %
          (os.path.relpath(TSV, ROOT), os.path.relpath(CEILINGS, ROOT),
           len(rows), secs))


def read_tsv():
    rows = []
    with open(TSV) as f:
        head = f.readline().split()
        for line in f:
            c = line.rstrip('\n').split('\t')
            rows.append((c[0], int(c[1]), int(c[2]), int(c[3]),
                         float(c[4]), int(c[5]), float(c[6]), int(c[7])))
    return head, rows


def median(xs):
    xs = sorted(xs)
    n = len(xs)
    return xs[n // 2] if n % 2 else (xs[n // 2 - 1] + xs[n // 2]) / 2


def show_db(p):
    return '∞' if p == math.inf else '%.2f' % p


def report():
    head, rows = read_tsv()
    secs, n_jobs = int(head[2]), int(head[4])
    cpu = ' (%s s of CPU)' % head[6] if head[5] == 'cpu' else ''
    gen = generated_sizes()
    by = {}
    for r in rows:
        by.setdefault((r[0], r[3]), []).append(r)
    out = []
    w = out.append
    def para(text):
        w(textwrap.fill(text, 72, break_on_hyphens=False) + '\n')
    w('## Over many sizes: flips against float32\n')
    para('Every figure above is taken at one size, and a flip depends on '
         'where the samples fall. So `make accuracy-sweep` '
         '(tools/accuracy_sweep.py) renders every scene in scenes/ at many '
         'sizes with the fixed-point core and with the float32 build of the '
         'reference (`fixtrace --reference-float`: the same '
         'port/posix/ref_*.c with float for double, port/posix/ref32.h), '
         'and compares both with the double reference. A flip is a pixel '
         'off by more than 64/255 in some channel (`fixtrace compare`\'s '
         'outliers): a decision (silhouette, shadow, texture cell, a ray '
         'through glass or in a mirror) that went the other way.')
    para('The sizes: %s at 1 spp, and %d sizes drawn by xorshift32 from '
         'seed %d (widths log-uniform in 97..801, width:height log-uniform '
         'in 1:2..2:1): %s. At 4 spp 320x240 and the first %d of them, at '
         '16 spp 320x240 and the first %d. The last run took %d s with %d '
         'renders at once%s.' %
         (' and '.join('%dx%d' % s for s in FIXED_SIZES), len(gen), SEED,
          ', '.join('%dx%d' % s for s in gen), SPP_SIZES[4], SPP_SIZES[16],
          secs, n_jobs, cpu))
    para('Flips are per megapixel over all sizes at that spp; PSNR is the '
         'median and the worst over the sizes. "float-class" holds when the '
         'fixed render has no more flips than float32, or at most 2 per '
         'megapixel where float32 has none. With more samples a pixel is '
         'the mean of its samples, so one flipped sample seldom moves it by '
         '64 levels: a flip there takes several samples of one pixel going '
         'the other way, as along an edge that runs with the sample grid.')
    para('A decision flips where a sample meets the scene closer to its '
         'edge than the arithmetic resolves: 1/65536 of a unit for a '
         'Q16.16 position, while float32\'s 24-bit significand resolves a '
         '16th of that or less within 16 units of the origin.')
    w('| scene | spp | sizes | flips/MP fixed | flips/MP float32 | '
      'median PSNR fixed | median PSNR float32 | worst PSNR fixed | '
      'worst PSNR float32 | float-class |')
    w('|---|--:|--:|--:|--:|--:|--:|--:|--:|:-:|')
    met = total = 0
    for sc in sorted({k[0] for k in by}):
        for spp in sorted(s for (c, s) in by if c == sc):
            rs = by[(sc, spp)]
            mp = sum(r[1] * r[2] for r in rs) / 1e6
            ff = sum(r[5] for r in rs) / mp
            f3 = sum(r[7] for r in rs) / mp
            ok = ff <= f3 or (f3 == 0 and ff <= 2)
            met += ok
            total += 1
            w('| %s | %d | %d | %.1f | %.1f | %s | %s | %s | %s | %s |' %
              (sc, spp, len(rs), ff, f3, show_db(median(r[4] for r in rs)),
               show_db(median(r[6] for r in rs)),
               show_db(min(r[4] for r in rs)), show_db(min(r[6] for r in rs)),
               'yes' if ok else 'no'))
    w('')
    para('Float-class in %d of %d rows. The raw figures, one line per '
         'scene, size and spp, are docs/accuracy-sweep.tsv; '
         'tests/accuracy_ceilings.txt records each scene\'s flips over a '
         'short set of the same renders (%s, 1 spp), which '
         'tests/suite_sweep.sh renders again in `make test`: a scene with '
         'more flips fails.' %
         (met, total, ', '.join('%dx%d' % gen[i] for i in SHORT)))
    if os.path.exists(DEPTHS):
        with open(DEPTHS) as f:
            drows = [l.rstrip('\n').split('\t') for l in f
                     if not l.startswith('#')]
        deepest = max(len(r) for r in drows) - 3
        para('Which decision: each flip of the short set, by the depth '
             'where it first appears when the scene is rendered again with '
             '`-d 0`, `-d 1`, ... (0: on the primary ray: a silhouette, a '
             'shadow edge or a texture cell where the ray from the eye '
             'lands; k: k reflections or refractions down), and how many '
             'of them are texture cells: gone when the scene is rendered '
             'again with each texture\'s two colours made one. '
             '`tools/accuracy_sweep.py classify` writes '
             'docs/accuracy-sweep-depths.tsv.')
        w('| scene | flips | ' + ' | '.join(
            'depth %d' % d for d in range(deepest + 1)) +
          ' | texture cells |')
        w('|---|--:|' + '--:|' * (deepest + 2))
        for r in drows:
            n = [int(x) for x in r[1:]]
            w('| %s | %d | ' % (r[0], sum(n[:-1])) + ' | '.join(
                str(n[d]) if d < len(n) - 1 else '–'
                for d in range(deepest + 1)) + ' | %d |' % n[-1])
        w('')
    w('    make accuracy-sweep                # the sweep, this section, '
      'the ceilings')
    w('    build/posix/fixtrace --reference-float -W 333 -H 250 -o f32.ppm '
      'scenes/glass.scene')
    w('    build/posix/fixtrace --reference -W 333 -H 250 -o ref.ppm '
      'scenes/glass.scene')
    w('    build/posix/fixtrace compare f32.ppm ref.ppm   # "outliers" are '
      'the flips')
    sys.stdout.write('\n'.join(out) + '\n')


def check(n_jobs):
    ceil = {}
    with open(CEILINGS) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            sc, ff, pf, f3 = line.split()
            ceil[sc] = (int(ff), float(pf), int(f3))
    rows = run(True, n_jobs)
    passed = failed = 0
    for sc, (ff, pf, f3) in sorted(short_summary(rows).items()):
        print('%s: fixed %d flips, worst %s dB; float32 %d flips' %
              (sc, ff, fmt_psnr(pf), f3))
        if sc not in ceil:
            print('FAILED: %s has no line in tests/accuracy_ceilings.txt '
                  '(run make accuracy-sweep)' % sc)
            failed += 1
            continue
        cf, cp, _ = ceil[sc]
        if ff > cf:
            print('FAILED: %s: %d flips, more than the ceiling %d' %
                  (sc, ff, cf))
            failed += 1
        else:
            passed += 1
        if pf < cp - PSNR_SLACK:
            print('FAILED: %s: worst PSNR %s dB, below %s - %.1f' %
                  (sc, fmt_psnr(pf), fmt_psnr(cp), PSNR_SLACK))
            failed += 1
        else:
            passed += 1
    # The float32 build is float: not the double's bytes, yet float-class
    # on the seed at the floors' size (79.48 dB, as the firmware's
    # soft-float build of the same files).
    with tempfile.TemporaryDirectory() as tmp:
        ft = fixtrace()
        seed = os.path.join(ROOT, 'scenes', 'seed.scene')
        f32, dbl = os.path.join(tmp, 'f32.ppm'), os.path.join(tmp, 'd.ppm')
        for path, flag in ((f32, '--reference-float'), (dbl, '--reference')):
            subprocess.run([ft, '-q', flag, '-W', '320', '-H', '240', '-o',
                            path, seed], check=True)
        p3, f3 = compare(ft, f32, dbl)
    print('seed, float32 at 320x240: %s dB, %d flips' % (fmt_psnr(p3), f3))
    if p3 != math.inf and p3 >= 75 and f3 == 0:
        passed += 1
    else:
        print('FAILED: the float32 reference of the seed should differ from '
              'the double, by no flip and at 75 dB or more')
        failed += 1
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


def read_ppm(path):
    """(width, height, bytes) of a binary PPM as fixtrace writes it."""
    with open(path, 'rb') as f:
        data = f.read()
    magic, w, h, _, rest = data.split(maxsplit=4)
    assert magic == b'P6'
    return int(w), int(h), rest


def flip_set(a, b):
    """Pixels where two same-sized RGB images differ by more than 64."""
    out = set()
    for i in range(0, len(a), 3):
        if (abs(a[i] - b[i]) > 64 or abs(a[i + 1] - b[i + 1]) > 64 or
                abs(a[i + 2] - b[i + 2]) > 64):
            out.add(i // 3)
    return out


def one_colour(text, scene_dir):
    """The scene with each texture's two colours made one (the material's
    colour becomes the texture's second), so that no texture-cell decision
    shows; mesh paths made absolute, as the copy lives elsewhere."""
    out = []
    for line in text.replace('\\\n', ' ').split('\n'):
        body = line.split('#', 1)[0]
        tok = body.split()
        if tok[:1] == ['material']:
            rgb = None
            for i, t in enumerate(tok):
                if t in ('checker', 'checker3d'):
                    rgb = tok[i + 1:i + 4]
                elif t == 'stripes':
                    rgb = tok[i + 2:i + 5]
            if rgb:
                if 'color' in tok:
                    i = tok.index('color')
                    tok[i + 1:i + 4] = rgb
                else:
                    tok += ['color'] + rgb
                line = ' '.join(tok)
        elif tok[:1] == ['mesh'] and 'file' in line:
            q = line.index('"')
            if line[q + 1] != '/':
                line = line[:q + 1] + scene_dir + '/' + line[q + 1:]
        out.append(line)
    return '\n'.join(out)


def classify(n_jobs):
    """Each flip of the short set by the depth where it first appears:
    the scene rendered again with -d 0, 1, ... (0: the primary ray's own
    decision; k: one taken k bounces or refractions down)."""
    gen = generated_sizes()
    ft = fixtrace()
    todo = []
    for sc in scenes():
        with open(os.path.join(ROOT, 'scenes', sc + '.scene')) as f:
            depth = 5
            for line in f:
                fl = line.split()
                if fl[:1] == ['image'] and 'depth' in fl:
                    depth = int(fl[fl.index('depth') + 1])
        for i in SHORT:
            todo.append((sc, gen[i][0], gen[i][1], depth))

    def flips(scene, w, h, d, tmp, tag):
        img = []
        for flag in ([], ['--reference']):
            path = os.path.join(tmp, '%s-%dx%d-%d-%d.ppm' %
                                (tag, w, h, d, len(flag)))
            subprocess.run([ft, '-q'] + flag + ['-W', str(w), '-H', str(h),
                            '-s', '1', '-d', str(d), '-o', path, scene],
                           check=True)
            img.append(read_ppm(path)[2])
            os.remove(path)
        return flip_set(img[0], img[1])

    def one(job, tmp):
        sc, w, h, depth = job
        scene = os.path.join(ROOT, 'scenes', sc + '.scene')
        sets = [flips(scene, w, h, d, tmp, sc) for d in range(depth + 1)]
        first = [0] * (depth + 1)
        for px in sets[-1]:
            first[min(d for d in range(depth + 1) if px in sets[d])] += 1
        plain = os.path.join(tmp, '%s-%dx%d-plain.scene' % (sc, w, h))
        with open(scene) as f, open(plain, 'w') as g:
            g.write(one_colour(f.read(), os.path.dirname(scene)))
        kept = flips(plain, w, h, depth, tmp, sc + '-plain')
        return sc, first + [len(sets[-1] - kept)]

    with tempfile.TemporaryDirectory() as tmp:
        with ThreadPoolExecutor(max_workers=n_jobs) as ex:
            res = list(ex.map(lambda j: one(j, tmp), todo))
    by = {}
    for sc, first in res:
        acc = by.setdefault(sc, [0] * len(first))
        for d, n in enumerate(first):
            acc[d] += n
    with open(DEPTHS, 'w') as f:
        f.write('# tools/accuracy_sweep.py classify: per scene, the short '
                'set\'s flips (1 spp) by the depth -d where each first '
                'appears, 0 up; last, how many of them go when each '
                'texture\'s two colours are made one\n')
        for sc in sorted(by):
            f.write('\t'.join([sc] + [str(n) for n in by[sc]]) + '\n')
    for sc in sorted(by):
        print('%-10s %s texture:%d' % (sc, ' '.join(
            'd%d:%d' % (d, n) for d, n in enumerate(by[sc][:-1])),
            by[sc][-1]))
    print('wrote %s' % os.path.relpath(DEPTHS, ROOT))
    return 0


def main(argv):
    n_jobs = 1
    args = argv[1:]
    if '-j' in args:
        i = args.index('-j')
        n_jobs = max(1, int(args[i + 1]))
        del args[i:i + 2]
    if args == ['measure']:
        measure(n_jobs)
        return 0
    if args == ['report']:
        report()
        return 0
    if args == ['check']:
        return check(n_jobs)
    if args == ['classify']:
        return classify(n_jobs)
    if args == ['sizes']:
        print(' '.join('%dx%d' % s for s in generated_sizes()))
        return 0
    sys.stderr.write(__doc__)
    return 2


if __name__ == '__main__':
    sys.exit(main(sys.argv))
