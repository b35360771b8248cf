#pragma once
// A region map: which points of a parameter plane satisfy a stated condition and which have the
// property the condition claims to characterise, with the disagreements in strong colours. Used for the
// "iff" theorems of the thesis (§2.2).
#include "plots/figure.hpp"

#include <string>
#include <vector>

namespace affinterp::plots {

struct RegionPoint {
  double x, y;
  bool condition;  ///< the stated condition holds
  bool property;   ///< the property holds (independent decision)
};

/// Draws the points to stem.png/.svg as coloured cells of half-width `dx` and half-height `dy` (half the
/// grid steps, so that the cells tile the plane); returns the file names.
inline std::vector<std::string> draw_region_map(const std::filesystem::path& stem, const std::string& title,
                                                const std::string& x_label, const std::string& y_label,
                                                const std::vector<RegionPoint>& points, double dx, double dy) {
  Table table;
  for (const RegionPoint& p : points)
    table.push_back({p.x, p.y, static_cast<double>(p.condition ? (p.property ? 0 : 2) : (p.property ? 3 : 1))});
  const std::string cell = "(" + std::to_string(dx) + "):(" + std::to_string(dy) + ")";
  const auto layer = [&](int category, const std::string& colour, const std::string& label) {
    return "$map using 1:($3 == " + std::to_string(category) + " ? $2 : 1/0):" + cell +
           " with boxxyerror fs solid 1.0 noborder lc rgb '" + colour + "' title '" + label + "'";
  };
  return Figure(stem)
      .size(1100, 720)
      .data("map", table)
      .script("set title '" + title + "'\nset xlabel '" + x_label + "'\nset ylabel '" + y_label +
              "'\nset key outside right center vertical box opaque\nset grid front\n"
              "plot " +
              layer(0, "#b8dcb0", "condition and property hold") + ", \\\n  " + layer(1, "#e6e6e6", "neither holds") +
              ", \\\n  " + layer(2, "#d7191c", "condition holds, property fails") + ", \\\n  " +
              layer(3, "#2c7bb6", "property holds, condition fails") + "\n")
      .render();
}

/// A region alone: where a condition holds (`condition`; `property` is not drawn), for a condition proved
/// exact elsewhere (the goodness atlas). Same cells and files as draw_region_map.
inline std::vector<std::string> draw_region(const std::filesystem::path& stem, const std::string& title,
                                            const std::string& x_label, const std::string& y_label,
                                            const std::string& inside_label, const std::vector<RegionPoint>& points,
                                            double dx, double dy) {
  Table table;
  for (const RegionPoint& p : points) table.push_back({p.x, p.y, p.condition ? 1.0 : 0.0});
  const std::string cell = "(" + std::to_string(dx) + "):(" + std::to_string(dy) + ")";
  const auto layer = [&](int category, const std::string& colour, const std::string& label) {
    return "$map using 1:($3 == " + std::to_string(category) + " ? $2 : 1/0):" + cell +
           " with boxxyerror fs solid 1.0 noborder lc rgb '" + colour + "' title '" + label + "'";
  };
  return Figure(stem)
      .size(1100, 720)
      .data("map", table)
      .script("set title '" + title + "'\nset xlabel '" + x_label + "'\nset ylabel '" + y_label +
              "'\nset key outside right center vertical box opaque\nset grid front\nplot " +
              layer(1, "#b8dcb0", inside_label) + ", \\\n  " + layer(0, "#e6e6e6", "outside") + "\n")
      .render();
}

}  // namespace affinterp::plots
