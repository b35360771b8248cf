"""The Python module affinterp (experiments/python): arrays in and out, the same vertices as the CLI, the
local theory, 3x3 symmetric functions, compatible pairs, and one-line ValueErrors on bad input.
Run by ctest (label unit) with PYTHONPATH at the built module, AFFINTERP_CLI and AFFINTERP_SOURCE_DIR set."""
import json
import os
import re
import subprocess
import sys

import numpy as np
import pytest

import affinterp

SOURCE_DIR = os.environ["AFFINTERP_SOURCE_DIR"]
CLI = os.environ["AFFINTERP_CLI"]
OUTLINES = os.path.join(SOURCE_DIR, "checks", "inputs", "outlines")


def one_line_value_error(call, *words):
    with pytest.raises(ValueError) as error:
        call()
    message = str(error.value)
    assert "\n" not in message, message
    for word in words:
        assert word in message, message
    return message


@pytest.fixture(scope="module")
def c_to_star():
    return affinterp.pair(os.path.join(OUTLINES, "letter-c.txt"), os.path.join(OUTLINES, "star.txt"))


def test_version():
    assert re.fullmatch(r"\d+\.\d+(\.\d+)?", affinterp.__version__)


def test_interpolation_joins_source_to_target(c_to_star):
    m = c_to_star
    interpolation = affinterp.Interpolation(m["V0"], m["V1"], m["F"])
    np.testing.assert_allclose(interpolation.vertices_at(0.0), m["V0"], atol=1e-9)
    np.testing.assert_allclose(interpolation.vertices_at(1.0), m["V1"], atol=1e-9)
    times = [0.0, 0.25, 0.5, 1.0]
    frames = interpolation.frames(times)
    assert frames.shape == (4, len(m["V0"]), 2) and frames.dtype == np.float64
    for k, t in enumerate(times):
        np.testing.assert_array_equal(frames[k], interpolation.vertices_at(t))
    assert abs(interpolation.energy_at(0.0)) < 1e-12
    assert interpolation.energy_at(0.5) >= 0


def read_obj_vertices(path):
    with open(path) as f:
        return np.array([[float(w) for w in line.split()[1:3]] for line in f if line.startswith("v ")])


def test_rotation_logs_are_the_polar_angles_on_their_branch(c_to_star):
    m = c_to_star
    interpolation = affinterp.Interpolation(m["V0"], m["V1"], m["F"])
    theta = interpolation.rotation_logs()
    assert theta.shape == (len(m["F"]),)
    for angle, (a, b, c) in zip(theta, m["F"]):
        P = np.column_stack([m["V0"][b] - m["V0"][a], m["V0"][c] - m["V0"][a]])
        Q = np.column_stack([m["V1"][b] - m["V1"][a], m["V1"][c] - m["V1"][a]])
        A = Q @ np.linalg.inv(P)
        polar = np.arctan2(A[1, 0] - A[0, 1], A[0, 0] + A[1, 1])
        assert abs(np.remainder(angle - polar + np.pi, 2 * np.pi) - np.pi) < 1e-9
    with pytest.raises(ValueError, match="3D meshes only") as error:
        interpolation.rotation_split()
    assert "\n" not in str(error.value)


@pytest.mark.parametrize("options, keywords", [
    ([], {}),
    (["--homotopy", "polar", "--energy", "F", "--pin", "0"], {"homotopy": "polar", "energy": "F", "pins": [0]}),
    (["--symmetric", "--no-area-weighted"], {"symmetric": True, "area_weighted": False}),
    (["--energy", "blend", "--blend-weight", "0.25", "--rotation-branch", "principal", "--locus", "1:0,0;1,1",
      "--edge-direction", "0:1:linear", "--barycentre-locus", "none"],
     {"energy": "blend", "blend_weight": 0.25, "rotation_branch": "principal", "loci": ["1:0,0;1,1"],
      "edge_directions": ["0:1:linear"], "barycentre_locus": "none"}),
])
def test_python_and_cli_give_the_same_vertices(tmp_path, options, keywords):
    subprocess.run([CLI, "shapes", "worm-curl", "--out", str(tmp_path / "pair")], check=True, capture_output=True)
    source, target = str(tmp_path / "pair" / "source.obj"), str(tmp_path / "pair" / "target.obj")
    subprocess.run([CLI, "interpolate", "--source", source, "--target", target, "--out", str(tmp_path / "run"),
                    "--times", "0,0.3,1", "--no-figures"] + options, check=True, capture_output=True)
    V0, F = affinterp.read_mesh(source)
    V1, _ = affinterp.read_mesh(target)
    interpolation = affinterp.Interpolation(V0, V1, F, **keywords)
    np.testing.assert_array_equal(interpolation.vertices_at(0.3), read_obj_vertices(tmp_path / "run" / "frame_0001.obj"))
    # metrics_at: metrics.json's entry for the frame, in its words and with its values
    with open(tmp_path / "run" / "metrics.json") as f:
        entry = json.load(f)["frames"][1]
    metrics = interpolation.metrics_at(0.3)
    assert {"t", "energy", "flipped_triangles", "mean_distortion"} <= metrics.keys()
    for key, value in metrics.items():
        assert entry[key] == value, (key, value, entry[key])


def python_defaults():
    """Interpolation's keyword defaults, as pybind11 writes them in the constructor's signature."""
    signature = affinterp.Interpolation.__init__.__doc__.splitlines()[0]
    keywords = signature[signature.index("*,") + 2:signature.rindex(")")]
    defaults = {}
    for item in re.findall(r"(\w+): [^=]+ = ('[^']*'|\[\]|\([^)]*\)|[^,]+)", keywords):
        name, text = item
        defaults[name] = text
    return defaults


def test_python_keywords_are_the_cli_options_with_the_same_defaults(tmp_path):
    """One name per option: each keyword of Interpolation is a key of metrics.json's "options", and its default
    is what the CLI ran with no option (the engine's InterpolationOptions{}); a front end that types a default
    or a name of its own fails here."""
    subprocess.run([CLI, "shapes", "random", "--out", str(tmp_path / "pair")], check=True, capture_output=True)
    subprocess.run([CLI, "interpolate", "--source", str(tmp_path / "pair" / "source.obj"), "--target",
                    str(tmp_path / "pair" / "target.obj"), "--out", str(tmp_path / "run"), "--frames", "2",
                    "--no-figures"], check=True, capture_output=True)
    with open(tmp_path / "run" / "metrics.json") as f:
        cli = json.load(f)["options"]
    defaults = python_defaults()
    assert set(defaults) == {"homotopy", "energy", "rotation_branch", "blend_weight", "blend_weights",
                             "area_weighted", "symmetric", "pins", "loci", "edge_directions", "barycentre_locus",
                             "time_range", "arap_iterations"}, defaults
    for name, text in defaults.items():
        assert name in cli, name
        expected = cli[name]
        if isinstance(expected, str):
            assert text == repr(expected), (name, text, expected)
        elif isinstance(expected, bool):
            assert text == str(expected), (name, text, expected)
        elif isinstance(expected, list) and name == "time_range":
            assert tuple(float(x) for x in text.strip("()").split(",")) == tuple(expected), (name, text)
        elif isinstance(expected, list):
            assert text == "[]" and expected == [], (name, text, expected)
        elif expected is None:
            assert text == "None", (name, text)
        else:
            assert float(text) == expected, (name, text, expected)


def test_python_takes_the_engines_names_and_refuses_others(c_to_star):
    m = c_to_star
    for keyword, names in [("homotopy", ["exp", "polar", "linear", "svd"]), ("energy", ["F", "S", "R", "blend"]),
                           ("rotation_branch", ["consistent", "principal"])]:
        for name in names:
            affinterp.Interpolation(m["V0"], m["V1"], m["F"], **{keyword: name})
        one_line_value_error(lambda: affinterp.Interpolation(m["V0"], m["V1"], m["F"], **{keyword: "nope"}),
                             "'nope'", "expected " + ", ".join(names))
    one_line_value_error(lambda: affinterp.Interpolation(m["V0"], m["V1"], m["F"], blend_weight=2.0),
                         "the blend weight w must lie in [0, 1]")
    one_line_value_error(lambda: affinterp.Interpolation(m["V0"], m["V1"], m["F"], time_range=(1.0, 0.0)),
                         "t_begin <= t_end")
    weights = np.full(len(m["F"]), 0.5)
    affinterp.Interpolation(m["V0"], m["V1"], m["F"], energy="blend", blend_weights=weights)
    one_line_value_error(lambda: affinterp.Interpolation(m["V0"], m["V1"], m["F"], energy="blend",
                                                         blend_weights=weights[1:]), "one weight w_i per triangle")


def test_bad_meshes_get_one_line_value_errors():
    V0 = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]])
    F = np.array([[0, 1, 2], [1, 3, 2]])
    affinterp.Interpolation(V0, 2 * V0, F)  # valid
    one_line_value_error(lambda: affinterp.Interpolation(V0[:, :1], V0, F), "V0", "(n, 2)")
    one_line_value_error(lambda: affinterp.Interpolation(V0, V0[:3], F), "V1")
    nan = V0.copy()
    nan[2, 1] = np.nan
    one_line_value_error(lambda: affinterp.Interpolation(nan, V0, F), "V0", "(2, 1)", "nan")
    one_line_value_error(lambda: affinterp.Interpolation(V0, V0, F.astype(float)), "F", "integer")
    one_line_value_error(lambda: affinterp.Interpolation(V0, V0, F[:, :2]), "F", "(m, 3)")
    one_line_value_error(lambda: affinterp.Interpolation(V0, V0, np.array([[0, 1, 7]])), "V0")
    flat = V0.copy()
    flat[2] = [2.0, 0.0]  # triangle 0 collinear
    one_line_value_error(lambda: affinterp.Interpolation(flat, V0, F), "V0")
    flipped = V0.copy()
    flipped[3] = [0.5, -1.0]  # triangle 1 turned over in the target
    one_line_value_error(lambda: affinterp.Interpolation(V0, flipped, F), "V1", "flipped")
    one_line_value_error(lambda: affinterp.Interpolation(V0, V0, F, homotopy="cubic"), "cubic")
    one_line_value_error(lambda: affinterp.Interpolation(V0, V0, F, pins=[9]), "9")
    interpolation = affinterp.Interpolation(V0, 2 * V0, F)
    one_line_value_error(lambda: interpolation.vertices_at(1.5), "outside the time range")
    one_line_value_error(lambda: interpolation.frames([0.0, np.inf]), "times")
    one_line_value_error(lambda: affinterp.read_mesh(os.path.join(OUTLINES, "star.txt")), "unknown extension")


def test_numpy_layouts_are_read_in_place_or_converted():
    V0 = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    F = np.array([[0, 1, 2]], dtype=np.int32)
    expected = affinterp.Interpolation(V0, 3 * V0, F, energy="F", pins=[0]).vertices_at(0.5)
    fortran = np.asfortranarray(V0)
    as_ints = np.array([[0, 0], [1, 0], [0, 1]])
    for source in (fortran, as_ints, V0.tolist()):
        got = affinterp.Interpolation(source, 3 * V0, F.astype(np.int64), energy="F", pins=[0]).vertices_at(0.5)
        np.testing.assert_array_equal(got, expected)


def test_local_homotopies_join_identity_to_A():
    A = np.array([[1.2, -0.7], [0.4, 0.9]])
    for name in ("exp", "polar", "linear", "svd"):
        path = affinterp.homotopy_at(A, [0.0, 0.5, 1.0], name)
        assert path.shape == (3, 2, 2)
        np.testing.assert_allclose(path[0], np.eye(2), atol=1e-14)
        np.testing.assert_allclose(path[2], A, atol=1e-14)
    # A^E(t) = R_{t theta} S^t: det A^E(t) = (det A)^t (Kaji eq. 3)
    t = np.linspace(0, 1, 7)
    np.testing.assert_allclose(np.linalg.det(affinterp.homotopy_at(A, t, "exp")), np.linalg.det(A) ** t, rtol=1e-13)
    np.testing.assert_allclose(affinterp.homotopy_at(A, 0.5, "linear")[0], (np.eye(2) + A) / 2, atol=1e-15)
    one_line_value_error(lambda: affinterp.homotopy_at(-np.eye(2) @ np.diag([1, -1]), 0.5), "det A")
    one_line_value_error(lambda: affinterp.homotopy_at(A, 0.5, "cubic"), "cubic")
    one_line_value_error(lambda: affinterp.homotopy_at(np.ones((2, 3)), 0.5), "A", "(2, 2)")


def test_goodness_matches_the_corrected_area_condition_and_is_exact():
    rng = np.random.default_rng(2012)
    B = rng.uniform(-1, 3, size=(400, 2, 2))
    B = B[np.linalg.det(B) > 0]
    tr, det = np.trace(B, axis1=1, axis2=2), np.linalg.det(B)
    corrected = ((2 * det <= tr) & (tr <= 2)) | ((2 <= tr) & (tr <= 2 * det))
    np.testing.assert_array_equal(affinterp.good_for_area(B), corrected)
    assert affinterp.good_for_area(np.eye(2)) is True
    # The shear [[1, 1], [0, 1]]: det A(t) = 1, good for area; |A(t) v| dips for v = (1, -2), where
    # P(v) = -2 < 0 < Q(v) = 2 (theory/local/goodness.hpp), so not good for norm
    shear = np.array([[1.0, 1.0], [0.0, 1.0]])
    assert affinterp.good_for_area(shear) and not affinterp.good_for_norm(shear)
    assert affinterp.good_for_norm(np.diag([2.0, 3.0]))
    one_line_value_error(lambda: affinterp.good_for_norm(np.full((2, 2), np.nan)), "B", "nan")


def test_sym3_exp_and_eigenvalues():
    rng = np.random.default_rng(3)
    X = rng.normal(size=(50, 3, 3))
    S = X + np.transpose(X, (0, 2, 1))
    w, Vec = np.linalg.eigh(S)
    expected = np.einsum("kij,kj,klj->kil", Vec, np.exp(w), Vec)
    np.testing.assert_allclose(affinterp.exp3(S), expected, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(affinterp.eig3(S), w, atol=1e-12)
    assert affinterp.exp3(S[0]).shape == (3, 3) and affinterp.eig3(S[0]).shape == (3,)
    bad = S[:2].copy()
    bad[1, 0, 2] += 1
    one_line_value_error(lambda: affinterp.exp3(bad), "S[1]", "not symmetric", "(1,3)")
    one_line_value_error(lambda: affinterp.eig3(np.zeros((4, 3))), "(k, 3, 3)")


def test_pair_gives_meshes_without_flips(c_to_star):
    m = c_to_star
    n = 16
    for V in (m["V0"], m["V1"]):
        a, b, c = V[m["F"][:, 0]], V[m["F"][:, 1]], V[m["F"][:, 2]]
        area = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
        assert (area > 0).all()
    np.testing.assert_array_equal(m["V0"][:n], np.loadtxt(os.path.join(OUTLINES, "letter-c.txt")))
    assert m["steiner_vertices"] > 0 and m["source_min_angle"] > 0 and m["target_min_angle"] > 0
    resampled = affinterp.pair(os.path.join(OUTLINES, "comb.txt"), np.loadtxt(os.path.join(OUTLINES, "blob.txt")),
                               resample=30)
    assert len(resampled["V0"]) >= 30


def test_pair_refuses_malformed_outlines():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    bowtie = np.array([[0, 0], [1, 0], [0, 1], [1, 1]], dtype=float)
    one_line_value_error(lambda: affinterp.pair(bowtie, square), "source", "not a simple polygon")
    one_line_value_error(lambda: affinterp.pair(square, square[:3]), "4 vertices", "3")
    one_line_value_error(lambda: affinterp.pair(square, square[::-1]), "orientation")
    one_line_value_error(lambda: affinterp.pair(square, np.full((4, 2), np.nan)), "target", "nan")


def test_decide_refuses_a_bad_condition_without_running_a_decider():
    one_line_value_error(lambda: affinterp.decide("x +* y", "polar", "norm"), "bad condition")
    one_line_value_error(lambda: affinterp.decide("x > 1", "cubic", "norm"), "cubic")
    one_line_value_error(lambda: affinterp.decide("l1 > 1", "svd", "norm", dim=3), "open")
    one_line_value_error(lambda: affinterp.decide("l1 > 1", "polar", "area", dim=3), "volume")
    one_line_value_error(lambda: affinterp.decide("x > 1", "polar", "norm", dim=4), "2 or 3")


def test_readme_example_runs_as_written(tmp_path):
    with open(os.path.join(SOURCE_DIR, "README.md")) as f:
        readme = f.read()
    example = re.search(r"```python\n(.*?)```", readme, re.S).group(1)
    assert len(example.strip().splitlines()) <= 12
    os.symlink(os.path.join(SOURCE_DIR, "checks"), tmp_path / "checks")
    env = dict(os.environ, MPLBACKEND="Agg")
    subprocess.run([sys.executable, "-c", example], cwd=tmp_path, env=env, check=True)
    assert (tmp_path / "frames.png").stat().st_size > 0
