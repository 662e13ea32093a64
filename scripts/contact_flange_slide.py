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

With --surface it prints instead, for each Y_WS of --y-ws and each yaw at one F_z (the first of
--fz), frictionless, where CONTACT's pressure lies and the direction it gives it
(doc/validation.md §6.8, "The direction of CONTACT's flange pressure"):
  planar approach: F_n, the contact plane's angle delta_cp (at CONTACT's contact reference point,
  the weighted centre of the interpenetration measured vertically), the load centre s_c (mm,
  along the plane from that point; the row loads' mean), the rail's own angle at s_c (from the
  built-in rail profile at full resolution) and F* = F_z/cos(that angle), the normal force of
  a pressure acting where it lies;
  conformal approach: F_n, the load-weighted angle of its curved contact surface and the rail's
  angle under that surface at the load centre;
  ours (`shcontact run`, friction 0.001): F_n and the reference point's gamma0 with the default
  slide and with `&normal slide = 'exact'`.
With --friction as well, the flange set's pure-rolling decks (set 1, mu = 0.3; F* then takes
CONTACT's f_y: F_z = F* (cos a - mu f_y sin a)), ours with mu = 0.3.
With --write-surface FILE it appends CONTACT's columns of that table to FILE
(data/exact/kinematic_flange/pressure_centre.csv, read by the test
contact_surface/flange_pressure_centre).

usage: scripts/contact_flange_slide.py [--approach conformal|planar] [--fz 30000,64700,...]
           [--yaw-mrad 0,8,-8] [--y-ws 7.0,...] [--workdir DIR] [--write-rows FILE]
           [--scan-fn F1,F2,...] [--surface [--friction] [--write-surface FILE]]
  CONTACT_EXE: CONTACT (scripts/contact_build.sh); SHCONTACT_EXE: the shcontact program (release
  build); needs numpy and h5py. Not part of the build or the tests.
"""
import argparse, os, re, shutil, subprocess, sys, tempfile
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_reference as cr  # noqa: E402
import contact_kinematic_set as ks  # noqa: E402

Y_WS = 7.0   # the position of the runs (--y-ws sets it for each in turn)


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


def ours_case(work, fz, yaw, load='vertical', slide=None, friction=0.0):
    """Our solution; load 'vertical' (fz: F_z) or 'force' (fz: F_n); `slide`: &normal slide
    (the default if None); friction 0 stands for 0.001 (frictionless), else pure rolling at
    V = 2000 mm/s with that mu."""
    import h5py
    name = os.path.join(work, 'ours_y%.2f_%s%d_yaw%+d%s_mu%g' % (
        Y_WS, load, round(fz), round(yaw * 1e3), '_' + slide if slide else '', friction))
    with open(name + '.nml', 'w') as f:
        f.write("&profiles wheel = 'builtin:S1002', rail = 'builtin:UIC60-canted' /\n"
                "&track rail_canted = .true. /\n&position t_y = %.4f, roll = 0.0 /\n"
                "&kinematics mode = 'on', yaw = %.6f, v_forward = 2000.0 /\n"
                "&material shear_modulus = 82670.0, poisson = 0.27, friction = %g /\n"
                "&load mode = '%s', %s = %.1f /\n"
                "&output fields = 'all' /\n"
                % (Y_WS, yaw, friction or 0.001, load,
                   {'vertical': 'vertical_force', 'force': 'normal_force'}[load], fz))
    options = ['--set', "normal%%slide='%s'" % slide] if slide else []
    subprocess.run(cr.shcontact_command() + ['run', name + '.nml', '-o', name + '.h5'] + options,
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with h5py.File(name + '.h5') as f:
        g = f['geometry/patch_1']
        s, gap = g['y'][:], g['gap'][:]
        fn, area = float(f['summary/fn_total'][0]), float(f['summary/area'][0])
        strips = f['cases/000001/patch_1/normal']
        loaded = strips['y'][:][strips['strip_load'][:] > 0]
        gamma0 = float(strips['gamma0'][()])
    try:
        dist = root_distance(s, gap, 0.1)
    except (TypeError, ValueError, np.linalg.LinAlgError):
        dist = np.nan
    return dict(fn=fn, area=area, dist=dist, s_end=loaded.max(), gamma0=gamma0)


def rail_angle(rail_profile, y, z):
    """The angle (rad, CONTACT's sign: < 0 on the gauge side) of the rail profile (y, z columns,
    z down) at its point nearest to (y, z): a least-squares parabola through the seven nearest
    profile points, evaluated at the foot of the perpendicular."""
    ry, rz = rail_profile[:, 0], rail_profile[:, 1]
    j = int(np.argmin((ry - y) ** 2 + (rz - z) ** 2))
    c = np.polyfit(ry[j - 3:j + 4], rz[j - 3:j + 4], 2)
    t = np.linspace(ry[j] - 0.1, ry[j] + 0.1, 4001)
    k = int(np.argmin((t - y) ** 2 + (np.polyval(c, t) - z) ** 2))
    return float(np.arctan(2.0 * c[0] * t[k] + c[1]))


def planar_point(rail_profile, y_ref, z_ref, delta, s):
    """The rail profile's point whose projection on CONTACT's contact plane (through (y_ref, z_ref),
    angle delta, lateral coordinate s along it) is s."""
    ry, rz = rail_profile[:, 0], rail_profile[:, 1]
    proj = (ry - y_ref) * np.cos(delta) + (rz - z_ref) * np.sin(delta)
    i = np.where((proj[:-1] - s) * (proj[1:] - s) <= 0.0)[0]
    i = i[np.argmin(abs(ry[i] - y_ref))]
    t = (s - proj[i]) / (proj[i + 1] - proj[i])
    return ry[i] + t * (ry[i + 1] - ry[i]), rz[i] + t * (rz[i + 1] - rz[i])


def contact_surface_case(work, rail, wheel, rail_profile, fz, yaw, approach, friction):
    """CONTACT's solution at Y_WS, F_z, yaw (its own folder under work), frictionless or (friction)
    the flange set's pure-rolling deck (set 1, mu = 0.3, F_z = 64.7 kN): F_n, f_y, the reference
    angle, and where its pressure lies (module text, --surface)."""
    folder = os.path.join(work, 'surface_y%.2f_%s%s' % (Y_WS, approach, '_mu' if friction else ''))
    os.makedirs(folder, exist_ok=True)
    for n in (rail, wheel):
        if not os.path.exists(os.path.join(folder, n)):
            shutil.copy(os.path.join(work, n), folder)
    name = os.path.join(folder, 'fz%d_yaw%+d' % (round(fz), round(yaw * 1e3)))
    if friction:
        text, _ = ks.deck(Y_WS, yaw, 1, rail, wheel, approach, cr.RNOM)
        with open(name + '.inp', 'w') as f:
            f.write(text)
        cr.run_contact(folder, os.path.basename(name))
    else:
        contact_case(folder, rail, wheel, fz, yaw, approach)
    out = open(name + '.out').read()
    m = cr.read_mat(name + '.0001a.mat')
    g = read_mat(name + '.0001a.mat')
    t = cr.grid_totals(m)
    q = np.nansum(g['pn'], axis=1) * g['dx'] * g['dy']           # load per grid row (N)
    s_c = float((q * g['s']).sum() / q.sum())
    r = dict(fn=t['Fn'], fy=t['fy'], delta=float(g['delta']), s_c=s_c)
    if approach == 'planar':
        y, z = planar_point(rail_profile, m['ycp_r'], m['zcp_r'], g['delta'], s_c)
        r['rail_angle'] = rail_angle(rail_profile, y, z)
    else:
        # The curved reference surface (track y, z, angle per row) and the rail's origin in track y.
        blk = out.split('CURVED REFERENCE SURFACE')[1]
        pts = []
        for line in blk.splitlines()[2:]:
            v = line.split()
            if len(v) != 4:
                break
            pts.append([float(x) for x in v])
        pts = np.array(pts)
        n = min(len(q), len(pts))
        r['surface_angle'] = -float(np.arccos((q[:n] * np.cos(pts[:n, 3])).sum() / q[:n].sum()))
        # The surface's point at s_c (linear between its rows), the rail under it.
        y = np.interp(s_c, g['s'][:n], pts[:n, 1]) - m['y_r']
        z = np.interp(s_c, g['s'][:n], pts[:n, 2])
        r['rail_angle'] = rail_angle(rail_profile, y, z)
    return r


def normal_force_at(fz, angle, mu_fy):
    """F_n whose pressure, normal to a surface at `angle` (rad), and lateral creep force mu f_y F_n
    (on the rail, CONTACT's sign) carry F_z: F_z = F_n (cos|angle| - mu f_y sin|angle|)."""
    return fz / (np.cos(abs(angle)) - mu_fy * np.sin(abs(angle)))


SURFACE_COLUMNS = ('y_ws_mm,yaw_rad,fz_N,friction,fn_planar_N,fy_planar,delta_planar_rad,'
                   's_centre_planar_mm,rail_angle_planar_rad,fn_conformal_N,fy_conformal,'
                   'surface_angle_conformal_rad,rail_angle_conformal_rad')


def surface(a, work, positions, yaws):
    """--surface: the table of the module text, and with --write-surface its CONTACT columns."""
    fz = float(a.fz.split(',')[0])
    mu = 0.3 if a.friction else 0.0
    if a.friction and fz != ks.FZ:
        raise SystemExit('--friction: the flange set\'s decks carry F_z = %.0f N' % ks.FZ)
    rail, wheel = ks.profiles('new', work)
    rail_profile = np.loadtxt(os.path.join(work, 'builtin', 'UIC60-canted.txt'), comments='#')
    print('F_z %.1f kN, %s. Angles in degrees (CONTACT\'s sign); s_c in mm; forces in kN; F* the '
          'F_n of a pressure normal to the rail where it lies' %
          (fz / 1e3, 'set 1 (pure rolling), mu 0.3' if a.friction else 'frictionless'))
    print(' Y_WS  yaw | planar: F_n  f_y   d_cp   s_c   rail(s_c)  F*    | conformal: F_n  f_y  '
          'surface  rail   F* | ours: default F_n gamma0 | exact F_n gamma0')
    rows = []
    global Y_WS
    for Y_WS in positions:
        for yaw in yaws:
            p = contact_surface_case(work, rail, wheel, rail_profile, fz, yaw, 'planar', a.friction)
            c = contact_surface_case(work, rail, wheel, rail_profile, fz, yaw, 'conformal',
                                     a.friction)
            o = ours_case(work, fz, yaw, friction=mu)
            x = ours_case(work, fz, yaw, slide='exact', friction=mu)
            deg = np.degrees
            print(' %4.1f %+4.0f | %6.1f %+6.3f %6.2f %+5.2f %6.2f %6.1f | %6.1f %+6.3f %6.2f '
                  '%6.2f %6.1f | %6.1f %6.2f | %6.1f %6.2f'
                  % (Y_WS, yaw * 1e3, p['fn'] / 1e3, p['fy'], deg(p['delta']), p['s_c'],
                     deg(p['rail_angle']), normal_force_at(fz, p['rail_angle'], mu * p['fy']) / 1e3,
                     c['fn'] / 1e3, c['fy'], deg(c['surface_angle']), deg(c['rail_angle']),
                     normal_force_at(fz, c['rail_angle'], mu * c['fy']) / 1e3,
                     o['fn'] / 1e3, deg(o['gamma0']), x['fn'] / 1e3, deg(x['gamma0'])), flush=True)
            rows.append((Y_WS, yaw, fz, mu, p['fn'], p['fy'], p['delta'], p['s_c'], p['rail_angle'],
                         c['fn'], c['fy'], c['surface_angle'], c['rail_angle']))
    if a.write_surface:
        new_file = not os.path.exists(a.write_surface)
        with open(a.write_surface, 'a') as f:
            if new_file:
                f.write(SURFACE_COLUMNS + '\n')
            for r in rows:
                f.write('%.2f,%.4f,%.1f,%.2f,%.1f,%.5f,%.6f,%.4f,%.6f,%.1f,%.5f,%.6f,%.6f\n' % r)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--approach', default='conformal', choices=('planar', 'conformal'))
    ap.add_argument('--fz', default='30000,64700,97000,150000')
    ap.add_argument('--yaw-mrad', default='0,8,-8')
    ap.add_argument('--workdir', default=None)
    ap.add_argument('--scan-fn', default=None)
    ap.add_argument('--write-rows', default=None)
    ap.add_argument('--y-ws', default='7.0')
    ap.add_argument('--surface', action='store_true')
    ap.add_argument('--friction', action='store_true')
    ap.add_argument('--write-surface', default=None)
    a = ap.parse_args()
    work = a.workdir or tempfile.mkdtemp(prefix='contact_flange_slide_')
    os.makedirs(work, exist_ok=True)
    positions = [float(v) for v in a.y_ws.split(',')]
    if a.surface:
        surface(a, work, positions, [float(v) * 1e-3 for v in a.yaw_mrad.split(',')])
        return
    global Y_WS
    if a.scan_fn:
        if len(positions) != 1:
            raise SystemExit('--scan-fn: one position')
        Y_WS = positions[0]
        yaws = [float(v) * 1e-3 for v in a.yaw_mrad.split(',')]
        print('ours, F_n prescribed, Y_WS %.1f mm: end of the loaded strips on the root side (mm)'
              % Y_WS)
        print('  F_n kN | ' + ' '.join('yaw %+4.0f' % (y * 1e3) for y in yaws))
        for fn in (float(v) for v in a.scan_fn.split(',')):
            print('  %6.1f | ' % (fn / 1e3) + ' '.join('%8.3f' % ours_case(work, fn, y, 'force')
                                                      ['s_end'] for y in yaws), flush=True)
        return
    rows = []
    for Y_WS in positions:
        # One folder per position (the case files are named by F_z and yaw).
        folder = work if len(positions) == 1 else os.path.join(work, 'rows_y%.2f' % Y_WS)
        os.makedirs(folder, exist_ok=True)
        rail, wheel = ks.profiles('new', folder)
        print('%s approach; Y_WS %.1f mm, frictionless; angle = acos(F_z/F_n); dist = gap minimum '
              'to the flange root (mm)' % (a.approach, Y_WS))
        print('  F_z kN  yaw | CONTACT: F_n kN  angle  area  approach  slide  dist | ours: F_n kN  '
              'angle  area  dist (first contact)')
        for fz in (float(v) for v in a.fz.split(',')):
            for yaw in (float(v) * 1e-3 for v in a.yaw_mrad.split(',')):
                c = contact_case(folder, rail, wheel, fz, yaw, a.approach)
                rows += [(Y_WS,) + r for r in c['rows']]
                o = ours_case(folder, fz, yaw)
                ang = lambda fn: np.degrees(np.arccos(fz / fn))  # noqa: E731
                print('  %6.1f %+4.0f | %7.1f %6.2f %5.1f %8.4f %6.3f %5.3f | %7.1f %6.2f %5.1f '
                      '%5.3f'
                      % (fz / 1e3, yaw * 1e3, c['fn'] / 1e3, ang(c['fn']), c['area'],
                         c['approach'], c['slide'], c['dist'], o['fn'] / 1e3, ang(o['fn']),
                         o['area'], o['dist']), flush=True)
    if a.write_rows:
        # A column of the position only when there are several (h_rows_7mm.csv has one).
        several = len(positions) > 1
        with open(a.write_rows, 'w') as f:
            f.write(('y_ws_mm,' if several else '')
                    + 'fz_N,yaw_rad,approach_mm,delta_rad,s_mm,h_mm\n')
            for r in rows:
                f.write(('%.2f,' % r[0] if several else '') + '%.1f,%.4f,%.6f,%.6f,%.4f,%.6e\n'
                        % r[1:])


if __name__ == '__main__':
    main()
