#pragma once
/// \file
/// \brief The `stackbook` program's command line (chapter 10): `run`, `list`, `check`,
/// and the demo when no arguments are given.

namespace stackbook::app {

/// Exit codes of the program.
enum ExitCode : int {
  kOk = 0,
  kRunFailed = 1,    ///< the simulation or an output writer failed
  kBadInput = 2,     ///< a bad scene file, a bad option or a missing file
};

/// Parses the command line and runs it; returns the process exit code. Errors are one line
/// on stderr, "stackbook: error: ...". Never throws.
int runCli(int argc, char** argv);

}  // namespace stackbook::app
