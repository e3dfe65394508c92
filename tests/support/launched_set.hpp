#pragma once
// A shipped service set run the way a user runs it: deploy/launch.sh in the foreground on a copy
// of deploy/sets/SET.set (lines edited by the test, e.g. to run the world in lockstep), with the
// test's domain, the build's programs and a run folder in the test's folder. The launcher is a
// child of the test (ProcessTest): killed at the end whatever happens, its processes get SIGTERM
// from the kernel (launch.sh sets their parent-death signal), so nothing outlives the test.
#include "tests/support/process_test.hpp"

#include <csignal>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace autonomy::test {

class LaunchedSet {
 public:
  // Edits one line of the set file (NAME and the rest of the line as written) and returns it.
  using LineEdit = std::function<std::string(const std::string& name, const std::string& line)>;

  // Writes the edited copy of deploy/sets/<set>.set into the test's folder. The run folder is
  // made now, so that files a set line names as {run}/... can be put there before the launch.
  LaunchedSet(const TestDir& dir, const std::string& set, const LineEdit& edit) : set_(set) {
    run_ = dir.file("run");
    std::filesystem::create_directories(run_);
    std::istringstream in(read_file(std::string(AUTONOMY_SOURCE_DIR) + "/deploy/sets/" + set + ".set"));
    std::string text;
    for (std::string line; std::getline(in, line);) {
      const auto first = line.find_first_not_of(" \t");
      if (first != std::string::npos && line[first] != '#') {
        const std::string name = line.substr(first, line.find_first_of(" \t", first) - first);
        line = edit(name, line);
      }
      text += line + "\n";
    }
    set_file_ = dir.file(set + ".set");
    write_file(set_file_, text);
  }

  const std::string& run_dir() const { return run_; }
  const std::string& set_file() const { return set_file_; }
  std::string file(const std::string& name) const { return run_ + "/" + name; }

  // The launcher's arguments: launch.sh [extra...] SET_FILE on `domain` with the build's programs.
  std::vector<std::string> launcher_args(int domain, const std::vector<std::string>& extra) const {
    std::vector<std::string> args = {std::string(AUTONOMY_SOURCE_DIR) + "/deploy/launch.sh",
                                     "--domain",
                                     std::to_string(domain),
                                     "--bin",
                                     std::filesystem::path(AUTONOMY_AUTONOMY_BIN).parent_path().string(),
                                     "--run-dir",
                                     run_,
                                     "--timeout",
                                     "60"};
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back(set_file_);
    return args;
  }

  // The pid in the run folder's pid file of process NAME (service/instance), 0 when none.
  pid_t pid_of(const std::string& name) const {
    std::string file = name;
    for (char& c : file)
      if (c == '/') c = '-';
    const std::string text = read_file(run_ + "/" + file + ".pid");
    try {
      return text.empty() ? 0 : static_cast<pid_t>(std::stol(text));
    } catch (const std::exception&) {
      return 0;  // being rewritten by the launcher
    }
  }

 private:
  std::string set_;
  std::string run_;
  std::string set_file_;
};

// Whether a set line contains `part`.
inline bool line_has(const std::string& line, const std::string& part) { return line.find(part) != std::string::npos; }

// `line` with the first `from` replaced by `to` (unchanged when absent).
inline std::string replaced(std::string line, const std::string& from, const std::string& to) {
  const auto at = line.find(from);
  if (at != std::string::npos) line.replace(at, from.size(), to);
  return line;
}

}  // namespace autonomy::test
