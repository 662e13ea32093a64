#!/usr/bin/env python3
"""Exact-theory kinematic sets of the project's own: CONTACT module 1 with the wheelset position
and velocities prescribed, on a grid of lateral positions x yaw angles x kinematic sets.

Every setting is that of the kinematic sample described in doc/validation.md §6 (the Manchester
set-up of data/exact/README.md: right wheel, gauge 1435 mm at 14 mm, flange-back distance 1360 mm
at -70 mm, R0 = 460 mm, G = 82670 MPa, nu = 0.27, mu = 0.3, 0.2 mm grid, tolerance 1e-5,
patches separated at 8 mm and combined below 4 mm, vertical force FZ = 64700 N prescribed,
VS = 2000 mm/s) but the profiles and the grid:

  --pair new    the project's built-in S1002 and UIC60 1:40 (`shcontact profiles --write`);
  --pair worn   the project's synthetic worn pair, data/profiles/worn/ (scripts/worn_profiles.py).

Kinematic set k = (xi_k, eta_k, omega_k): VY = eta_k VS, VYAW = omega_k VS / 750 mm,
VPITCH = -(VS/R)(1 + xi_k) with R = R0 or --pitch-radius; the six sets of the sample, numbered 1..6:
(0,0,0), (1e-3,0,0), (0,1e-3,0), (0,0,1e-3), (-1e-3,-1e-3,0), (1e-3,1e-3,1e-3).

--approach planar (CONTACT's D = 2, the sample's) or conformal (D = 4).

Writes OUTCSV with one row per case and contact patch, the columns of the kinematic sample
(README there; forces on the rail, CONTACT's signs), and keeps the decks in WORKDIR.

usage: scripts/contact_kinematic_set.py OUTCSV --pair new|worn --positions 6.5,7,...
           --yaw-mrad -8,0,8 [--sets 1,2,3,4,5,6] [--approach planar|conformal] [--workdir DIR]
  CONTACT_EXE: the CONTACT program (scripts/contact_build.sh); SHCONTACT_EXE: shcontact (else
  fpm run), used for the built-in profiles.
"""
import argparse, csv, os, re, shutil, subprocess, sys, tempfile
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_reference as cr  # noqa: E402  (module1_deck, thin_profile, run_contact, parse_out1)

HERE = os.path.dirname(os.path.abspath(__file__))
SETS = [(0.0, 0.0, 0.0), (1e-3, 0.0, 0.0), (0.0, 1e-3, 0.0), (0.0, 0.0, 1e-3),
        (-1e-3, -1e-3, 0.0), (1e-3, 1e-3, 1e-3)]
HALF_BASE = 750.0   # mm: the yaw-rate creepage omega_k = VYAW * 750 / VS (the sample's README)
FZ = 64700.0

COLUMNS = ['case', 'y_ws_mm', 'yaw_rad', 'vs_mm_s', 'vy_mm_s', 'vyaw_rad_s', 'vpitch_rad_s',
           'xi_k', 'eta_k', 'omega_k', 'npatch', 'patch', 'xcp_tr_mm', 'ycp_tr_mm', 'zcp_tr_mm',
           'delta_rad', 'y_r_mm', 'y_w_mm', 'cksi', 'ceta', 'cphi_per_mm', 'veloc_mm_s', 'fn_N',
           'fx_N', 'fs_N', 'mn_Nmm', 'fx_norm', 'fs_norm', 'approach_mm', 'pmax_MPa', 'ncon',
           'nadh', 'nslip', 'fx_tr_total_N', 'fy_tr_total_N', 'fz_tr_total_N', 'wall_s',
           'status']

F = cr.FLOAT
# Planar: FN FX FS MN ... / FN/G FX/FSTAT/FN ...; conformal: BAR_FN BAR_FX BAR_FS MN ... /
# TILDE_FN FX/FSTAT/FN ... (the normal force of the curved surface, which f is taken over).
FORCES = re.compile(r'(?:BAR_)?FN\s+(?:BAR_)?FX\s+(?:BAR_)?FS\s+MN.*\n\s*' + r'\s+'.join(['(' + F + ')'] * 4) +
                    r'.*\n.*APPROACH\s+PMAX\s*\n\s*' + r'\s+'.join(['(' + F + ')'] * 5))
STATS = re.compile(r'NPOT\s+NCON\s+NADH\s+NSLIP.*\n\s*' + r'\s+'.join([r'(\d+)'] * 4))


def profiles(pair, workdir):
    """Put the pair's wheel and rail files (chords >= 0.2 mm, for CONTACT's module 1) in
    workdir; returns (rail file, wheel file)."""
    if pair == 'worn':
        src = os.path.join(HERE, '..', 'data', 'profiles', 'worn')
        names = ('UIC60-canted-worn.txt', 'S1002-worn.txt')
    elif pair == 'new':
        src = os.path.join(workdir, 'builtin')   # this script's own folder: written anew
        shutil.rmtree(src, ignore_errors=True)
        os.makedirs(src)
        subprocess.run(cr.shcontact_command() + ['profiles', '--write', src], check=True,
                       stdout=subprocess.DEVNULL)
        names = ('UIC60-canted.txt', 'S1002.txt')
    else:
        raise SystemExit("--pair must be 'new' or 'worn'")
    for n in names:
        cr.thin_profile(os.path.join(src, n), os.path.join(workdir, n), cr.CONTACT_MIN_CHORD)
    return names


def deck(y, yaw, kset, rail, wheel, approach, pitch_radius):
    xi, eta, omega = SETS[kset - 1]
    vy = eta * cr.VS
    vyaw = omega * cr.VS / HALF_BASE
    vpitch = -(cr.VS / pitch_radius) * (1.0 + xi)
    text = cr.module1_deck(y, FZ, vpitch, rail, wheel, 0.0)
    pos = re.compile(r'^(\s*0\.0\s+\S+\s+\S+\s+\S+\s+)0\.0(\s+0\.0\s+S, Y, FZ, ROLL, YAW, PITCH)',
                     re.M)
    text, n1 = pos.subn(r'\g<1>%.8f\g<2>' % yaw, text)
    vel = re.compile(r'^\s*\S+\s+0\.0\s+0\.0\s+0\.0\s+0\.0\s+(\S+)(\s+VS,VY,VZ, VROLL,VYAW,VPITCH)',
                     re.M)
    text, n2 = vel.subn('  %.1f  %.10f  0.0  0.0  %.12f  %.11f\\g<2>' % (cr.VS, vy, vyaw, vpitch),
                        text)
    if approach == 'conformal':
        text, n3 = re.subn(r'^(\s*\d\d)2(\d{4}\s+V-L-D-C-M-Z-E)', r'\g<1>4\g<2>', text, flags=re.M)
    else:
        n3 = 1
    if (n1, n2, n3) != (1, 1, 1):
        raise SystemExit('deck template changed: %s' % ((n1, n2, n3),))
    return text, (xi, eta, omega, vy, vyaw, vpitch)


def patch_rows(out, base):
    """One row per patch of a module-1 .out file."""
    r1 = cr.parse_out1(out)
    txt = open(out).read()
    blocks = re.split(r'----- DATA FOR CONTACT PATCH\s+\d+\s+-----', txt)[1:]
    rows = []
    for p, b in zip(r1['patches'], blocks):
        mf, ms = FORCES.search(b), STATS.search(b)
        if not (mf and ms):
            return []
        fn, fx, fs, mn, fn2, fxn, fsn, app, pmax = (cr.ffloat(mf.group(k)) for k in range(1, 10))
        if 'TILDE_FN' in b:
            fn = fn2
        row = dict(base, npatch=len(blocks), patch=p['ipatch'], xcp_tr_mm=p.get('xcp_tr'),
                   ycp_tr_mm=p.get('ycp_tr'), zcp_tr_mm=p.get('zcp_tr'),
                   delta_rad=p.get('deltcp_tr'), y_r_mm=p.get('ycp_r'), y_w_mm=p.get('ycp_w'),
                   cksi=p.get('cksi'), ceta=p.get('ceta'), cphi_per_mm=p.get('cphi'),
                   veloc_mm_s=p.get('veloc'), fn_N=fn, fx_N=fx, fs_N=fs, mn_Nmm=mn,
                   fx_norm=fxn, fs_norm=fsn, approach_mm=app, pmax_MPa=pmax,
                   ncon=int(ms.group(2)), nadh=int(ms.group(3)), nslip=int(ms.group(4)),
                   fx_tr_total_N=r1.get('FX_tr'), fy_tr_total_N=r1.get('FY_tr'),
                   fz_tr_total_N=r1.get('FZ_tr'), status='ok')
        rows.append(row)
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('outcsv')
    ap.add_argument('--pair', required=True)
    ap.add_argument('--positions', required=True, help='Y_WS values, mm, comma-separated')
    ap.add_argument('--yaw-mrad', default='0')
    ap.add_argument('--sets', default='1,2,3,4,5,6')
    ap.add_argument('--approach', default='planar', choices=('planar', 'conformal'))
    ap.add_argument('--workdir', default=None)
    ap.add_argument('--pitch-radius', type=float, default=cr.RNOM,
                    help='mm: the pitch rate is -(VS/R)(1 + xi_k) (default R0 = 460 mm); the '
                         'rolling radius of the centred wheelset makes it roll freely there')
    ap.add_argument('--reuse', action='store_true',
                    help='take a case from WORKDIR/CASE.out where CONTACT already ended there '
                         'with the same deck')
    a = ap.parse_args()
    work = a.workdir or tempfile.mkdtemp(prefix='contact_kinematic_set_')
    os.makedirs(work, exist_ok=True)
    rail, wheel = profiles(a.pair, work)
    rows, k = [], 0
    for y in (float(v) for v in a.positions.split(',')):
        for yaw in (float(v) * 1e-3 for v in a.yaw_mrad.split(',')):
            for kset in (int(v) for v in a.sets.split(',')):
                k += 1
                name = 'c%04d' % k
                text, (xi, eta, omega, vy, vyaw, vpitch) = deck(y, yaw, kset, rail, wheel,
                                                                a.approach, a.pitch_radius)
                inp, log = (os.path.join(work, name + e) for e in ('.inp', '.log'))
                if (a.reuse and os.path.exists(inp) and open(inp).read() == text
                        and os.path.exists(log) and 'ended succesfully' in open(log).read()):
                    ok, wall = True, None
                else:
                    with open(inp, 'w') as f:
                        f.write(text)
                    ok, _, wall, _ = cr.run_contact(work, name)
                base = dict(case=name, y_ws_mm=y, yaw_rad=yaw, vs_mm_s=cr.VS, vy_mm_s=vy,
                            vyaw_rad_s=vyaw, vpitch_rad_s=vpitch, xi_k=xi, eta_k=eta,
                            omega_k=omega, wall_s='' if wall is None else '%.2f' % wall, status='failed', npatch=0,
                            patch=0)
                out = os.path.join(work, name + '.out')
                got = patch_rows(out, base) if ok and os.path.exists(out) else []
                rows += got or [base]
                print(name, y, yaw, kset, 'ok' if got else 'failed',
                      ' '.join('%.4f/%.4f' % (r['fx_norm'], r['fs_norm']) for r in got),
                      flush=True)
    with open(a.outcsv, 'w', newline='') as fh:
        w = csv.DictWriter(fh, fieldnames=COLUMNS)
        w.writeheader()
        for r in rows:
            w.writerow({c: ('' if r.get(c) is None else r.get(c)) for c in COLUMNS})


if __name__ == '__main__':
    main()
