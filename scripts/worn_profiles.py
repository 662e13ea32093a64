#!/usr/bin/env python3
"""Write the project's synthetic worn wheel-rail pair (data/profiles/worn/, its README).

The new S1002 wheel and the new UIC60 rail (1:40 inclination in the profile) that
`shcontact profiles --write` writes are worn by removing material normal to the surface, with
depths that are smooth bell curves of the arc length along the profile (the way wear spreads
along a running band):

  wheel  hollow tread   0.8 mm at the arc length 2 mm on the field side of the taping line,
                        half-width 12 mm (the running band of a wheel that runs centred);
         flange face    0.6 mm where the flange face is steepest, half-width 5 mm;
  rail   crown          0.4 mm at 6 mm on the gauge side of the top, half-width 12 mm;
         gauge corner   1.0 mm where the head is inclined 45 deg, half-width 4 mm.

(half-width = the Gaussian's standard deviation). The worn wheel is shifted so that its tape
circle (y = 0) stays at z = 0 and the worn rail so that its highest point stays at z = 0, the
origins of the new profiles. The worn surfaces become more conformal (a
hollow tread on a flattened crown; a thinned flange face on a worn gauge corner), which is what
the pair is for: exact-theory data on wide, non-elliptic patches on profiles nobody tuned on.
The depths are typical of wheels and rails between reprofilings; they are not a wear
prediction.

usage: scripts/worn_profiles.py OUTDIR [--new DIR]
  --new DIR: the new profiles written by `shcontact profiles --write DIR` (default: written to a
  temporary folder with $SHCONTACT_EXE, else `fpm run --profile release --`).
"""
import argparse, os, subprocess, sys, tempfile
import numpy as np

# (name, depth mm, centre rule, sigma mm) per body; see the docstring.
WHEEL_WEAR = (('hollow tread', 0.8, 'taping', -2.0, 12.0),
              ('flange face', 0.6, 'steepest', 0.0, 5.0))
RAIL_WEAR = (('crown', 0.4, 'top', 6.0, 12.0),
             ('gauge corner', 1.0, 'slope45', 0.0, 4.0))


def read_profile(path):
    head, pts = [], []
    for line in open(path):
        if line.lstrip().startswith('#') or not line.strip():
            head.append(line.rstrip('\n'))
        else:
            pts.append([float(v) for v in line.split()[:2]])
    return head, np.array(pts)


def arc_length(p):
    return np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(p, axis=0).T))))


def inward_normal(p):
    """Unit normal pointing into the material: the points are ordered with the material on
    their right (y towards the field side, z down), which is (-t_z, t_y)."""
    t = np.gradient(p, axis=0)
    t /= np.hypot(t[:, 0], t[:, 1])[:, None]
    return np.column_stack((-t[:, 1], t[:, 0]))


def centre_of(p, s, rule, offset):
    """Arc length of a wear band's centre; offset (mm of arc) towards the gauge side (for the
    wheel towards the flange, for the rail towards the track centre)."""
    y, z = p[:, 0], p[:, 1]
    slope = np.abs(np.gradient(z) / np.gradient(y))
    if rule == 'taping':            # wheel: y = 0
        i = np.argmin(np.abs(y))
    elif rule == 'top':             # rail: the highest point (smallest z)
        i = np.argmin(z)
    elif rule == 'steepest':        # wheel: steepest point of the flange face (y < -30)
        m = np.where(y < -30.0, np.arctan(slope), -1.0)
        i = np.argmax(m)
    elif rule == 'slope45':         # rail: 45 deg on the gauge side of the top
        i0 = np.argmin(z)
        cand = [k for k in range(len(y)) if y[k] < y[i0] and slope[k] <= 1.0]
        i = min(cand, key=lambda k: abs(slope[k] - 1.0) + (0.0 if y[k] < -20 else 1e3))
    else:
        raise ValueError(rule)
    # The gauge side is the side of decreasing y for both bodies (right-side profiles).
    # Arc length grows towards the gauge side where y falls along the points (the wheel).
    direction = 1.0 if p[min(i + 1, len(p) - 1), 0] < p[i, 0] else -1.0
    return s[i] + direction * offset


def worn(p, bands):
    s = arc_length(p)
    depth = np.zeros(len(p))
    for _name, d, rule, offset, sigma in bands:
        depth += d * np.exp(-0.5 * ((s - centre_of(p, s, rule, offset)) / sigma) ** 2)
    return p + depth[:, None] * inward_normal(p), depth


def write(path, source, kind, order, p, bands):
    with open(path, 'w') as f:
        f.write('# shcontact profile, source: %s, worn by scripts/worn_profiles.py\n' % source)
        f.write('# kind = %s\n' % kind)
        f.write('# units: mm; right-side profile, y towards the field side, z positive downward\n')
        f.write('# points ordered %s (material on the right)\n' % order)
        for name, d, rule, offset, sigma in bands:
            f.write('# wear: %s, %.2f mm deep normal to the surface, Gaussian in arc length, '
                    'sigma %.1f mm\n' % (name, d, sigma))
        f.write('#%21s %24s\n' % ('y', 'z'))
        for y, z in p:
            f.write('%24.14e %24.14e\n' % (y, z))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('outdir')
    ap.add_argument('--new', default=None)
    a = ap.parse_args()
    new = a.new
    if new is None:
        new = tempfile.mkdtemp(prefix='shcontact_new_profiles_')
        exe = os.environ.get('SHCONTACT_EXE')
        cmd = [exe] if exe else ['fpm', 'run', '--profile', 'release', '--']
        subprocess.run(cmd + ['profiles', '--write', new], check=True, stdout=subprocess.DEVNULL)
    os.makedirs(a.outdir, exist_ok=True)
    _, wheel = read_profile(os.path.join(new, 'S1002.txt'))
    _, rail = read_profile(os.path.join(new, 'UIC60-canted.txt'))
    w, dw = worn(wheel, WHEEL_WEAR)
    r, dr = worn(rail, RAIL_WEAR)
    # The origins stay where the new profiles have them: the wheel's on its tape circle (z = 0
    # at y = 0, so that the nominal radius is the worn wheel's radius there, for shcontact, which
    # takes it at the tape circle, and for CONTACT, which takes it at the profile's z = 0), the
    # rail's at its highest point.
    w[:, 1] -= np.interp(0.0, w[::-1, 0], w[::-1, 1])
    r[:, 1] -= r[:, 1].min()
    write(os.path.join(a.outdir, 'S1002-worn.txt'), 'builtin:S1002', 'wheel',
          'from the field side to the flange back', w, WHEEL_WEAR)
    write(os.path.join(a.outdir, 'UIC60-canted-worn.txt'), 'builtin:UIC60-canted', 'rail',
          'from the track centre to the field side', r, RAIL_WEAR)
    print('wheel: largest depth %.3f mm; rail: %.3f mm' % (dw.max(), dr.max()), file=sys.stderr)


if __name__ == '__main__':
    main()
