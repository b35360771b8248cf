#pragma once
// What every drawing shares: finding programs on PATH, quoting for the shell, writing gnuplot datablocks
// with full precision, and starting gnuplot with its diagnostics captured.
#include "plots/figure.hpp"

#include <gnuplot-iostream.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

namespace affinterp::plots {

/// The path of an executable `name` on PATH, if any.
std::optional<std::filesystem::path> find_program(const std::string& name);

/// A path in single quotes for /bin/sh.
std::string shell_quoted(const std::filesystem::path& path);

/// `text` as a gnuplot single-quoted string ('' stands for ').
std::string gnuplot_string(const std::string& text);

/// `table` as the datablock $name, numbers with 17 significant digits, NaN as "NaN".
void write_datablock(std::ostream& out, const std::string& name, const Table& table);

/// A gnuplot process whose standard error goes to `log`, with the house style already sent. Throws
/// std::runtime_error (one line) when gnuplot is not on PATH, rather than dying of SIGPIPE later.
std::unique_ptr<Gnuplot> start_gnuplot(const std::filesystem::path& log);

/// The first line of gnuplot's diagnostics in `log` that reports an error, or "" when there is none.
std::string first_error_line(const std::filesystem::path& log);

}  // namespace affinterp::plots
