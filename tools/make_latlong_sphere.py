#!/usr/bin/python3
"""Lat-long unit sphere for the surface recipe's docs and acceptance (tests/recipes/surface_test.cc
builds the same mesh in C++): 64 meridians, R rings shifted by half a step on every other ring;
needles at the north pole (the first ring far from it), tiny triangles at the south pole (rings
crowd towards it, the last one EPS away), valence-64 poles. Writes OUTBASE.msh (Gmsh 2.2, 17
digits) and OUTBASE.obj. Defaults give 3968 triangles, mean ratio min 0.0099, mean 0.567.
usage: make_latlong_sphere.py OUTBASE [R=31] [THETA1=0.6] [GAMMA=0.27] [EPS=1.4e-4]"""
import sys, math, numpy as np, meshio
out = sys.argv[1]; R = int(sys.argv[2]) if len(sys.argv) > 2 else 31
th1 = float(sys.argv[3]) if len(sys.argv) > 3 else 0.6
gam = float(sys.argv[4]) if len(sys.argv) > 4 else 0.27
K = 64
# ring colatitudes: theta_1 = th1 (needles), then towards pi with spacing shrinking like (1-t)^gam-ish
t = np.linspace(0, 1, R)
th = th1 + (math.pi - th1) * (1 - (1 - t) ** (1 / gam)) * (1 - 1e-3)
eps = float(sys.argv[5]) if len(sys.argv) > 5 else 1.4e-4
th[-1] = math.pi - eps   # last ring very close to the south pole: tiny triangles
P = [[0, 0, 1]]
for r in range(R):
    for k in range(K):
        ph = 2 * math.pi * (k + 0.5 * (r % 2)) / K
        P.append([math.sin(th[r]) * math.cos(ph), math.sin(th[r]) * math.sin(ph), math.cos(th[r])])
P.append([0, 0, -1]); P = np.array(P)
P /= np.linalg.norm(P, axis=1)[:, None]
S = len(P) - 1
idx = lambda r, k: 1 + r * K + (k % K)
T = []
for k in range(K): T.append([0, idx(0, k), idx(0, k + 1)])
for r in range(R - 1):
    for k in range(K):
        a, b = idx(r, k), idx(r, k + 1)
        if r % 2 == 0: c, d = idx(r + 1, k), idx(r + 1, k + 1)
        else: c, d = idx(r + 1, k + 1), idx(r + 1, k + 2)
        # ring r+1 is shifted by half a step when r even
        if r % 2 == 0:
            T.append([a, c, b]); T.append([b, c, d])
        else:
            c, d = idx(r + 1, k), idx(r + 1, k + 1)
            T.append([a, d, b]); T.append([a, c, d])
for k in range(K): T.append([S, idx(R - 1, k + 1), idx(R - 1, k)])
T = np.array(T)
# orient outward
c = P[T].mean(1); n = np.cross(P[T[:, 1]] - P[T[:, 0]], P[T[:, 2]] - P[T[:, 0]])
flip = (n * c).sum(1) < 0; T[flip] = T[flip][:, [0, 2, 1]]
meshio.write(out + ".msh", meshio.Mesh(P, [("triangle", T)]), file_format="gmsh22", binary=False)
with open(out + ".obj", "w") as f:
    for p in P: f.write("v %.17g %.17g %.17g\n" % tuple(p))
    for t_ in T: f.write("f %d %d %d\n" % tuple(t_ + 1))
print(len(P), "vertices", len(T), "triangles; flipped", int(flip.sum()), "max |r-1|", np.abs(np.linalg.norm(P, axis=1) - 1).max())
