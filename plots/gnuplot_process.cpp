#include "plots/gnuplot_process.hpp"

#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace affinterp::plots {

namespace fs = std::filesystem;

std::optional<fs::path> find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');) {
    const fs::path candidate = fs::path(folder.empty() ? "." : folder) / name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

std::string shell_quoted(const fs::path& path) {
  std::string quoted = "'";
  for (const char c : path.string()) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string gnuplot_string(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

void write_datablock(std::ostream& out, const std::string& name, const Table& table) {
  const auto precision = out.precision(17);
  out << "$" << name << " << EOD\n";
  for (const Row& row : table) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i) out << ' ';
      if (std::isnan(row[i]))
        out << "NaN";
      else
        out << row[i];
    }
    out << '\n';
  }
  out << "EOD\n";
  out.precision(precision);
}

std::unique_ptr<Gnuplot> start_gnuplot(const fs::path& log) {
  const auto gnuplot = find_program("gnuplot");
  if (!gnuplot) throw std::runtime_error("gnuplot is not on PATH (Debian package gnuplot-nox)");
  // A gnuplot that dies early must surface as its error message, not as SIGPIPE in this process.
  std::signal(SIGPIPE, SIG_IGN);
  auto gp = std::make_unique<Gnuplot>(shell_quoted(*gnuplot) + " 2>" + shell_quoted(log));
  *gp << house_style();
  return gp;
}

std::string first_error_line(const fs::path& log) {
  // gnuplot echoes the offending command, marks it with '^', then says "line N: <what>" (or "...
  // error ..."); warnings say "warning" and pass.
  static const std::regex error(R"((line \d+:)|rror)");
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, error) && line.find("arning") == std::string::npos) return line;
  return "";
}

}  // namespace affinterp::plots
