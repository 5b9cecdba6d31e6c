// Copyright contactlaws authors.
//
// What the commands print besides their files: warnings on stderr (by rank
// 0 alone in a cluster job), table cells.

#ifndef CONTACTLAWS_CLI_REPORT_H_
#define CONTACTLAWS_CLI_REPORT_H_

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "contactlaws/contactlaws.h"

namespace contactlaws::cli {

// The line of what --settle moved, on stderr (nothing without it).
void ReportSettle(const Simulation& sim);

// "contactlaws: warning: SCENE: WHAT" on stderr.
void Warn(const std::string& scene, const std::string& what);

// The tags' own warnings (ContactModel::warnings: each names its file and
// tag), once each: warned keeps what was printed.
void WarnAboutTags(const ContactModel& model, std::set<std::string>* warned);

// The warnings a finished run leaves: energy growth, MuJoCo's own.
std::vector<std::string> RunWarnings(const Simulation& sim, const AdvanceResult& result);

// A table cell: "-" for a value that does not exist.
std::string Cell(const std::optional<double>& value, const char* format);

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_REPORT_H_
