#include "experiments/measurements/engine3_closeup.hpp"

#include "plots/mesh3/mesh3_figures.hpp"
#include "theory/global3/frame_metrics3.hpp"
#include "theory/global3/target_folds3.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace affinterp::measurements {

namespace {

using Eigen::Index;
using plots::FaceMark;

/// The triangles whose corners all lie within `rings` vertex rings of triangle `centre`'s corners, increasing.
std::vector<Index> piece_around(const Eigen::Matrix3Xi& triangles, Index vertex_count, Index centre, int rings) {
  std::vector<unsigned char> inside(static_cast<std::size_t>(vertex_count), 0);
  for (int c = 0; c < 3; ++c) inside[static_cast<std::size_t>(triangles(c, centre))] = 1;
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<unsigned char> grown = inside;
    for (Index i = 0; i < triangles.cols(); ++i) {
      const auto corner = [&](int c) { return static_cast<std::size_t>(triangles(c, i)); };
      if (inside[corner(0)] || inside[corner(1)] || inside[corner(2)])
        grown[corner(0)] = grown[corner(1)] = grown[corner(2)] = 1;
    }
    inside = std::move(grown);
  }
  std::vector<Index> piece;
  for (Index i = 0; i < triangles.cols(); ++i)
    if (inside[static_cast<std::size_t>(triangles(0, i))] && inside[static_cast<std::size_t>(triangles(1, i))] &&
        inside[static_cast<std::size_t>(triangles(2, i))])
      piece.push_back(i);
  return piece;
}

Eigen::MatrixXd matrix_of(const nlohmann::json& columns, Index rows) {
  Eigen::MatrixXd m(rows, static_cast<Index>(columns.size()));
  for (Index j = 0; j < m.cols(); ++j)
    for (Index r = 0; r < rows; ++r) m(r, j) = columns.at(static_cast<std::size_t>(j)).at(static_cast<std::size_t>(r));
  return m;
}

template <class Matrix>
nlohmann::json columns_of(const Matrix& m) {
  nlohmann::json columns = nlohmann::json::array();
  for (Index j = 0; j < m.cols(); ++j) {
    nlohmann::json column = nlohmann::json::array();
    for (Index r = 0; r < m.rows(); ++r) column.push_back(m(r, j));
    columns.push_back(std::move(column));
  }
  return columns;
}

std::vector<int> numbers_of(const std::vector<FaceMark>& marks) {
  std::vector<int> numbers;
  for (const FaceMark mark : marks) numbers.push_back(static_cast<int>(mark));
  return numbers;
}

std::vector<FaceMark> marks_of(const nlohmann::json& numbers) {
  std::vector<FaceMark> marks;
  for (const int n : numbers.get<std::vector<int>>()) {
    if (n < 0 || n > static_cast<int>(FaceMark::inverted)) throw std::runtime_error("closeup: a mark out of range");
    marks.push_back(static_cast<FaceMark>(n));
  }
  return marks;
}

}  // namespace

std::optional<Engine3Closeup> closeup_of_frame(const std::string& pair, const global3::Mesh3& source,
                                               const global3::Mesh3& target, double t, const Eigen::Matrix3Xd& frame,
                                               std::span<const Eigen::Matrix3d> local_maps, int rings) {
  if (source.kind() != global3::ElementKind::triangle) return std::nullopt;
  const std::vector<Index> folds = global3::target_folds(source, target);
  const std::vector<unsigned char> near = global3::near_folds(source, folds);
  const global3::FrameMetrics3 metrics = global3::frame_metrics3(source, frame, local_maps, near);
  if (metrics.inverted.empty()) return std::nullopt;
  const auto away = std::find_if(metrics.inverted.begin(), metrics.inverted.end(),
                                 [&](Index i) { return !near[static_cast<std::size_t>(i)]; });
  Engine3Closeup closeup;
  closeup.pair = pair, closeup.t = t;
  closeup.inverted = static_cast<long>(metrics.inverted_elements);
  closeup.inverted_away = static_cast<long>(metrics.inverted_elements - metrics.inverted_near_folds);
  closeup.centre = static_cast<long>(away != metrics.inverted.end() ? *away : metrics.inverted.front());

  const std::vector<Index> piece = piece_around(source.elements, source.vertex_count(), closeup.centre, rings);
  std::vector<int> local(static_cast<std::size_t>(source.vertex_count()), -1);
  std::vector<Index> used;
  closeup.triangles.resize(3, static_cast<Index>(piece.size()));
  for (std::size_t k = 0; k < piece.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      int& v = local[static_cast<std::size_t>(source.elements(c, piece[k]))];
      if (v < 0) v = static_cast<int>(used.size()), used.push_back(source.elements(c, piece[k]));
      closeup.triangles(c, static_cast<Index>(k)) = v;
    }
  const auto restricted = [&](const Eigen::Matrix3Xd& all) {
    Eigen::Matrix3Xd out(3, static_cast<Index>(used.size()));
    for (std::size_t j = 0; j < used.size(); ++j) out.col(static_cast<Index>(j)) = all.col(used[j]);
    return out;
  };
  closeup.source = restricted(source.vertices), closeup.frame = restricted(frame);
  closeup.target = restricted(target.vertices);

  std::vector<unsigned char> fold(static_cast<std::size_t>(source.element_count()), 0), inverted(fold);
  for (const Index i : folds) fold[static_cast<std::size_t>(i)] = 1;
  for (const Index i : metrics.inverted) inverted[static_cast<std::size_t>(i)] = 1;
  for (const Index i : piece) {
    const auto at = static_cast<std::size_t>(i);
    const FaceMark in_input = fold[at] ? FaceMark::fold : FaceMark::none;
    closeup.fold_marks.push_back(in_input);
    closeup.frame_marks.push_back(!inverted[at] ? in_input
                                  : near[at]    ? FaceMark::inverted_near_fold
                                                : FaceMark::inverted);
  }
  return closeup;
}

std::vector<std::string> draw_engine3_closeup(const claims::RunSettings& settings, const Engine3Closeup& closeup) {
  std::ostringstream frame_label;
  frame_label << "frame at t = " << std::setprecision(3) << closeup.t;
  const std::vector<plots::MarkedPatch> patches{{closeup.source, closeup.fold_marks, "source"},
                                                {closeup.frame, closeup.frame_marks, frame_label.str()},
                                                {closeup.target, closeup.fold_marks, "target"}};
  return claims::RunSettings::figure_refs(
      plots::draw_patches3(settings.figure_stem("sequel-3d-inversion-closeup"), closeup.triangles, patches,
                           {{FaceMark::fold, "a fold of the target"},
                            {FaceMark::inverted_near_fold, "inverted, at or beside a fold"},
                            {FaceMark::inverted, "inverted, away from the folds"}},
                           closeup.pair + ", exp-log E^F: " + std::to_string(closeup_rings) +
                               " vertex rings around triangle " + std::to_string(closeup.centre)));
}

void to_json(nlohmann::json& json, const Engine3Closeup& closeup) {
  json = {{"pair", closeup.pair},
          {"t", closeup.t},
          {"inverted", closeup.inverted},
          {"inverted_away", closeup.inverted_away},
          {"centre", closeup.centre},
          {"triangles", columns_of(closeup.triangles)},
          {"source", columns_of(closeup.source)},
          {"frame", columns_of(closeup.frame)},
          {"target", columns_of(closeup.target)},
          {"fold_marks", numbers_of(closeup.fold_marks)},
          {"frame_marks", numbers_of(closeup.frame_marks)}};
}

void from_json(const nlohmann::json& json, Engine3Closeup& closeup) {
  closeup.pair = json.at("pair"), closeup.t = json.at("t");
  closeup.inverted = json.at("inverted"), closeup.inverted_away = json.at("inverted_away");
  closeup.centre = json.at("centre");
  closeup.triangles = matrix_of(json.at("triangles"), 3).cast<int>();
  closeup.source = matrix_of(json.at("source"), 3), closeup.frame = matrix_of(json.at("frame"), 3);
  closeup.target = matrix_of(json.at("target"), 3);
  closeup.fold_marks = marks_of(json.at("fold_marks"));
  closeup.frame_marks = marks_of(json.at("frame_marks"));
}

}  // namespace affinterp::measurements
