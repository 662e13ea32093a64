#!/usr/bin/env python3
"""The flange's normal problem alone, ours against CONTACT's (doc/validation.md §6.8, "Yaw and
the flange root"): S1002 / UIC60 1:40 at Y_WS = 7.0 mm (the straight 70° flange face against
the gauge corner), frictionless, the vertical force F_z prescribed, yaw 0 and ±8 mrad.

For each F_z and yaw it prints, for CONTACT's module 1 (the decks of
scripts/contact_kinematic_set.py, set 1, with T = 0: no tangential problem) and for shcontact
(`shcontact run`, kinematic mode, load mode 'vertical', friction 0.001):
  F_n (kN), the effective contact angle acos(F_z/F_n) (deg), the area (mm²), and the distance
  (mm, along the contact plane) from the minimum of the undeformed distance to the flange root,
  i.e. to where the gap leaves the flange face's parabola by 0.003 mm: CONTACT's from its h of
  the loaded state (the .mat file), ours from the geometry table of the first contact.
CONTACT's approach times tan(delta) is the slide of the vertical approach along the flange face.

With --write-rows FILE it also writes CONTACT's rows (F_z, yaw, approach, delta_cp, s, min over x of
h) to FILE (data/exact/kinematic_flange/h_rows_7mm.csv, read by the test
vertical_approach/flange_root_slide).

With --scan-fn F1,F2,... it prints instead, for ours alone, where the loaded strips end on the
root side (s, mm from the first contact) with the normal force prescribed at each F_n (N).

usage: scripts/contact_flange_slide.py [--approach conformal|planar] [--fz 30000,64700,...]
           [--yaw-mrad 0,8,-8] [--workdir DIR] [--write-rows FILE] [--scan-fn F1,F2,...]
  CONTACT_EXE: CONTACT (scripts/contact_build.sh); SHCONTACT_EXE: the shcontact program (release
  build); needs numpy and h5py. Not part of the build or the tests.
"""
import argparse, os, re, subprocess, sys, tempfile
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_reference as cr  # noqa: E402
import contact_kinematic_set as ks  # noqa: E402

Y_WS = 7.0


def read_mat(path):
    """The grid of a module-1 .mat file: s (rows, mm), h and pn (rows x columns; h NaN where
    CONTACT lists no element), dx, dy, delta (contact angle, rad)."""
    m = cr.read_mat(path)
    g = m['grid']
    shape = (m['my'], m['mx'])
    h = np.where(g['listed'], g['h'], np.nan).reshape(shape)
    return dict(s=m['yl'] + (np.arange(m['my']) + 0.5) * m['dy'], h=h,
                pn=g['pn'].reshape(shape), dx=m['dx'], dy=m['dy'], delta=m['delt_r'])


def root_distance(s, gap, tip_side_limit):
    """Distance from the minimum of gap(s) to where it leaves the parabola fitted on the flange
    face (s below tip_side_limit) by 0.003 mm on the root side (s increasing)."""
    face = (s < tip_side_limit) & (gap < 0.15)
    c = np.polyfit(s[face], gap[face], 2)
    s0 = -c[1] / (2.0 * c[0])
    dev = np.polyval(c, s) - gap
    i = np.where((s > s0) & (dev > 0.003))[0]
    if len(i) == 0 or i[0] == 0:
        return np.nan
    i = i[0]
    sk = s[i - 1] + (0.003 - dev[i - 1]) / (dev[i] - dev[i - 1]) * (s[i] - s[i - 1])
    return sk - s0


def contact_case(work, rail, wheel, fz, yaw, approach):
    text, _ = ks.deck(Y_WS, yaw, 1, rail, wheel, approach, cr.RNOM)
    text, n1 = re.subn(r'^(\s*\d\d\d)3(\d\d\d\s+C-P-B)', r'\g<1>0\g<2>', text, flags=re.M)
    text, n2 = re.subn(r'^(\s*0\.0\s+\S+\s+)64700\.0000', r'\g<1>%.4f' % fz, text, flags=re.M)
    if (n1, n2) != (1, 1):
        raise SystemExit('deck template changed')
    name = 'fz%d_yaw%+d' % (round(fz), round(yaw * 1e3))
    with open(os.path.join(work, name + '.inp'), 'w') as f:
        f.write(text)
    ok, _, _, _ = cr.run_contact(work, name)
    out = open(os.path.join(work, name + '.out')).read()
    app = float(re.search(r'APPROACH\s+PMAX\s*\n\s*\S+\s+\S+\s+\S+\s+(\S+)', out).group(1))
    g = read_mat(os.path.join(work, name + '.0001a.mat'))
    hmin = np.nanmin(g['h'], axis=1)
    fn = g['pn'].sum() * g['dx'] * g['dy']
    rows = [(fz, yaw, app, g['delta'], s, h) for s, h in zip(g['s'], hmin) if np.isfinite(h)]
    return dict(fn=fn, area=(g['pn'] > 0).sum() * g['dx'] * g['dy'], approach=app, rows=rows,
                slide=app * abs(np.tan(g['delta'])),
                dist=root_distance(g['s'], hmin, g['s'][np.argmin(hmin)] + 0.1))


def ours_case(work, fz, yaw, load='vertical'):
    """Our solution; load 'vertical' (fz: F_z) or 'force' (fz: F_n)."""
    import h5py
    name = os.path.join(work, 'ours_%s%d_yaw%+d' % (load, round(fz), round(yaw * 1e3)))
    with open(name + '.nml', 'w') as f:
        f.write("&profiles wheel = 'builtin:S1002', rail = 'builtin:UIC60-canted' /\n"
                "&track rail_canted = .true. /\n&position t_y = %.4f, roll = 0.0 /\n"
                "&kinematics mode = 'on', yaw = %.6f, v_forward = 2000.0 /\n"
                "&material shear_modulus = 82670.0, poisson = 0.27, friction = 0.001 /\n"
                "&load mode = '%s', %s = %.1f /\n"
                "&output fields = 'all' /\n"
                % (Y_WS, yaw, load, {'vertical': 'vertical_force', 'force': 'normal_force'}[load],
                   fz))
    subprocess.run(cr.shcontact_command() + ['run', name + '.nml', '-o', name + '.h5'],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with h5py.File(name + '.h5') as f:
        g = f['geometry/patch_1']
        s, gap = g['y'][:], g['gap'][:]
        fn, area = float(f['summary/fn_total'][0]), float(f['summary/area'][0])
        strips = f['cases/000001/patch_1/normal']
        loaded = strips['y'][:][strips['strip_load'][:] > 0]
    return dict(fn=fn, area=area, dist=root_distance(s, gap, 0.1), s_end=loaded.max())


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--approach', default='conformal', choices=('planar', 'conformal'))
    ap.add_argument('--fz', default='30000,64700,97000,150000')
    ap.add_argument('--yaw-mrad', default='0,8,-8')
    ap.add_argument('--workdir', default=None)
    ap.add_argument('--scan-fn', default=None)
    ap.add_argument('--write-rows', default=None)
    a = ap.parse_args()
    work = a.workdir or tempfile.mkdtemp(prefix='contact_flange_slide_')
    os.makedirs(work, exist_ok=True)
    if a.scan_fn:
        yaws = [float(v) * 1e-3 for v in a.yaw_mrad.split(',')]
        print('ours, F_n prescribed, Y_WS %.1f mm: end of the loaded strips on the root side (mm)'
              % Y_WS)
        print('  F_n kN | ' + ' '.join('yaw %+4.0f' % (y * 1e3) for y in yaws))
        for fn in (float(v) for v in a.scan_fn.split(',')):
            print('  %6.1f | ' % (fn / 1e3) + ' '.join('%8.3f' % ours_case(work, fn, y, 'force')
                                                      ['s_end'] for y in yaws), flush=True)
        return
    rail, wheel = ks.profiles('new', work)
    print('%s approach; Y_WS %.1f mm, frictionless; angle = acos(F_z/F_n); dist = gap minimum '
          'to the flange root (mm)' % (a.approach, Y_WS))
    print('  F_z kN  yaw | CONTACT: F_n kN  angle  area  approach  slide  dist | ours: F_n kN  '
          'angle  area  dist (first contact)')
    rows = []
    for fz in (float(v) for v in a.fz.split(',')):
        for yaw in (float(v) * 1e-3 for v in a.yaw_mrad.split(',')):
            c = contact_case(work, rail, wheel, fz, yaw, a.approach)
            rows += c['rows']
            o = ours_case(work, fz, yaw)
            ang = lambda fn: np.degrees(np.arccos(fz / fn))  # noqa: E731
            print('  %6.1f %+4.0f | %7.1f %6.2f %5.1f %8.4f %6.3f %5.3f | %7.1f %6.2f %5.1f %5.3f'
                  % (fz / 1e3, yaw * 1e3, c['fn'] / 1e3, ang(c['fn']), c['area'], c['approach'],
                     c['slide'], c['dist'], o['fn'] / 1e3, ang(o['fn']), o['area'], o['dist']),
                  flush=True)
    if a.write_rows:
        with open(a.write_rows, 'w') as f:
            f.write('fz_N,yaw_rad,approach_mm,delta_rad,s_mm,h_mm\n')
            for r in rows:
                f.write('%.1f,%.4f,%.6f,%.6f,%.4f,%.6e\n' % r)


if __name__ == '__main__':
    main()
