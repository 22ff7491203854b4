#pragma once
/// \file
/// \brief The `stackbook` program's command line (chapter 10): `run`, `list`, `check`,
/// and the demo when no arguments are given.

namespace stackbook::app {

/// Exit codes of the program (the table on the scene format page, \ref scene_exit_codes).
enum ExitCode : int {
  kOk = 0,
  /// Bad input, found before anything is simulated: a scene, sweep spec or mesh file, a
  /// `--set`, a command-line argument, a missing path, an `--out` that cannot be written.
  kBadInput = 1,
  /// The input was accepted but the run failed: it ended in a non-finite state, an output
  /// could not be written after the folder was probed, or an internal error.
  kRunFailed = 2,
};

/// Parses the command line and runs it; returns the process exit code. Errors are one line
/// on stderr, "stackbook: error: ...". Never throws.
int runCli(int argc, char** argv);

}  // namespace stackbook::app
