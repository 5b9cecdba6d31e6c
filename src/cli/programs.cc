// Copyright contactlaws authors.

#include "cli/programs.h"

#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"

namespace contactlaws::cli {
namespace {

constexpr const char* kPluginFile = "libcontactlaws_plugin.so";

// The directory of the running program (/proc/self/exe), or "".
std::string ProgramDirectory() {
  std::vector<char> buffer(4096);
  const ssize_t n = readlink("/proc/self/exe", buffer.data(), buffer.size() - 1);
  if (n <= 0) return "";
  const std::string path(buffer.data(), static_cast<size_t>(n));
  return path.substr(0, path.rfind('/'));
}

}  // namespace

std::string FindOnPath(std::string_view program) {
  if (program.find('/') != std::string_view::npos) {
    const std::string path(program);
    return access(path.c_str(), X_OK) == 0 ? path : "";
  }
  const char* path = std::getenv("PATH");
  std::string_view rest = path ? path : "/usr/bin:/bin";
  while (true) {
    const size_t colon = rest.find(':');
    const std::string_view dir = rest.substr(0, colon);
    const std::string candidate = fmt::format("{}/{}", dir.empty() ? "." : dir, program);
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
    if (colon == std::string_view::npos) return "";
    rest.remove_prefix(colon + 1);
  }
}

std::string RequireProgram(std::string_view command, std::string_view program,
                           std::string_view package) {
  std::string path = FindOnPath(program);
  if (path.empty()) {
    throw Error(fmt::format("{} needs {}, which is not on PATH (Debian package {})", command,
                            program, package));
  }
  return path;
}

std::string FindPlugin() {
  if (const char* given = std::getenv("CONTACTLAWS_PLUGIN")) {
    if (access(given, R_OK) == 0) return given;
    throw Error(fmt::format("CONTACTLAWS_PLUGIN={} cannot be read", given));
  }
  const std::vector<std::string> places = {
      fmt::format("{}/{}", ProgramDirectory(), kPluginFile),
      fmt::format("{}/{}", CONTACTLAWS_PLUGIN_INSTALL_DIR, kPluginFile)};
  for (const std::string& place : places) {
    if (access(place.c_str(), R_OK) == 0) return place;
  }
  throw Error(fmt::format("{} is neither next to this program nor installed ({}, {}); set "
                          "CONTACTLAWS_PLUGIN to its path",
                          kPluginFile, places[0], places[1]));
}

}  // namespace contactlaws::cli
