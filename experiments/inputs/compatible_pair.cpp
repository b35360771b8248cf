#include "experiments/inputs/compatible_pair.hpp"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <numbers>
#include <optional>
#include <set>

namespace affinterp::io {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;  // exact predicates on doubles
using EK = CGAL::Exact_predicates_exact_constructions_kernel;   // exact constructions (the overlay)
using Triangle = std::array<int, 3>;
using Triangles = std::vector<Triangle>;

K::Point_2 point(const Eigen::Matrix2Xd& v, Eigen::Index i) { return {v(0, i), v(1, i)}; }

bool positive(const Eigen::Matrix2Xd& v, const Triangle& t) {
  return CGAL::orientation(point(v, t[0]), point(v, t[1]), point(v, t[2])) == CGAL::LEFT_TURN;
}

bool all_positive(const Eigen::Matrix2Xd& v, const Triangles& triangles) {
  return std::all_of(triangles.begin(), triangles.end(), [&](const Triangle& t) { return positive(v, t); });
}

/// The smallest angle of triangle t in v, in radians.
double min_angle(const Eigen::Matrix2Xd& v, const Triangle& t) {
  double smallest = std::numbers::pi;
  for (int c = 0; c < 3; ++c) {
    const Eigen::Vector2d e1 = v.col(t[(c + 1) % 3]) - v.col(t[c]), e2 = v.col(t[(c + 2) % 3]) - v.col(t[c]);
    smallest = std::min(smallest, std::atan2(std::abs(e1.x() * e2.y() - e1.y() * e2.x()), e1.dot(e2)));
  }
  return smallest;
}

double min_angle(const Eigen::Matrix2Xd& v, const Triangles& triangles) {
  double smallest = std::numbers::pi;
  for (const Triangle& t : triangles) smallest = std::min(smallest, min_angle(v, t));
  return smallest;
}

/// Throws OutlineError unless `v` is a simple polygon: at least 3 finite, distinct vertices; adjacent edges
/// that do not fold back onto each other; non-adjacent edges that do not meet.
void check_simple(const Eigen::Matrix2Xd& v, const std::string& name) {
  const int n = static_cast<int>(v.cols());
  if (n < 3) throw OutlineError(name + ": " + std::to_string(n) + " vertices; a polygon needs at least 3");
  for (int i = 0; i < n; ++i)
    if (!v.col(i).allFinite()) throw OutlineError(name + ": vertex " + std::to_string(i) + " is not finite");
  std::map<std::pair<double, double>, int> seen;
  for (int i = 0; i < n; ++i)
    if (const auto [it, fresh] = seen.emplace(std::pair{v(0, i), v(1, i)}, i); !fresh)
      throw OutlineError(name + ": not a simple polygon: vertices " + std::to_string(it->second) + " and " +
                         std::to_string(i) + " coincide");
  const auto edge = [&](int i) { return K::Segment_2(point(v, i), point(v, (i + 1) % n)); };
  const auto edge_name = [&](int i) { return std::to_string(i) + "-" + std::to_string((i + 1) % n); };
  for (int i = 0; i < n; ++i) {
    const K::Point_2 a = point(v, i), b = point(v, (i + 1) % n), c = point(v, (i + 2) % n);
    if (CGAL::collinear(a, b, c) && !CGAL::collinear_are_ordered_along_line(a, b, c))
      throw OutlineError(name + ": not a simple polygon: edges " + edge_name(i) + " and " + edge_name((i + 1) % n) +
                         " overlap (the outline turns back on itself)");
  }
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j)
      if (!(i == 0 && j == n - 1) && CGAL::do_intersect(edge(i), edge(j)))
        throw OutlineError(name + ": not a simple polygon: edges " + edge_name(i) + " and " + edge_name(j) + " meet");
}

/// A triangulation of the counter-clockwise simple polygon v by its own vertices (constrained Delaunay),
/// each triangle with ascending indices: counter-clockwise in v and on any convex polygon numbered alike.
Triangles triangulate_polygon(const Eigen::Matrix2Xd& v) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<int, K>>;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb, Fb>,
                                                         CGAL::No_constraint_intersection_tag>;
  const int n = static_cast<int>(v.cols());
  CDT cdt;
  std::vector<CDT::Vertex_handle> corners;
  for (int i = 0; i < n; ++i) corners.push_back(cdt.insert(point(v, i))), corners.back()->info() = i;
  for (int i = 0; i < n; ++i) cdt.insert_constraint(corners[i], corners[(i + 1) % n]);
  // Outside: the faces reached from the infinite face without crossing the outline.
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = 1;
  std::deque<CDT::Face_handle> queue{cdt.infinite_face()};
  cdt.infinite_face()->info() = 0;
  while (!queue.empty()) {
    const CDT::Face_handle f = queue.front();
    queue.pop_front();
    for (int e = 0; e < 3; ++e) {
      const CDT::Face_handle g = f->neighbor(e);
      if (g->info() == 1 && !cdt.is_constrained({f, e})) g->info() = 0, queue.push_back(g);
    }
  }
  Triangles triangles;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() == 0) continue;
    Triangle t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::sort(t.begin(), t.end());
    triangles.push_back(t);
  }
  if (static_cast<int>(triangles.size()) != n - 2)
    throw std::logic_error("triangulate_polygon: " + std::to_string(triangles.size()) + " triangles for " +
                           std::to_string(n) + " vertices");
  return triangles;
}

/// The common refinement of T_P and T_Q over the convex domain, mapped to P and Q exactly (see the header).
struct Refinement {
  Triangles triangles;
  std::vector<EK::Point_2> in_source, in_target;  ///< by vertex index
};

/// Affine map φ of triangle t from the domain to `shape`, at the domain point p.
EK::Point_2 affine_image(const std::vector<EK::Point_2>& domain, const Eigen::Matrix2Xd& shape, const Triangle& t,
                         const EK::Point_2& p) {
  const EK::Point_2 &a = domain[t[0]], &b = domain[t[1]], &c = domain[t[2]];
  const EK::FT area = CGAL::area(a, b, c);
  const std::array<EK::FT, 3> lambda{CGAL::area(p, b, c) / area, CGAL::area(a, p, c) / area,
                                     CGAL::area(a, b, p) / area};
  EK::FT x = 0, y = 0;
  for (int c2 = 0; c2 < 3; ++c2) x += lambda[c2] * shape(0, t[c2]), y += lambda[c2] * shape(1, t[c2]);
  return {x, y};
}

/// The triangle of `triangles` whose interior holds p (on the domain).
const Triangle& containing(const std::vector<EK::Point_2>& domain, const Triangles& triangles, const EK::Point_2& p) {
  for (const Triangle& t : triangles)
    if (CGAL::orientation(domain[t[0]], domain[t[1]], p) == CGAL::LEFT_TURN &&
        CGAL::orientation(domain[t[1]], domain[t[2]], p) == CGAL::LEFT_TURN &&
        CGAL::orientation(domain[t[2]], domain[t[0]], p) == CGAL::LEFT_TURN)
      return t;
  throw std::logic_error("overlay: a face lies in no triangle");
}

Refinement overlay(const Eigen::Matrix2Xd& P, const Eigen::Matrix2Xd& Q, const Triangles& TP, const Triangles& TQ) {
  using Traits = CGAL::Arr_segment_traits_2<EK>;
  using Arrangement = CGAL::Arrangement_2<Traits>;
  const int n = static_cast<int>(P.cols());
  std::vector<EK::Point_2> domain;
  std::map<std::pair<double, double>, int> domain_index;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * i / n;
    domain.emplace_back(std::cos(angle), std::sin(angle));
    domain_index[{std::cos(angle), std::sin(angle)}] = i;
  }
  for (int i = 0; i < n; ++i)
    if (CGAL::orientation(domain[i], domain[(i + 1) % n], domain[(i + 2) % n]) != CGAL::LEFT_TURN)
      throw OutlineError("the outlines have too many vertices (" + std::to_string(n) +
                         ") for a strictly convex domain in double precision");
  std::set<std::pair<int, int>> edges;
  for (int i = 0; i < n; ++i) edges.insert(std::minmax(i, (i + 1) % n));
  for (const Triangles* T : {&TP, &TQ})
    for (const Triangle& t : *T)
      for (int c = 0; c < 3; ++c) edges.insert(std::minmax(t[c], t[(c + 1) % 3]));
  std::vector<Traits::Curve_2> segments;
  for (const auto& [i, j] : edges) segments.emplace_back(domain[i], domain[j]);
  Arrangement arrangement;
  CGAL::insert(arrangement, segments.begin(), segments.end());

  Refinement r;
  r.in_source.resize(n), r.in_target.resize(n);
  for (int i = 0; i < n; ++i) r.in_source[i] = {P(0, i), P(1, i)}, r.in_target[i] = {Q(0, i), Q(1, i)};
  std::vector<bool> placed(n, true);
  std::map<Arrangement::Vertex_const_handle, int> index;
  const auto vertex_index = [&](Arrangement::Vertex_const_handle v) {
    if (const auto it = index.find(v); it != index.end()) return it->second;
    const EK::Point_2& p = v->point();
    const auto known = domain_index.find({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
    int id;
    if (known != domain_index.end() && domain[known->second] == p) {
      id = known->second;
    } else {
      id = static_cast<int>(domain.size());
      domain.push_back(p), r.in_source.emplace_back(), r.in_target.emplace_back(), placed.push_back(false);
    }
    return index[v] = id;
  };
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
    if (f->is_unbounded()) continue;
    std::vector<int> ring;  // counter-clockwise: the face lies left of its outer boundary
    auto edge = f->outer_ccb();
    const auto first = edge;
    do ring.push_back(vertex_index(edge->target()));
    while (++edge != first);
    const int k = static_cast<int>(ring.size());
    EK::FT gx = 0, gy = 0;
    for (int id : ring) gx += domain[id].x(), gy += domain[id].y();
    const EK::Point_2 g(gx / k, gy / k);  // strictly inside the convex face
    const Triangle &tp = containing(domain, TP, g), &tq = containing(domain, TQ, g);
    // Triangulate the face: a fan from a corner whose triangles are all proper, else from g.
    std::optional<int> apex;
    for (int a = 0; a < k && !apex; ++a) {
      bool proper = true;
      for (int i = 1; i + 1 < k && proper; ++i)
        proper = CGAL::orientation(domain[ring[a]], domain[ring[(a + i) % k]], domain[ring[(a + i + 1) % k]]) ==
                 CGAL::LEFT_TURN;
      if (proper) apex = a;
    }
    if (apex) {
      for (int i = 1; i + 1 < k; ++i)
        r.triangles.push_back({ring[*apex], ring[(*apex + i) % k], ring[(*apex + i + 1) % k]});
    } else {
      const int centre = static_cast<int>(domain.size());
      domain.push_back(g), r.in_source.emplace_back(), r.in_target.emplace_back(), placed.push_back(false);
      ring.push_back(centre);
      for (int i = 0; i < k; ++i) r.triangles.push_back({centre, ring[i], ring[(i + 1) % k]});
    }
    for (int id : ring)
      if (!placed[id]) {
        r.in_source[id] = affine_image(domain, P, tp, domain[id]);
        r.in_target[id] = affine_image(domain, Q, tq, domain[id]);
        placed[id] = true;
      }
  }
  return r;
}

Eigen::Matrix2Xd rounded(const std::vector<EK::Point_2>& points) {
  Eigen::Matrix2Xd v(2, static_cast<Eigen::Index>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k)
    v.col(static_cast<Eigen::Index>(k)) << CGAL::to_double(CGAL::exact(points[k].x())),
        CGAL::to_double(CGAL::exact(points[k].y()));
  return v;
}

/// Flips edges that are strictly convex quadrilaterals in both shapes where the smaller smallest angle of the
/// two triangles, over both shapes, grows. Returns the number of flips.
int flip_pass(const Eigen::Matrix2Xd& P, const Eigen::Matrix2Xd& Q, Triangles& triangles) {
  std::map<std::pair<int, int>, std::vector<int>> by_edge;
  for (int i = 0; i < static_cast<int>(triangles.size()); ++i)
    for (int c = 0; c < 3; ++c) by_edge[std::minmax(triangles[i][c], triangles[i][(c + 1) % 3])].push_back(i);
  std::vector<bool> touched(triangles.size(), false);
  const auto quality = [&](const Triangle& s, const Triangle& t) {
    return std::min({min_angle(P, s), min_angle(P, t), min_angle(Q, s), min_angle(Q, t)});
  };
  int flips = 0;
  for (const auto& [edge, owners] : by_edge) {
    if (owners.size() != 2 || touched[owners[0]] || touched[owners[1]]) continue;
    const Triangle &s = triangles[owners[0]], &t = triangles[owners[1]];
    const auto opposite = [&](const Triangle& x) {
      for (int c = 0; c < 3; ++c)
        if (x[c] != edge.first && x[c] != edge.second) return c;
      return 0;
    };
    const int cs = opposite(s), ct = opposite(t);
    // s = (c, a, b) counter-clockwise with the edge a-b, t = (d, b, a): the flip gives (c, a, d) and (c, d, b).
    const int c = s[cs], a = s[(cs + 1) % 3], b = s[(cs + 2) % 3], d = t[ct];
    const Triangle s2{c, a, d}, t2{c, d, b};
    if (!positive(P, s2) || !positive(P, t2) || !positive(Q, s2) || !positive(Q, t2)) continue;
    if (!(quality(s2, t2) > quality(s, t))) continue;
    triangles[owners[0]] = s2, triangles[owners[1]] = t2;
    touched[owners[0]] = touched[owners[1]] = true;
    ++flips;
  }
  return flips;
}

/// Moves each interior vertex (index ≥ n) of v towards the centroid of its neighbours when every incident
/// triangle stays positive and their smallest angle grows.
void smooth_pass(Eigen::Matrix2Xd& v, const Triangles& triangles, int n) {
  std::vector<std::vector<int>> incident(static_cast<std::size_t>(v.cols()));
  for (int i = 0; i < static_cast<int>(triangles.size()); ++i)
    for (int c = 0; c < 3; ++c) incident[triangles[i][c]].push_back(i);
  for (int k = n; k < v.cols(); ++k) {
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    int count = 0;
    double before = std::numbers::pi;
    for (int i : incident[k]) {
      before = std::min(before, min_angle(v, triangles[i]));
      for (int c = 0; c < 3; ++c)
        if (triangles[i][c] != k) centroid += v.col(triangles[i][c]), ++count;
    }
    const Eigen::Vector2d old = v.col(k);
    v.col(k) = centroid / count;
    double after = std::numbers::pi;
    bool proper = true;
    for (int i : incident[k])
      proper = proper && positive(v, triangles[i]), after = std::min(after, min_angle(v, triangles[i]));
    if (!proper || !(after > before)) v.col(k) = old;
  }
}

}  // namespace

CompatiblePair compatible_pair(const Eigen::Matrix2Xd& source, const Eigen::Matrix2Xd& target,
                               const std::string& source_name, const std::string& target_name, int quality_passes) {
  check_simple(source, source_name);
  check_simple(target, target_name);
  const int n = static_cast<int>(source.cols());
  if (target.cols() != n)
    throw OutlineError(source_name + " has " + std::to_string(n) + " vertices but " + target_name + " has " +
                       std::to_string(target.cols()) + " (the i-th vertices correspond; or resample both)");
  const auto orientation = [](const Eigen::Matrix2Xd& v) {
    CGAL::Polygon_2<K> polygon;
    for (Eigen::Index i = 0; i < v.cols(); ++i) polygon.push_back(point(v, i));
    return polygon.orientation();
  };
  const CGAL::Orientation so = orientation(source), to = orientation(target);
  if (so != to)
    throw OutlineError(source_name + " runs " + (so == CGAL::COUNTERCLOCKWISE ? "counter-clockwise" : "clockwise") +
                       " but " + target_name + " the other way: no orientation-preserving correspondence");
  // Work counter-clockwise: a clockwise pair is numbered backwards, and renumbered at the end.
  const bool backwards = so == CGAL::CLOCKWISE;
  const auto ccw = [&](const Eigen::Matrix2Xd& v) { return backwards ? Eigen::Matrix2Xd(v.rowwise().reverse()) : v; };
  const Eigen::Matrix2Xd P = ccw(source), Q = ccw(target);

  const Triangles TP = triangulate_polygon(P), TQ = triangulate_polygon(Q);
  Triangles triangles;
  Eigen::Matrix2Xd VP, VQ;
  const bool TP_fits = all_positive(Q, TP), TQ_fits = all_positive(P, TQ);
  if (TP_fits || TQ_fits) {  // one triangulation serves both: no Steiner points
    const auto score = [&](const Triangles& T) { return std::min(min_angle(P, T), min_angle(Q, T)); };
    triangles = TP_fits && (!TQ_fits || score(TP) >= score(TQ)) ? TP : TQ;
    VP = P, VQ = Q;
  } else {
    const Refinement r = overlay(P, Q, TP, TQ);
    triangles = r.triangles;
    VP = rounded(r.in_source), VQ = rounded(r.in_target);
    for (std::size_t i = 0; i < triangles.size(); ++i)
      if (!positive(VP, triangles[i]) || !positive(VQ, triangles[i]))
        throw OutlineError("triangle " + std::to_string(i) +
                           " of the common refinement is proper in exact arithmetic but flattened by rounding its "
                           "vertices to doubles; scale the outlines up or resample them");
  }
  for (int pass = 0; pass < quality_passes; ++pass) {
    const int flips = flip_pass(VP, VQ, triangles);
    smooth_pass(VP, triangles, n);
    smooth_pass(VQ, triangles, n);
    if (flips == 0 && VP.cols() == n) break;
  }
  if (!all_positive(VP, triangles) || !all_positive(VQ, triangles))
    throw std::logic_error("compatible_pair: a flipped triangle after the quality passes");

  CompatiblePair pair;
  pair.steiner_vertices = static_cast<int>(VP.cols()) - n;
  pair.source_min_angle = min_angle(VP, triangles) * 180 / std::numbers::pi;
  pair.target_min_angle = min_angle(VQ, triangles) * 180 / std::numbers::pi;
  const auto renumbered = [&](int k) { return backwards && k < n ? n - 1 - k : k; };
  global::Mesh mesh;
  mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (int c = 0; c < 3; ++c) mesh.triangles(c, static_cast<Eigen::Index>(i)) = renumbered(triangles[i][c]);
  pair.source = pair.target = mesh;
  pair.source.vertices.resize(2, VP.cols()), pair.target.vertices.resize(2, VQ.cols());
  for (Eigen::Index k = 0; k < VP.cols(); ++k)
    pair.source.vertices.col(renumbered(static_cast<int>(k))) = VP.col(k),
    pair.target.vertices.col(renumbered(static_cast<int>(k))) = VQ.col(k);
  return pair;
}

Eigen::Matrix2Xd resample_outline(const Eigen::Matrix2Xd& outline, int n) {
  const Eigen::Index m = outline.cols();
  if (n < 3) throw OutlineError("resample: at least 3 vertices, not " + std::to_string(n));
  if (m < 2) throw OutlineError("resample: the outline has " + std::to_string(m) + " vertices");
  std::vector<double> at{0.0};  // arc length at each vertex, closing edge included
  for (Eigen::Index i = 0; i < m; ++i) at.push_back(at.back() + (outline.col((i + 1) % m) - outline.col(i)).norm());
  const double length = at.back();
  if (!(length > 0) || !std::isfinite(length)) throw OutlineError("resample: the outline has no length");
  Eigen::Matrix2Xd out(2, n);
  Eigen::Index edge = 0;
  for (int k = 0; k < n; ++k) {
    const double s = length * k / n;
    while (edge + 1 < m && at[edge + 1] <= s) ++edge;
    const double span = at[edge + 1] - at[edge], u = span > 0 ? (s - at[edge]) / span : 0.0;
    out.col(k) = (1 - u) * outline.col(edge) + u * outline.col((edge + 1) % m);
  }
  return out;
}

}  // namespace affinterp::io
