#include "services/behavior/core/plan_resource.hpp"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace autonomy::behavior {

namespace {

constexpr char kMagic[8] = {'A', 'U', 'T', 'P', 'L', 'A', 'N', 'S'};

std::uint32_t crc32(const unsigned char* data, std::size_t n) {
  static const auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i) c = table[(c ^ data[i]) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

class Writer {
 public:
  void u32(std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out_.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
  }
  void u64(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) out_.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
  }
  void f64(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, 8);
    u64(b);
  }
  void f32(float v) {
    std::uint32_t b;
    std::memcpy(&b, &v, 4);
    u32(b);
  }
  void str(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    out_ += s;
  }
  void raw(const std::string& s) { out_ += s; }
  std::string& bytes() { return out_; }

 private:
  std::string out_;
};

class Reader {
 public:
  Reader(const std::string& bytes, std::size_t begin, std::size_t end) : b_(bytes), pos_(begin), end_(end) {}
  bool has(std::size_t n) const { return end_ - pos_ >= n; }
  std::size_t left() const { return end_ - pos_; }
  std::size_t pos() const { return pos_; }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(b_[pos_ + i])) << (8 * i);
    pos_ += 4;
    return v;
  }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(b_[pos_ + i])) << (8 * i);
    pos_ += 8;
    return v;
  }
  double f64() {
    const std::uint64_t b = u64();
    double v;
    std::memcpy(&v, &b, 8);
    return v;
  }
  float f32() {
    const std::uint32_t b = u32();
    float v;
    std::memcpy(&v, &b, 4);
    return v;
  }
  std::string take(std::size_t n) {
    std::string s = b_.substr(pos_, n);
    pos_ += n;
    return s;
  }

 private:
  const std::string& b_;
  std::size_t pos_;
  std::size_t end_;
};

PlanResourceResult fail(const std::string& source, const std::string& message) {
  PlanResourceResult r;
  r.error = source + ": " + message;
  return r;
}

}  // namespace

bool StoredPlan::operator==(const StoredPlan& o) const {
  return name == o.name && constraint_set == o.constraint_set && map_name == o.map_name &&
         world_width_m == o.world_width_m && world_height_m == o.world_height_m && resolution_m == o.resolution_m &&
         inflation_radius_m == o.inflation_radius_m && goal == o.goal && cols == o.cols && rows == o.rows &&
         costs.size() == o.costs.size() &&
         (costs.empty() || std::memcmp(costs.data(), o.costs.data(), costs.size() * sizeof(float)) == 0);
}

const StoredPlan* PlanResource::find(const std::string& name) const {
  for (const StoredPlan& p : plans)
    if (p.name == name) return &p;
  return nullptr;
}

const StoredPlan* PlanResource::match(const geometry::Vec2& goal, const std::string& constraint_set,
                                      const GridGeometry& geometry, double inflation_radius_m) const {
  for (const StoredPlan& p : plans) {
    if (p.constraint_set == constraint_set && (p.goal - goal).norm() <= 1e-6 &&
        static_cast<int>(p.cols) == geometry.cols() && static_cast<int>(p.rows) == geometry.rows() &&
        p.resolution_m == geometry.resolution_m() && std::abs(p.inflation_radius_m - inflation_radius_m) <= 1e-9) {
      return &p;
    }
  }
  return nullptr;
}

StoredPlan make_stored_plan(std::string name, std::string constraint_set, std::string map_name, double world_width_m,
                            double world_height_m, double inflation_radius_m, const CostToGoField& field) {
  StoredPlan p;
  p.name = std::move(name);
  p.constraint_set = std::move(constraint_set);
  p.map_name = std::move(map_name);
  p.world_width_m = world_width_m;
  p.world_height_m = world_height_m;
  p.resolution_m = field.geometry().resolution_m();
  p.inflation_radius_m = inflation_radius_m;
  p.goal = field.goal();
  p.cols = static_cast<std::uint32_t>(field.geometry().cols());
  p.rows = static_cast<std::uint32_t>(field.geometry().rows());
  p.costs = field.costs();
  return p;
}

std::string encode_plan_resource(const PlanResource& resource) {
  Writer w;
  w.raw(std::string(kMagic, sizeof kMagic));
  w.u32(kPlanResourceVersion);
  w.u32(static_cast<std::uint32_t>(resource.plans.size()));
  for (const StoredPlan& p : resource.plans) {
    Writer body;
    body.str(p.name);
    body.str(p.constraint_set);
    body.str(p.map_name);
    body.f64(p.world_width_m);
    body.f64(p.world_height_m);
    body.f64(p.resolution_m);
    body.f64(p.inflation_radius_m);
    body.f64(p.goal.x());
    body.f64(p.goal.y());
    body.u32(p.cols);
    body.u32(p.rows);
    for (float c : p.costs) body.f32(c);
    const std::string& b = body.bytes();
    w.u32(static_cast<std::uint32_t>(b.size()));
    w.raw(b);
    w.u32(crc32(reinterpret_cast<const unsigned char*>(b.data()), b.size()));
  }
  return std::move(w.bytes());
}

PlanResourceResult decode_plan_resource(const std::string& bytes, const std::string& source) {
  Reader r(bytes, 0, bytes.size());
  if (!r.has(16) || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
    return fail(source, "not a plan resource file (no AUTPLANS header)");
  }
  (void)r.take(8);
  const std::uint32_t version = r.u32();
  if (version != kPlanResourceVersion) {
    return fail(source, "plan resource version " + std::to_string(version) + " is not supported (this build reads " +
                            std::to_string(kPlanResourceVersion) + ")");
  }
  const std::uint32_t count = r.u32();
  PlanResource resource;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::string where = "plan " + std::to_string(i + 1) + " of " + std::to_string(count) + " (offset " +
                              std::to_string(r.pos()) + ")";
    if (!r.has(4)) return fail(source, where + ": truncated: the file ends before the record");
    const std::uint32_t body_bytes = r.u32();
    if (!r.has(static_cast<std::size_t>(body_bytes) + 4)) {
      return fail(source, where + ": truncated: the record needs " + std::to_string(body_bytes + 4) +
                              " bytes, the file has " + std::to_string(r.left()));
    }
    const std::size_t body_begin = r.pos();
    const std::uint32_t expected_crc = crc32(reinterpret_cast<const unsigned char*>(bytes.data()) + body_begin, body_bytes);
    Reader b(bytes, body_begin, body_begin + body_bytes);
    StoredPlan p;
    std::string* strings[] = {&p.name, &p.constraint_set, &p.map_name};
    for (std::string* s : strings) {
      if (!b.has(4)) return fail(source, where + ": record too short for its names");
      const std::uint32_t n = b.u32();
      if (!b.has(n)) return fail(source, where + ": a name of " + std::to_string(n) + " bytes overruns the record");
      *s = b.take(n);
    }
    if (!b.has(6 * 8 + 2 * 4)) return fail(source, where + " '" + p.name + "': record too short for its header");
    p.world_width_m = b.f64();
    p.world_height_m = b.f64();
    p.resolution_m = b.f64();
    p.inflation_radius_m = b.f64();
    const double gx = b.f64();
    const double gy = b.f64();
    p.goal = geometry::Vec2(gx, gy);
    p.cols = b.u32();
    p.rows = b.u32();
    const std::uint64_t cells = static_cast<std::uint64_t>(p.cols) * p.rows;
    if (cells * 4 != b.left()) {
      return fail(source, where + " '" + p.name + "': " + std::to_string(p.cols) + " x " + std::to_string(p.rows) +
                              " cells need " + std::to_string(cells * 4) + " bytes of costs, the record holds " +
                              std::to_string(b.left()));
    }
    if (!(p.resolution_m > 0.0) || !std::isfinite(p.resolution_m) || p.cols == 0 || p.rows == 0 ||
        !std::isfinite(gx) || !std::isfinite(gy)) {
      return fail(source, where + " '" + p.name + "': invalid grid (resolution, size or goal)");
    }
    p.costs.resize(cells);
    for (auto& c : p.costs) c = b.f32();
    (void)r.take(body_bytes);
    const std::uint32_t crc = r.u32();
    if (crc != expected_crc) return fail(source, where + " '" + p.name + "': checksum mismatch (corrupt file)");
    if (resource.find(p.name)) return fail(source, where + ": duplicate plan name '" + p.name + "'");
    resource.plans.push_back(std::move(p));
  }
  if (r.left() != 0) return fail(source, std::to_string(r.left()) + " unexpected bytes after the last plan");
  PlanResourceResult ok;
  ok.resource = std::move(resource);
  return ok;
}

PlanResourceResult load_plan_resource(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(path, std::string("cannot open: ") + std::strerror(errno));
  std::stringstream ss;
  ss << in.rdbuf();
  return decode_plan_resource(ss.str(), path);
}

bool save_plan_resource(const std::string& path, const PlanResource& resource, std::string* error) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    const std::string bytes = encode_plan_resource(resource);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      if (error) *error = tmp + ": cannot write";
      std::remove(tmp.c_str());
      return false;
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    if (error) *error = path + ": cannot rename from " + tmp + ": " + std::strerror(errno);
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

}  // namespace autonomy::behavior
