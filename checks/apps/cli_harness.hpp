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
#include <system_error>

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

/// The standard output of `affinterp ARGS` (ARGS as shell words), standard error discarded.
inline std::string cli_output(const std::string& args) {
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / ("affinterp_cli_" + std::to_string(getpid()) + ".out");
  std::system((std::string(AFFINTERP_CLI) + " " + args + " >'" + out.string() + "' 2>/dev/null").c_str());
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  std::filesystem::remove(out);
  return text.str();
}

/// A fresh, empty folder `name` in this test program's own temporary folder, `program`_PID, which is removed
/// when the program exits normally (every call of one program passes the same `program`).
inline std::filesystem::path scratch_folder(const std::string& program, const std::string& name) {
  struct RemovedAtExit {
    std::filesystem::path root;
    ~RemovedAtExit() {
      std::error_code ignored;
      std::filesystem::remove_all(root, ignored);
    }
  };
  static const RemovedAtExit own{std::filesystem::temp_directory_path() / (program + "_" + std::to_string(getpid()))};
  const std::filesystem::path folder = own.root / name;
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
