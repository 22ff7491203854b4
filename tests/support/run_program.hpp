#pragma once
/// \file
/// \brief Runs the built `stackbook` program as a user would, for the tests of chapters 10
/// and 11: its exit code and what it wrote on stdout and stderr.

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace stackbook::test_support {

/// The program's exit codes as its documentation states them (docs/scene_format.md, "Exit
/// codes"): the tests check these numbers, not the program's own enum.
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitRunFailed = 2;
/// What `timeout` returns when it had to stop the program.
inline constexpr int kExitTimedOut = 124;

/// The built program: `stackbook` in the build tree, found by walking up from this test
/// binary (the program is written to the top of the build folder); empty if not built.
inline std::filesystem::path programPath() {
  namespace fs = std::filesystem;
  fs::path dir = fs::read_symlink("/proc/self/exe").parent_path();
  for (; !dir.empty() && dir != dir.root_path(); dir = dir.parent_path()) {
    const fs::path candidate = dir / "stackbook";
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  return {};
}

/// The bytes of a file ("" if it cannot be read).
inline std::string slurpFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// How a run of the program ended: the exit code (-1 if it ended by a signal), stdout, stderr.
struct ProgramOutcome {
  int code = -1;
  std::string out;
  std::string err;
};

/// Runs `stackbook ARGUMENTS` (shell syntax) in `workDir` under `timeout`, so a hang ends as
/// exit code 124 (a failed check) instead of a stuck test. Returns an outcome with code -1
/// and the reason in `err` if the program is not built. Each process writes its own pair of
/// capture files: CTest runs test cases in parallel, each in its own process.
inline ProgramOutcome runProgram(const std::string& arguments, const std::filesystem::path& workDir,
                                 int timeoutSeconds = 300) {
  namespace fs = std::filesystem;
  ProgramOutcome o;
  const fs::path program = programPath();
  if (program.empty()) {
    o.err = "the stackbook program is not built (target stackbook_program)";
    return o;
  }
  const fs::path scratch = fs::temp_directory_path() / "stackbook_program_runs";
  fs::create_directories(scratch);
  const std::string id = std::to_string(::getpid());
  const fs::path out = scratch / ("stdout_" + id + ".txt"), err = scratch / ("stderr_" + id + ".txt");
  const std::string command = "cd '" + workDir.string() + "' && timeout " + std::to_string(timeoutSeconds) + " '" +
                              program.string() + "' " + arguments + " >'" + out.string() + "' 2>'" + err.string() +
                              "'";
  const int status = std::system(command.c_str());
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  o.out = slurpFile(out);
  o.err = slurpFile(err);
  return o;
}

}  // namespace stackbook::test_support
