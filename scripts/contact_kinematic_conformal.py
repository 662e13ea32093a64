#!/usr/bin/env python3
"""CONTACT's conformal approach on the shared kinematic sample (doc/validation.md §6.3, §6.6).

The shared kinematic sample (reference/kinematic_sample/ of the external data) was solved with
CONTACT's planar contact approach (D = 2): one contact plane per patch, a uniform rigid slip
(xi - phi*y, eta + phi*x) over it. This script solves the same decks with CONTACT's conformal
approach (D = 4: a curved contact reference surface, whose rigid slip carries each point's own
rolling radius and contact angle) and changes nothing else in the deck. It writes one row per
case: the patch's forces on the rail over mu*Fn, its normal force, its reference point and
creepages, and the track totals.

usage: scripts/contact_kinematic_conformal.py OUTCSV [--workdir DIR] [--cases c0001,...] [--reuse]
  SHCONTACT_EXTERNAL_DATA: the external data (decks in reference/kinematic_sample/inp/,
  profiles in profiles/); CONTACT_EXE: the CONTACT program (scripts/contact_build.sh).
"""
import argparse, csv, os, re, shutil, sys, tempfile
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_reference as cr  # noqa: E402  (run_contact, parse_out1, ffloat, FLOAT)

# CONTACT's control digits V-L-D-C-M-Z-E: the third is D (DISCNS), 2 planar, 4 conformal.
DIGITS = re.compile(r'^(\s*\d\d)2(\d{4}\s+V-L-D-C-M-Z-E)', re.M)
FORCES = re.compile(r'TILDE_FN\s+FX/FSTAT/FN\s+FS/FSTAT/FN.*\n\s*(' + cr.FLOAT + r')\s+(' +
                    cr.FLOAT + r')\s+(' + cr.FLOAT + ')')


def conformal_deck(src, dst):
    text = open(src).read()
    new, n = DIGITS.subn(r'\g<1>4\g<2>', text)
    if n != 1:
        raise SystemExit(f'{src}: expected one V-L-D-C-M-Z-E line with D = 2, found {n}')
    open(dst, 'w').write(new)


def patch_forces(out):
    """Per patch: (FN, fx, fs) from the .out file, in the order of the patches."""
    txt = open(out).read()
    blocks = re.split(r'----- DATA FOR CONTACT PATCH\s+\d+\s+-----', txt)[1:]
    res = []
    for b in blocks:
        m = FORCES.search(b)
        res.append(tuple(cr.ffloat(m.group(k)) for k in (1, 2, 3)) if m else None)
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('outcsv')
    ap.add_argument('--workdir', default=None)
    ap.add_argument('--cases', default=None)
    ap.add_argument('--reuse', action='store_true',
                    help='take a case from WORKDIR/CASE.out where CONTACT already ended there')
    args = ap.parse_args()
    ext = os.environ.get('SHCONTACT_EXTERNAL_DATA')
    if not ext:
        raise SystemExit('SHCONTACT_EXTERNAL_DATA is not set')
    inp = os.path.join(ext, 'reference', 'kinematic_sample', 'inp')
    names = sorted(f[:-4] for f in os.listdir(inp) if f.endswith('.inp'))
    if args.cases:
        names = [c for c in names if c in args.cases.split(',')]
    work = args.workdir or tempfile.mkdtemp(prefix='contact_conformal_')
    os.makedirs(work, exist_ok=True)
    for f in ('MBench_S1002_v3.prw', 'MBench_UIC60_v3.prr'):
        shutil.copy(os.path.join(ext, 'profiles', f), work)
    rows = []
    for c in names:
        conformal_deck(os.path.join(inp, c + '.inp'), os.path.join(work, c + '.inp'))
        out, log = (os.path.join(work, c + e) for e in ('.out', '.log'))
        if args.reuse and os.path.exists(log) and 'ended succesfully' in open(log).read():
            ok, wall = True, None
        else:
            ok, _, wall, _ = cr.run_contact(work, c)
        row = {'case': c, 'status': 'failed', 'wall_s': '' if wall is None else f'{wall:.2f}'}
        if ok and os.path.exists(out):
            r1 = cr.parse_out1(out)
            forces = patch_forces(out)
            if r1['patches'] and forces and all(f is not None for f in forces):
                k = max(range(len(forces)), key=lambda i: forces[i][0])
                p = r1['patches'][k]
                row.update(status='ok', npatch=len(forces), patch=k + 1, fn_N=forces[k][0],
                           fx_norm=forces[k][1], fs_norm=forces[k][2],
                           fn_all_N=sum(f[0] for f in forces), ycp_tr_mm=p.get('ycp_tr'),
                           delta_rad=p.get('deltcp_tr'), cksi=p.get('cksi'),
                           ceta=p.get('ceta'), cphi_per_mm=p.get('cphi'),
                           fx_tr_total_N=r1.get('FX_tr'), fy_tr_total_N=r1.get('FY_tr'),
                           fz_tr_total_N=r1.get('FZ_tr'))
        rows.append(row)
        print(c, row['status'], row.get('fx_norm'), row.get('fs_norm'), flush=True)
    cols = ['case', 'status', 'npatch', 'patch', 'fn_N', 'fx_norm', 'fs_norm', 'fn_all_N',
            'ycp_tr_mm', 'delta_rad', 'cksi', 'ceta', 'cphi_per_mm', 'fx_tr_total_N',
            'fy_tr_total_N', 'fz_tr_total_N', 'wall_s']
    with open(args.outcsv, 'w', newline='') as fh:
        w = csv.DictWriter(fh, fieldnames=cols, extrasaction='ignore')
        w.writeheader()
        for r in rows:
            w.writerow({k: ('' if r.get(k) is None else r.get(k)) for k in cols})


if __name__ == '__main__':
    main()
