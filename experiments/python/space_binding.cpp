#include "experiments/python/space_binding.hpp"

#include "experiments/inputs/constraint_spec.hpp"
#include "experiments/inputs/frame_metrics_json.hpp"
#include "experiments/inputs/mesh3_poses.hpp"
#include "experiments/inputs/mesh_file.hpp"
#include "experiments/python/bindings.hpp"
#include "experiments/python/engine_errors.hpp"
#include "experiments/python/json_dict.hpp"
#include "theory/global3/blend3.hpp"
#include "theory/global3/frame_metrics3.hpp"
#include "theory/global3/target_folds3.hpp"

#include <pybind11/stl.h>

#include <mutex>

namespace affinterp::python {

namespace {

/// The meshes checked as the CLI checks them, `names` naming them in the one-line ValueError.
void check_meshes3(const std::vector<global3::Mesh3>& meshes, const std::vector<std::string>& names) {
  try {
    io::check_poses3(meshes, names);
  } catch (const io::MeshFileError& e) {
    value_error(e.what());
  }
}

global3::Interpolation3Options options3(const SpaceKeywords& k, Eigen::Index vertex_count) {
  global3::Interpolation3Options options;
  options.homotopy = global::parse_option<global::LocalHomotopy>(k.homotopy);
  options.rotation_branch = global::parse_option<global::RotationBranch>(k.rotation_branch);
  options.area_weighted = k.area_weighted, options.symmetric = k.symmetric;
  options.arap_iterations = k.arap_iterations;
  options.constraints = io::parse_constraints3(k.pins, k.loci, k.barycentre_locus, vertex_count);
  return options;
}

/// affinterp.Blend: Blend3 over K poses sharing F.
class SpaceBlend {
 public:
  SpaceBlend(const py::iterable& poses, const py::object& F, bool allow_extrapolation,
             const std::string& rotation_branch, bool area_weighted, int arap_iterations) {
    std::vector<global3::Mesh3> meshes = pose_meshes(poses, F, planar_);
    global3::Blend3Options options = blend_options(rotation_branch, area_weighted, arap_iterations);
    options.allow_extrapolation = allow_extrapolation;
    engine_ = translated([&] { return std::make_unique<global3::Blend3>(meshes, options); });
    vertex_count_ = meshes[0].vertex_count();
    poses_ = std::move(meshes);
  }

  /// w of shape (K,): the (n, 3) blend ((n, 2) for poses in the plane); (frames, K): (frames, n, 3) or (frames, n, 2).
  py::array_t<double> vertices_at(const py::object& w) const {
    const DoubleArray weights = DoubleArray::ensure(w);
    if (!weights || weights.ndim() < 1 || weights.ndim() > 2) value_error("w: expected shape (k,) or (frames, k)");
    check_finite(weights, "w");
    const py::ssize_t rows = weights.ndim() == 1 ? 1 : weights.shape(0), k = weights.shape(weights.ndim() - 1);
    std::vector<Eigen::VectorXd> vectors;
    for (py::ssize_t r = 0; r < rows; ++r)
      vectors.push_back(Eigen::Map<const Eigen::VectorXd>(weights.data() + r * k, k));
    std::vector<Eigen::Matrix3Xd> frames;
    {
      py::gil_scoped_release unlocked;
      frames = translated([&] { return engine_->vertices_at(vectors); });
    }
    if (weights.ndim() == 2) return stacked(frames, vertex_count_, planar_ ? 2 : 3);
    return frame_points(std::move(frames[0]), planar_);
  }

  /// `affinterp blend`'s metrics.json entry of the blend for w, shape (K,), as a dict.
  py::object metrics_at(const py::object& w) const {
    const DoubleArray weights = DoubleArray::ensure(w);
    if (!weights || weights.ndim() != 1) value_error("w: expected shape (k,)");
    check_finite(weights, "w");
    const Eigen::VectorXd vector = Eigen::Map<const Eigen::VectorXd>(weights.data(), weights.shape(0));
    nlohmann::json entry;
    {
      py::gil_scoped_release unlocked;
      std::call_once(folds_found_, [&] {  // the CLI's mask: at or beside the folds of any pose against the first
        near_folds_ = global3::near_pose_folds(poses_, global3::pose_folds(poses_));
      });
      translated([&] {
        const Eigen::Matrix3Xd v = engine_->vertices_at(vector);
        entry = {{"weights", std::vector<double>(vector.data(), vector.data() + vector.size())}};
        entry.update(io::metrics3_json(
            global3::frame_metrics3(poses_[0], v, engine_->local_maps_at(vector), near_folds_), !near_folds_.empty()));
      });
    }
    return dict_of(entry);
  }

 private:
  std::unique_ptr<global3::Blend3> engine_;
  std::vector<global3::Mesh3> poses_;              ///< for the metrics
  bool planar_ = false;                            ///< poses given as (n, 2): frames returned as (n, 2)
  mutable std::vector<unsigned char> near_folds_;  ///< as SpaceInterpolation's, over every pose's folds
  mutable std::once_flag folds_found_;
  Eigen::Index vertex_count_ = 0;
};

}  // namespace

bool is_space_points(const py::object& V0) {
  const py::array a = py::array::ensure(V0);
  return a && a.ndim() == 2 && a.shape(1) == 3;
}

py::array_t<double> stacked(const std::vector<Eigen::Matrix3Xd>& frames, Eigen::Index vertex_count, Eigen::Index d) {
  py::array_t<double> out(
      {static_cast<py::ssize_t>(frames.size()), static_cast<py::ssize_t>(vertex_count), static_cast<py::ssize_t>(d)});
  for (std::size_t k = 0; k < frames.size(); ++k)
    Eigen::Map<Eigen::MatrixXd>(out.mutable_data() + d * vertex_count * static_cast<Eigen::Index>(k), d, vertex_count) =
        frames[k].topRows(d);
  return out;
}

std::vector<global3::Mesh3> pose_meshes(const py::iterable& poses, const py::object& F, bool& planar) {
  std::vector<py::object> given;
  for (const py::handle pose : poses) given.push_back(py::reinterpret_borrow<py::object>(pose));
  planar = !given.empty() && !is_space_points(given.front());
  std::vector<Eigen::Matrix3Xd> points;
  std::vector<std::string> names;
  for (const py::object& pose : given) {
    names.push_back("poses[" + std::to_string(points.size()) + "]");
    if (!planar) {
      points.push_back(points3(pose, names.back()));
      continue;
    }
    const Eigen::Matrix2Xd xy = python::points(pose, names.back());
    points.emplace_back(Eigen::Matrix3Xd::Zero(3, xy.cols()));
    points.back().topRows<2>() = xy;
  }
  const Eigen::MatrixXi elements3 = elements(F, "F", !planar);
  std::vector<global3::Mesh3> meshes;
  for (Eigen::Matrix3Xd& pose : points) meshes.push_back({std::move(pose), elements3});
  if (meshes.size() < 2) value_error("poses: at least two poses are needed, got " + std::to_string(meshes.size()));
  check_meshes3(meshes, names);
  return meshes;
}

global3::Blend3Options blend_options(const std::string& rotation_branch, bool area_weighted, int arap_iterations) {
  global3::Blend3Options options;
  options.rotation_branch = global::parse_option<global::RotationBranch>(rotation_branch);
  options.area_weighted = area_weighted, options.arap_iterations = arap_iterations;
  return options;
}

py::array_t<double> frame_points(Eigen::Matrix3Xd&& v, bool planar) {
  if (planar) return to_points(Eigen::Matrix2Xd(v.topRows<2>()));
  return to_points(std::move(v));
}

SpaceInterpolation::SpaceInterpolation(const py::object& V0, const py::object& V1, const py::object& F,
                                       const SpaceKeywords& keywords)
    : time_range_(keywords.time_range) {
  const global3::Mesh3 source{points3(V0, "V0"), elements(F, "F")}, target{points3(V1, "V1"), source.elements};
  check_meshes3({source, target}, {"V0", "V1"});
  if (!(time_range_.first <= time_range_.second)) value_error("time_range: expected t0 <= t1");
  const global3::Interpolation3Options options = options3(keywords, source.vertex_count());
  engine_ = translated([&] { return std::make_unique<global3::Interpolation3>(source, target, options); });
  vertex_count_ = source.vertex_count();
  source_ = source, target_ = target;
}

void SpaceInterpolation::check_time(double t) const {
  if (!(t >= time_range_.first && t <= time_range_.second))
    throw std::invalid_argument("t = " + std::to_string(t) + " lies outside time_range");
}

py::array_t<double> SpaceInterpolation::vertices_at(double t) const {
  check_time(t);
  Eigen::Matrix3Xd v;
  {
    py::gil_scoped_release unlocked;
    v = translated([&] { return engine_->vertices_at(t); });
  }
  return to_points(std::move(v));
}

py::array_t<double> SpaceInterpolation::frames(const py::object& times) const {
  const std::vector<double> ts = reals(times, "times");
  for (const double t : ts) check_time(t);
  std::vector<Eigen::Matrix3Xd> frames;
  {
    py::gil_scoped_release unlocked;
    frames = translated([&] { return engine_->vertices_at(ts); });
  }
  return stacked(frames, vertex_count_, 3);
}

double SpaceInterpolation::energy_at(double t) const {
  check_time(t);
  py::gil_scoped_release unlocked;
  return translated([&] { return engine_->energy_at(t, engine_->vertices_at(t)); });
}

py::object SpaceInterpolation::metrics_at(double t) const {
  check_time(t);
  nlohmann::json entry;
  {
    py::gil_scoped_release unlocked;
    std::call_once(folds_found_, [&] {
      const std::vector<Eigen::Index> folds = global3::target_folds(source_, target_);
      if (!folds.empty()) near_folds_ = global3::near_folds(source_, folds);
    });
    translated([&] {
      const Eigen::Matrix3Xd v = engine_->vertices_at(t);
      entry = {{"t", t}, {"energy", io::finite_or_null(engine_->energy_at(t, v))}};
      entry.update(io::metrics3_json(global3::frame_metrics3(source_, v, engine_->local_maps_at(t), near_folds_),
                                     !near_folds_.empty()));
    });
  }
  return dict_of(entry);
}

py::array_t<double> SpaceInterpolation::rotation_logs() const {
  return to_points(Eigen::Matrix3Xd(engine_->rotation_logs()));
}

py::tuple SpaceInterpolation::rotation_split() const {
  const global3::RotationSplit3& split = engine_->rotation_split();
  return py::make_tuple(to_points(Eigen::Matrix3Xd(split.carrier)), to_points(Eigen::Matrix3Xd(split.remainder)));
}

void bind_blend(py::module_& m) {
  py::class_<SpaceBlend>(m, "Blend",
                         R"(N-way blend of K >= 2 compatible poses, in space or in the plane (Kaji et al.'s Lie-algebra
parametrisation): each element's map exp(sum_k w_k log R_k) exp(sum_k w_k log S_k) from poses[0] (on the
consistent branch each log R_k split into its smoothed carrier and remainder, exp(sum_k w_k carrier_k)
exp(sum_k w_k remainder_k)), then the vertices minimising E^F against these maps, one factorisation for all weight
vectors.

  poses                a sequence of K (n, 3) float arrays, or K (n, 2) ones for poses in the plane (frames (n, 2);
                       two poses at weights (1 - t, t) give Interpolation's energy='F' frames)
  F                    (m, 3) triangles or (m, 4) tetrahedra (0-based), shared by the poses
  allow_extrapolation  accept weights off the simplex (a negative entry, or a sum other than 1)
  rotation_branch      'consistent' (logarithms consistent over neighbours) or 'principal'
  area_weighted        weigh each element by its rest area or volume
  arap_iterations      as-rigid-as-possible steps on each frame (as Interpolation's)
Bad input raises ValueError with a one-line message.)")
      .def(py::init<const py::iterable&, const py::object&, bool, const std::string&, bool, int>(), py::arg("poses"),
           py::arg("F"), py::kw_only(), py::arg("allow_extrapolation") = false,
           py::arg("rotation_branch") = global::to_string(global3::Blend3Options{}.rotation_branch),
           py::arg("area_weighted") = true, py::arg("arap_iterations") = global3::Blend3Options{}.arap_iterations)
      .def("vertices_at", &SpaceBlend::vertices_at, py::arg("w"),
           "The blend for weights w: shape (K,) gives (n, 3), shape (frames, K) gives (frames, n, 3). ValueError "
           "for a wrong count or, without allow_extrapolation, weights off the simplex.")
      .def("metrics_at", &SpaceBlend::metrics_at, py::arg("w"),
           "The blend for weights w (shape (K,))'s entry of `affinterp blend`'s metrics.json as a dict: weights, "
           "inverted_elements, min_ratio, max_ratio, max_distortion, mean_distortion, measure_ratio, and "
           "inverted_near_folds when a surface pose folds triangles within the surface against the first; None "
           "where not finite.");
}

}  // namespace affinterp::python
