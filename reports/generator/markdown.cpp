#include "reports/generator/markdown.hpp"

#include <cctype>
#include <sstream>

namespace affinterp::report {

std::string cell(std::string text) {
  std::string out;
  for (const char c : text) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n')
      out += ' ';
    else
      out += c;
  }
  return out;
}

std::string number(const nlohmann::json& value) {
  if (value.is_null()) return "";
  std::ostringstream out;
  out << value.get<double>();
  return out.str();
}

std::string fixed(const std::optional<double>& value, int digits) {
  if (!value) return "—";
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << *value;
  return out.str();
}

std::string fixed(double value, int digits) { return fixed(std::optional(value), digits); }

std::string heading_anchor(const std::string& heading) {
  std::string out;
  for (const char c : heading) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80 || std::isalnum(u) || c == '-' || c == '_')
      out += static_cast<char>(u < 0x80 ? std::tolower(u) : u);
    else if (c == ' ')
      out += '-';
  }
  return out;
}

std::string claim_page_path(const std::string& id) { return "claims/" + id + ".md"; }

}  // namespace affinterp::report
