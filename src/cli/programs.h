// Copyright contactlaws authors.
//
// The programs the commands start (mujoco-simulate, ffmpeg) and the plugin
// they preload: found on PATH, or next to this program, or where it is
// installed; a missing one is an Error naming the Debian package.

#ifndef CONTACTLAWS_CLI_PROGRAMS_H_
#define CONTACTLAWS_CLI_PROGRAMS_H_

#include <string>
#include <string_view>

namespace contactlaws::cli {

// The path of program on PATH, or "" when absent.
std::string FindOnPath(std::string_view program);

// The path of program on PATH; else Error "COMMAND needs PROGRAM, which is not
// on PATH (Debian package PACKAGE)".
std::string RequireProgram(std::string_view command, std::string_view program,
                           std::string_view package);

// libcontactlaws_plugin.so: $CONTACTLAWS_PLUGIN when set, else next to this
// program (a build tree), else in the install's lib/contactlaws; Error
// naming the places looked at when none has it.
std::string FindPlugin();

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_PROGRAMS_H_
