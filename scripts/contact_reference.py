#!/usr/bin/env python3
"""Generate exact-theory (CONTACT) reference data at a wheelset lateral position Y_WS.

Procedure (data/exact/README.md):
  0. Profiles: the built-in S1002 and UIC60 written by `shcontact profiles --write` (default),
     or CONTACT_PROFILES=mbench for the Manchester-benchmark files from an external-data folder.
  1. CONTACT module 1 (S1002 / UIC60 1:40 Manchester set-up, right wheel), zero yaw, VY=VYAW=0,
     VPITCH adjusted so that CKSI ~ 0 ("pure-rolling-ish"), FZ iterated by secant so that the
     normal force of the largest patch (integrated pn*dx*dy from the .mat file) is 64700 N.
  2. h(x,y) of that patch exported from the module-1 .mat file (same grid); geometric point G
     = min of h refined with 3-point parabolas in x and y; curvatures A1,B1 from a quadratic
     least-squares fit in a +-1 mm (x) by +-0.6 mm (y) window around G.
  3. Module 3, IPOTCN=3, IBASE=9 with h inline, FN=64700 prescribed, spin centre at G,
     exact solver (B=0, M=0); DOE over (xi, eta, phi); CSVs in the shared formats.

usage: scripts/contact_reference.py YWS OUTDIR [--corner] [--n 6] [--workdir DIR]
  YWS: the wheelset's lateral shift (mm); OUTDIR: the folder written (data/exact/<name>/)
  CONTACT_EXE: the CONTACT program (scripts/contact_build.sh); SHCONTACT_EXE: shcontact (else fpm run)
  CONTACT_PROFILES: 'builtin' (default) or 'mbench' (the Manchester files, as the committed
  data/exact folders were made; they are read from $SHCONTACT_EXTERNAL_DATA/profiles)
"""
import argparse, csv, math, os, re, shutil, subprocess, sys, time
import numpy as np

CONTACT = os.environ.get('CONTACT_EXE', os.path.join(os.path.dirname(__file__), '..', 'build',
                                                     'contact', 'contact'))  # scripts/contact_build.sh
FN_TARGET = 64700.0
MU = 0.3
VS = 2000.0
RNOM = 460.0

# Profiles: 'builtin' (default) writes the project's built-in S1002 and UIC60-canted (the 1:40
# inclination in the profile, origin at its highest point, as in the Manchester file) with
# `shcontact profiles --write`; 'mbench' takes the Manchester-benchmark files MBench_S1002_v3.prw / MBench_UIC60_v3.prr (inclination
# in the file) from $SHCONTACT_EXTERNAL_DATA/profiles, the set the committed data/exact was made
# with. The two agree to 6.5e-4 mm on the running surfaces (doc/profiles.md, "Built-in
# profiles"), and CONTACT's forces with them to about 1e-4 of mu*Fn (data/exact/README.md).
PROFILE_SOURCE = os.environ.get('CONTACT_PROFILES', 'builtin')
EXTERNAL = os.environ.get('SHCONTACT_EXTERNAL_DATA',
                          os.path.join(os.path.dirname(__file__), '..', '..', 'shared'))
# CONTACT's module 1 stops with NaN in its vertical-position iteration on profiles sampled at
# 0.1 mm (the built-in sampling); at chords of 0.2 mm and more it converges, so the written
# profiles are thinned to this spacing for CONTACT.
CONTACT_MIN_CHORD = 0.2   # mm


def shcontact_command():
    """The shcontact program: $SHCONTACT_EXE, else `fpm run --profile release --`."""
    exe = os.environ.get('SHCONTACT_EXE')
    return [exe] if exe else ['fpm', 'run', '--profile', 'release', '--']


def thin_profile(src, dst, min_chord):
    """Copy a 2-column profile file, keeping comment lines, the first and last point, and
    the points at least min_chord (mm) from the last one kept."""
    comments, pts = [], []
    for line in open(src):
        if line.lstrip().startswith('#') or not line.strip():
            comments.append(line)
        else:
            pts.append(tuple(float(v) for v in line.split()[:2]))
    kept = [pts[0]]
    for q in pts[1:-1]:
        if math.hypot(q[0] - kept[-1][0], q[1] - kept[-1][1]) >= min_chord:
            kept.append(q)
    kept.append(pts[-1])
    with open(dst, 'w') as f:
        f.writelines(comments)
        f.writelines('%24.14e %24.14e\n' % q for q in kept)


def write_profiles(workdir):
    """Put the wheel and rail files in workdir; returns (rail file, wheel file, cant [rad])."""
    if PROFILE_SOURCE == 'mbench':
        names = ('MBench_UIC60_v3.prr', 'MBench_S1002_v3.prw')
        for n in names:
            shutil.copy(os.path.join(EXTERNAL, 'profiles', n), workdir)
        return names[0], names[1], 0.0
    if PROFILE_SOURCE != 'builtin':
        sys.exit("CONTACT_PROFILES must be 'builtin' or 'mbench', not '%s'" % PROFILE_SOURCE)
    raw = os.path.join(workdir, 'builtin')   # this script's own folder: written anew each run
    shutil.rmtree(raw, ignore_errors=True)
    os.makedirs(raw)
    subprocess.run(shcontact_command() + ['profiles', '--write', raw], check=True,
                   stdout=subprocess.DEVNULL)
    for n in ('UIC60-canted.txt', 'S1002.txt'):
        thin_profile(os.path.join(raw, n), os.path.join(workdir, n), CONTACT_MIN_CHORD)
    return 'UIC60-canted.txt', 'S1002.txt', 0.0


def module1_deck(y, fz, vpitch, rail_file, wheel_file, cant):
    """CONTACT module-1 input (wheel-rail, one case): the Manchester-benchmark set-up of
    data/exact/README.md. Right wheel; Y_WS = y (mm), vertical force FZ = fz (N), no roll or
    yaw, forward speed VS, no lateral or yaw velocity, pitch rate vpitch (rad/s)."""
    control = [
        # C P B T N F S: wheel-rail config, steady rolling, 0/1/2 tangential/normal flags,
        # N=1 vertical force prescribed, F=0, S=0 (CONTACT user guide, control digits)
        ('1203100', 'C-P-B-T-N-F-S   CONFIG, PVTIME, BOUND,  TANG,   NORM,   FORCE,  STRESS'),
        # V L D C M Z E: Coulomb friction, contact approach D=2 (weighted centre), influence
        # coefficients C=2 (piecewise constant), elastic material, track/wheel input given
        ('0022033', 'V-L-D-C-M-Z-E   VARFRC, FRCLAW, DISCNS, INFLCF, MATER,  ZTRACK, EWHEEL'),
        ('0002321', 'H-G-I-A-O-W-R     HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW,   RETURN'),
    ]
    lines = ['  1 MODULE']
    lines += [' %s    %s' % c for c in control]
    lines += [
        '    999     100    30    1     1e-05         MAXGS , MAXIN , MAXNR , MAXOUT, EPS',
        '  %.3f   %.3f                                 FSTAT, FKIN' % (MU, MU),
        '  0.270   0.270   82670.0  82670.0                POISS 1,2,  GG 1,2',
        # grid 0.2 mm, patches separated at 8 mm and combined below 4 mm
        '  0.2000   0.2000   1.000   90d   8.0   4.0      DX, DS, DQREL, A_SEP, D_SEP, D_COMB',
        '   14.0     0    1435.0   %.10f                GAUGHT, GAUGSQ, GAUGWD, CANT' % cant,
        "  '%s'   0     1.0   0.0       RFNAME, MIRRORY, SCALE, SMOOTH" % rail_file,
        '     0.0    0.0   0.000   0.0   0.0   0.000     DY, DZ, ROLL, VY, VZ, VROLL',
        '  1360.0  -70.0   %.1f                         FBDIST, FBPOS, NOMRAD' % RNOM,
        "  '%s'   0     1.0   0.0       WFNAME, MIRRORY, SCALE, SMOOTH" % wheel_file,
        '  0.0  %.6f  %.4f  0.0000000000  0.0  0.0          S, Y, FZ, ROLL, YAW, PITCH' % (y, fz),
        '  %.1f  0.0  0.0  0.0  0.0  %.11f   VS,VY,VZ, VROLL,VYAW,VPITCH' % (VS, vpitch),
        '',
        '  0 MODULE',
    ]
    return '\n'.join(lines) + '\n'

FLOAT = r'[-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+)?'


def ffloat(s):
    """A Fortran number as CONTACT prints it: D exponents, and 0.145781-310 (an exponent below
    -99 written without its letter)."""
    m = re.match(r'^([-+]?\d*\.\d+)([-+]\d{3})$', s)
    if m:
        return float(m.group(1) + 'E' + m.group(2))
    return float(s.replace('D', 'E').replace('d', 'e'))


# ------------------------------------------------------------------------------------------------
# .mat reader (format 2410)

def read_mat(fname):
    hdr, rows = [], []
    with open(fname) as f:
        lines = f.read().splitlines()
    vals = []
    for ln in lines:
        if ln.startswith('%'):
            hdr.append(ln)
            continue
        vals.append([ffloat(t) for t in ln.split()])
    # first 6 value lines are meta blocks, rest are element rows
    m = {}
    r = vals
    m['fmt'] = int(r[0][-1])
    m['y_r'], m['z_r'] = r[0][3], r[0][4]
    m['x_w'], m['y_w'], m['z_w'] = r[1][0], r[1][1], r[1][2]
    (m['xcp_r'], m['ycp_r'], m['zcp_r'], m['delt_r'], m['xcp_w'], m['ycp_w'], m['zcp_w']) = r[2][:7]
    m['npatch'], m['ipatch'] = int(r[2][7]), int(r[2][8])
    m['mx'], m['my'] = int(r[3][0]), int(r[3][1])
    m['xl'], m['yl'], m['dx'], m['dy'] = r[3][2:6]
    m['veloc'] = r[5][2]
    el = np.array(r[6:])
    mx, my = m['mx'], m['my']
    n = mx * my
    cols = ['igs', 'h', 'mu', 'pn', 'px', 'py', 'un', 'ux', 'uy', 'srel']
    g = {c: np.zeros(n) for c in cols}
    g['h'][:] = 2 * el[:, 2].max()
    idx = el[:, 0].astype(int) - 1
    for k, c in enumerate(cols):
        g[c][idx] = el[:, 1 + k]
    g['igs'] = g['igs'].astype(int)
    ii = np.arange(n)
    g['ix'] = ii % mx + 1
    g['iy'] = ii // mx + 1
    g['x'] = m['xl'] + (g['ix'] - 0.5) * m['dx']
    g['y'] = m['yl'] + (g['iy'] - 0.5) * m['dy']
    g['listed'] = np.zeros(n, bool)
    g['listed'][idx] = True
    m['grid'] = g
    return m


def grid_totals(m):
    g = m['grid']
    dA = m['dx'] * m['dy']
    Fn = g['pn'].sum() * dA
    Fx = g['px'].sum() * dA
    Fy = g['py'].sum() * dA
    Mz = ((g['x'] * g['py'] - g['y'] * g['px']) * dA).sum()
    con = g['igs'] > 0
    t = dict(Fn=Fn, Fx=Fx, Fy=Fy, fx=Fx / (MU * Fn), fy=Fy / (MU * Fn), Mz=Mz,
             ncon=int(con.sum()), nadh=int((g['igs'] == 1).sum()), nslip=int((g['igs'] == 2).sum()),
             pmax=g['pn'].max())
    if con.any():
        hx, hy = m['dx'] / 2, m['dy'] / 2
        t['cx_min'] = g['x'][con].min() - hx
        t['cx_max'] = g['x'][con].max() + hx
        t['cy_min'] = g['y'][con].min() - hy
        t['cy_max'] = g['y'][con].max() + hy
        t['length'] = t['cx_max'] - t['cx_min']
        t['width'] = t['cy_max'] - t['cy_min']
        t['area'] = t['ncon'] * dA
    return t


def write_grid_csv(m, fname):
    g = m['grid']
    with open(fname, 'w', newline='') as f:
        w = csv.writer(f)
        w.writerow(['i', 'ix', 'iy', 'x_mm', 'y_mm', 'h_mm', 'igs', 'mu', 'pn_MPa', 'px_MPa', 'py_MPa',
                    'un_mm', 'ux_mm', 'uy_mm', 'srel'])
        for i in range(len(g['x'])):
            w.writerow([i + 1, g['ix'][i], g['iy'][i], '%.10g' % round(g['x'][i], 6), '%.10g' % round(g['y'][i], 6),
                        '%.6g' % g['h'][i], g['igs'][i], '%.6g' % g['mu'][i], '%.6g' % g['pn'][i],
                        '%.6g' % g['px'][i], '%.6g' % g['py'][i], '%.6g' % g['un'][i], '%.6g' % g['ux'][i],
                        '%.6g' % g['uy'][i], '%.6g' % g['srel'][i]])


# ------------------------------------------------------------------------------------------------
# module-1 .out parsing

def parse_out1(fname):
    txt = open(fname).read()
    res = {'patches': []}
    mt = re.search(r'TOTAL FORCES ON RAIL\s*\n.*\n\s*(' + FLOAT + r')\s+(' + FLOAT + r')\s+(' + FLOAT + ')', txt)
    if mt:
        res['FX_tr'], res['FY_tr'], res['FZ_tr'] = [ffloat(mt.group(k)) for k in (1, 2, 3)]
    mp = re.search(r'(\d+) CONTACT PATCH', txt)
    res['npatch_out'] = int(mp.group(1)) if mp else 0
    blocks = re.split(r'----- DATA FOR CONTACT PATCH\s+(\d+)\s+-----', txt)
    for k in range(1, len(blocks), 2):
        ip = int(blocks[k]); b = blocks[k + 1]
        p = {'ipatch': ip}
        ma = re.search(r'XCP\(TR\)\s+YCP\(TR\)\s+ZCP\(TR\)\s+DELTCP\(TR\)\s+YCP\(R\)\s+ZCP\(R\)\s*\n\s*' +
                       r'\s+'.join(['(' + FLOAT + ')'] * 6), b)
        if ma:
            for key, v in zip(['xcp_tr', 'ycp_tr', 'zcp_tr', 'deltcp_tr', 'ycp_r', 'zcp_r'], ma.groups()):
                p[key] = ffloat(v)
        mb = re.search(r'XCP\(W\)\s+YCP\(W\)\s+ZCP\(W\)\s*\n\s*' + r'\s+'.join(['(' + FLOAT + ')'] * 3), b)
        if mb:
            for key, v in zip(['xcp_w', 'ycp_w', 'zcp_w'], mb.groups()):
                p[key] = ffloat(v)
        mk = re.search(r'CKSI\s+CETA\s+CPHI\s*\n\s*' + r'\s+'.join(['(' + FLOAT + ')'] * 6), b)
        if mk:
            p['veloc'] = ffloat(mk.group(3))
            p['cksi'], p['ceta'], p['cphi'] = [ffloat(mk.group(k)) for k in (4, 5, 6)]
        res['patches'].append(p)
    return res


def run_contact(workdir, name, log=None, timestamps=False):
    env = dict(os.environ, GFORTRAN_UNBUFFERED_ALL='1', OMP_NUM_THREADS='1')
    t0 = time.time()
    stamps = []
    with open(os.path.join(workdir, name + '.log'), 'w') as flog:
        p = subprocess.Popen([CONTACT, '2', name], cwd=workdir, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True, env=env, bufsize=1)
        for ln in p.stdout:
            if timestamps:
                mm = re.match(r'\s*Case\s+(\d+)\s*$', ln)
                if mm:
                    stamps.append((int(mm.group(1)), time.time()))
            flog.write(ln)
        p.wait()
    t1 = time.time()
    ok = 'ended succesfully' in open(os.path.join(workdir, name + '.log')).read()
    return ok, stamps, t1 - t0, t1


# ------------------------------------------------------------------------------------------------
# module 1 with FZ (secant) and VPITCH iteration

def module1(yws, workdir, log):
    rail_file, wheel_file, cant = write_profiles(workdir)
    vpitch = -VS / RNOM
    fz_hist, fn_hist = [], []
    fz = FN_TARGET * 0.98
    best = None
    for it in range(14):
        name = 'm1'
        for fn_ in os.listdir(workdir):
            if fn_.startswith(name + '.') and fn_.endswith('.mat'):
                os.remove(os.path.join(workdir, fn_))
        with open(os.path.join(workdir, name + '.inp'), 'w') as f:
            f.write(module1_deck(yws, fz, vpitch, rail_file, wheel_file, cant))
        ok, _, _, _ = run_contact(workdir, name)
        out = parse_out1(os.path.join(workdir, name + '.out'))
        mats = sorted(fn_ for fn_ in os.listdir(workdir) if re.match(r'm1\.0001[a-z]?\.mat$', fn_))
        if not ok or not mats:
            log('module 1 failed at it %d (ok=%s, mats=%s)' % (it, ok, mats))
            return None
        pm = []
        for fn_ in mats:
            m = read_mat(os.path.join(workdir, fn_))
            t = grid_totals(m)
            pm.append((t['Fn'], fn_, m, t))
        pm.sort(key=lambda z: -z[0])
        Fn, matname, m, t = pm[0]
        ipatch = m['ipatch']
        pinfo = [p for p in out['patches'] if p['ipatch'] == ipatch]
        pinfo = pinfo[0] if pinfo else {}
        log('  it %2d: FZ=%.4f VPITCH=%.8f -> npatch=%d, Fn(patch %d)=%.4f  [%s]  cksi=%s' %
            (it, fz, vpitch, len(pm), ipatch, Fn, ', '.join('%.1f' % z[0] for z in pm), pinfo.get('cksi')))
        best = dict(fz=fz, vpitch=vpitch, out=out, patches=pm, m=m, t=t, pinfo=pinfo, matname=matname)
        fz_hist.append(fz); fn_hist.append(Fn)
        # update VPITCH for CKSI ~ 0: cksi ~ (VS + vpitch*r)/VS  ->  r ~ (cksi-1)*VS/vpitch (r>0)
        cksi = pinfo.get('cksi', 0.0)
        if abs(Fn - FN_TARGET) < 0.05 and abs(cksi) < 2e-5:
            break
        if abs(cksi) >= 2e-5:
            vpitch = vpitch * (1.0 - cksi)   # to first order
        if len(fz_hist) == 1:
            fz = fz * FN_TARGET / Fn
        else:
            d = (fn_hist[-1] - fn_hist[-2])
            if abs(d) < 1e-9:
                fz = fz * FN_TARGET / Fn
            else:
                fz = fz_hist[-1] + (FN_TARGET - fn_hist[-1]) * (fz_hist[-1] - fz_hist[-2]) / d
    # keep the mat/out of the final run
    return best


def geo_point(m):
    g = m['grid']; mx, my = m['mx'], m['my']
    h = g['h'].reshape(my, mx)
    iy, ix = np.unravel_index(np.argmin(h), h.shape)

    def para(a, b, c):
        den = a - 2 * b + c
        return 0.0 if den == 0 else 0.5 * (a - c) / den

    ox = para(h[iy, ix - 1], h[iy, ix], h[iy, ix + 1]) if 0 < ix < mx - 1 else 0.0
    oy = para(h[iy - 1, ix], h[iy, ix], h[iy + 1, ix]) if 0 < iy < my - 1 else 0.0
    xg = m['xl'] + (ix + 0.5 + ox) * m['dx']
    yg = m['yl'] + (iy + 0.5 + oy) * m['dy']
    # local quadratic fit in window +-1 mm (x) by +-0.6 mm (y)
    X = g['x'].reshape(my, mx) - xg
    Y = g['y'].reshape(my, mx) - yg
    sel = (np.abs(X) <= 1.0 + 1e-9) & (np.abs(Y) <= 0.6 + 1e-9)
    x, y, z = X[sel], Y[sel], h[sel]
    Amat = np.column_stack([np.ones_like(x), x, y, x * x, y * y, x * y])
    coef, *_ = np.linalg.lstsq(Amat, z, rcond=None)
    return xg, yg, coef[3], coef[4], coef[5], h.min()


# ------------------------------------------------------------------------------------------------
# module 3

def m3_first_block(m, fn, cksi, ceta, cphi, xg, yg, xhga='00000201', first=True):
    s = []
    s.append('  3  MODULE\n')
    s.append('  203100     P-B-T-N-F-S   PVTIME, BOUND , TANG  , NORM  , FORCE , STRESS\n')
    s.append('  022020     L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER , RZNORM, EXRHS\n')
    s.append(' %s   X-H-G-I-A-O-W-R   HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN\n' % xhga)
    s.append('  999   100    30    1   1e-05             MAXGS, MAXIN, MAXNR, MAXOUT, EPS\n')
    s.append('  %.4f  %.10g  %.10g  %.10g  %.6f  %.6f   FN, CKSI, CETA, CPHI, SPINXO, SPINYO\n' %
             (fn, cksi, ceta, cphi, xg, yg))
    s.append('  0.300  0.300                                FSTAT, FKIN\n')
    s.append('  0.000  0.200000  2000.0                    CHI, DQ, VELOC\n')
    s.append('  0.270  0.270  82670.0  82670.0          POISS 1,2,  GG 1,2\n')
    s.append('   3                                            IPOTCN\n')
    s.append('  %d  %d  %.6f  %.6f  %.6f  %.6f   MX, MY, XC1, YC1, DX, DY\n' %
             (m['mx'], m['my'], m['xl'] + 0.5 * m['dx'], m['yl'] + 0.5 * m['dy'], m['dx'], m['dy']))
    s.append('   9   1                                        IBASE, IPLAN\n')
    h = m['grid']['h']
    for k in range(0, len(h), 8):
        s.append(' ' + ' '.join('%.9e' % v for v in h[k:k + 8]) + '\n')
    return ''.join(s)


def m3_next_block(fn, cksi, ceta, cphi, xg, yg, xhga='00100201'):
    return ('  3  MODULE\n'
            '  203100     P-B-T-N-F-S   PVTIME, BOUND , TANG  , NORM  , FORCE , STRESS\n'
            '  100000     L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER , RZNORM, EXRHS\n'
            ' %s   X-H-G-I-A-O-W-R   HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN\n'
            '  %.4f  %.10g  %.10g  %.10g  %.6f  %.6f   FN, CKSI, CETA, CPHI, SPINXO, SPINYO\n'
            % (xhga, fn, cksi, ceta, cphi, xg, yg))


def parse_out3(fname):
    txt = open(fname).read()
    parts = re.split(r'\n Case\s+(\d+)\s*\n', txt)
    res = {}
    for k in range(1, len(parts), 2):
        ic = int(parts[k]); b = parts[k + 1]
        r = {}
        mf = re.search(r'FN\s+FX\s+FY\s+MZ\s+ELAST.EN.\s+FRIC.POWER\s*\n\s*' + r'\s+'.join(['(' + FLOAT + ')'] * 4), b)
        mg = re.search(r'FN/G\s+FX/FSTAT/FN\s+FY/FSTAT/FN\s+APPROACH\s+PMAX\s*\n\s*' + r'\s+'.join(['(' + FLOAT + ')'] * 5), b)
        mc = re.search(r'NPOT\s+NCON\s+NADH\s+NSLIP\s+INORM\s+ITANG\s*\n\s*(\d+)\s+(\d+)\s+(\d+)\s+(\d+)', b)
        if mf:
            r['Fn'], r['Fx'], r['Fy'], r['Mz'] = mf.groups()
        if mg:
            r['fx'], r['fy'], r['pen'], r['pmax'] = mg.group(2), mg.group(3), mg.group(4), mg.group(5)
        if mc:
            r['ncon'], r['nadh'], r['nslip'] = mc.group(2), mc.group(3), mc.group(4)
        res[ic] = r
    return res


def num(s):
    v = ffloat(s)
    return '%.10g' % v


def run_m3_cases(m, xg, yg, cases, workdir, name, matcase=None):
    """cases: list of (xi, eta, phi_per_mm). Writes deck, runs, returns rows."""
    s = []
    for k, (xi, eta, phi) in enumerate(cases):
        a = '2' if (matcase is not None and k == matcase) else '0'
        if k == 0:
            s.append(m3_first_block(m, FN_TARGET, xi, eta, phi, xg, yg, xhga='0000%s201' % a))
        else:
            s.append(m3_next_block(FN_TARGET, xi, eta, phi, xg, yg, xhga='0010%s201' % a))
    s.append('  0  MODULE\n')
    with open(os.path.join(workdir, name + '.inp'), 'w') as f:
        f.write(''.join(s))
    ok, stamps, wall, tend = run_contact(workdir, name, timestamps=True)
    res = parse_out3(os.path.join(workdir, name + '.out'))
    tmap = dict(stamps)
    rows = []
    for k, (xi, eta, phi) in enumerate(cases):
        ic = k + 1
        r = res.get(ic, {})
        if ic in tmap:
            tn = tmap.get(ic + 1, tend)
            ws = tn - tmap[ic]
        else:
            ws = float('nan')
        rows.append([ic, '%.10g' % xi, '%.10g' % eta, '%.10g' % (phi * 1e3)] +
                    [num(r[c]) if c in r else 'nan' for c in ('Fn', 'Fx', 'Fy', 'fx', 'fy', 'Mz')] +
                    [r.get('ncon', 'nan'), r.get('nadh', 'nan'), r.get('nslip', 'nan'),
                     num(r['pmax']) if 'pmax' in r else 'nan', num(r['pen']) if 'pen' in r else 'nan',
                     '%.9g' % ws])
    return ok, rows, wall


DOE_HDR = ['case', 'nux', 'nuy', 'phi_1_per_m', 'Fn_N', 'Fx_N', 'Fy_N', 'fx', 'fy', 'Mz_Nmm', 'ncon', 'nadh',
           'nslip', 'pmax_MPa', 'pen_mm', 'wall_s']


def write_rows(fname, rows):
    with open(fname, 'w', newline='') as f:
        w = csv.writer(f)
        w.writerow(DOE_HDR)
        w.writerows(rows)


def doe_cases(n, cmax=2e-3, phimax=2e-3):
    v = np.linspace(0, cmax, n)
    p = np.linspace(0, phimax, n)   # 1/mm
    return [(a, b, c) for a in v for b in v for c in p]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('yws', type=float)
    ap.add_argument('outdir')
    ap.add_argument('--n', type=int, default=6)
    ap.add_argument('--corner', action='store_true', help='validation: 8 corner cases only')
    ap.add_argument('--workdir', default=None)
    a = ap.parse_args()
    tag = ('yws%.3f' % a.yws).replace('-', 'm').replace('.', 'p').rstrip('0').rstrip('p')
    workdir = a.workdir or '/tmp/contact-work/run_%s' % tag
    os.makedirs(workdir, exist_ok=True)
    os.makedirs(a.outdir, exist_ok=True)
    inpdir = os.path.join(a.outdir, 'inp'); os.makedirs(inpdir, exist_ok=True)
    logf = open(os.path.join(a.outdir, 'run.log'), 'a')

    def log(msg):
        line = time.strftime('%H:%M:%S ') + msg
        print(line, flush=True); logf.write(line + '\n'); logf.flush()

    log('=== Y_WS = %.4f mm, workdir %s' % (a.yws, workdir))
    b = module1(a.yws, workdir, log)
    if b is None:
        log('MODULE 1 FAILED; no output for this position')
        sys.exit(2)
    m, t1, pinfo, out = b['m'], b['t'], b['pinfo'], b['out']
    shutil.copy(os.path.join(workdir, 'm1.inp'), os.path.join(inpdir, 'module1.inp'))
    write_grid_csv(m, os.path.join(a.outdir, 'grid_module1_exact.csv'))
    xg, yg, A1, B1, Axy, hmin = geo_point(m)
    log('module 1: npatch=%d, patch %d: Fn=%.3f delt=%.5f rad (%.3f deg), grid %dx%d, G=(%.6f,%.6f), A1=%.6g B1=%.6g'
        % (len(b['patches']), m['ipatch'], t1['Fn'], m['delt_r'], math.degrees(m['delt_r']), m['mx'], m['my'], xg, yg, A1, B1))

    results = {}
    # zero-creepage case (with .mat) and headline creepages (with .mat)
    for label, case in (('zero', (0.0, 0.0, 0.0)), ('headline', (0.58e-3, 0.061e-3, 0.274e-3))):
        nm = 'm3_%s' % label
        for fn_ in os.listdir(workdir):
            if fn_.startswith(nm + '.') and fn_.endswith('.mat'):
                os.remove(os.path.join(workdir, fn_))
        ok, rows, wall = run_m3_cases(m, xg, yg, [case], workdir, nm, matcase=0)
        shutil.copy(os.path.join(workdir, nm + '.inp'), os.path.join(inpdir, 'module3_%s_exact_nonhertz.inp' % label))
        m3 = read_mat(os.path.join(workdir, nm + '.0001.mat'))
        results[label] = (rows[0], m3, grid_totals(m3))
        suffix = '' if label == 'zero' else '_headline'
        write_grid_csv(m3, os.path.join(a.outdir, 'grid_module3_exact_nonhertz%s.csv' % suffix))
        log('module 3 %s: %s' % (label, rows[0]))

    if a.corner:
        cases = [(xi, eta, phi) for xi in (0, 2e-3) for eta in (0, 2e-3) for phi in (0, 2e-3)]
        name = 'corner_exact_nonhertz'
    else:
        cases = doe_cases(a.n)
        name = 'doe_%dx%dx%d_exact_nonhertz' % (a.n, a.n, a.n)
    ok, rows, wall = run_m3_cases(m, xg, yg, cases, workdir, name)
    shutil.copy(os.path.join(workdir, name + '.inp'), os.path.join(inpdir, name + '.inp'))
    write_rows(os.path.join(a.outdir, name + '.csv'), rows)
    log('%s: ok=%s, %d cases, %.1f s' % (name, ok, len(rows), wall))

    # summary
    z = results['zero'][2]
    S = []
    add = lambda k, v, u='', n='': S.append([k, v, u, n])
    add('y_ws', a.yws, 'mm', 'CONTACT module-1 lateral wheelset position Y_WS (track coords, right wheel)')
    add('npatch', len(b['patches']), '-', 'number of contact patches found by module 1')
    add('ipatch_used', m['ipatch'], '-', 'patch used (largest normal force)')
    if len(b['patches']) > 1:
        add('other_patches_Fn', ';'.join('%s:%.1f' % (q[1], q[0]) for q in b['patches'][1:]), 'N',
            'normal force of the other patches (mat file: value) in the final module-1 run')
    add('fz_vertical_input', b['fz'], 'N', 'module-1 prescribed vertical force FZ (iterated so that Fn of this patch = 64700 N)')
    add('vs_ws', VS, 'mm/s', 'forward velocity VS')
    add('vpitch', b['vpitch'], 'rad/s', 'wheelset pitch rate (adjusted so that module-1 CKSI ~ 0)')
    add('vy_ws', 0.0, 'mm/s', '')
    add('vyaw', 0.0, 'rad/s', '')
    add('roll_ws', 0.0, 'rad', '')
    add('yaw_ws', 0.0, 'rad', '')
    for k, u, n in (('xcp_tr', 'mm', 'contact reference point (CONTACT weighted centre), track coords'),
                    ('ycp_tr', 'mm', ''), ('zcp_tr', 'mm', 'z positive downwards')):
        add(k, pinfo.get(k, ''), u, n)
    add('delt', m['delt_r'], 'rad', 'contact angle DELT_CP (from .mat; = DELTCP(TR) with zero roll/cant): rotation from track z-axis to contact n-axis')
    add('delt_deg', math.degrees(m['delt_r']), 'deg', '')
    add('deltcp_tr_out', pinfo.get('deltcp_tr', ''), 'rad', 'as printed in module-1 .out (4 decimals)')
    add('ycp_r', m['ycp_r'], 'mm', 'reference point in rail-profile coords (+ = field side for right rail)')
    add('zcp_r', m['zcp_r'], 'mm', '')
    add('xcp_w', m['xcp_w'], 'mm', 'reference point in wheel-profile coords')
    add('ycp_w', m['ycp_w'], 'mm', '')
    add('zcp_w', m['zcp_w'], 'mm', '')
    add('grid_mx', m['mx'], '-', 'potential contact grid (contact-local x = rolling dir., y = lateral in tangent plane)')
    add('grid_my', m['my'], '-', '')
    add('grid_xl', m['xl'], 'mm', 'lower-left corner')
    add('grid_yl', m['yl'], 'mm', '')
    add('grid_dx', m['dx'], 'mm', '')
    add('grid_dy', m['dy'], 'mm', '')
    add('x_geo', xg, 'mm', 'geometric contact point (min of undeformed distance h, quadratic-refined) in local coords')
    add('y_geo', yg, 'mm', 'creepages/spin are referred to this point (SPINXO,SPINYO in module 3)')
    add('h_min', hmin, 'mm', 'minimum of h on the grid')
    add('A1_local', A1, '1/mm', 'coefficient of x^2 in a quadratic LSQ fit of h, window +-1 mm (x) by +-0.6 mm (y) around G')
    add('B1_local', B1, '1/mm', 'coefficient of y^2 in the same fit')
    add('Axy_local', Axy, '1/mm', 'coefficient of x*y in the same fit')
    add('cksi_ref_contact', pinfo.get('cksi', ''), '-', 'module-1 creepage at CONTACT reference point (printed 4 digits; pure-rolling-ish kinematics)')
    add('ceta_ref_contact', pinfo.get('ceta', ''), '-', '')
    add('cphi_ref_contact', pinfo.get('cphi', ''), '1/mm', 'geometric spin for zero yaw rate, VY=0')
    add('G', 82670, 'MPa', '')
    add('poisson', 0.27, '-', '')
    add('mu', MU, '-', '')
    for k, u in (('Fn', 'N'), ('Fx', 'N'), ('Fy', 'N'), ('fx', '-'), ('fy', '-'), ('Mz', 'N mm'), ('ncon', '-'),
                 ('nadh', '-'), ('nslip', '-'), ('pmax', 'MPa')):
        add('module1_' + k, t1[k], u, 'integrated from module-1 .mat (pn*dx*dy); module-1 kinematics only' if k == 'Fn' else '')
    for k in ('FX_tr', 'FY_tr', 'FZ_tr'):
        add('module1_' + k, out.get(k, ''), 'N', 'total force on rail (all patches), track coords (from .out)')
    add('Fn', z['Fn'], 'N', 'module 3 (zero creepage), integrated pn*dx*dy; prescribed 64700')
    add('pmax', z['pmax'], 'MPa', 'module 3')
    add('pen', ffloat(results['zero'][0][14]), 'mm', 'approach, module 3')
    add('ncon', z['ncon'], '-', 'elements in contact')
    for k in ('cx_min', 'cx_max', 'cy_min', 'cy_max'):
        add('contact_' + k[1:], z[k], 'mm', 'extent of elements in contact (cell edges)')
    add('contact_length', z['length'], 'mm', '')
    add('contact_width', z['width'], 'mm', '')
    add('contact_area', z['area'], 'mm^2', 'ncon*dx*dy')
    h = results['headline'][2]
    for k in ('Fn', 'Fx', 'Fy', 'fx', 'fy', 'Mz', 'nadh', 'nslip'):
        add('headline_' + k, h[k], '', 'module 3, xi=0.58e-3, eta=0.061e-3, phi=0.274 1/m at G, integrated from .mat')
    with open(os.path.join(a.outdir, 'summary.csv'), 'w', newline='') as f:
        w = csv.writer(f)
        w.writerow(['key', 'value', 'unit', 'note'])
        for r in S:
            w.writerow([r[0], ('%.10g' % r[1]) if isinstance(r[1], float) else r[1], r[2], r[3]])
    log('done: %s' % a.outdir)


if __name__ == '__main__':
    main()
