#include "common/grid/map_classes.hpp"

#include "common/grid/random_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>

namespace autonomy::grid {
namespace {

struct Rng {
  std::mt19937_64 engine;
  explicit Rng(std::uint64_t seed) : engine(seed) {}
  // Uniform in [lo, hi] (a tiny modulo bias is fine for maps).
  int uniform(int lo, int hi) {
    if (hi <= lo) return lo;
    return lo + static_cast<int>(engine() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  bool chance(int percent) { return static_cast<int>(engine() % 100) < percent; }
};

// Sets [c0, c1) x [r0, r1), clipped to the raster.
void fill(OccupancyRaster& r, int c0, int r0, int c1, int r1, bool blocked) {
  c0 = std::max(c0, 0);
  r0 = std::max(r0, 0);
  c1 = std::min(c1, r.width());
  r1 = std::min(r1, r.height());
  for (int row = r0; row < r1; ++row)
    for (int col = c0; col < c1; ++col) r.set_blocked({col, row}, blocked);
}

// A wall across a region, along x (horizontal) at rows [at, at + t) or along y at columns, with
// doors: gaps of 5..16 cells, one per `door_every` cells of wall (at least one).
void wall_with_doors(OccupancyRaster& r, Rng& rng, bool along_x, int at, int t, int from, int to,
                     int door_every) {
  if (along_x)
    fill(r, from, at, to, at + t, true);
  else
    fill(r, at, from, at + t, to, true);
  const int len = to - from;
  const int doors = 1 + len / door_every;
  for (int d = 0; d < doors; ++d) {
    const int width = rng.uniform(5, 16);
    const int p = from + rng.uniform(0, std::max(0, len - width));
    if (along_x)
      fill(r, p, at, p + width, at + t, false);
    else
      fill(r, at, p, at + t, p + width, false);
  }
}

void furnish(OccupancyRaster& r, Rng& rng, int x0, int y0, int x1, int y1) {
  if (!rng.chance(60)) return;
  const int pieces = rng.uniform(1, 4);
  for (int k = 0; k < pieces; ++k) {
    const int w = rng.uniform(4, 20);
    const int h = rng.uniform(4, 20);
    if (x1 - x0 < w + 8 || y1 - y0 < h + 8) continue;
    const int c = rng.uniform(x0 + 4, x1 - 4 - w);
    const int row = rng.uniform(y0 + 4, y1 - 4 - h);
    fill(r, c, row, c + w, row + h, true);
  }
}

constexpr int kMinRoom = 40;
constexpr int kMaxRoom = 150;

// Free region [x0, x1) x [y0, y1): split it by walls (or a corridor between two walls) until the
// pieces are rooms.
void split_floor(OccupancyRaster& r, Rng& rng, int x0, int y0, int x1, int y1) {
  const int w = x1 - x0;
  const int h = y1 - y0;
  const bool vertical_wall = w >= h;  // cut the longer side
  const int len = vertical_wall ? w : h;
  const int across_from = vertical_wall ? y0 : x0;
  const int across_to = vertical_wall ? y1 : x1;
  const bool small = w <= kMaxRoom && h <= kMaxRoom;
  if (len < 2 * kMinRoom + 3 || (small && rng.chance(40))) {
    furnish(r, rng, x0, y0, x1, y1);
    return;
  }
  const int base = vertical_wall ? x0 : y0;
  const int t = rng.uniform(1, 3);
  const bool corridor = len > 500 && rng.chance(70);
  if (corridor) {
    const int cw = rng.uniform(18, 36);
    const int pos = base + rng.uniform(kMinRoom, len - kMinRoom - cw - 2 * t);
    wall_with_doors(r, rng, !vertical_wall, pos, t, across_from, across_to, 120);
    wall_with_doors(r, rng, !vertical_wall, pos + t + cw, t, across_from, across_to, 120);
    if (vertical_wall) {
      split_floor(r, rng, x0, y0, pos, y1);
      split_floor(r, rng, pos + 2 * t + cw, y0, x1, y1);
    } else {
      split_floor(r, rng, x0, y0, x1, pos);
      split_floor(r, rng, x0, pos + 2 * t + cw, x1, y1);
    }
    return;
  }
  const int pos = base + rng.uniform(kMinRoom, len - kMinRoom - t);
  wall_with_doors(r, rng, !vertical_wall, pos, t, across_from, across_to, 300);
  if (vertical_wall) {
    split_floor(r, rng, x0, y0, pos, y1);
    split_floor(r, rng, pos + t, y0, x1, y1);
  } else {
    split_floor(r, rng, x0, y0, x1, pos);
    split_floor(r, rng, x0, pos + t, x1, y1);
  }
}

OccupancyRaster building(int width, int height, Rng& rng, double res) {
  OccupancyRaster r(width, height, res);
  fill(r, 0, 0, width, height, true);
  fill(r, 2, 2, width - 2, height - 2, false);  // a 2-cell outer wall
  split_floor(r, rng, 2, 2, width - 2, height - 2);
  return r;
}

// The building as a SLAM map shows it: the plan is 85 % of the map, rotated by 6-17 degrees (walls
// become staircases), unknown (blocked) outside it and in a few unscanned patches, wall edges
// ragged, isolated speckle in free space.
OccupancyRaster slam(int width, int height, Rng& rng, double res) {
  const int pw = std::max(8, width * 85 / 100);
  const int ph = std::max(8, height * 85 / 100);
  const auto plan = building(pw, ph, rng, res);
  const double angle = 0.1 + 0.2 * static_cast<double>(rng.uniform(0, 100)) / 100.0;
  const double ca = std::cos(angle), sa = std::sin(angle);
  OccupancyRaster r(width, height, res);
  const double cx = 0.5 * width, cy = 0.5 * height;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const double dx = col + 0.5 - cx, dy = row + 0.5 - cy;
      const int pc = static_cast<int>(std::floor(ca * dx - sa * dy + 0.5 * pw));
      const int pr = static_cast<int>(std::floor(sa * dx + ca * dy + 0.5 * ph));
      r.set_blocked({col, row}, plan.blocked({pc, pr}));
    }
  }
  // Unscanned patches.
  const int patches = 1 + width * height / 40000;
  for (int k = 0; k < patches; ++k) {
    const int w = rng.uniform(10, 60), h = rng.uniform(10, 60);
    const int c = rng.uniform(0, width - 1), row = rng.uniform(0, height - 1);
    fill(r, c, row, c + w, row + h, true);
  }
  // Ragged edges: a free cell beside a wall becomes occupied with probability 1/4 (decided on
  // the map before this pass, so walls grow by one cell at most).
  const OccupancyRaster before = r;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      if (before.blocked({col, row})) continue;
      const bool edge = before.blocked({col + 1, row}) || before.blocked({col - 1, row}) ||
                        before.blocked({col, row + 1}) || before.blocked({col, row - 1});
      if ((edge && rng.chance(25)) || rng.engine() % 1000 < 3) r.set_blocked({col, row}, true);
    }
  }
  return r;
}

// Randomised depth-first maze on a lattice of 6-cell corridors with 2-cell walls, plus 5 % of the
// remaining inner walls opened (loops, as in real corridor networks).
OccupancyRaster maze(int width, int height, Rng& rng, double res) {
  constexpr int kCorridor = 6, kWall = 2, kPitch = kCorridor + kWall;
  OccupancyRaster r(width, height, res);
  fill(r, 0, 0, width, height, true);
  const int nx = std::max(1, (width - kWall) / kPitch);
  const int ny = std::max(1, (height - kWall) / kPitch);
  const auto carve_cell = [&](int i, int j) {
    fill(r, kWall + i * kPitch, kWall + j * kPitch, kWall + i * kPitch + kCorridor,
         kWall + j * kPitch + kCorridor, false);
  };
  // Opens the wall between cell (i, j) and its neighbour (i + di, j + dj), di, dj in {0, 1}.
  const auto open_wall = [&](int i, int j, int di, int dj) {
    const int c0 = kWall + i * kPitch + di * kCorridor;
    const int r0 = kWall + j * kPitch + dj * kCorridor;
    fill(r, c0, r0, c0 + (di ? kWall : kCorridor), r0 + (dj ? kWall : kCorridor), false);
  };
  std::vector<std::uint8_t> visited(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  const auto at = [nx](int i, int j) {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i);
  };
  std::vector<std::pair<int, int>> stack{{0, 0}};
  visited[0] = 1;
  carve_cell(0, 0);
  const int di[4] = {1, 0, -1, 0}, dj[4] = {0, 1, 0, -1};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    int options[4], n = 0;
    for (int k = 0; k < 4; ++k) {
      const int a = i + di[k], b = j + dj[k];
      if (a >= 0 && b >= 0 && a < nx && b < ny && !visited[at(a, b)]) options[n++] = k;
    }
    if (n == 0) {
      stack.pop_back();
      continue;
    }
    const int k = options[rng.uniform(0, n - 1)];
    const int a = i + di[k], b = j + dj[k];
    visited[at(a, b)] = 1;
    carve_cell(a, b);
    open_wall(std::min(i, a), std::min(j, b), di[k] != 0, dj[k] != 0);
    stack.push_back({a, b});
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (i + 1 < nx && rng.chance(5)) open_wall(i, j, 1, 0);
      if (j + 1 < ny && rng.chance(5)) open_wall(i, j, 0, 1);
    }
  }
  return r;
}

OccupancyRaster clutter(int width, int height, Rng& rng, double res) {
  OccupancyRaster r(width, height, res);
  const auto target = static_cast<std::size_t>(0.15 * static_cast<double>(r.cell_count()));
  std::size_t blocked = 0;
  for (std::size_t tries = 0; blocked < target && tries < 10 * r.cell_count(); ++tries) {
    const int w = rng.uniform(2, 10), h = rng.uniform(2, 10);
    const int c0 = rng.uniform(0, width - 1), r0 = rng.uniform(0, height - 1);
    for (int row = r0; row < std::min(height, r0 + h); ++row) {
      for (int col = c0; col < std::min(width, c0 + w); ++col) {
        if (!r.blocked({col, row})) {
          r.set_blocked({col, row}, true);
          ++blocked;
        }
      }
    }
  }
  return r;
}

// A small mapped arena inside a large unknown grid, as a robot's map of a test arena or the start
// of an exploration looks (Nav2's tb3_sandbox: 384 x 384 cells, 5.4 % known free, the rest
// unknown): everything is unknown (blocked) except a regular hexagon whose circumradius is 0.14 of
// the smaller side, closed by a 2-cell wall, with a 3 x 3 grid of round pillars, 2..4 wall stubs
// reaching in, ragged edges and speckle. About 4-5 % of the cells are free. Integer arithmetic
// only (sqrt(3) / 2 as 866 / 1000).
OccupancyRaster arena(int width, int height, Rng& rng, double res) {
  OccupancyRaster r(width, height, res);
  fill(r, 0, 0, width, height, true);
  const long long cx = width / 2, cy = height / 2;
  const long long radius =
      std::max(4LL, static_cast<long long>(std::min(width, height)) * 14 / 100);
  // Inside the hexagon (flat top and bottom) of circumradius q around the centre.
  const auto inside = [&](long long col, long long row, long long q) {
    const long long dx = std::llabs(col - cx), dy = std::llabs(row - cy);
    return 1000 * dy <= 866 * q && 1732 * dx + 1000 * dy <= 1732 * q;
  };
  for (int row = 0; row < height; ++row)
    for (int col = 0; col < width; ++col)
      if (inside(col, row, radius - 2)) r.set_blocked({col, row}, false);
  const long long spacing = std::max(2LL, radius * 10 / 22);
  const long long pillar = std::max(1LL, radius / 12);
  for (long long i = -1; i <= 1; ++i) {
    for (long long j = -1; j <= 1; ++j) {
      const long long px = cx + i * spacing, py = cy + j * spacing;
      for (long long y = py - pillar; y <= py + pillar; ++y)
        for (long long x = px - pillar; x <= px + pillar; ++x)
          if ((x - px) * (x - px) + (y - py) * (y - py) <= pillar * pillar && x >= 0 && y >= 0 &&
              x < width && y < height)
            r.set_blocked({static_cast<int>(x), static_cast<int>(y)}, true);
    }
  }
  const int stubs = rng.uniform(2, 4);
  for (int k = 0; k < stubs; ++k) {
    const int len = static_cast<int>(radius) / 3 + rng.uniform(0, static_cast<int>(radius) / 6);
    const int off = rng.uniform(-static_cast<int>(radius) / 3, static_cast<int>(radius) / 3);
    const int c = static_cast<int>(cx), row = static_cast<int>(cy);
    const int reach = static_cast<int>(radius * 866 / 1000);
    switch (rng.uniform(0, 3)) {
      case 0:  // from the bottom wall up
        fill(r, c + off, row - reach, c + off + 2, row - reach + len, true);
        break;
      case 1:  // from the top wall down
        fill(r, c + off, row + reach - len, c + off + 2, row + reach, true);
        break;
      case 2:  // from the left across
        fill(r, c - static_cast<int>(radius) / 2 - len / 2, row + off,
             c - static_cast<int>(radius) / 2 + len / 2, row + off + 2, true);
        break;
      default:
        fill(r, c + static_cast<int>(radius) / 2 - len / 2, row + off,
             c + static_cast<int>(radius) / 2 + len / 2, row + off + 2, true);
        break;
    }
  }
  const OccupancyRaster before = r;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      if (before.blocked({col, row})) continue;
      const bool edge = before.blocked({col + 1, row}) || before.blocked({col - 1, row}) ||
                        before.blocked({col, row + 1}) || before.blocked({col, row - 1});
      if ((edge && rng.chance(25)) || rng.engine() % 1000 < 3) r.set_blocked({col, row}, true);
    }
  }
  return r;
}

// Label of the largest 4-connected free region per cell (1) or not (0).
std::vector<std::uint8_t> largest_region(const OccupancyRaster& r) {
  const std::size_t n = r.cell_count();
  std::vector<std::uint32_t> label(n, 0);
  std::vector<std::uint32_t> queue;
  std::uint32_t best = 0, next = 0;
  std::size_t best_size = 0;
  const int w = r.width();
  for (std::size_t s = 0; s < n; ++s) {
    const Cell sc{static_cast<int>(s % static_cast<std::size_t>(w)),
                  static_cast<int>(s / static_cast<std::size_t>(w))};
    if (label[s] != 0 || r.blocked(sc)) continue;
    label[s] = ++next;
    queue.assign(1, static_cast<std::uint32_t>(s));
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const std::uint32_t i = queue[q];
      const int col = static_cast<int>(i % static_cast<std::uint32_t>(w));
      const int row = static_cast<int>(i / static_cast<std::uint32_t>(w));
      const Cell nb[4] = {{col + 1, row}, {col - 1, row}, {col, row + 1}, {col, row - 1}};
      for (const Cell& c : nb) {
        if (r.blocked(c)) continue;
        const std::size_t j = r.index(c);
        if (label[j] != 0) continue;
        label[j] = next;
        queue.push_back(static_cast<std::uint32_t>(j));
      }
    }
    if (queue.size() > best_size) {
      best_size = queue.size();
      best = next;
    }
  }
  std::vector<std::uint8_t> in(n, 0);
  for (std::size_t i = 0; i < n; ++i) in[i] = best != 0 && label[i] == best;
  return in;
}

}  // namespace

const char* to_string(MapClass c) {
  switch (c) {
    case MapClass::kClutter:
      return "clutter";
    case MapClass::kBlocks:
      return "blocks";
    case MapClass::kBuilding:
      return "building";
    case MapClass::kSlam:
      return "slam";
    case MapClass::kMaze:
      return "maze";
    case MapClass::kArena:
      return "arena";
  }
  return "?";
}

std::optional<MapClass> map_class_from_string(const std::string& name) {
  for (MapClass c : kAllMapClasses)
    if (name == to_string(c)) return c;
  return std::nullopt;
}

const char* to_string(GoalPlacement g) {
  switch (g) {
    case GoalPlacement::kCentre:
      return "centre";
    case GoalPlacement::kCorner:
      return "corner";
    case GoalPlacement::kNarrow:
      return "narrow";
  }
  return "?";
}

std::optional<GoalPlacement> goal_placement_from_string(const std::string& name) {
  for (GoalPlacement g : kAllGoalPlacements)
    if (name == to_string(g)) return g;
  return std::nullopt;
}

OccupancyRaster make_map(MapClass c, int width, int height, std::uint64_t seed,
                         double resolution_m) {
  if (width <= 0 || height <= 0)
    return OccupancyRaster(std::max(width, 0), std::max(height, 0), resolution_m);
  Rng rng(seed);
  switch (c) {
    case MapClass::kClutter:
      return clutter(width, height, rng, resolution_m);
    case MapClass::kBlocks:
      return random_rectangles(width, height, 0.15, seed, resolution_m);
    case MapClass::kBuilding:
      return building(width, height, rng, resolution_m);
    case MapClass::kSlam:
      return slam(width, height, rng, resolution_m);
    case MapClass::kMaze:
      return maze(width, height, rng, resolution_m);
    case MapClass::kArena:
      return arena(width, height, rng, resolution_m);
  }
  return OccupancyRaster(width, height, resolution_m);
}

std::optional<Cell> place_goal(const OccupancyRaster& r, GoalPlacement g) {
  const auto region = largest_region(r);
  const int w = r.width(), h = r.height();
  // Nearest region cell to a target point (squared distance, first in row-major order on ties).
  const auto nearest = [&](double tx, double ty, auto&& accept) -> std::optional<Cell> {
    std::optional<Cell> best;
    double best_d = 0.0;
    for (int row = 0; row < h; ++row) {
      for (int col = 0; col < w; ++col) {
        if (!region[r.index({col, row})] || !accept(col, row)) continue;
        const double d = (col - tx) * (col - tx) + (row - ty) * (row - ty);
        if (!best || d < best_d) {
          best = Cell{col, row};
          best_d = d;
        }
      }
    }
    return best;
  };
  const auto any = [](int, int) { return true; };
  const double cx = 0.5 * (w - 1), cy = 0.5 * (h - 1);
  switch (g) {
    case GoalPlacement::kCentre:
      return nearest(cx, cy, any);
    case GoalPlacement::kCorner:
      return nearest(w / 16.0, h / 16.0, any);
    case GoalPlacement::kNarrow: {
      // Free runs through each cell along x and y; a passage is at most 6 cells across one way
      // and at least 3 times as long the other way.
      std::vector<int> hrun(r.cell_count(), 0), vrun(r.cell_count(), 0);
      for (int row = 0; row < h; ++row) {
        for (int col = 0; col < w;) {
          if (r.blocked({col, row})) {
            ++col;
            continue;
          }
          int end = col;
          while (end < w && !r.blocked({end, row})) ++end;
          for (int c = col; c < end; ++c) hrun[r.index({c, row})] = end - col;
          col = end;
        }
      }
      for (int col = 0; col < w; ++col) {
        for (int row = 0; row < h;) {
          if (r.blocked({col, row})) {
            ++row;
            continue;
          }
          int end = row;
          while (end < h && !r.blocked({col, end})) ++end;
          for (int y = row; y < end; ++y) vrun[r.index({col, y})] = end - row;
          row = end;
        }
      }
      const auto narrow = [&](int col, int row) {
        const int a = hrun[r.index({col, row})], b = vrun[r.index({col, row})];
        const int lo = std::min(a, b), hi = std::max(a, b);
        return lo <= 6 && hi >= 3 * lo;
      };
      if (auto c = nearest(cx, cy, narrow)) return c;
      return nearest(cx, cy, any);
    }
  }
  return std::nullopt;
}

}  // namespace autonomy::grid
