#!/usr/bin/python3
"""high_order_curving.py: the det J ratio of curved quadratic meshes, tmop against Gmsh (issue 18).

Makes the curved test meshes of docs/recipes/high_order.md (the gear tri6 of
tests/recipes/high_order_untangle_test.cc, a wavy annulus tri6, a sphere in a box tet10; and
Gmsh's t5 at order 2 with --t5), each at order 2 with its boundary mid nodes on the curves and no
high-order optimisation (NAME_in.msh); runs Gmsh 4.8's HighOrderElastic and HighOrder optimizers
on the same mesh (NAME_elastic.msh, NAME_hoopt.msh; python3-gmsh) and tmop_optimize's default
recipe (NAME_tmop.msh); measures every file here, independently of tmop: per tri6 / tet10 the
corner simplex's mean ratio, the pointwise mean ratio (minimum over the nodes, relative to the
ideal element) and the det J ratio min / max det J over the nodes (worst / mean over the cells),
and the interior edges whose mid node is off the chord by more than 1e-9 of the length (count,
largest offset / length).

usage: high_order_curving.py [--tools=build/tools] [--outdir=DIR] [--t5]
"""
import argparse
import collections
import contextlib
import io
import math
import os
import subprocess
import sys

import gmsh
import meshio
import numpy as np

def gear_geo(path):
    n = 60
    with open(path, 'w') as g:
        for i in range(n):
            t = 2 * math.pi * i / n
            r = 1 + 0.2 * math.sin(10 * t)
            g.write("Point(%d) = {%.17g, %.17g, 0};\n" % (i + 1, r * math.cos(t), r * math.sin(t)))
        g.write("Spline(1) = {" + ",".join(str(i + 1) for i in range(n)) + ",1};\n"
                "Curve Loop(1) = {1};\nPlane Surface(1) = {1};\nPhysical Surface(1) = {1};\n"
                "Mesh.CharacteristicLengthMax = 0.6;\n")


def wavy_annulus_geo(path):
    n = 48
    with open(path, 'w') as g:
        for i in range(n):
            t = 2 * math.pi * i / n
            r = 0.45 + 0.1 * math.sin(6 * t)
            g.write("Point(%d) = {%.17g, %.17g, 0};\n" % (i + 1, r * math.cos(t), r * math.sin(t)))
        g.write("Spline(1) = {" + ",".join(str(i + 1) for i in range(n)) + ",1};\n")
        g.write("Point(101)={0,0,0};Point(102)={1.2,0,0};Point(103)={0,1.2,0};"
                "Point(104)={-1.2,0,0};Point(105)={0,-1.2,0};\n")
        g.write("Circle(11)={102,101,103};Circle(12)={103,101,104};Circle(13)={104,101,105};"
                "Circle(14)={105,101,102};\n")
        g.write("Curve Loop(1)={11,12,13,14};Curve Loop(2)={1};Plane Surface(1)={1,2};"
                "Physical Surface(1)={1};\n")


def sphere_box_geo(path):
    with open(path, 'w') as g:
        g.write('SetFactory("OpenCASCADE");\nBox(1) = {-1, -1, -1, 2, 2, 2};\n'
                'Sphere(2) = {0, 0, 0, 0.55};\n'
                'BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }\n'
                'Mesh.CharacteristicLengthMax = 0.6;\n')


def gmsh_meshes(geo, dim, prefix):
    """PREFIX_in.msh (order 2, no HO optimisation), then Gmsh's optimizers on that mesh."""
    for method, suffix in [(None, "in"), ("HighOrderElastic", "elastic"), ("HighOrder", "hoopt")]:
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("General.NumThreads", 1)
        gmsh.open(geo)
        gmsh.option.setNumber("Mesh.ElementOrder", 2)
        gmsh.option.setNumber("Mesh.HighOrderOptimize", 0)
        gmsh.option.setNumber("Mesh.SecondOrderLinear", 0)
        gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
        gmsh.model.mesh.generate(dim)
        if method:
            gmsh.model.mesh.optimize(method)
        gmsh.write(prefix + "_" + suffix + ".msh")
        gmsh.finalize()

def tri6_gradients(xi):
    """d N_i / d (r, s) of Gmsh's tri6 (meshio keeps Gmsh's order)."""
    r, s = xi
    t = 1 - r - s
    return np.array([[-(4 * t - 1), 4 * r - 1, 0, 4 * (t - r), 4 * s, -4 * s],
                     [-(4 * t - 1), 0, 4 * s - 1, -4 * r, 4 * r, 4 * (t - s)]])


def tet10_gradients(xi):
    """d N_i / d (r, s, u) of a tet10 in meshio's (VTK) order: mid nodes 01 12 20 30 31 32."""
    L = [1 - sum(xi)] + list(xi)
    dL = np.array([[-1, -1, -1], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    g = [(4 * L[i] - 1) * dL[i] for i in range(4)]
    g += [4 * (L[a] * dL[b] + L[b] * dL[a]) for a, b in TET_EDGES]
    return np.array(g).T


TRI_EDGES = [(0, 1), (1, 2), (2, 0)]
TET_EDGES = [(0, 1), (1, 2), (2, 0), (3, 0), (3, 1), (3, 2)]
TYPES = {
    'triangle6': (2, 3, TRI_EDGES, tri6_gradients, np.array([[1, .5], [0, math.sqrt(3) / 2]])),
    'tetra10': (3, 4, TET_EDGES, tet10_gradients,
                np.array([[1, .5, .5], [0, math.sqrt(3) / 2, math.sqrt(3) / 6],
                          [0, 0, math.sqrt(2. / 3)]])),
}


def mean_ratio(T):
    d = T.shape[0]
    det = np.linalg.det(T)
    return np.sign(det) * d * abs(det) ** (2. / d) / np.sum(T * T)


def measure(path):
    """{type: (corner, pointwise, det ratio (worst, mean) each, curved edges, largest offset)}."""
    with contextlib.redirect_stdout(io.StringIO()):  # meshio prints a blank line
        m = meshio.read(path)
    P = m.points
    blocks = collections.OrderedDict()
    for b in m.cells:
        blocks.setdefault(b.type, []).append(b.data)
    out = {}
    dim_max = max(TYPES[t][0] for t in blocks if t in TYPES)
    for typ, datas in blocks.items():
        if typ not in TYPES or TYPES[typ][0] != dim_max:
            continue
        dim, nc, edges, grads, W = TYPES[typ]
        C = np.concatenate(datas)
        corners = [np.eye(dim)[i - 1] if i else np.zeros(dim) for i in range(nc)]
        nodes = corners + [(corners[a] + corners[b]) / 2 for a, b in edges]
        G = [grads(x) for x in nodes]
        Winv = np.linalg.inv(W)
        corner, pointwise, ratio, mid, count = [], [], [], {}, {}
        for c in C:
            x = P[c][:, :dim]
            corner.append(mean_ratio((x[1:nc] - x[0]).T @ Winv))
            A = [x.T @ g.T for g in G]
            dets = np.array([np.linalg.det(a) for a in A])
            pointwise.append(min(mean_ratio(a @ Winv) for a in A))
            ratio.append(dets.min() / dets.max() if dets.max() > 0 else -1)
            for e, (a, b) in enumerate(edges):
                key = tuple(sorted((c[a], c[b])))
                mid[key] = c[nc + e]
        # Interior edges: not on a boundary facet (2D: an edge of one cell).
        facets = collections.Counter()
        for c in C:
            for f in ([(0, 1), (1, 2), (2, 0)] if dim == 2 else
                      [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)]):
                facets[tuple(sorted(c[list(f)]))] += 1
        on_boundary = set()
        for f, k in facets.items():
            if k == 1:
                for i in range(len(f)):
                    for j in range(i + 1, len(f)):
                        on_boundary.add(tuple(sorted((f[i], f[j]))))
        curved, largest, interior = 0, 0.0, 0
        for (a, b), v in mid.items():
            if (a, b) in on_boundary:
                continue
            interior += 1
            off = np.linalg.norm(P[v] - (P[a] + P[b]) / 2) / np.linalg.norm(P[a] - P[b])
            if off > 1e-9:
                curved += 1
                largest = max(largest, off)
        stats = lambda v: (min(v), float(np.mean(v)))
        out[typ] = (stats(corner), stats(pointwise), stats(ratio), curved, interior, largest)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--tools', default='build/tools')
    ap.add_argument('--outdir', default='/tmp/tmop_high_order_curving')
    ap.add_argument('--t5', action='store_true', help="also Gmsh's t5 at order 2 (slower)")
    args = ap.parse_args()
    tool = os.path.abspath(os.path.join(args.tools, 'tmop_optimize'))
    os.makedirs(args.outdir, exist_ok=True)
    os.chdir(args.outdir)
    cases = [('gear', gear_geo, 2), ('wavy_annulus', wavy_annulus_geo, 2),
             ('sphere_box', sphere_box_geo, 3)]
    if args.t5:
        t5 = '/usr/share/doc/gmsh-doc/doc/gmsh/tutorial/t5.geo.gz'
        cases.append(('t5', lambda p: open(p, 'wb').write(
            subprocess.run(['gunzip', '-c', t5], check=True, capture_output=True).stdout), 3))
    print('| mesh | file | corner worst / mean | pointwise mean ratio worst / mean | '
          'det J ratio worst / mean | curved interior edges, max |')
    print('|---|---|---|---|---|---|')
    for name, make_geo, dim in cases:
        make_geo(name + '.geo')
        gmsh_meshes(name + '.geo', dim, name)
        run = subprocess.run([tool, '--input=%s_in.msh' % name, '--output=%s_tmop.msh' % name,
                              '--threads=1'], capture_output=True, text=True)
        if run.returncode != 0:
            print('%s: tmop_optimize exit %d: %s' % (name, run.returncode,
                                                    run.stderr.strip().splitlines()[-1]))
        for suffix in ['in', 'tmop', 'elastic', 'hoopt']:
            path = '%s_%s.msh' % (name, suffix)
            if not os.path.exists(path):
                continue
            for typ, (co, pw, dr, curved, interior, largest) in measure(path).items():
                print('| %s %s | %s | %.3f / %.3f | %.3f / %.3f | %.3f / %.3f | %d of %d, %.3f |' %
                      (name, typ, suffix, co[0], co[1], pw[0], pw[1], dr[0], dr[1], curved,
                       interior, largest))
    return 0


if __name__ == '__main__':
    sys.exit(main())
