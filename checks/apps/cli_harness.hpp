#pragma once
// Running the affinterp executable from a test: its exit status and standard error; scratch folders and
// text files around it.
#include <sys/wait.h>
#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace affinterp::checks {

struct CliResult {
  int status;
  std::string error;  ///< standard error
};

/// Runs `affinterp ARGS` (ARGS as shell words) with standard output discarded.
inline CliResult run_cli(const std::string& args) {
  const std::filesystem::path err =
      std::filesystem::temp_directory_path() / ("affinterp_cli_" + std::to_string(getpid()) + ".err");
  const std::string command = std::string(AFFINTERP_CLI) + " " + args + " >/dev/null 2>'" + err.string() + "'";
  const int raw = std::system(command.c_str());
  std::ifstream in(err);
  std::stringstream text;
  text << in.rdbuf();
  std::filesystem::remove(err);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw), text.str()};
}

/// A fresh, empty folder `name` in this test program's own temporary folder, `program`_PID.
inline std::filesystem::path scratch_folder(const std::string& program, const std::string& name) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / (program + "_" + std::to_string(getpid())) / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

inline void write_text(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// True when `text` is exactly one line.
inline bool one_line(const std::string& text) { return !text.empty() && text.find('\n') == text.size() - 1; }

}  // namespace affinterp::checks
