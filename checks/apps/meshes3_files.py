"""Small 3D mesh files for the CLI tests of the 3D engine, written without NumPy: a bar of tetrahedra (MEDIT
.mesh, Kuhn's six tetrahedra a box, as checks/global3/meshes3.hpp builds it) and an open tube of triangles (OFF),
each in the rest pose and turned about the x axis by turn * x / length. A tube file ending in .ply, .stl or .obj
is written in that format (ASCII) instead.

Usage: meshes3_files.py KIND TURN FILE [OPTION], KIND bar or tube; OPTION degenerate (a tetrahedron or triangle
collapsed), inverted (mirrored in z: each tetrahedron
inverted), nan (a coordinate not a number), fewer (one element left out),
split (a second, disconnected bar), reversed (every
tetrahedron's corners 1 and 2 swapped), folded (a tube vertex dragged past the next ring: the triangles around it
turned over within the surface)."""
import math
import sys
from itertools import permutations


def bar(slices=4, length=4.0, width=1.0):
    vertices = [[s * length / slices, (j - 0.5) * width, (k - 0.5) * width]
                for s in range(slices + 1) for j in range(2) for k in range(2)]
    tets = []
    for s in range(slices):
        for order in permutations(range(3)):
            step, corners = [0, 0, 0], []
            for c in range(4):
                corners.append(4 * (s + step[0]) + 2 * step[1] + step[2])
                if c < 3:
                    step[order[c]] = 1
            tets.append(corners)
    for t in tets:  # positively oriented: det [p1-p0 p2-p0 p3-p0] > 0
        e = [[vertices[t[c]][r] - vertices[t[0]][r] for r in range(3)] for c in (1, 2, 3)]
        det = (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0])
               + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]))
        if det < 0:
            t[1], t[2] = t[2], t[1]
    return vertices, tets, length


def tube(rings=4, around=8, length=4.0):
    vertices = [[r * length / rings, math.cos(2 * math.pi * a / around), math.sin(2 * math.pi * a / around)]
                for r in range(rings + 1) for a in range(around)]
    triangles = []
    for r in range(rings):
        for a in range(around):
            p, q = r * around + a, r * around + (a + 1) % around
            triangles += [[p, p + around, q], [q, p + around, q + around]]
    return vertices, triangles, length


def twisted(vertices, turn, length):
    out = []
    for x, y, z in vertices:
        phi = turn * x / length
        out.append([x, math.cos(phi) * y - math.sin(phi) * z, math.sin(phi) * y + math.cos(phi) * z])
    return out


def write(file, vertices, elements):
    with open(file, "w") as f:
        if len(elements[0]) == 4:
            f.write(f"MeshVersionFormatted 2\nDimension 3\nVertices\n{len(vertices)}\n")
            f.writelines(f"{x!r} {y!r} {z!r} 0\n" for x, y, z in vertices)
            f.write(f"Tetrahedra\n{len(elements)}\n")
            f.writelines(" ".join(str(i + 1) for i in e) + " 0\n" for e in elements)
            f.write("End\n")
        elif file.endswith(".ply"):
            f.write(f"ply\nformat ascii 1.0\nelement vertex {len(vertices)}\nproperty double x\nproperty double y\n"
                    f"property double z\nelement face {len(elements)}\nproperty list uchar int vertex_indices\n"
                    "end_header\n")
            f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in vertices)
            f.writelines("3 " + " ".join(map(str, e)) + "\n" for e in elements)
        elif file.endswith(".stl"):  # corners repeated per facet, as STL stores them
            f.write("solid tube\n")
            for e in elements:
                f.write("facet normal 0 0 0\nouter loop\n")
                f.writelines("vertex {!r} {!r} {!r}\n".format(*vertices[i]) for i in e)
                f.write("endloop\nendfacet\n")
            f.write("endsolid tube\n")
        elif file.endswith(".obj"):
            f.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in vertices)
            f.writelines("f " + " ".join(str(i + 1) for i in e) + "\n" for e in elements)
        else:
            f.write(f"OFF\n{len(vertices)} {len(elements)} 0\n")
            f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in vertices)
            f.writelines("3 " + " ".join(map(str, e)) + "\n" for e in elements)


def main(kind, turn, file, option=None):
    vertices, elements, length = bar() if kind == "bar" else tube()
    vertices = twisted(vertices, float(turn), length)
    if option == "degenerate":
        vertices[elements[0][1]] = list(vertices[elements[0][0]])
    elif option == "inverted":  # mirrored in z: every tetrahedron inverted
        vertices = [[x, y, -z] for x, y, z in vertices]
    elif option == "nan":
        vertices[3][1] = float("nan")
    elif option == "reversed":  # every tetrahedron negatively oriented, as some meshers write them
        elements = [[e[0], e[2], e[1], e[3]] for e in elements]
    elif option == "folded":
        vertices[2 * 8][0] += 1.6
    elif option == "fewer":
        elements = elements[1:]
    elif option == "split":
        n = len(vertices)
        vertices += [[x + 10, y, z] for x, y, z in vertices]
        elements += [[i + n for i in e] for e in elements]
    write(file, vertices, elements)


if __name__ == "__main__":
    main(*sys.argv[1:])
