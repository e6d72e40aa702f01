#!/usr/bin/python3
"""Field sweep: a structured complement of the fuzzer. Every field of every
data line of the seed decks (fuzz/corpus/*.rad, or the decks given) is set
in turn to each of a list of hostile values (nan, +-1e308, denormals, 0,
negative, blank, small integers), one change per deck, and the variants are
replayed through the fuzz target (build/fuzz_replay: no crash, clean status,
a place in every input error). Failing variants are copied to OUT.
   fuzz/sweep.py [--every N] [--replay BIN] [--out DIR] [DECK...]
--every N keeps one variant in N (default 1: all, about 200000 for the
seeds, a few minutes)."""
import argparse
import glob
import os
import shutil
import subprocess
import sys
import tempfile

VALUES = ['nan', '1e308', '-1e308', '-1', '0', '1e-320', '', '3', '2', '1e-9', '1e9', '5', '4',
          '1', '-1e-9', '1e-300']
NO_TITLE = ('/NODE', '/RUN', '/SOLVER')


def variants(lines):
    """(index, new line) for each field of each data line and each value; the
    fields are taken on both grids of the fixed format (10 and 20 columns)."""
    for i, ln in enumerate(lines):
        if not ln or ln[0] in '#$/':
            continue
        if i > 0 and lines[i - 1].startswith('/') and not lines[i - 1].upper().startswith(NO_TITLE):
            continue  # a title line
        spans = sorted({(c, c + w) for w in (10, 20) for c in range(0, max(len(ln), 10), w)})
        for a, b in spans:
            for v in VALUES:
                if len(v) > b - a:
                    continue
                pad = ln.ljust(b)
                new = (pad[:a] + v.rjust(b - a) + pad[b:]).rstrip()
                if new != ln:
                    yield i, new


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--every', type=int, default=1)
    ap.add_argument('--replay', default='build/fuzz_replay')
    ap.add_argument('--out', default='build/sweep-failures')
    ap.add_argument('decks', nargs='*')
    args = ap.parse_args()
    decks = args.decks or sorted(glob.glob('fuzz/corpus/*.rad'))
    tmp = tempfile.mkdtemp(prefix='ricochet-sweep-')
    n = kept = 0
    try:
        for path in decks:
            with open(path) as f:
                lines = f.read().split('\n')
            for i, new in variants(lines):
                n += 1
                if n % args.every:
                    continue
                d = list(lines)
                d[i] = new
                with open(os.path.join(tmp, '%07d.rad' % n), 'w') as f:
                    f.write('\n'.join(d))
                kept += 1
        files = sorted(glob.glob(os.path.join(tmp, '*.rad')))
        fails = []
        for k in range(0, len(files), 1000):
            r = subprocess.run([args.replay, '-t', '20'] + files[k:k + 1000], capture_output=True, text=True)
            fails += [ln.split()[1][len('fuzz.'):].rstrip(':') for ln in r.stdout.splitlines()
                      if ln.startswith('FAIL ')]
            sys.stderr.write(r.stderr)
        if fails:
            os.makedirs(args.out, exist_ok=True)
            for name in fails:
                shutil.copy(os.path.join(tmp, name), args.out)
        print('sweep: %d variants of %d decks replayed, %d failed%s' %
              (kept, len(decks), len(fails), ' (copied to %s)' % args.out if fails else ''))
        return 1 if fails else 0
    finally:
        shutil.rmtree(tmp)


sys.exit(main())
