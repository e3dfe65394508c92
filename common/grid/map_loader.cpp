#include "common/grid/map_loader.hpp"

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace autonomy::grid {

namespace {

constexpr long kMaxPixels = 256L * 1024L * 1024L;

bool read_file(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return true;
}

// Header tokens: whitespace separated, '#' starts a comment that runs to the end of the line.
class PgmHeaderReader {
 public:
  explicit PgmHeaderReader(const std::string& bytes) : b_(bytes) {}

  void skip_space_and_comments() {
    while (pos_ < b_.size()) {
      const char c = b_[pos_];
      if (c == '#') {
        while (pos_ < b_.size() && b_[pos_] != '\n' && b_[pos_] != '\r') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else {
        return;
      }
    }
  }

  // A non-negative decimal; false when there is none or it exceeds `max`.
  bool number(long max, long& value) {
    skip_space_and_comments();
    if (pos_ >= b_.size() || !std::isdigit(static_cast<unsigned char>(b_[pos_]))) return false;
    value = 0;
    while (pos_ < b_.size() && std::isdigit(static_cast<unsigned char>(b_[pos_]))) {
      value = value * 10 + (b_[pos_] - '0');
      if (value > max) return false;
      ++pos_;
    }
    return true;
  }

  std::size_t pos() const { return pos_; }
  void advance(std::size_t n) { pos_ += n; }
  bool at_end() const { return pos_ >= b_.size(); }
  char peek() const { return b_[pos_]; }

 private:
  const std::string& b_;
  std::size_t pos_ = 0;
};

std::string where(const std::string& file, const YAML::Mark& mark) {
  return file + ":" + std::to_string(mark.line + 1);
}

}  // namespace

PgmResult parse_pgm(const std::string& bytes, const std::string& name) {
  PgmResult r;
  const auto fail = [&](const std::string& msg) {
    r.error = name + ": " + msg;
    return r;
  };
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '5' && bytes[1] != '2')) {
    return fail("not a PGM image (expected magic P5 or P2)");
  }
  const bool binary = bytes[1] == '5';
  PgmHeaderReader in(bytes);
  in.advance(2);
  long width = 0, height = 0, maxval = 0;
  if (!in.number(1L << 20, width) || width == 0)
    return fail("bad header: missing or invalid width");
  if (!in.number(1L << 20, height) || height == 0)
    return fail("bad header: missing or invalid height");
  if (width * height > kMaxPixels)
    return fail("image too large (" + std::to_string(width) + " x " + std::to_string(height) + ")");
  if (!in.number(65535, maxval) || maxval == 0) return fail("bad header: maxval must be 1..65535");

  PgmImage img;
  img.width = static_cast<int>(width);
  img.height = static_cast<int>(height);
  img.maxval = static_cast<int>(maxval);
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  img.pixels.resize(count);

  if (binary) {
    // Exactly one whitespace character separates maxval from the samples.
    if (in.at_end() || !std::isspace(static_cast<unsigned char>(in.peek()))) {
      return fail("bad header: expected whitespace after maxval");
    }
    in.advance(1);
    const std::size_t bytes_per_sample = maxval < 256 ? 1 : 2;
    const std::size_t need = count * bytes_per_sample;
    const std::size_t have = bytes.size() - in.pos();
    if (have < need) {
      return fail("truncated pixel data: expected " + std::to_string(need) + " bytes for " +
                  std::to_string(width) + " x " + std::to_string(height) + " pixels, found " +
                  std::to_string(have));
    }
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data() + in.pos());
    for (std::size_t i = 0; i < count; ++i) {
      const unsigned v = bytes_per_sample == 1 ? p[i] : (unsigned{p[2 * i]} << 8) | p[2 * i + 1];
      if (static_cast<long>(v) > maxval) {
        return fail("pixel " + std::to_string(i) + " has value " + std::to_string(v) +
                    " above maxval " + std::to_string(maxval));
      }
      img.pixels[i] = static_cast<std::uint16_t>(v);
    }
  } else {
    for (std::size_t i = 0; i < count; ++i) {
      long v = 0;
      if (!in.number(std::numeric_limits<long>::max() / 16, v)) {
        in.skip_space_and_comments();
        if (in.at_end()) {
          return fail("truncated pixel data: expected " + std::to_string(count) +
                      " samples, found " + std::to_string(i));
        }
        return fail("bad sample " + std::to_string(i) + ": not a number");
      }
      if (v > maxval) {
        return fail("pixel " + std::to_string(i) + " has value " + std::to_string(v) +
                    " above maxval " + std::to_string(maxval));
      }
      img.pixels[i] = static_cast<std::uint16_t>(v);
    }
  }
  r.image = std::move(img);
  return r;
}

PgmResult load_pgm(const std::string& path) {
  std::string bytes;
  if (!read_file(path, bytes)) {
    PgmResult r;
    r.error = path + ": cannot read file";
    return r;
  }
  return parse_pgm(bytes, path);
}

OccupancyMap occupancy_from_image(const PgmImage& image, double resolution_m, RasterOrigin origin,
                                  const MapMetadata& metadata) {
  OccupancyMap map{OccupancyRaster(image.width, image.height, resolution_m, origin), metadata};
  auto& md = map.metadata;
  md.free_cells = md.occupied_cells = md.unknown_cells = 0;
  const double maxval = image.maxval;
  for (int y = 0; y < image.height; ++y) {
    const int row = image.height - 1 - y;  // first image row = top = highest raster row
    for (int x = 0; x < image.width; ++x) {
      const double v =
          image.pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                       static_cast<std::size_t>(x)];
      const double p = md.negate ? v / maxval : (maxval - v) / maxval;
      if (p < md.free_thresh) {
        ++md.free_cells;
        continue;
      }
      if (p > md.occupied_thresh) {
        ++md.occupied_cells;
      } else {
        ++md.unknown_cells;
      }
      map.raster.set_blocked({x, row}, true);
    }
  }
  return map;
}

MapLoadResult load_ros_map(const std::string& yaml_path) {
  MapLoadResult r;
  std::string text;
  if (!read_file(yaml_path, text)) {
    r.error = yaml_path + ": cannot read file";
    return r;
  }
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    r.error = where(yaml_path, e.mark) + ": YAML syntax error: " + e.msg;
    return r;
  }
  if (!root.IsMap()) {
    r.error = yaml_path + ":1: expected a mapping with image, resolution, origin, thresholds";
    return r;
  }

  MapMetadata md;
  md.yaml_path = yaml_path;
  const auto missing = [&](const char* key) {
    r.error = where(yaml_path, root.Mark()) + ": missing required key '" + key + "'";
    return r;
  };
  const auto bad = [&](const YAML::Node& n, const std::string& msg) {
    r.error = where(yaml_path, n.Mark()) + ": " + msg;
    return r;
  };
  // A scalar read with a checked conversion.
  const auto number = [](const YAML::Node& n, double& out) {
    if (!n.IsScalar()) return false;
    try {
      out = n.as<double>();
    } catch (const YAML::Exception&) {
      return false;
    }
    return std::isfinite(out);
  };

  const YAML::Node image = root["image"];
  if (!image) return missing("image");
  if (!image.IsScalar() || image.Scalar().empty()) return bad(image, "'image' must be a file name");

  const YAML::Node res = root["resolution"];
  if (!res) return missing("resolution");
  double resolution = 0.0;
  if (!number(res, resolution) || resolution <= 0.0) {
    return bad(res, "'resolution' must be a positive number (metres per pixel)");
  }

  const YAML::Node origin = root["origin"];
  if (!origin) return missing("origin");
  RasterOrigin o;
  if (!origin.IsSequence() || origin.size() != 3 || !number(origin[0], o.x) ||
      !number(origin[1], o.y) || !number(origin[2], o.yaw)) {
    return bad(origin, "'origin' must be a list of three numbers [x, y, yaw]");
  }

  const YAML::Node occ = root["occupied_thresh"];
  if (!occ) return missing("occupied_thresh");
  if (!number(occ, md.occupied_thresh) || md.occupied_thresh < 0.0 || md.occupied_thresh > 1.0) {
    return bad(occ, "'occupied_thresh' must be a number in [0, 1]");
  }
  const YAML::Node fre = root["free_thresh"];
  if (!fre) return missing("free_thresh");
  if (!number(fre, md.free_thresh) || md.free_thresh < 0.0 || md.free_thresh > 1.0) {
    return bad(fre, "'free_thresh' must be a number in [0, 1]");
  }
  if (md.free_thresh > md.occupied_thresh) {
    return bad(fre, "'free_thresh' must not exceed 'occupied_thresh'");
  }

  if (const YAML::Node neg = root["negate"]) {
    const std::string s = neg.IsScalar() ? neg.Scalar() : std::string();
    if (s == "0" || s == "false" || s == "False") {
      md.negate = false;
    } else if (s == "1" || s == "true" || s == "True") {
      md.negate = true;
    } else {
      return bad(neg, "'negate' must be 0 or 1");
    }
  }
  if (const YAML::Node mode = root["mode"]) {
    const std::string s = mode.IsScalar() ? mode.Scalar() : std::string();
    if (s == "trinary") {
      md.mode = MapMode::kTrinary;
    } else if (s == "scale") {
      md.mode = MapMode::kScale;
    } else if (s == "raw") {
      return bad(mode, "mode 'raw' is not supported (use trinary or scale)");
    } else {
      return bad(mode, "'mode' must be trinary or scale");
    }
  }

  std::string image_path = image.Scalar();
  if (image_path.front() != '/') {
    const auto slash = yaml_path.find_last_of('/');
    if (slash != std::string::npos) image_path = yaml_path.substr(0, slash + 1) + image_path;
  }
  md.image_path = image_path;
  const std::string ext = image_path.size() >= 4 ? image_path.substr(image_path.size() - 4) : "";
  if (ext != ".pgm" && ext != ".PGM") {
    return bad(image, "image '" + image.Scalar() + "' is not a .pgm file (only PGM is supported)");
  }

  auto pgm = load_pgm(image_path);
  if (!pgm.ok()) {
    r.error = where(yaml_path, image.Mark()) + ": image: " + pgm.error;
    return r;
  }
  r.map = occupancy_from_image(*pgm.image, resolution, o, md);
  return r;
}

}  // namespace autonomy::grid
