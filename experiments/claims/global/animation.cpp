#include "experiments/claims/global/animation.hpp"

#include "plots/figure.hpp"
#include "plots/gnuplot_process.hpp"
#include "plots/mesh_overlay.hpp"
#include "plots/mesh_strip.hpp"
#include "plots/viewer.hpp"
#include "theory/global/locus.hpp"

#include <algorithm>
#include <cstdio>

namespace affinterp::claims::global_figures {

Eigen::Index Animation::most_flips() const {
  Eigen::Index most = 0;
  for (const auto& m : metrics) most = std::max(most, m.flipped_triangles);
  return most;
}

double Animation::min_det() const {
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& m : metrics) smallest = std::min(smallest, m.min_det);
  return smallest;
}

Animation animate(const std::string& label, const global::Mesh& source, const global::Interpolation& interpolation,
                  int count) {
  Animation animation{label, {}, {}, {}, {}};
  for (int k = 0; k < count; ++k) {
    const double t = static_cast<double>(k) / (count - 1);
    animation.t.push_back(t);
    animation.frames.push_back(interpolation.vertices_at(t));
    animation.metrics.push_back(global::frame_metrics(source, animation.frames.back()));
    animation.energy.push_back(interpolation.energy_at(t, animation.frames.back()).total);
  }
  return animation;
}

Eigen::Index extreme_vertex(const global::Mesh& mesh, const Eigen::Vector2d& direction) {
  Eigen::Index best = 0;
  for (Eigen::Index k = 1; k < mesh.vertex_count(); ++k)
    if (direction.dot(mesh.vertices.col(k)) > direction.dot(mesh.vertices.col(best))) best = k;
  return best;
}

std::vector<std::string> draw_animations(const RunSettings& ctx, const std::string& name, const global::Mesh& source,
                                         const std::vector<Animation>& animations, const std::vector<int>& shown_frames,
                                         const std::string& title) {
  std::vector<std::string> refs;
  for (std::size_t a = 0; a < animations.size(); ++a) {
    std::vector<plots::MeshFrame> frames;
    for (const int k : shown_frames) {
      char label[32];
      std::snprintf(label, sizeof label, "t = %.2f", animations[a].t[static_cast<std::size_t>(k)]);
      frames.push_back({animations[a].frames[static_cast<std::size_t>(k)], label});
    }
    const std::string stem = name + "-" + std::to_string(a + 1);
    for (const auto& file :
         plots::draw_filmstrip(ctx.figure_stem(stem), source.triangles, frames, title + ": " + animations[a].label))
      if (file.ends_with(".png"))
        refs.push_back(RunSettings::figure_ref(std::filesystem::path(file).filename().string()));
  }
  plots::Table table;
  for (std::size_t k = 0; k < animations.front().t.size(); ++k) {
    plots::Row row{animations.front().t[k]};
    for (const auto& animation : animations)
      row.push_back(animation.metrics[k].min_det),
          row.push_back(static_cast<double>(animation.metrics[k].flipped_triangles));
    table.push_back(row);
  }
  std::string plot_det = "plot ", plot_flips = "plot ";
  for (std::size_t a = 0; a < animations.size(); ++a) {
    const std::string sep = a + 1 < animations.size() ? ", " : "";
    plot_det += "$metrics using 1:" + std::to_string(2 + 2 * a) + " with linespoints title " +
                plots::gnuplot_string(animations[a].label) + sep;
    plot_flips += "$metrics using 1:" + std::to_string(3 + 2 * a) + " with linespoints title " +
                  plots::gnuplot_string(animations[a].label) + sep;
  }
  const auto files = plots::Figure(ctx.figure_stem(name + "-metrics"))
                         .size(1000, 420)
                         .data("metrics", table)
                         .script("set multiplot layout 1,2 title " + plots::gnuplot_string(title) +
                                 "\nset xlabel 't'\nset ylabel 'min_i det B_i(t)'\n" + plot_det +
                                 "\nset ylabel 'flipped triangles'\n" + plot_flips + "\nunset multiplot\n")
                         .render();
  for (const auto& file : files)
    if (file.ends_with(".png")) refs.push_back(RunSettings::figure_ref(file));
  // the same interpolations to scrub through, side by side on one slider, each with its energy E_t
  std::vector<plots::ViewerRun> runs;
  for (const Animation& animation : animations)
    runs.push_back(
        {animation.label, source, animation.t, animation.frames, animation.metrics, {{"E_t", animation.energy}}});
  plots::write_viewer(ctx.figure_stem(name + "-viewer.html"), title, runs);
  refs.push_back(RunSettings::figure_ref(name + "-viewer.html"));
  return refs;
}

double worst_locus_distance(const Animation& animation, const std::vector<global::VertexLocus>& loci) {
  double worst = 0;
  for (const auto& locus : loci) {
    const global::Locus u(locus.points);
    for (std::size_t k = 0; k < animation.t.size(); ++k)
      worst = std::max(worst, (animation.frames[k].col(locus.vertex) - u.at(animation.t[k])).norm());
  }
  return worst;
}

std::vector<std::string> draw_loci_overlays(const RunSettings& ctx, const std::string& name, const global::Mesh& source,
                                            const std::vector<Animation>& animations,
                                            const std::vector<global::VertexLocus>& loci,
                                            const std::vector<int>& shown_frames, const std::string& title) {
  std::vector<std::string> refs;
  for (std::size_t a = 0; a < animations.size(); ++a) {
    const Animation& animation = animations[a];
    std::vector<plots::MeshFrame> frames;
    for (const int k : shown_frames) frames.push_back({animation.frames[static_cast<std::size_t>(k)], ""});
    std::vector<plots::Curve> curves;
    for (std::size_t l = 0; l < loci.size(); ++l) {
      const bool first = l == 0;
      const global::Locus u(loci[l].points);
      Eigen::Matrix2Xd prescribed(2, 101), taken(2, static_cast<Eigen::Index>(animation.t.size()));
      for (Eigen::Index j = 0; j < prescribed.cols(); ++j) prescribed.col(j) = u.at(static_cast<double>(j) / 100);
      for (std::size_t k = 0; k < animation.t.size(); ++k)
        taken.col(static_cast<Eigen::Index>(k)) = animation.frames[k].col(loci[l].vertex);
      curves.push_back({prescribed, first ? "prescribed locus u_k(t)" : "", "with lines lc rgb '#e08000' lw 2.5"});
      curves.push_back({loci[l].points, first ? "its points" : "", "with points pt 7 ps 1.3 lc rgb '#e08000'"});
      curves.push_back({taken, first ? "path of v_k(t)" : "", "with lines lc rgb '#000000' lw 1.2 dt 2"});
    }
    const std::string stem = name + "-loci-" + std::to_string(a + 1);
    for (const auto& file : plots::draw_overlay(ctx.figure_stem(stem), source.triangles, frames, curves,
                                                title + ": " + animation.label + " (frames light to dark in time)"))
      if (file.ends_with(".png"))
        refs.push_back(RunSettings::figure_ref(std::filesystem::path(file).filename().string()));
  }
  return refs;
}

}  // namespace affinterp::claims::global_figures
