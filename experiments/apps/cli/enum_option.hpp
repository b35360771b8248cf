#pragma once
// An option of the engine's enums (theory/global/options.hpp) bound straight into the engine's variable: the
// accepted names, their meanings in --help, the default shown and the error for an unknown name all come from
// the engine's name table, so the CLI cannot drift from it.
#include "theory/global/options.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace affinterp::cli {

/// Adds `flag` to `command`, parsing a name of OptionNames<Enum> into `value`; `value`'s current content is the
/// default shown.
template <global::OptionEnum Enum>
CLI::Option* add_enum_option(CLI::App& command, const std::string& flag, Enum& value, const std::string& help) {
  std::string described = help + ":";
  for (const auto& named : global::OptionNames<Enum>::values)
    described += " " + std::string(named.name) + " (" + std::string(named.meaning) + "),";
  described.back() = '.';
  const CLI::Validator known_name(
      [](std::string& text) -> std::string {
        try {
          global::parse_option<Enum>(text);
          return {};
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
      },
      "{" + global::option_choices<Enum>() + "}");
  return command
      .add_option_function<std::string>(
          flag, [&value](const std::string& name) { value = global::parse_option<Enum>(name); }, described)
      ->check(known_name)
      ->default_str(global::to_string(value));
}

}  // namespace affinterp::cli
