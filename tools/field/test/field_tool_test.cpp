// Runs the real field_tool on maps written here, then reads its output file back.
#include "common/grid/cost_to_go.hpp"
#include "common/grid/map_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Run {
  int status = -1;
  std::string output;  // stdout and stderr
};

Run run_tool(const std::string& args) {
  Run r;
  const std::string cmd = std::string(FIELD_TOOL_PATH) + " " + args + " 2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  if (p == nullptr) return r;
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
  const int st = ::pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

std::vector<float> read_f32(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<float> v(bytes.size() / 4);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + 4 * i);
    const std::uint32_t u = b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t{b[3]} << 24);
    std::memcpy(&v[i], &u, 4);
  }
  return v;
}

class FieldToolTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("field_tool_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // 5 x 3 map, image rows top first ('#' = 0 occupied, '.' = 254 free):
    //   . . . . .
    //   . # # # .
    //   . . G . .     goal at column 2, row 2 (from the top)
    const std::vector<std::string> rows = {".....", ".###.", "....."};
    std::string pgm = "P5\n5 3\n255\n";
    for (const auto& r : rows) {
      for (char c : r) pgm.push_back(c == '#' ? '\0' : static_cast<char>(254));
    }
    std::ofstream(dir_ / "map.pgm", std::ios::binary) << pgm;
    std::ofstream(dir_ / "map.yaml") << "image: map.pgm\nresolution: 0.5\norigin: [0.0, 0.0, 0.0]\n"
                                        "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const char* name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(FieldToolTest, WritesTheFieldTopRowFirst) {
  const auto r = run_tool("--map " + path("map.yaml") + " --goal 2 2 --out " + path("f.f32"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("cells: 15"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("reachable: 12"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("compute_ms: "), std::string::npos) << r.output;
  ASSERT_EQ(fs::file_size(path("f.f32")), 15u * 4u);
  const auto f = read_f32(path("f.f32"));
  const auto at = [&f](int col, int row_from_top) {
    return f[static_cast<std::size_t>(row_from_top * 5 + col)];
  };
  EXPECT_EQ(at(2, 2), 0.0f);
  EXPECT_EQ(at(0, 2), 2.0f);  // costs in cells by default
  EXPECT_TRUE(std::isinf(at(1, 1)));
  EXPECT_TRUE(std::isinf(at(3, 1)));
  EXPECT_EQ(at(0, 1), 3.0f);  // up from (0, 2): the diagonal from (1, 2) would clip the wall
  EXPECT_EQ(at(1, 0), 5.0f);  // round the wall's end, no corner cutting
  EXPECT_EQ(at(2, 0), 6.0f);
}

TEST_F(FieldToolTest, ResolutionScaleGivesMetres) {
  const auto r = run_tool("--map " + path("map.yaml") + " --goal 2 2 --resolution-scale --out " +
                          path("m.f32"));
  ASSERT_EQ(r.status, 0) << r.output;
  const auto f = read_f32(path("m.f32"));
  ASSERT_EQ(f.size(), 15u);
  EXPECT_EQ(f[2 * 5 + 0], 1.0f);  // two cells of 0.5 m
}

TEST_F(FieldToolTest, RejectsBadGoalsAndMaps) {
  auto r = run_tool("--map " + path("map.yaml") + " --goal 2 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("blocked"), std::string::npos) << r.output;
  r = run_tool("--map " + path("map.yaml") + " --goal 5 0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("outside the 5 x 3 map"), std::string::npos) << r.output;
  std::ofstream(dir_ / "bad.yaml") << "image: map.pgm\nresolution: zero\n";
  r = run_tool("--map " + path("bad.yaml") + " --goal 0 0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("bad.yaml:2: 'resolution'"), std::string::npos) << r.output;
  r = run_tool("--map " + path("none.yaml") + " --goal 0 0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("cannot read"), std::string::npos) << r.output;
}

}  // namespace
