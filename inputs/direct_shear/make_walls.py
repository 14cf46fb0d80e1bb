#!/usr/bin/python3
"""Write the wall meshes (ASCII STL, metres) of the direct shear cell for LIGGGHTS.

Usage: /usr/bin/python3 inputs/direct_shear/make_walls.py [OUTDIR]   (default: this directory)

For each size (smoke, default, paper) three files, the geometry of in.lammps / in.liggghts:
The cell: the paper's heights at every size, sample height H = 25 mm at solid fraction 0.6,
split at Hlow = 15 mm (15 mm lower + 10 mm upper part), the radius R from the number of grains.
  lower_SIZE.stl  the fixed lower ring: cylinder r = R from z = 0 to Hlow, the floor (a square
                  at z = 0) and the top rim (a square flange with a circular hole of radius R at
                  z = Hlow, which holds the grains of the upper ring that pass beyond r = R)
  upper_SIZE.stl  the moving upper ring: cylinder r = R from Hlow to Htop = 1.3 x the sample
                  height + 2 mm (the deposit stays below it) and its bottom rim
                  (the same flange at z = Hlow, which covers the grains of the lower ring that the
                  displaced upper ring no longer covers)
  plate_SIZE.stl  the top plate: a square at z = 0, moved to its place by the deck
The rims and the plate reach beyond R by the total shear displacement plus a margin, so that no
grain finds an opening at any displacement.
"""
import math
import os
import sys

# the size table of the decks (in.lammps, in.liggghts): grains, shear in <D>
SIZES = {"smoke": (600, 1.5), "default": (2400, 3.0), "paper": (7307, 4.0)}
HEIGHT = 25e-3                                  # sample height at solid fraction 0.6
H_LOW = 0.6 * HEIGHT                            # the split: 15 mm lower + 10 mm upper part
D_MEAN = 0.5 * 2e-3 + 0.3 * 1.5e-3 + 0.2 * 1e-3  # <D> by number
PLATE_SPHERE = 1.5e-3                           # the margin (the LAMMPS plate sphere diameter)
SEGMENTS = 64                                   # facets around the cylinder (a multiple of 8)


def geometry(n, n_d):
    """R, Hlow, Htop, half-width of rims and plate; the same formulas as the decks."""
    n1 = round(0.5 * n)
    n2 = round(0.3 * n)
    n3 = n - n1 - n2
    v_grains = math.pi / 6 * (n1 * 8 + n2 * 3.375 + n3 * 1) * 1e-9
    radius = math.sqrt(v_grains / (0.6 * math.pi * HEIGHT))
    h_top = 1.3 * HEIGHT + 2e-3                   # the upper ring's top, above the deposit
    half = radius + n_d * D_MEAN + 2 * PLATE_SPHERE
    return radius, H_LOW, h_top, half


def circle(radius, z):
    return [(radius * math.cos(2 * math.pi * k / SEGMENTS),
             radius * math.sin(2 * math.pi * k / SEGMENTS), z) for k in range(SEGMENTS)]


def cylinder(radius, z0, z1):
    """Side of a cylinder, rows of facets at most three times as high as they are wide."""
    width = 2 * math.pi * radius / SEGMENTS
    rows = max(1, math.ceil((z1 - z0) / (3 * width)))
    tris = []
    for r in range(rows):
        lo = circle(radius, z0 + (z1 - z0) * r / rows)
        hi = circle(radius, z0 + (z1 - z0) * (r + 1) / rows)
        for k in range(SEGMENTS):
            k1 = (k + 1) % SEGMENTS
            tris += [(lo[k], lo[k1], hi[k1]), (lo[k], hi[k1], hi[k])]
    return tris


def square(half, z):
    a, b, c, d = (-half, -half, z), (half, -half, z), (half, half, z), (-half, half, z)
    return [(a, b, c), (a, c, d)]


def flange(radius, half, z):
    """A square of half-width `half` with a circular hole of `radius`: each arc segment joined
    to the point of the square's border at the same angle (corners at 45 degrees included)."""
    inner = circle(radius, z)
    outer = []
    for k in range(SEGMENTS):
        t = 2 * math.pi * k / SEGMENTS
        c, s = math.cos(t), math.sin(t)
        m = max(abs(c), abs(s))
        outer.append((half * c / m, half * s / m, z))
    tris = []
    for k in range(SEGMENTS):
        k1 = (k + 1) % SEGMENTS
        tris += [(inner[k], outer[k], outer[k1]), (inner[k], outer[k1], inner[k1])]
    return tris


def write_stl(path, name, tris):
    with open(path, "w") as f:
        # STL has no comments: the name on the solid line says how the file was made
        f.write(f"solid {name} made by: /usr/bin/python3 inputs/direct_shear/make_walls.py\n")
        for tri in tris:
            f.write("  facet normal 0 0 0\n    outer loop\n")
            for p in tri:
                f.write("      vertex {:.9e} {:.9e} {:.9e}\n".format(*p))
            f.write("    endloop\n  endfacet\n")
        f.write(f"endsolid {name}\n")


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    for size, (n, n_d) in SIZES.items():
        radius, h_low, h_top, half = geometry(n, n_d)
        write_stl(os.path.join(outdir, f"lower_{size}.stl"), f"lower_{size}",
                  cylinder(radius, 0.0, h_low) + square(half, 0.0) + flange(radius, half, h_low))
        write_stl(os.path.join(outdir, f"upper_{size}.stl"), f"upper_{size}",
                  cylinder(radius, h_low, h_top) + flange(radius, half, h_low))
        write_stl(os.path.join(outdir, f"plate_{size}.stl"), f"plate_{size}", square(half, 0.0))
        print(f"{size}: R {radius} m, Hlow {h_low:.6e} m, Htop {h_top:.6e} m, rim half-width {half:.6e} m")


if __name__ == "__main__":
    main()
