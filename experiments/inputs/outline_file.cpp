#include "experiments/inputs/outline_file.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <regex>
#include <vector>

namespace affinterp::io {

namespace {

namespace fs = std::filesystem;

Eigen::Matrix2Xd closed(std::vector<Eigen::Vector2d> points) {
  if (points.size() > 1 && points.front() == points.back()) points.pop_back();
  Eigen::Matrix2Xd v(2, static_cast<Eigen::Index>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) v.col(static_cast<Eigen::Index>(k)) = points[k];
  return v;
}

/// The reals of an SVG number list ("1,2 3e1-4": commas, spaces and signs separate).
class SvgNumbers {
 public:
  SvgNumbers(std::string_view text, const std::string& where) : text_(text), where_(where) {}
  void skip() {
    while (pos_ < text_.size() && (std::isspace(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == ',')) ++pos_;
  }
  bool at_number() {
    skip();
    return pos_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '-' ||
                                   text_[pos_] == '+' || text_[pos_] == '.');
  }
  bool done() {
    skip();
    return pos_ >= text_.size();
  }
  char command() { return text_[pos_++]; }
  double number() {
    if (!at_number()) throw MeshFileError(where_ + ": expected a number at offset " + std::to_string(pos_));
    std::size_t start = pos_;
    if (text_[pos_] == '+') ++start, ++pos_;
    double x = 0;
    const auto [end, error] = std::from_chars(text_.data() + pos_, text_.data() + text_.size(), x);
    if (error != std::errc() || !std::isfinite(x))
      throw MeshFileError(where_ + ": not a finite number at offset " + std::to_string(start));
    pos_ = static_cast<std::size_t>(end - text_.data());
    return x;
  }

 private:
  std::string_view text_;
  std::string where_;
  std::size_t pos_ = 0;
};

std::vector<Eigen::Vector2d> svg_points(std::string_view list, const std::string& where) {
  SvgNumbers numbers(list, where);
  std::vector<Eigen::Vector2d> points;
  while (!numbers.done()) {
    const double x = numbers.number(), y = numbers.number();
    points.emplace_back(x, y);
  }
  return points;
}

std::vector<Eigen::Vector2d> svg_path(std::string_view d, const std::string& where) {
  SvgNumbers numbers(d, where);
  std::vector<Eigen::Vector2d> points;
  Eigen::Vector2d current = Eigen::Vector2d::Zero();
  char command = 0;
  while (!numbers.done()) {
    if (!numbers.at_number()) {
      command = numbers.command();
      if (std::string_view("MmLlHhVvZz").find(command) == std::string_view::npos)
        throw MeshFileError(where + ": path command '" + std::string(1, command) +
                            "' is not supported (straight segments only: M L H V Z; flatten curves first)");
      if (command == 'Z' || command == 'z') {
        if (!numbers.done()) throw MeshFileError(where + ": the path continues after Z (one closed outline expected)");
        break;
      }
      if ((command == 'M' || command == 'm') && !points.empty())
        throw MeshFileError(where + ": the path has several subpaths (one closed outline expected)");
    }
    if (command == 0) throw MeshFileError(where + ": the path does not start with M");
    const bool relative = std::islower(static_cast<unsigned char>(command));
    Eigen::Vector2d next = current;
    switch (std::tolower(static_cast<unsigned char>(command))) {
      case 'm':
      case 'l': {
        const double x = numbers.number(), y = numbers.number();
        next = relative ? current + Eigen::Vector2d(x, y) : Eigen::Vector2d(x, y);
        break;
      }
      case 'h':
        next.x() = relative ? current.x() + numbers.number() : numbers.number();
        break;
      case 'v':
        next.y() = relative ? current.y() + numbers.number() : numbers.number();
        break;
    }
    points.push_back(current = next);
  }
  return points;
}

Eigen::Matrix2Xd parse_svg(std::string_view text, const std::string& name) {
  const std::string document(text);
  static const std::regex element(R"(<(polygon|polyline|path)\b([^>]*)>)", std::regex::icase);
  std::smatch match;
  if (!std::regex_search(document, match, element))
    throw MeshFileError(name + ": no <polygon>, <polyline> or <path> element");
  const std::string tag = match[1], attributes = match[2];
  const std::regex attribute(tag == "path" ? R"(\bd\s*=\s*["']([^"']*)["'])" : R"(\bpoints\s*=\s*["']([^"']*)["'])");
  std::smatch value;
  if (!std::regex_search(attributes, value, attribute))
    throw MeshFileError(name + ": the <" + tag + "> has no " + (tag == "path" ? "d" : "points") + " attribute");
  const std::string where = name + ": <" + tag + ">";
  std::vector<Eigen::Vector2d> points =
      tag == "path" ? svg_path(value[1].str(), where) : svg_points(value[1].str(), where);
  for (auto& p : points) p.y() = -p.y();  // SVG's y points down
  return closed(std::move(points));
}

}  // namespace

Eigen::Matrix2Xd parse_outline(std::string_view text, const std::string& name) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && text[first] == '<') return parse_svg(text, name);
  std::vector<Eigen::Vector2d> points;
  std::size_t line_number = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1, ++line_number;
    line = line.substr(0, line.find('#'));
    const std::string where = name + ":" + std::to_string(line_number);
    SvgNumbers numbers(line, where);
    if (numbers.done()) continue;
    if (line.find(',') != std::string_view::npos || !numbers.at_number())
      throw MeshFileError(where + ": expected 'x y'");
    const double x = numbers.number(), y = numbers.number();
    if (!numbers.done()) throw MeshFileError(where + ": expected 'x y', found more");
    points.emplace_back(x, y);
  }
  if (points.empty()) throw MeshFileError(name + ": no vertices");
  return closed(std::move(points));
}

Eigen::Matrix2Xd read_outline(const fs::path& file) {
  const std::string name = file.string();
  std::error_code error;
  if (!fs::is_regular_file(file, error)) throw MeshFileError(name + ": no such file");
  std::ifstream in(file, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw MeshFileError(name + ": cannot be read");
  if (text.find('\0') != std::string::npos) throw MeshFileError(name + ": contains NUL bytes (not text)");
  return parse_outline(text, name);
}

}  // namespace affinterp::io
