#include "common/grid/map_loader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace autonomy::grid {
namespace {

namespace fs = std::filesystem;
using namespace std::string_literals;

// A fresh directory per test, removed afterwards; nothing shared between tests.
class MapLoaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("grid_map_loader_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& bytes) {
    const auto path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
  std::string yaml(const std::string& image, const std::string& extra = "") {
    return "image: " + image +
           "\nresolution: 0.5\norigin: [-1.0, 2.0, 0.0]\n"
           "occupied_thresh: 0.65\nfree_thresh: 0.196\n" +
           extra;
  }

  fs::path dir_;
};

// 3 x 2 image, top row: free(254) occupied(0) unknown(205); bottom row: 0 254 254.
const std::string kP5 = "P5\n# made by a test\n3 2\n255\n"s + "\xfe\x00\xcd"s + "\x00\xfe\xfe"s;

TEST_F(MapLoaderTest, LoadsTrinaryP5AndFlipsRows) {
  write("m.pgm", kP5);
  const auto path = write("m.yaml", yaml("m.pgm"));
  const auto r = load_ros_map(path);
  ASSERT_TRUE(r.ok()) << r.error;
  const auto& m = *r.map;
  EXPECT_EQ(m.raster.width(), 3);
  EXPECT_EQ(m.raster.height(), 2);
  EXPECT_DOUBLE_EQ(m.raster.resolution_m(), 0.5);
  EXPECT_DOUBLE_EQ(m.raster.origin().x, -1.0);
  EXPECT_DOUBLE_EQ(m.raster.origin().y, 2.0);
  // Raster row 1 is the image's top row.
  EXPECT_FALSE(m.raster.blocked({0, 1}));
  EXPECT_TRUE(m.raster.blocked({1, 1}));
  EXPECT_TRUE(m.raster.blocked({2, 1}));  // unknown counts as blocked
  EXPECT_TRUE(m.raster.blocked({0, 0}));
  EXPECT_FALSE(m.raster.blocked({1, 0}));
  EXPECT_FALSE(m.raster.blocked({2, 0}));
  EXPECT_EQ(m.metadata.free_cells, 3u);
  EXPECT_EQ(m.metadata.occupied_cells, 2u);
  EXPECT_EQ(m.metadata.unknown_cells, 1u);
  EXPECT_EQ(m.metadata.image_path, (dir_ / "m.pgm").string());
}

TEST_F(MapLoaderTest, NegateInvertsTheMeaningOfPixels) {
  write("m.pgm", kP5);
  const auto r = load_ros_map(write("m.yaml", yaml("m.pgm", "negate: 1\nmode: scale\n")));
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(r.map->metadata.negate);
  EXPECT_EQ(r.map->metadata.mode, MapMode::kScale);
  EXPECT_TRUE(r.map->raster.blocked({0, 1}));   // 254: p = 0.996, occupied
  EXPECT_FALSE(r.map->raster.blocked({1, 1}));  // 0: p = 0, free
  EXPECT_TRUE(r.map->raster.blocked({2, 1}));   // 205: p = 0.80, occupied
}

TEST_F(MapLoaderTest, ReadsAsciiAnd16BitImages) {
  write("a.pgm", "P2\n3 2 # comment after a number\n15\n15 0 15\n0 0 7\n");
  auto r = load_ros_map(write("a.yaml", yaml("a.pgm")));
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_FALSE(r.map->raster.blocked({0, 1}));
  EXPECT_TRUE(r.map->raster.blocked({1, 1}));
  EXPECT_TRUE(r.map->raster.blocked({2, 0}));  // 7/15: p = 0.53, unknown

  write("b.pgm", "P5 2 1 65535\n"s + "\xff\xff"s + "\x00\x01"s);
  r = load_ros_map(write("b.yaml", yaml("b.pgm")));
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_FALSE(r.map->raster.blocked({0, 0}));
  EXPECT_TRUE(r.map->raster.blocked({1, 0}));
}

TEST_F(MapLoaderTest, YamlErrorsNameFileAndLine) {
  write("m.pgm", kP5);
  auto path = write("bad.yaml",
                    "image: m.pgm\nresolution: -2\norigin: [0, 0, 0]\n"
                    "occupied_thresh: 0.65\nfree_thresh: 0.2\n");
  auto r = load_ros_map(path);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error.rfind(path + ":2: 'resolution'", 0), 0u) << r.error;

  path = write("origin.yaml",
               "image: m.pgm\nresolution: 1\norigin: [0, 0]\n"
               "occupied_thresh: 0.65\nfree_thresh: 0.2\n");
  r = load_ros_map(path);
  EXPECT_NE(r.error.find("origin.yaml:3: 'origin' must be a list of three numbers"),
            std::string::npos)
      << r.error;

  path =
      write("missing.yaml", "image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\nfree_thresh: 0.2\n");
  r = load_ros_map(path);
  EXPECT_NE(r.error.find("missing.yaml:1: missing required key 'occupied_thresh'"),
            std::string::npos)
      << r.error;

  path = write("syntax.yaml", "image: m.pgm\nresolution: 1\norigin: [0, 0, 0\n");
  r = load_ros_map(path);
  EXPECT_NE(r.error.find("syntax.yaml:"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("YAML syntax error"), std::string::npos) << r.error;

  path = write("mode.yaml", yaml("m.pgm", "mode: raw\n"));
  r = load_ros_map(path);
  EXPECT_NE(r.error.find("mode.yaml:6: mode 'raw' is not supported"), std::string::npos) << r.error;

  path = write("thr.yaml",
               "image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\n"
               "occupied_thresh: 0.3\nfree_thresh: 0.5\n");
  r = load_ros_map(path);
  EXPECT_NE(r.error.find("thr.yaml:5: 'free_thresh' must not exceed"), std::string::npos)
      << r.error;

  r = load_ros_map((dir_ / "nope.yaml").string());
  EXPECT_NE(r.error.find("nope.yaml: cannot read file"), std::string::npos) << r.error;
}

TEST_F(MapLoaderTest, ImageProblemsAreReportedWithTheYamlLine) {
  const auto path = write("m.yaml", yaml("absent.pgm"));
  const auto r = load_ros_map(path);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error.find("m.yaml:1: image: "), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("absent.pgm: cannot read file"), std::string::npos) << r.error;

  const auto png = load_ros_map(write("p.yaml", yaml("map.png")));
  EXPECT_NE(png.error.find("only PGM is supported"), std::string::npos) << png.error;
}

TEST(ParsePgm, RejectsBadHeadersAndTruncatedData) {
  EXPECT_NE(parse_pgm("P6\n1 1\n255\n\0\0\0", "x.pgm").error.find("x.pgm: not a PGM image"),
            std::string::npos);
  EXPECT_NE(parse_pgm("P5\n0 1\n255\n", "x.pgm").error.find("invalid width"), std::string::npos);
  EXPECT_NE(parse_pgm("P5\n2 1\n", "x.pgm").error.find("maxval"), std::string::npos);
  EXPECT_NE(parse_pgm("P5\n2 1\n70000\n", "x.pgm").error.find("maxval"), std::string::npos);
  const auto truncated = parse_pgm("P5\n4 2\n255\nabc", "x.pgm");
  EXPECT_FALSE(truncated.ok());
  EXPECT_NE(
      truncated.error.find("truncated pixel data: expected 8 bytes for 4 x 2 pixels, found 3"),
      std::string::npos)
      << truncated.error;
  const auto short16 = parse_pgm("P5\n2 1\n1000\n\x01\x02\x03", "x.pgm");
  EXPECT_NE(short16.error.find("expected 4 bytes"), std::string::npos) << short16.error;
  EXPECT_NE(parse_pgm("P2\n2 2\n9\n1 2 3\n", "x.pgm").error.find("expected 4 samples, found 3"),
            std::string::npos);
  EXPECT_NE(parse_pgm("P2\n2 1\n9\n1 12\n", "x.pgm").error.find("above maxval"), std::string::npos);
  EXPECT_NE(parse_pgm("P2\n2 1\n9\n1 x\n", "x.pgm").error.find("not a number"), std::string::npos);
}

TEST(ParsePgm, ReadsSamplesTopRowFirst) {
  const auto r = parse_pgm("P2\n2 2\n100\n1 2\n3 100\n", "x.pgm");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.image->maxval, 100);
  EXPECT_EQ(r.image->pixels, (std::vector<std::uint16_t>{1, 2, 3, 100}));
}

}  // namespace
}  // namespace autonomy::grid
