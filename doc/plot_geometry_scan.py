"""Plot the Manchester lateral-shift scan of doc/geometry.md as an SVG (no dependencies).

Usage: python3 doc/plot_geometry_scan.py scan.dat doc/geometry_scan.svg, where scan.dat is
written by `SHCONTACT_GEOMETRY_SCAN=scan.dat fpm test -- geometry manchester_scan_0_to_10`.
"""
import sys
rows = [l.split() for l in open(sys.argv[1]) if not l.startswith('#')]
# CONTACT, doc/theory.md §5.6 (yawed, weighted centre at 10 kN): y_ws, y_r, delta
ref = [(0, -8.660, -0.0290), (0.5, -16.030, -0.0568), (1, -18.542, -0.0696), (2, -19.618, -0.0806),
       (4, -21.794, -0.1078), (5, -33.447, -0.2905), (6, -35.395, -0.4176), (6.5, -42.039, -1.1591),
       (10, -39.445, -0.7992)]
W, H, L, T, PH = 640, 520, 70, 20, 210           # size, margins, panel height
def panel(k, lo, hi, label, col, refcol):
    y0 = T + k * (PH + 50)
    X = lambda v: L + (W - L - 20) * v / 10.0
    Y = lambda v: y0 + PH * (hi - v) / (hi - lo)
    s = [f'<rect x="{L}" y="{y0}" width="{W-L-20}" height="{PH}" fill="none" stroke="black"/>',
         f'<text x="15" y="{y0+PH/2}" transform="rotate(-90 15 {y0+PH/2})" text-anchor="middle">{label}</text>']
    for i in range(11):
        s.append(f'<text x="{X(i)}" y="{y0+PH+15}" text-anchor="middle" font-size="11">{i}</text>')
    for i in range(6):
        v = lo + (hi - lo) * i / 5
        s.append(f'<text x="{L-5}" y="{Y(v)+4}" text-anchor="end" font-size="11">{v:g}</text>')
    for r in rows:
        fill = 'black' if r[1] == '1' else 'none'
        s.append(f'<circle cx="{X(float(r[0])):.1f}" cy="{Y(float(r[col])):.1f}" r="2.2" fill="{fill}" stroke="black"/>')
    for r in ref:
        x, y = X(r[0]), Y(r[refcol])
        s.append(f'<path d="M{x-5},{y-5}L{x+5},{y+5}M{x-5},{y+5}L{x+5},{y-5}" stroke="red" stroke-width="1.5"/>')
    return s
out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif">',
       '<rect width="100%" height="100%" fill="white"/>']
out += panel(0, -45, -5, 'rail contact point y_r [mm]', 3, 1)
out += panel(1, -1.3, 0.1, 'contact angle gamma0 [rad]', 5, 2)
out.append(f'<text x="{(W+L)/2}" y="{H-5}" text-anchor="middle">lateral shift y_ws [mm]  (filled: deepest patch, open: other candidates, red: CONTACT yawed rows)</text>')
out.append('</svg>')
open(sys.argv[2], 'w').write('\n'.join(out) + '\n')
