#!/usr/bin/env python3
"""CONTACT's undeformed distance h of the loaded state along the row through the geometric
contact point G, for the positions in data/exact/ (doc/geometry.md "Vertical approach").

For each folder data/exact/<name>/ this re-runs CONTACT's module 1 with the vertical force and
pitch rate of its summary.csv (the run that made the folder's data, scripts/contact_reference.py),
and writes h_module1_row.csv: CONTACT's local y (mm) and h (mm) of the grid row nearest G
(x_geo = 0 at zero yaw). G's y is the folder's summary y_geo, the approach its pen. Needs a CONTACT executable (CONTACT_EXE), like contact_reference.py;
not part of the build or the tests, which read the rows written.

usage: contact_gap_rows.py [NAME ...]     (default: every folder of data/exact with a summary)
"""
import csv, os, re, shutil, sys
import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
import contact_reference as cr  # noqa: E402

ROOT = os.path.join(os.path.dirname(__file__), '..', 'data', 'exact')


def summary(folder):
    with open(os.path.join(folder, 'summary.csv')) as f:
        return {r['key']: r['value'] for r in csv.DictReader(f)}


def main():
    if any(a in ('-h', '--help') for a in sys.argv[1:]):
        print(__doc__)
        return
    names = sys.argv[1:] or sorted(d for d in os.listdir(ROOT)
                                   if os.path.isfile(os.path.join(ROOT, d, 'summary.csv')))
    for name in names:
        folder = os.path.join(ROOT, name)
        s = summary(folder)
        work = '/tmp/contact-gap-rows/%s' % name
        os.makedirs(work, exist_ok=True)
        rail_file, wheel_file, cant = cr.write_profiles(work)
        with open(os.path.join(work, 'm1.inp'), 'w') as f:
            f.write(cr.module1_deck(float(s['y_ws']), float(s['fz_vertical_input']),
                                    float(s['vpitch']), rail_file, wheel_file, cant))
        ok, _, _, _ = cr.run_contact(work, 'm1')
        mats = sorted(f for f in os.listdir(work) if re.match(r'm1\.0001[a-z]?\.mat$', f))
        if not ok or not mats:
            print('%s: module 1 failed' % name)
            continue
        best = max((cr.read_mat(os.path.join(work, f)) for f in mats),
                   key=lambda m: cr.grid_totals(m)['Fn'])
        xg, yg, _, _, _, _ = cr.geo_point(best)
        g = best['grid']
        mx, my = best['mx'], best['my']
        x = g['x'].reshape(my, mx)[0]
        y = g['y'].reshape(my, mx)[:, 0]
        h = g['h'].reshape(my, mx)
        ix = int(np.argmin(np.abs(x - xg)))
        with open(os.path.join(folder, 'h_module1_row.csv'), 'w', newline='') as f:
            w = csv.writer(f)
            w.writerow(['y_mm', 'h_mm'])
            for j in range(my):
                w.writerow(['%.4f' % y[j], '%.6e' % h[j, ix]])
        print('%s: %d rows, y_geo = %.4f' % (name, my, yg))


if __name__ == '__main__':
    main()
