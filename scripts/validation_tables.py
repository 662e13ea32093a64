#!/usr/bin/env python3
"""Tables 3, 4, 5, 7 and 10 of doc/validation.md from the files that `shcontact-validate` writes.

    python3 scripts/validation_tables.py            # rewrite the tables' rows in doc/validation.md
    python3 scripts/validation_tables.py --check    # exit 1 (and show the rows) where they differ

Table 3 and 4: doc/validation/errors.csv, FASTSIM_SH on the local-Hertz strips, spin
flexibility `longitudinal` (Table 3) and `spin` (Table 4), every bound x spin model; Table 5:
the baselines and diagnostics of the same file; Table 7: doc/validation/discretisation.csv;
Table 10: the two tables of doc/validation/patches_doe.md, copied whole. The
numbers are rounded as the tables print them (f to 3 decimals, Table 7's headline to 4); the
time per solve of Table 7 is measured anew by every run and is not checked. The test
`validation_normal/doc_tables_from_csv` runs the check, so that the prose's tables cannot drift
from the files the program writes (they did: issue 28's review found 64 of 280 numbers of
Table 3 stale). Standard library only.
"""
import csv
import os
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
DOC = os.path.join(ROOT, 'doc', 'validation.md')
ERRORS = os.path.join(ROOT, 'doc', 'validation', 'errors.csv')
DISCRETISATION = os.path.join(ROOT, 'doc', 'validation', 'discretisation.csv')

MINUS = '\u2212'
BOUNDS = [('ellipsoidal', 'ellipsoidal'), ('parabolic', 'parabolic'), ('weighted', 'weighted (W1)'),
          ('weighted-slip', 'weighted-slip (W2)'), ('clipped', 'clipped (W3)')]
SPIN_MODELS = ['additive', 'uniform', 'scaled', 'geometric']
SWEEPS = ['sweep_spin_0to2', 'sweep_spin_0to5', 'sweep_creep_0to2permille', 'doe']
RECOMMENDED = ('weighted', 'uniform')


def number(x, digits=3, sign=False):
    """x rounded to `digits` decimals, with a Unicode minus (and '+' when `sign`)."""
    text = f'{float(x):+.{digits}f}' if sign else f'{float(x):.{digits}f}'
    if text.lstrip('+-') == f'{0:.{digits}f}':
        text = ('+' if sign else '') + text.lstrip('+-')
    return text.replace('-', MINUS)


def pair(row, a, b, digits=3, sign=False):
    return f'{number(row[a], digits, sign)}, {number(row[b], digits, sign)}'


def slash(row, a, b):
    return f'{number(row[a])} / {number(row[b])}'


def error_columns(row, with_forces):
    """The columns of Tables 3-5 after the labels."""
    cells = [pair(row, 'headline_fx', 'headline_fy')] if with_forces else []
    cells.append(pair(row, 'headline_dfx', 'headline_dfy', sign=True))
    for sweep in SWEEPS[:3]:
        cells.append(slash(row, f'{sweep}_max_dfx', f'{sweep}_max_dfy'))
    cells.append(slash(row, 'doe_max_dfx', 'doe_max_dfy'))
    cells.append(slash(row, 'doe_p80_dfx', 'doe_p80_dfy'))
    return cells


def markdown(cells, bold=False):
    if bold:
        cells = [f'**{c}**' for c in cells]
    return '| ' + ' | '.join(cells) + ' |'


def read(path):
    with open(path, newline='') as f:
        return list(csv.DictReader(f))


def find(rows, **keys):
    found = [r for r in rows if all(r[k] == v for k, v in keys.items())]
    if len(found) != 1:
        sys.exit(f'validation_tables.py: {len(found)} rows of {keys} in the CSV (expected one)')
    return found[0]


def bound_spin_table(rows, flexibility, with_forces):
    lines = []
    for spin in SPIN_MODELS:
        for bound, label in BOUNDS:
            row = find(rows, method='fastsim-sh', normal='local-hertz', bound=bound,
                       spin_model=spin, spin_flexibility=flexibility)
            lines.append(markdown([label, spin] + error_columns(row, with_forces),
                                  bold=(bound, spin) == RECOMMENDED and with_forces))
    return lines


def baseline_table(rows):
    spec = [
        ('FASTSIM_SH W1, uniform, normal `constant`',
         dict(method='fastsim-sh', normal='constant', bound='weighted', spin_model='uniform',
              spin_flexibility='longitudinal')),
        ('FASTSIM_SH ellipsoidal, uniform, normal `constant`',
         dict(method='fastsim-sh', normal='constant', bound='ellipsoidal', spin_model='uniform',
              spin_flexibility='longitudinal')),
        ('FASTSIM_SH W1, uniform, CONTACT pressure',
         dict(method='fastsim-sh', normal='contact-pressure', bound='weighted',
              spin_model='uniform', spin_flexibility='longitudinal')),
        ('FASTSIM_SH ellipsoidal, uniform, CONTACT pressure',
         dict(method='fastsim-sh', normal='contact-pressure', bound='ellipsoidal',
              spin_model='uniform', spin_flexibility='longitudinal')),
        ('FASTSIM, Hertz ellipse at the geometric point, ellipsoidal',
         dict(method='fastsim', normal='hertz', bound='ellipsoidal')),
        ('FASTSIM, Hertz ellipse, parabolic', dict(method='fastsim', normal='hertz',
                                                   bound='parabolic')),
        ('FASTSIM, Hertz ellipse, W1', dict(method='fastsim', normal='hertz', bound='weighted')),
        ("CONTACT's FASTSIM on its exact pressure (`fastsim_nonhertz`)",
         dict(method='contact-fastsim_nonhertz')),
        ("CONTACT's FASTSIM on its Hertz ellipse (`fastsim_hertz`)",
         dict(method='contact-fastsim_hertz')),
    ]
    return [markdown([label] + error_columns(find(rows, **keys), False)) for label, keys in spec]


def microseconds(x):
    x = float(x)
    return f'{x:.1f}' if x < 30.0 else f'{x:.0f}'


def discretisation_table(rows):
    lines = []
    for strips, elements in [(100, 10), (100, 25), (25, 50), (50, 50), (100, 50), (100, 100),
                             (100, 400), (400, 50)]:
        row = find(rows, n_strips=str(strips), n_elements=str(elements))
        cells = [f'{strips} × {elements}', pair(row, 'headline_fx', 'headline_fy', digits=4),
                 slash(row, 'doe_max_dfx', 'doe_max_dfy'),
                 slash(row, 'doe_p80_dfx', 'doe_p80_dfy'), microseconds(row['us_per_solve'])]
        lines.append(markdown(cells, bold=(strips, elements) == (100, 50)))
    return lines


def table_span(lines, name):
    """First and last+1 index of the data rows of the markdown table after the line that
    begins with `name` ('Table 3')."""
    start = next((i for i, line in enumerate(lines)
                  if line == name or line.startswith(name + '.') or line.startswith(name + ' ')),
                 None)
    if start is None:
        sys.exit(f'validation_tables.py: no "{name}" in {DOC}')
    i = start
    while not lines[i].startswith('|'):
        i += 1
    first = i + 2  # after the header and the |---| line
    last = first
    while last < len(lines) and lines[last].startswith('|'):
        last += 1
    return first, last


def markdown_tables(lines):
    """The (first, last+1) spans of every markdown table (consecutive lines beginning with
    '|') of `lines`."""
    spans, i = [], 0
    while i < len(lines):
        if lines[i].startswith('|'):
            j = i
            while j < len(lines) and lines[j].startswith('|'):
                j += 1
            spans.append((i, j))
            i = j
        else:
            i += 1
    return spans


def copied_tables(lines, name, source):
    """The spans of the tables after the line beginning with `name` that copy the tables of
    the generated markdown file `source` (as many as it has), and those tables' lines."""
    with open(os.path.join(ROOT, 'doc', 'validation', source), encoding='utf-8') as f:
        theirs = f.read().split('\n')
    blocks = [theirs[a:b] for a, b in markdown_tables(theirs)]
    start = next(i for i, line in enumerate(lines) if line.startswith(name + '.'))
    ours = [(a, b) for a, b in markdown_tables(lines) if a > start][:len(blocks)]
    return ours, blocks


def without_time(line):
    """A Table 7 row without its last cell (the time per solve, measured anew every run)."""
    return line.rstrip().rstrip('|').rsplit('|', 1)[0]


def main(argv):
    check = '--check' in argv
    errors = read(ERRORS)
    tables = {
        'Table 3': bound_spin_table(errors, 'longitudinal', True),
        'Table 4': bound_spin_table(errors, 'spin', False),
        'Table 5': baseline_table(errors),
        'Table 7': discretisation_table(read(DISCRETISATION)),
    }
    with open(DOC, encoding='utf-8') as f:
        lines = f.read().split('\n')
    differences = 0
    for name, rows in tables.items():
        first, last = table_span(lines, name)
        now = lines[first:last]
        same = now == rows
        if name == 'Table 7':
            same = [without_time(r) for r in now] == [without_time(r) for r in rows]
        if same:
            continue
        differences += 1
        if check:
            print(f'{name} of doc/validation.md differs from its CSV:')
            for a, b in zip(now, rows):
                if a != b:
                    print(f'  doc: {a}\n  csv: {b}')
            if len(now) != len(rows):
                print(f'  {len(now)} rows in the doc, {len(rows)} from the CSV')
        else:
            if name == 'Table 7' and len(now) == len(rows):
                # The doc keeps its measured times (the run that its prose quotes).
                rows = [without_time(r) + '|' + n.rstrip().rstrip('|').rsplit('|', 1)[1] + '|'
                        for r, n in zip(rows, now)]
            lines[first:last] = rows
    # Table 10: the tables of patches_doe.md, whole (last first: the spans stay valid).
    spans, blocks = copied_tables(lines, 'Table 10', 'patches_doe.md')
    for (first, last), block in reversed(list(zip(spans, blocks))):
        if lines[first:last] == block:
            continue
        differences += 1
        if check:
            print('Table 10 of doc/validation.md differs from doc/validation/patches_doe.md:')
            for a, b in zip(lines[first:last], block):
                if a != b:
                    print(f'  doc: {a}\n  md:  {b}')
        else:
            lines[first:last] = block
    if check:
        return 1 if differences else 0
    with open(DOC, 'w', encoding='utf-8') as f:
        f.write('\n'.join(lines))
    print(f'validation_tables.py: {differences} table(s) of doc/validation.md rewritten')
    return 0


if __name__ == '__main__':
    if '--help' in sys.argv or '-h' in sys.argv:
        print(__doc__)
        sys.exit(0)
    sys.exit(main(sys.argv[1:]))
