#pragma once
// A folder of its own for one test: logs, trajectories. Removed when the test passed, kept (and
// its path printed) when it failed or AUTONOMY_KEEP_TEST_DIRS is set.
#include "common/process/child_process.hpp"

#include <string>

namespace autonomy::test {

// The integration tests' children are the tools' children (common/process).
using process::ChildProcess;
using process::ExitStatus;

class TestDir {
 public:
  explicit TestDir(const std::string& test_name);
  ~TestDir();
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

}  // namespace autonomy::test
