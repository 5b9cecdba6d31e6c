// Copyright contactlaws authors.
//
// The program's sink for MuJoCo's messages: kept instead of printed.

#ifndef CONTACTLAWS_CLI_MUJOCO_WARNINGS_H_
#define CONTACTLAWS_CLI_MUJOCO_WARNINGS_H_

#include <string>
#include <vector>

#include "contactlaws/simulation.h"

namespace contactlaws::cli {

// MuJoCo's messages to mju_user_warning. The program installs
// RecordMujocoWarning, which keeps them (thread-safe) instead of letting
// MuJoCo print to stdout, where CSV may go. Runs report their warnings from
// d->warning with counts and note them here; UnreportedMujocoWarnings gives
// the others (a model's, say), each once with the times it came.
void RecordMujocoWarning(const char* text);
void NoteReportedMujocoWarning(const std::string& text);
std::vector<MujocoWarning> UnreportedMujocoWarnings();

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_MUJOCO_WARNINGS_H_
