#pragma once
// Plan resource files: many named internalized plans in one binary file, computed before a mission
// and shipped with the robot (Wagner & Arkin 2003, section 2.1: "a resource file ... may contain
// any number of plans based on different sets of constraints"). Written by `plan_tool build`,
// read by `behavior --plans FILE`, which uses a stored plan when a goal's position and constraint
// set match one (and its grid matches the robot's), and computes the field otherwise.
//
// Format (all little-endian; version 1):
//   file   = magic "AUTPLANS" (8 bytes) | u32 version | u32 plan_count | plan_count * record
//   record = u32 body_bytes | body | u32 crc32(body)            (CRC-32/ISO-HDLC, as zlib)
//   body   = str name | str constraint_set | str map_name
//            | f64 world_width_m | f64 world_height_m | f64 resolution_m | f64 inflation_radius_m
//            | f64 goal_x | f64 goal_y | u32 cols | u32 rows | f32 costs[cols * rows]
//   str    = u32 length | bytes (UTF-8, no terminator)
// Costs are row-major (row 0 = lowest y), +inf where unreachable: exactly CostToGoField::costs().
// A 250 x 250 m map at 1 m costs 250 KB per plan.
//
// Loading checks everything and fails with one clear message (source: what, where): wrong magic,
// unsupported version, truncated record, size fields that disagree, CRC mismatch, trailing bytes.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/cost_to_go_field.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior {

inline constexpr std::uint32_t kPlanResourceVersion = 1;

struct StoredPlan {
  std::string name;
  std::string constraint_set;  // canonical (ConstraintSet::name()): "obstacles", "obstacles+comm"
  std::string map_name;        // WorldMap.name of the map it was computed on ("" when unknown)
  double world_width_m = 0.0;
  double world_height_m = 0.0;
  double resolution_m = 0.0;
  double inflation_radius_m = 0.0;
  geometry::Vec2 goal = geometry::Vec2::Zero();
  std::uint32_t cols = 0;
  std::uint32_t rows = 0;
  std::vector<float> costs;  // cols * rows

  bool operator==(const StoredPlan& o) const;  // bitwise on costs (inf == inf)
  GridGeometry geometry() const { return GridGeometry(static_cast<int>(cols), static_cast<int>(rows), resolution_m); }
  CostToGoField field() const { return CostToGoField(geometry(), goal, costs); }
};

struct PlanResource {
  std::vector<StoredPlan> plans;

  const StoredPlan* find(const std::string& name) const;
  // The first plan for this goal (within 1e-6 m) and canonical constraint set whose grid is
  // exactly `geometry` with this inflation radius (within 1e-9 m); nullptr when none.
  const StoredPlan* match(const geometry::Vec2& goal, const std::string& constraint_set,
                          const GridGeometry& geometry, double inflation_radius_m) const;
};

// Snapshot of a computed field.
StoredPlan make_stored_plan(std::string name, std::string constraint_set, std::string map_name,
                            double world_width_m, double world_height_m, double inflation_radius_m,
                            const CostToGoField& field);

std::string encode_plan_resource(const PlanResource& resource);

struct [[nodiscard]] PlanResourceResult {
  std::optional<PlanResource> resource;  // set exactly when error is empty
  std::string error;                     // "source: message"
  bool ok() const { return error.empty(); }
};

PlanResourceResult decode_plan_resource(const std::string& bytes, const std::string& source);
PlanResourceResult load_plan_resource(const std::string& path);
// Writes atomically enough for tools (temporary file, then rename); false with *error on failure.
bool save_plan_resource(const std::string& path, const PlanResource& resource, std::string* error);

}  // namespace autonomy::behavior
