"""Plot the wheelset contact geometry of doc/geometry.md: dr(y), the contact angles and the
equivalent conicity against the amplitude, from two outputs of the program.

Usage (from the repository root, with the installed `shcontact` or build/.../app/shcontact):
    shcontact geometry --wheelset -10,10,0.05 > wheelset.txt
    shcontact geometry --conicity 0.5,1,1.5,2,2.5,3,3.5,4,4.5,5,5.5,6,6.5,7,7.5,8 > conicity.txt
    python3 doc/plot_wheelset_geometry.py wheelset.txt conicity.txt doc/figures/wheelset_geometry.png
"""
import sys


def table(name):
    """The numeric rows of one of the program's tables (comment lines start with #)."""
    with open(name) as f:
        return [[float(v) for v in line.split()] for line in f
                if line.strip() and not line.startswith('#')]


def main(argv):
    if len(argv) != 4:
        sys.exit(__doc__)
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit('plot_wheelset_geometry.py: needs matplotlib (pip install matplotlib)')
    rows, con = table(argv[1]), table(argv[2])
    y = [r[0] for r in rows]
    fig, ax = plt.subplots(1, 3, figsize=(13, 4.2))
    ax[0].plot(y, [r[9] for r in rows], 'k-', lw=1.2, label='Δr = r_R − r_L')
    t3 = next(c[1] for c in con if abs(c[0] - 3.0) < 1e-9)
    ax[0].plot(y, [2 * t3 * v for v in y], 'b--', lw=0.8,
               label=f'2y·tan γe(3 mm) = 2y·{t3:.3f}')
    ax[0].set_xlabel('lateral shift y [mm]')
    ax[0].set_ylabel('rolling-radius difference Δr [mm]')
    ax[0].set_ylim(-25, 25)
    ax[0].legend(loc='upper left', fontsize=8)
    ax[1].plot(y, [-r[10] for r in rows], 'r-', lw=1.2, label='right wheel, −γ_R')
    ax[1].plot(y, [-r[11] for r in rows], 'g-', lw=1.2, label='left wheel, −γ_L')
    ax[1].set_xlabel('lateral shift y [mm]')
    ax[1].set_ylabel('contact angle −γ [rad] (> 0 towards the flange)')
    ax[1].legend(loc='upper center', fontsize=8)
    ax[2].plot([c[0] for c in con], [c[1] for c in con], 'ko-', ms=3, label='EN 15302 (wavelength)')
    ax[2].plot([c[0] for c in con], [c[2] for c in con], 'bs--', ms=3, mfc='none',
               label='first harmonic of Δr')
    ax[2].set_xlabel('amplitude ŷ [mm]')
    ax[2].set_ylabel('equivalent conicity tan γe [−]')
    ax[2].set_ylim(bottom=0)
    ax[2].legend(loc='upper right', fontsize=8)
    for a in ax:
        a.grid(alpha=0.3)
    fig.suptitle('S1002 / UIC60 1:40, gauge 1435 mm, flange-back distance 1360 mm '
                 '(shcontact geometry --wheelset, --conicity)', fontsize=10)
    fig.tight_layout()
    fig.savefig(argv[3], dpi=110)


if __name__ == '__main__':
    main(sys.argv)
