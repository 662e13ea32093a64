#!/usr/bin/env python3
"""Make the exact-ellipse correction table (doc/tangential.md, "Exact-ellipse correction").

  1. `shcontact-ellipse-table decks WORK EXACT` writes the CONTACT decks of every table node that
     data/exact/ellipse_table.csv lacks (Hertz ellipses with prescribed semi-axes, module 3,
     exact solver, 50 x 50 elements) and WORK/cases.csv;
  2. CONTACT runs the two decks in parallel (CONTACT_EXE, default build/contact/contact,
     built by scripts/contact_build.sh from CONTACT's public source at a pinned revision);
  3. its FX/(mu FN), FY/(mu FN) are added to data/exact/ellipse_table.csv
     (i_ratio,k_x,k_y,t_phi,fx,fy; CONTACT's sign);
  4. `shcontact-ellipse-table source` writes src/shcontact/tangential/ellipse_table.f90.

usage: scripts/contact_ellipse_table.py [--work DIR] [--skip-contact]
  --skip-contact  reuse data/exact/ellipse_table.csv and only rewrite the table module (after a
                  change to FASTSIM_SH: the table holds exact minus FASTSIM_SH)
Run from the repository root. The whole grid (33 120 nodes) is about 170 CPU-minutes of CONTACT;
after a change of the grid only the new nodes are run.
"""
import argparse, os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contact_reference import CONTACT, run_contact, parse_out3  # noqa: E402

EXACT = 'data/exact/ellipse_table.csv'
MODULE = 'src/shcontact/tangential/ellipse_table.f90'


def example(*args):
    subprocess.run(['fpm', 'run', '--profile', 'release', '--example', 'shcontact-ellipse-table',
                    '--'] + list(args), check=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--work', default=None)
    ap.add_argument('--skip-contact', action='store_true')
    a = ap.parse_args()
    if not a.skip_contact:
        work = a.work or tempfile.mkdtemp(prefix='ellipse_table_')
        os.makedirs(work, exist_ok=True)
        if not os.path.exists(EXACT):
            with open(EXACT, 'w') as f:
                f.write('i_ratio,k_x,k_y,t_phi,fx,fy\n')
        example('decks', work, EXACT)
        keys = [line.split(',')[:4] for line in open(os.path.join(work, 'cases.csv'))][1:]
        if keys:
            procs = [subprocess.Popen([sys.executable, '-c',
                                       'import sys; sys.path.insert(0, %r); '
                                       'from contact_reference import run_contact; '
                                       'run_contact(%r, %r)' % (os.path.dirname(
                                           os.path.abspath(__file__)), work, 'part%d' % k)])
                     for k in (1, 2)]
            for p in procs:
                p.wait()
            parts = [parse_out3(os.path.join(work, 'part%d.out' % k)) for k in (1, 2)]
            with open(EXACT, 'a') as f:
                for i, key in enumerate(keys):
                    r = parts[i % 2][i // 2 + 1]
                    f.write('%s,%s,%s\n' % (','.join(key), r['fx'], r['fy']))
        print('added', len(keys), 'nodes to', EXACT, 'from', CONTACT)
    example('source', EXACT, MODULE)
    print('wrote', MODULE)


if __name__ == '__main__':
    main()
