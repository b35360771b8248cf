#include "experiments/proofs/transcript.hpp"

#include <openssl/evp.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace affinterp::proofs {

namespace {

constexpr std::string_view marker = "# affinterp transcript";

/// The value of a header line "# key: value", or nullopt when `line` is not that line.
std::optional<std::string> header_value(const std::string& line, std::string_view key) {
  const std::string prefix = "# " + std::string(key) + ": ";
  if (!line.starts_with(prefix)) return std::nullopt;
  return line.substr(prefix.size());
}

std::optional<double> to_number(const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    return used == text.size() ? std::optional(value) : std::nullopt;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

bool Transcript::answers(std::string_view tool_name, std::string_view input_text) const {
  return tool == tool_name && input_sha256 == sha256_hex(input_text);
}

std::string transcript_file_name(std::string_view sentence, std::string_view tool) {
  return std::string(sentence) + "." + std::string(tool) + ".out";
}

std::string to_text(const Transcript& t) {
  std::ostringstream out;
  out << marker << "\n"
      << "# decider: " << t.tool << " " << t.version << "\n"
      << "# input: " << t.input << " sha256:" << t.input_sha256 << "\n"
      << "# cpu-limit-seconds: " << t.cpu_limit_seconds << "\n";
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.2f", t.seconds);
  out << "# seconds: " << seconds << "\n";
  if (t.cpu_seconds) {
    std::snprintf(seconds, sizeof seconds, "%.2f", *t.cpu_seconds);
    out << "# cpu-seconds: " << seconds << "\n";
  }
  if (t.max_rss_kb) out << "# max-rss-kb: " << *t.max_rss_kb << "\n";
  out << t.output;
  return out.str();
}

std::optional<Transcript> parse_transcript(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != marker) return std::nullopt;
  Transcript t;
  std::string decider, input, limit, seconds;
  for (auto [key, value] :
       {std::pair{"decider", &decider}, {"input", &input}, {"cpu-limit-seconds", &limit}, {"seconds", &seconds}}) {
    if (!std::getline(in, line)) return std::nullopt;
    const std::optional<std::string> v = header_value(line, key);
    if (!v) return std::nullopt;
    *value = *v;
  }
  const std::size_t space = decider.find(' '), hash = input.rfind(" sha256:");
  if (space == std::string::npos || hash == std::string::npos) return std::nullopt;
  t.tool = decider.substr(0, space);
  t.version = decider.substr(space + 1);
  t.input = input.substr(0, hash);
  t.input_sha256 = input.substr(hash + 8);
  const std::optional<double> l = to_number(limit), s = to_number(seconds);
  if (!l || !s || t.input_sha256.size() != 64) return std::nullopt;
  t.cpu_limit_seconds = *l;
  t.seconds = *s;
  // The optional lines: CPU time and peak memory.
  std::streamoff header_end = in.tellg();
  while (header_end >= 0 && std::getline(in, line)) {
    if (const std::optional<std::string> v = header_value(line, "cpu-seconds"); v && to_number(*v))
      t.cpu_seconds = to_number(*v);
    else if (const std::optional<std::string> m = header_value(line, "max-rss-kb"); m && to_number(*m))
      t.max_rss_kb = static_cast<long>(*to_number(*m));
    else
      break;
    header_end = in.tellg();
  }
  t.output = header_end < 0 ? "" : text.substr(static_cast<std::size_t>(header_end));
  return t;
}

std::optional<Transcript> read_transcript(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return parse_transcript(text.str());
}

void write_transcript(const std::filesystem::path& file, const Transcript& transcript) {
  const std::filesystem::path temporary = file.string() + ".partial";
  {
    std::ofstream out(temporary);
    out << to_text(transcript);
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, file);
}

std::string sha256_hex(std::string_view text) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(text.data(), text.size(), digest, &length, EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256 failed (OpenSSL)");
  static constexpr char hex[] = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < length; ++i) {
    out += hex[digest[i] >> 4];
    out += hex[digest[i] & 15];
  }
  return out;
}

}  // namespace affinterp::proofs
