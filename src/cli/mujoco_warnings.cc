// Copyright contactlaws authors.

#include "cli/mujoco_warnings.h"

#include <algorithm>
#include <map>
#include <mutex>
#include <set>

namespace contactlaws::cli {
namespace {

struct MujocoMessages {
  std::mutex mutex;
  std::map<std::string, int> received;  // text -> times
  std::set<std::string> reported;
};

MujocoMessages& Messages() {
  static MujocoMessages* messages = new MujocoMessages;  // used until exit
  return *messages;
}

}  // namespace

void RecordMujocoWarning(const char* text) {
  MujocoMessages& m = Messages();
  std::lock_guard lock(m.mutex);
  ++m.received[text ? text : ""];
}

void NoteReportedMujocoWarning(const std::string& text) {
  MujocoMessages& m = Messages();
  std::lock_guard lock(m.mutex);
  m.reported.insert(text);
}

std::vector<MujocoWarning> UnreportedMujocoWarnings() {
  MujocoMessages& m = Messages();
  std::lock_guard lock(m.mutex);
  std::vector<MujocoWarning> unreported;
  for (const auto& entry : m.received) {
    const std::string& text = entry.first;
    // MuJoCo sends a run's warning text with " Time = ..." appended
    const bool reported = std::any_of(m.reported.begin(), m.reported.end(),
                                      [&](const std::string& r) { return text.rfind(r, 0) == 0; });
    if (!reported) unreported.push_back({text, entry.second});
  }
  return unreported;
}

}  // namespace contactlaws::cli
