"""Helpers shared by the machine rigs' plot scripts (examples/hpgr, examples/jaw_crusher):
reading the CSV outputs by column name and the size distributions of product and feed."""
import csv
import sys


def read(path):
    """Rows of a CSV output as dicts keyed by header ('name [unit]')."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def column(rows, name, path):
    """The column `name` of rows as floats; exits naming the file when it is missing."""
    if not rows or name not in rows[0]:
        sys.exit(f"{path}: no column '{name}'")
    return [float(r[name]) for r in rows]


def mass_passing(sizes_masses, sieves):
    """Percent of the mass of (diameter, mass) pairs with diameter <= each sieve."""
    total = sum(m for _, m in sizes_masses)
    return [100 * sum(m for d, m in sizes_masses if d <= s) / total for s in sieves]


def uniform_feed_passing(sieves, a, b):
    """Percent mass passing each sieve of diameters uniform in number on [a, b]:
    (s^4 - a^4) / (b^4 - a^4), clipped to [0, 100]."""
    return [100 * min(1, max(0, (s**4 - a**4) / (b**4 - a**4))) for s in sieves]
