"""The Python module's 3D side: Interpolation on (n, 3) vertices with tetrahedra or triangles (the 3D engine,
theory/global3) and Blend over K poses, on small generated meshes (a tetrahedralised bar, a tube surface): the
ends are the source and the target, a blend at e_k is pose k, the same frames and metrics as the CLI writes, a blend
of poses in the plane is the 2D engine's E^F interpolation, keyframes pass through their poses, and bad input raises
a one-line ValueError. Run by ctest (label unit) as test_affinterp.py is."""
import itertools
import json
import os
import subprocess

import numpy as np
import pytest

import affinterp

CLI = os.environ["AFFINTERP_CLI"]


def bar(slices=4, length=4.0):
    """The bar [0, length] x [-1/2, 1/2]^2, each box in Kuhn's six tetrahedra, positively oriented."""
    V = np.array([[s * length / slices, j - 0.5, k - 0.5] for s in range(slices + 1) for j in (0, 1) for k in (0, 1)])
    T = []
    for s in range(slices):
        for order in itertools.permutations(range(3)):
            step, corners = [0, 0, 0], []
            for c in range(4):
                corners.append(4 * (s + step[0]) + 2 * step[1] + step[2])
                if c < 3:
                    step[order[c]] = 1
            if np.linalg.det((V[corners[1:]] - V[corners[0]]).T) < 0:
                corners[1], corners[2] = corners[2], corners[1]
            T.append(corners)
    return V, np.array(T)


def tube(rings=4, around=8, length=4.0):
    phi = 2 * np.pi * np.arange(around) / around
    V = np.array([[r * length / rings, np.cos(p), np.sin(p)] for r in range(rings + 1) for p in phi])
    F = []
    for r in range(rings):
        for a in range(around):
            p, q = r * around + a, r * around + (a + 1) % around
            F += [[p, p + around, q], [q, p + around, q + around]]
    return V, np.array(F)


def twisted(V, turn, length=4.0):
    phi = turn * V[:, 0] / length
    c, s = np.cos(phi), np.sin(phi)
    return np.stack([V[:, 0], c * V[:, 1] - s * V[:, 2], s * V[:, 1] + c * V[:, 2]], axis=1)


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in V)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in F)


def assert_entry_is_the_clis(metrics, entry):
    """Every key of a metrics_at dict is one of the CLI's metrics.json entry for that frame, with its value."""
    for key, value in metrics.items():
        assert entry[key] == value, (key, value, entry[key])


def one_line_value_error(call, *words):
    with pytest.raises(ValueError) as error:
        call()
    message = str(error.value)
    assert "\n" not in message, message
    for word in words:
        assert word in message, message


@pytest.mark.parametrize("mesh", [bar, tube])
@pytest.mark.parametrize("homotopy", ["exp", "polar", "linear", "svd"])
@pytest.mark.parametrize("symmetric", [False, True])
def test_interpolation_ends_are_source_and_target(mesh, homotopy, symmetric):
    V, F = mesh()
    W = twisted(V, np.pi / 2)
    interpolation = affinterp.Interpolation(V, W, F, homotopy=homotopy, symmetric=symmetric)
    frames = interpolation.frames([0, 0.5, 1])
    assert frames.shape == (3, len(V), 3)
    np.testing.assert_allclose(frames[0], V, atol=1e-9)
    np.testing.assert_allclose(frames[2], W, atol=1e-9)
    np.testing.assert_array_equal(interpolation.vertices_at(0.5), frames[1])
    assert interpolation.energy_at(0.5) > 0 and interpolation.energy_at(1) < 1e-18


def test_interpolation_matches_the_cli(tmp_path):
    V, T = bar()
    W = twisted(V, 1.0)
    for name, points in (("a", V), ("b", W)):
        with open(tmp_path / f"{name}.mesh", "w") as f:
            f.write(f"MeshVersionFormatted 2\nDimension 3\nVertices\n{len(points)}\n")
            f.writelines(f"{x!r} {y!r} {z!r} 0\n" for x, y, z in points)
            f.write(f"Tetrahedra\n{len(T)}\n" + "".join(" ".join(str(i + 1) for i in t) + " 0\n" for t in T) + "End\n")
    subprocess.run([CLI, "interpolate", "--source", tmp_path / "a.mesh", "--target", tmp_path / "b.mesh", "--out",
                    tmp_path / "out", "--frames", "3", "--format", "npy"], check=True, capture_output=True)
    subprocess.run([CLI, "interpolate", "--source", tmp_path / "a.mesh", "--target", tmp_path / "b.mesh", "--out",
                    tmp_path / "sym", "--frames", "3", "--format", "npy", "--symmetric"], check=True, capture_output=True)
    # the same bits: no contraction is left to the compiler (CMakeLists.txt), so the templates the CLI and the
    # module each compile round alike
    np.testing.assert_array_equal(np.load(tmp_path / "out" / "frames.npy"),
                                  affinterp.Interpolation(V, W, T).frames([0, 0.5, 1]))
    np.testing.assert_array_equal(np.load(tmp_path / "sym" / "frames.npy"),
                                  affinterp.Interpolation(V, W, T, symmetric=True).frames([0, 0.5, 1]))
    subprocess.run([CLI, "interpolate", "--source", tmp_path / "a.mesh", "--target", tmp_path / "b.mesh", "--out",
                    tmp_path / "arap", "--frames", "3", "--format", "npy", "--arap-iterations", "3", "--pin", "0"],
                   check=True, capture_output=True)
    refined = affinterp.Interpolation(V, W, T, arap_iterations=3, pins=[0])
    np.testing.assert_array_equal(np.load(tmp_path / "arap" / "frames.npy"), refined.frames([0, 0.5, 1]))
    with open(tmp_path / "arap" / "metrics.json") as f:
        metrics = json.load(f)
    assert metrics["options"]["arap_iterations"] == 3
    assert metrics["frames"][1]["energy"] == refined.energy_at(0.5)


def rotation(omega):
    """exp [omega]x by Rodrigues' formula."""
    angle = np.linalg.norm(omega)
    if angle == 0:
        return np.eye(3)
    k = np.array([[0, -omega[2], omega[1]], [omega[2], 0, -omega[0]], [-omega[1], omega[0], 0]]) / angle
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def test_rotation_logs_go_beyond_pi_and_split_into_carrier_and_remainder():
    V, T = bar(slices=12, length=12.0)
    W = twisted(V, 1.5 * np.pi, length=12.0)
    consistent = affinterp.Interpolation(V, W, T)
    principal = affinterp.Interpolation(V, W, T, rotation_branch="principal")
    logs = consistent.rotation_logs()
    assert logs.shape == (len(T), 3)
    assert np.linalg.norm(logs, axis=1).max() > 1.4 * np.pi  # the bar's far end turns by 1.5 pi about x
    assert np.linalg.norm(principal.rotation_logs(), axis=1).max() <= np.pi + 1e-12
    carrier, remainder = consistent.rotation_split()
    assert carrier.shape == remainder.shape == (len(T), 3)
    for omega, c, r in zip(logs, carrier, remainder):
        np.testing.assert_allclose(rotation(c) @ rotation(r), rotation(omega), atol=1e-12)
    np.testing.assert_array_equal(principal.rotation_split()[0], principal.rotation_logs())
    assert not principal.rotation_split()[1].any()


def test_metrics_are_the_clis_with_the_targets_folds(tmp_path):
    V, F = tube()
    W = twisted(V, 0.5)
    W[16, 0] += 1.6  # vertex 16 dragged past the next ring: the triangles around it turned over within the surface
    files = [str(tmp_path / f"{name}.off") for name in "abc"]
    for file, points in zip(files, (V, W, twisted(V, 1.0))):
        write_off(file, points, F)
    subprocess.run([CLI, "interpolate", "--source", files[0], "--target", files[1], "--out", tmp_path / "run",
                    "--frames", "3", "--no-figures"], check=True, capture_output=True)
    with open(tmp_path / "run" / "metrics.json") as f:
        entries = json.load(f)["frames"]
    interpolation = affinterp.Interpolation(V, W, F)
    for entry in entries:
        metrics = interpolation.metrics_at(entry["t"])
        assert {"t", "energy", "inverted_elements", "inverted_near_folds", "measure_ratio"} <= metrics.keys()
        assert_entry_is_the_clis(metrics, entry)
    subprocess.run([CLI, "blend", "--poses"] + files + ["--weights", "0.2,0.5,0.3", "--out", tmp_path / "blend",
                    "--no-figures"], check=True, capture_output=True)
    with open(tmp_path / "blend" / "metrics.json") as f:
        entry = json.load(f)["frames"][0]
    metrics = affinterp.Blend([V, W, twisted(V, 1.0)], F).metrics_at([0.2, 0.5, 0.3])
    assert {"weights", "inverted_elements", "inverted_near_folds"} <= metrics.keys()
    assert_entry_is_the_clis(metrics, entry)
    assert "inverted_near_folds" not in affinterp.Interpolation(V, twisted(V, 0.5), F).metrics_at(0.5)


def test_a_vertex_locus_of_large_weight_is_followed():
    V, T = bar()
    W = twisted(V, 1.0)
    interpolation = affinterp.Interpolation(V, W, T, loci=["3@1e8:0,0,0;1,2,3"], barycentre_locus="0,0,0;1,1,1")
    np.testing.assert_allclose(interpolation.vertices_at(0.25)[3], [0.25, 0.5, 0.75], atol=1e-6)


@pytest.mark.parametrize("mesh", [bar, tube])
def test_blend_at_a_vertex_of_the_simplex_is_that_pose(mesh):
    V, F = mesh()
    poses = [V, twisted(V, 1.0), twisted(V, 2.0)]
    blend = affinterp.Blend(poses, F)
    frames = blend.vertices_at(np.eye(3))
    assert frames.shape == (3, len(V), 3)
    for k in range(3):
        np.testing.assert_allclose(frames[k], poses[k], atol=1e-9)
    refined = affinterp.Blend(poses, F, arap_iterations=2).vertices_at(np.eye(3))
    for k in range(3):
        np.testing.assert_allclose(refined[k], poses[k], atol=1e-9)
    single = blend.vertices_at([0.2, 0.5, 0.3])
    assert single.shape == (len(V), 3)
    np.testing.assert_array_equal(single, blend.vertices_at([[0.2, 0.5, 0.3]])[0])


def test_blend_in_the_plane_is_the_2d_engines_ef_interpolation(tmp_path):
    """Poses given as (n, 2) arrays blend in the plane: two poses at (1 - t, t) are the 2D engine's E^F exp-log
    frames (the worm curled by 3 pi, so through full turns), the frames stay (n, 2), unit weights give the poses, and
    `affinterp blend` on the same OBJ files writes the same vertices with z = 0."""
    subprocess.run([CLI, "shapes", "worm-curl", "--out", str(tmp_path / "pair")], check=True, capture_output=True)
    source, target = str(tmp_path / "pair" / "source.obj"), str(tmp_path / "pair" / "target.obj")
    V0, F = affinterp.read_mesh(source)
    V1, _ = affinterp.read_mesh(target)
    size = np.ptp(V1, axis=0).max()
    blend = affinterp.Blend([V0, V1], F)
    interpolation = affinterp.Interpolation(V0, V1, F, energy="F")
    for t in (0.25, 0.5, 0.75):
        np.testing.assert_allclose(blend.vertices_at([1 - t, t]), interpolation.vertices_at(t), rtol=0, atol=1e-12 * size)
    turned = V1 @ np.array([[0.5, np.sqrt(3) / 2], [-np.sqrt(3) / 2, 0.5]])
    frames = affinterp.Blend([V0, V1, turned], F).vertices_at(np.eye(3))
    assert frames.shape == (3, len(V0), 2)
    for frame, pose in zip(frames, (V0, V1, turned)):
        np.testing.assert_allclose(frame, pose, rtol=0, atol=1e-9 * size)
    subprocess.run([CLI, "blend", "--poses", source, target, "--weights", "0.3,0.7", "--format", "npy", "--out",
                    str(tmp_path / "run")], check=True, capture_output=True)
    written = np.load(tmp_path / "run" / "frames.npy")
    np.testing.assert_array_equal(written[0, :, 2], 0)
    np.testing.assert_array_equal(written[0, :, :2], blend.vertices_at([0.3, 0.7]))


@pytest.mark.parametrize("mesh", [bar, tube])
def test_keyframes_pass_through_their_poses_and_blend_neighbours_between(mesh):
    """Keyframes at times 0, 0.5, 1: each key time gives its pose, a time between two keys the blend of those two
    poses, a sequence of times the frames stacked; in the plane too."""
    V, F = mesh()
    poses = [V, twisted(V, 1.0), twisted(V, 2.0)]
    keys = affinterp.Keyframes(poses, F, [0, 0.5, 1])
    for t, pose in zip((0, 0.5, 1), poses):
        np.testing.assert_allclose(keys.vertices_at(t), pose, atol=1e-9)
    np.testing.assert_array_equal(keys.weights_at(0.75), [0, 0.5, 0.5])
    np.testing.assert_allclose(keys.vertices_at(0.75), affinterp.Blend(poses, F).vertices_at([0, 0.5, 0.5]),
                               rtol=0, atol=1e-12)
    assert keys.vertices_at([0, 0.3, 1]).shape == (3, len(V), 3)
    if mesh is tube:  # and a grid of unit squares in the plane, stretched along x, then sheared
        G = np.array([[i, j] for j in range(3) for i in range(4)], dtype=float)
        squares = [(j * 4 + i, j * 4 + i + 1, j * 4 + i + 5, j * 4 + i + 4) for j in range(2) for i in range(3)]
        T = np.array([t for a, b, c, d in squares for t in ((a, b, c), (a, c, d))])
        flat = affinterp.Keyframes([G, G * [2, 1], G @ [[1, 0], [0.5, 1]]], T, [0, 1, 2])
        assert flat.vertices_at([0.5, 1.5]).shape == (2, len(G), 2)
        np.testing.assert_allclose(flat.vertices_at(1), G * [2, 1], atol=1e-12)
    one_line_value_error(lambda: keys.vertices_at(1.5), "outside the key times")
    one_line_value_error(lambda: affinterp.Keyframes(poses, F, [0, 1, 1]), "increase")
    one_line_value_error(lambda: affinterp.Keyframes(poses[:1], F, [0]), "two poses")


def test_bad_input_raises_one_line_value_errors():
    V, T = bar()
    W = twisted(V, 1.0)
    flat = V.copy()
    flat[T[0][1]] = flat[T[0][0]]
    nan = W.copy()
    nan[3, 1] = np.nan
    one_line_value_error(lambda: affinterp.Interpolation(V, W[:-1], T), "V1")
    one_line_value_error(lambda: affinterp.Interpolation(flat, W, T), "degenerate")
    one_line_value_error(lambda: affinterp.Interpolation(V, W * [1, 1, -1], T), "inverted")
    one_line_value_error(lambda: affinterp.Interpolation(V, nan, T), "V1", "nan")
    one_line_value_error(lambda: affinterp.Interpolation(V, W, T[:, :2]), "F", "(m, 3) or (m, 4)")
    one_line_value_error(lambda: affinterp.Interpolation(V, W, T, energy="S"), "energy")
    one_line_value_error(lambda: affinterp.Interpolation(V, W, T, loci=["0:1,2;3,4"]), "--locus", "x,y,z")
    for keyword, value in (("edge_directions", ["0:1"]),
                           ("blend_weight", 0.25)):
        one_line_value_error(lambda: affinterp.Interpolation(V, W, T, **{keyword: value}), keyword)
    one_line_value_error(lambda: affinterp.Interpolation(V, W, T, barycentre_locus="0,0;1,1"), "x,y,z")
    one_line_value_error(lambda: affinterp.Interpolation(V, W, T).vertices_at(2.0), "time_range")
    one_line_value_error(lambda: affinterp.Interpolation(V, W, T, arap_iterations=-1), "arap_iterations")
    plane = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    one_line_value_error(lambda: affinterp.Interpolation(plane, plane, np.array([[0, 1, 2]]), arap_iterations=1),
                         "arap_iterations", "2D")
    blend = affinterp.Blend([V, W, twisted(V, 2.0)], T)
    one_line_value_error(lambda: blend.vertices_at([0.5, 0.5]), "3 weights")
    one_line_value_error(lambda: blend.metrics_at([[0.2, 0.5, 0.3]]), "w", "(k,)")
    one_line_value_error(lambda: blend.vertices_at([-1, 2, 0]), "non-negative")
    one_line_value_error(lambda: affinterp.Blend([V], T), "two poses")
    one_line_value_error(lambda: affinterp.Blend([V, W[:, :2]], T), "poses[1]", "(n, 3)")
    one_line_value_error(lambda: affinterp.Blend([V[:, :2], W], T[:, :3]), "poses[1]", "(n, 2)")
    extrapolated = affinterp.Blend([V, W], T, allow_extrapolation=True).vertices_at([-0.5, 1.5])
    assert extrapolated.shape == (len(V), 3)
