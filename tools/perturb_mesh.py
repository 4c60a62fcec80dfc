# Perturb the interior nodes of a gmsh tet mesh by up to `amount` x the shortest incident edge,
# keeping every tet positively oriented. Usage: perturb.py IN.msh OUT.msh amount seed
import sys, random
import numpy as np
import gmsh
inp, out, amount, seed = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
random.seed(seed)
gmsh.initialize(); gmsh.option.setNumber("General.Terminal", 0)
gmsh.open(inp)
tags, xyz, _ = gmsh.model.mesh.getNodes()
x = xyz.reshape(-1, 3).copy(); index = {int(t): i for i, t in enumerate(tags)}
_, tet_tags, tet_nodes = gmsh.model.mesh.getElements(3)
tets = np.array([index[int(n)] for n in tet_nodes[0]]).reshape(-1, 4)
_, _, tri_nodes = gmsh.model.mesh.getElements(2)
boundary = set(index[int(n)] for arr in tri_nodes for n in arr)
def vol(t): a = x[t[0]]; return np.dot(np.cross(x[t[1]] - a, x[t[2]] - a), x[t[3]] - a)
shortest = np.full(len(x), np.inf); incident = [[] for _ in x]
for k, t in enumerate(tets):
    for i in range(4):
        incident[t[i]].append(k)
        for j in range(i + 1, 4):
            l = np.linalg.norm(x[t[i]] - x[t[j]]); shortest[t[i]] = min(shortest[t[i]], l); shortest[t[j]] = min(shortest[t[j]], l)
for v in range(len(x)):
    if v in boundary or not incident[v]: continue
    old = x[v].copy()
    for _ in range(20):
        d = np.random.default_rng(seed * 1000003 + v + _).uniform(-1, 1, 3); d *= amount * shortest[v] / max(np.linalg.norm(d), 1e-12)
        x[v] = old + d
        if all(vol(tets[k]) > 0 for k in incident[v]): break
        x[v] = old
for i, t in enumerate(tags):
    gmsh.model.mesh.setNode(int(t), list(x[i]), [])
gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
gmsh.write(out)
gmsh.finalize()
