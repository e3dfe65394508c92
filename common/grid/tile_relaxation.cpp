#include "common/grid/tile_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#if defined(__GNUC__) && !defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
#define AUTONOMY_TILE_SEARCH 1
#include <immintrin.h>
// The tile code is compiled for AVX2 (eight float lanes per row vector; on plain SSE2 the same
// code measured 5-6x slower, so it only runs where the CPU has AVX2: see tile_search_available).
// The pragma comes after every include, so library code stays compiled for the baseline.
#pragma GCC push_options
#pragma GCC target("avx2")
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"  // vectors never cross this file's boundary
#endif

// Why this is exact.
// Labels start at +inf (the goal at 0) and only ever take values float(label(u) + step) that some
// relaxation produced, so each label is always the float cost of a real path (evaluated from the
// goal outwards, one rounding per step). The search stops only when no allowed move improves any
// label: label(v) <= float(label(u) + step(u, v)) for every move. Float addition of a positive
// step is monotone, so along the float-cheapest path g = v0, v1, ..., vk = v induction gives
// label(vi) <= float(label(v(i-1)) + step) <= float-cost of that path prefix; hence every label is
// the minimum over paths of the float path cost. The textbook float Dijkstra computes the same
// minimum (float addition is monotone and, below 2^20 steps, strictly increasing, so it expands in
// order and never needs to revisit), so the two agree bit for bit whatever order the relaxations
// here run in. The order matters for speed only.
//
// Why it is fast.
// A cell-by-cell queue pays about 250 instructions per cell (a pop, eight relaxations, pushes,
// bucket arithmetic) for one cache-unfriendly visit. Here the unit of work is an 8 x 8 tile: its
// 64 labels, the one-cell ring around it and its step costs are copied into registers-sized row
// vectors, and the tile is swept upwards and downwards (each row: the three moves from the row
// below or above as whole-vector adds and mins, then the moves along the row repeated until no
// lane improves) until a sweep changes nothing. The tile is then written back and the neighbours
// that a move out of it now improves are queued, in buckets of the smallest improved label, so
// the wave crosses the map roughly in distance order and most tiles are relaxed once.
// The step costs come from the raster's bits at each run (no per-cell move array): nothing but
// the output is prepared per cell, so a map whose reachable part is small costs little more than
// its +inf fill.
namespace autonomy::grid::detail {
#ifdef AUTONOMY_TILE_SEARCH
namespace {

typedef float v8f __attribute__((vector_size(32)));
typedef std::int32_t v8i __attribute__((vector_size(32)));
typedef std::uint32_t v8u __attribute__((vector_size(32)));  // bit sets: shifts without sign
typedef std::uint8_t v8u8 __attribute__((vector_size(8)));

constexpr int kLanes = 8;  // tile width: one row vector
constexpr int kRows = 8;   // tile height (measured: 4 and 16 rows 5-20 % slower)
constexpr float kInf = std::numeric_limits<float>::infinity();
// Scheduler buckets: one per resolution of label; keys further ahead than the ring are clamped to
// its end (the order is a heuristic, exactness does not depend on it).
constexpr double kBucketsPerRes = 1.0;  // measured: 0.25 .. 4 alike
constexpr std::size_t kRing = 64;
constexpr std::size_t kPrefetchAhead = 4;  // tiles of the bucket ahead of the one running

inline v8f splat(float x) {
  return v8f{x, x, x, x, x, x, x, x};
}
inline v8i splat_i(std::int32_t x) {
  return v8i{x, x, x, x, x, x, x, x};
}
inline v8u splat_u(std::uint32_t x) {
  return v8u{x, x, x, x, x, x, x, x};
}
// Lanes whose top bit is set (all ones), as a select mask.
inline v8i top_bit(v8u x) {
  return reinterpret_cast<v8i>(x) < 0;
}
inline v8f vmin(v8f a, v8f b) {
  return a < b ? a : b;
}
inline bool any(v8i m) {
  return _mm256_movemask_ps(reinterpret_cast<__m256>(m)) != 0;
}
// Lane i <- a[i - 1], lane 0 <- west: the west neighbours of a row.
inline v8f west_of(v8f a, float west) {
  return __builtin_shuffle(a, splat(west), v8i{8, 0, 1, 2, 3, 4, 5, 6});
}
// Lane i <- a[i + 1], lane 7 <- east.
inline v8f east_of(v8f a, float east) {
  return __builtin_shuffle(a, splat(east), v8i{1, 2, 3, 4, 5, 6, 7, 8});
}
// GCC 12 dropped __builtin_prefetch / _mm_prefetch in the scheduler loop (the loop has no other
// effect); a volatile asm stays.
inline void prefetch(const float* p) {
  asm volatile("prefetcht0 %0" : : "m"(*p));
}
inline float hmin(v8f a) {
  float m = a[0];
  for (int i = 1; i < kLanes; ++i) m = std::min(m, a[i]);
  return m;
}

enum Move { kE, kN, kW, kS, kNE, kNW, kSW, kSE };

// One tile in registers-sized pieces. Local row 0 is the ring row below the tile, kRows + 1 the
// one above; west/east are the ring columns (the corners sit in rows 0 and kRows + 1).
struct Tile {
  v8f row[kRows + 2];
  float west[kRows + 2];
  float east[kRows + 2];
  v8f step[kRows][8];  // per tile row and move: the step cost per lane, +inf where not allowed
  const v8f (*steps[kRows])[8];  // per tile row: its step[] or, in open space, the base steps
  v8f before[kRows];             // the labels as loaded
  // Per tile row: bit 8 m + i set when move m (E, N, W, S) is allowed from lane i; diag the same
  // for NE, NW, SW, SE. Vectors over the rows.
  v8u orth;
  v8u diag;
};

class TileSearch {
 public:
  TileSearch(const OccupancyRaster& raster, float orthogonal, float diagonal, float* dist)
      : raster_(raster),
        row_bytes_(raster.words_per_row() * sizeof(std::uint64_t)),
        w_(raster.width()),
        h_(raster.height()),
        tiles_x_((w_ + kLanes - 1) / kLanes),
        tiles_y_((h_ + kRows - 1) / kRows),
        dist_(dist),
        per_bucket_(kBucketsPerRes / raster.resolution_m()),
        pending_(static_cast<std::size_t>(tiles_x_) * static_cast<std::size_t>(tiles_y_), kInf),
        ring_(kRing) {
    for (int m = 0; m < 8; ++m) base_[m] = splat(m < 4 ? orthogonal : diagonal);
  }

  TileSearchStats run(std::size_t goal) {
    const int gc = static_cast<int>(goal % static_cast<std::size_t>(w_));
    const int gr = static_cast<int>(goal / static_cast<std::size_t>(w_));
    activate(gc / kLanes, gr / kRows, 0.0f);
    std::uint64_t k = 0;
    while (queued_ != 0) {
      std::vector<std::uint32_t>& bucket = ring_[k % kRing];
      for (std::size_t i = 0; i < bucket.size(); ++i) {  // may grow while read
        if (i + kPrefetchAhead < bucket.size()) prefetch_tile(bucket[i + kPrefetchAhead]);
        const std::uint32_t t = bucket[i];
        --queued_;
        if (pending_[t] == kInf) continue;  // ran already from an earlier entry
        pending_[t] = kInf;
        relax_tile(static_cast<int>(t % static_cast<std::uint32_t>(tiles_x_)),
                   static_cast<int>(t / static_cast<std::uint32_t>(tiles_x_)));
      }
      bucket.clear();
      current_ = ++k;
    }
    stats_.reachable += 1;  // the goal, finite before its tile first ran
    stats_.tiles = pending_.size();
    stats_.buckets = kRing;
    stats_.work_bytes = pending_.capacity() * sizeof(float) + ring_.capacity() * sizeof(ring_[0]);
    for (const auto& b : ring_) stats_.work_bytes += b.capacity() * sizeof(std::uint32_t);
    return stats_;
  }

 private:
  void activate(int tx, int ty, float key) {
    if (tx < 0 || ty < 0 || tx >= tiles_x_ || ty >= tiles_y_) return;
    const std::size_t t = static_cast<std::size_t>(ty) * static_cast<std::size_t>(tiles_x_) +
                          static_cast<std::size_t>(tx);
    if (!(key < pending_[t])) return;
    pending_[t] = key;
    auto b = static_cast<std::uint64_t>(static_cast<double>(key) * per_bucket_);
    b = std::clamp<std::uint64_t>(b, current_, current_ + kRing - 1);
    ring_[b % kRing].push_back(static_cast<std::uint32_t>(t));
    ++queued_;
  }

  // Row y of the raster into a vector at columns x0 .. x0 + 7, +inf outside; plus the ring cells.
  void load_row(int y, int x0, v8f& row, float& west, float& east) const {
    if (y < 0 || y >= h_) {
      row = splat(kInf);
      west = east = kInf;
      return;
    }
    const float* p = dist_ + static_cast<std::size_t>(y) * static_cast<std::size_t>(w_);
    if (x0 + kLanes <= w_) {
      std::memcpy(&row, p + x0, sizeof row);
    } else {
      row = splat(kInf);
      for (int i = 0; x0 + i < w_; ++i) row[i] = p[x0 + i];
    }
    west = x0 > 0 ? p[x0 - 1] : kInf;
    east = x0 + kLanes < w_ ? p[x0 + kLanes] : kInf;
  }

  // The free cells of row y at columns x0 - 1 .. x0 + 8 (x0 = 8 tx) as bits 0 .. 9, cells outside
  // the raster blocked. Read from the raster's bits for each tile run: no per-cell array is
  // prepared, so the raster's unreached parts cost nothing.
  unsigned free_window(int y, int tx) const {
    if (y < 0 || y >= h_) return 0;
    const auto* b = reinterpret_cast<const unsigned char*>(raster_.row_words(y));
    const int x0 = tx * kLanes;
    if (tx > 0 && x0 + kLanes < w_ && static_cast<std::size_t>(tx) + 2 < row_bytes_) {
      // The usual case: all ten columns inside, four bytes readable from column x0 - 8.
      std::uint32_t bytes;
      std::memcpy(&bytes, b + tx - 1, sizeof bytes);
      return ~(bytes >> 7) & 0x3ffu;
    }
    unsigned blocked = static_cast<unsigned>(b[tx]) << 1;
    blocked |= tx > 0 ? b[tx - 1] >> 7 : 1u;
    if (x0 + kLanes < w_) blocked |= (static_cast<unsigned>(b[tx + 1]) & 1u) << 9;
    // Columns x0 - 1 + j for j < w - x0 + 1 exist (the raster's padding bits read as free).
    const int inside = std::min(10, w_ - x0 + 1);
    return ~blocked & ((1u << inside) - 1u);
  }

  // The step cost of every move from the cells of the tile's rows, +inf where the move is not
  // allowed: the target must be free and a diagonal needs both cells beside it free. Also the
  // allowed-move bits per row (orth, diag), for offer_beside.
  void load_steps(int y0, int tx, Tile& t) const {
    std::uint32_t win[kRows + 2];
    for (int r = 0; r < kRows + 2; ++r) win[r] = free_window(y0 + r - 1, tx);
    // Lane r: tile row r (0-based) and its rows below and above. The move bits of all eight rows
    // at once.
    v8u dn, cur, up;
    std::memcpy(&dn, &win[0], sizeof dn);
    std::memcpy(&cur, &win[1], sizeof cur);
    std::memcpy(&up, &win[2], sizeof up);
    const v8u byte = splat_u(0xffu);
    // Bit i of each: lane i's neighbour in that direction (or the cell itself) is free.
    const v8u c = (cur >> 1) & byte, cw = cur & byte, ce = (cur >> 2) & byte;
    const v8u u = (up >> 1) & byte, uw = up & byte, ue = (up >> 2) & byte;
    const v8u d = (dn >> 1) & byte, dw = dn & byte, de = (dn >> 2) & byte;
    const v8u e = c & ce, n = c & u, wst = c & cw, s = c & d;
    const v8u ne = e & n & ue, nw = wst & n & uw, sw = wst & s & dw, se = e & s & de;
    t.orth = e | n << 8 | wst << 16 | s << 24;
    t.diag = ne | nw << 8 | sw << 16 | se << 24;
    const int open =
        _mm256_movemask_ps(reinterpret_cast<__m256>((t.orth & t.diag) == splat_u(0xffffffffu)));
    const v8f inf = splat(kInf);
    // Lane i's bit of byte m % 4 moved to the top: a blend on the sign bit, no compare.
    const v8u to_top[4] = {v8u{31, 30, 29, 28, 27, 26, 25, 24}, v8u{23, 22, 21, 20, 19, 18, 17, 16},
                           v8u{15, 14, 13, 12, 11, 10, 9, 8}, v8u{7, 6, 5, 4, 3, 2, 1, 0}};
    for (int r = 0; r < kRows; ++r) {
      if (open >> r & 1) {  // open space: every move allowed, the shared base steps
        t.steps[r] = &base_;
        continue;
      }
      v8f(&step)[8] = t.step[r];
      t.steps[r] = &t.step[r];
      const v8u vo = __builtin_shuffle(t.orth, splat_u(static_cast<std::uint32_t>(r)));
      const v8u vg = __builtin_shuffle(t.diag, splat_u(static_cast<std::uint32_t>(r)));
      for (int m = 0; m < 4; ++m) {
        step[m] = top_bit(vo << to_top[m]) ? base_[m] : inf;
        step[m + 4] = top_bit(vg << to_top[m]) ? base_[m + 4] : inf;
      }
    }
  }

  // The rows a tile run will read, fetched while earlier tiles of the bucket run: on big maps the
  // rows of a tile are a row-length apart and the wave visits tiles all along its front, so
  // nearly every row would otherwise miss the cache.
  void prefetch_tile(std::uint32_t t) const {
    const int tx = static_cast<int>(t % static_cast<std::uint32_t>(tiles_x_));
    const int ty = static_cast<int>(t / static_cast<std::uint32_t>(tiles_x_));
    const int x0 = tx * kLanes;
    const int first = std::max(0, ty * kRows - 1);
    const int last = std::min(h_ - 1, ty * kRows + kRows);
    const std::size_t left = static_cast<std::size_t>(x0 > 0 ? x0 - 1 : 0);
    const std::size_t right = static_cast<std::size_t>(std::min(x0 + kLanes, w_ - 1));
    for (int y = first; y <= last; ++y) {
      const float* p = dist_ + static_cast<std::size_t>(y) * static_cast<std::size_t>(w_);
      prefetch(p + left);
      prefetch(p + right);
    }
  }

  void store_row(int y, int x0, const v8f& row) const {
    if (y >= h_) return;
    float* p = dist_ + static_cast<std::size_t>(y) * static_cast<std::size_t>(w_);
    if (x0 + kLanes <= w_) {
      std::memcpy(p + x0, &row, sizeof row);
    } else {
      for (int i = 0; x0 + i < w_; ++i) p[x0 + i] = row[i];
    }
  }

  // The moves along row r of the tile (local r in 1 .. kRows), repeated until no lane improves.
  static v8f along_row(const Tile& t, int r, v8f c) {
    const v8f(&st)[8] = *t.steps[r - 1];
    for (;;) {
      const v8f n = vmin(c, vmin(west_of(c, t.west[r]) + st[kW], east_of(c, t.east[r]) + st[kE]));
      if (!any(n < c)) return c;
      c = n;
    }
  }

  // Bottom to top: moves from the row below, then along the row. True if a label changed.
  // closed: every row already holds its along-row fixed point (a sweep ran along_row on it and the
  // ring columns do not change within a run), so a row the moves from the row below or above do
  // not improve stays as it is.
  static bool sweep_up(Tile& t, bool closed) {
    v8i changed{};
    for (int r = 1; r <= kRows; ++r) {
      const v8f(&st)[8] = *t.steps[r - 1];
      const v8f& b = t.row[r - 1];
      v8f c = vmin(t.row[r], b + st[kS]);
      c = vmin(c, west_of(b, t.west[r - 1]) + st[kSW]);
      c = vmin(c, east_of(b, t.east[r - 1]) + st[kSE]);
      if (closed && !any(c < t.row[r])) continue;
      c = along_row(t, r, c);
      changed |= c < t.row[r];
      t.row[r] = c;
    }
    return any(changed);
  }

  static bool sweep_down(Tile& t, bool closed) {
    v8i changed{};
    for (int r = kRows; r >= 1; --r) {
      const v8f(&st)[8] = *t.steps[r - 1];
      const v8f& a = t.row[r + 1];
      v8f c = vmin(t.row[r], a + st[kN]);
      c = vmin(c, west_of(a, t.west[r + 1]) + st[kNW]);
      c = vmin(c, east_of(a, t.east[r + 1]) + st[kNE]);
      if (closed && !any(c < t.row[r])) continue;
      c = along_row(t, r, c);
      changed |= c < t.row[r];
      t.row[r] = c;
    }
    return any(changed);
  }

  void relax_tile(int tx, int ty) {
    ++stats_.tile_runs;
    const int x0 = tx * kLanes;
    const int y0 = ty * kRows;
    Tile& t = tile_;
    if (x0 > 0 && x0 + kLanes < w_ && y0 > 0 && y0 + kRows < h_) {  // the usual case: no edge near
      const float* p = dist_ + static_cast<std::size_t>(y0 - 1) * static_cast<std::size_t>(w_) + x0;
      for (int r = 0; r < kRows + 2; ++r, p += w_) {
        std::memcpy(&t.row[r], p, sizeof t.row[r]);
        t.west[r] = p[-1];
        t.east[r] = p[kLanes];
      }
    } else {
      for (int r = 0; r < kRows + 2; ++r) load_row(y0 + r - 1, x0, t.row[r], t.west[r], t.east[r]);
    }
    load_steps(y0, tx, t);
    for (int r = 0; r < kRows; ++r) t.before[r] = t.row[r + 1];
    // Start from the side the better labels come from; stop when a sweep changes nothing after
    // at least one sweep of each direction (the last sweeps of both directions then hold: every
    // move into the tile is satisfied).
    bool up = hmin(t.row[0]) <= hmin(t.row[kRows + 1]);
    for (int sweeps = 1;; ++sweeps, up = !up) {
      const bool changed = up ? sweep_up(t, sweeps > 1) : sweep_down(t, sweeps > 1);
      if (!changed && sweeps >= 2) {
        stats_.passes += static_cast<std::size_t>(sweeps);
        break;
      }
    }
    // Write back the rows that changed; queue the neighbours that a move from this tile now
    // improves (only those: a neighbour that no move improves is still at its fixed point).
    bool changed = false;
    for (int r = 0; r < kRows; ++r) {
      if (!any(t.row[r + 1] < t.before[r])) continue;
      store_row(y0 + r, x0, t.row[r + 1]);
      changed = true;
      const v8i reached = (t.before[r] == splat(kInf)) & (t.row[r + 1] < splat(kInf));
      stats_.reachable += static_cast<std::size_t>(
          __builtin_popcount(_mm256_movemask_ps(reinterpret_cast<__m256>(reached))));
    }
    if (!changed) return;
    offer_across(t, 1, 0, kS, kSW, kSE, tx, ty - 1);
    offer_across(t, kRows, kRows + 1, kN, kNW, kNE, tx, ty + 1);
    offer_beside(t, 0, kW, kNW, kSW, t.west, tx - 1, ty);
    offer_beside(t, kLanes - 1, kE, kNE, kSE, t.east, tx + 1, ty);
  }

  // Moves from tile row `from` (local 1 or kRows) into the ring row `to` (0 or kRows + 1): to the
  // tile across (tile row ty_to) and, through the corner cells, to its two diagonal neighbours.
  void offer_across(const Tile& t, int from, int to, Move straight, Move to_west, Move to_east,
                    int tx, int ty_to) {
    const v8f& c = t.row[from];
    const v8f(&st)[8] = *t.steps[from - 1];
    const v8f inf = splat(kInf);
    const v8f dw = c + st[to_west];  // lane i offers to lane i - 1
    const v8f de = c + st[to_east];  // lane i offers to lane i + 1
    const v8f offer = vmin(c + st[straight], vmin(east_of(dw, kInf), west_of(de, kInf)));
    const v8i better = offer < t.row[to];
    if (any(better)) activate(tx, ty_to, hmin(better ? offer : inf));
    if (dw[0] < t.west[to]) activate(tx - 1, ty_to, dw[0]);
    if (de[kLanes - 1] < t.east[to]) activate(tx + 1, ty_to, de[kLanes - 1]);
  }

  // Moves from lane `lane` (0 or 7) of tile rows 1 .. kRows into the ring column `ring` beside it
  // (rows 1 .. kRows; the corner cells are offer_across's). Vector lane r - 1 stands for tile row
  // r: the tile's column is gathered, the allowed moves come from the rows' orth / diag bits.
  void offer_beside(const Tile& t, int lane, Move straight, Move up, Move down,
                    const float (&ring)[kRows + 2], int tx_to, int ty) {
    const v8i rows{0, 1, 2, 3, 4, 5, 6, 7};
    const v8f col = reinterpret_cast<v8f>(_mm256_i32gather_ps(
        &t.row[1][lane], reinterpret_cast<__m256i>(rows * kLanes), sizeof(float)));
    const v8f inf = splat(kInf);
    // Bit 8 (m % 4) + lane of each row's word to the sign.
    const auto allowed = [&](Move m) {
      const v8u& words = m < 4 ? t.orth : t.diag;
      return top_bit(words << static_cast<unsigned>(31 - 8 * (m % 4) - lane));
    };
    v8f ring_here, ring_above, ring_below;  // ring rows r, r + 1 and r - 1 for lane r - 1
    std::memcpy(&ring_here, &ring[1], sizeof ring_here);
    std::memcpy(&ring_above, &ring[2], sizeof ring_above);
    std::memcpy(&ring_below, &ring[0], sizeof ring_below);
    const v8f step_s = allowed(straight) ? base_[straight] : inf;
    // The last row's move up and the first row's move down reach the corners: not here.
    const v8i not_top{-1, -1, -1, -1, -1, -1, -1, 0}, not_bottom{0, -1, -1, -1, -1, -1, -1, -1};
    const v8f step_u = (allowed(up) & not_top) ? base_[up] : inf;
    const v8f step_d = (allowed(down) & not_bottom) ? base_[down] : inf;
    const v8f s = col + step_s, u = col + step_u, d = col + step_d;
    const v8f best =
        vmin(s < ring_here ? s : inf, vmin(u < ring_above ? u : inf, d < ring_below ? d : inf));
    const float m = hmin(best);
    if (m < kInf) activate(tx_to, ty, m);
  }

  const OccupancyRaster& raster_;
  std::size_t row_bytes_;
  int w_, h_, tiles_x_, tiles_y_;
  float* dist_;
  double per_bucket_;
  v8f base_[8];
  std::vector<float> pending_;  // per tile: the key it is queued with, +inf when not queued
  std::vector<std::vector<std::uint32_t>> ring_;
  std::size_t queued_ = 0;
  std::uint64_t current_ = 0;
  Tile tile_;
  TileSearchStats stats_;
};

}  // namespace

TileSearchStats tile_search(std::size_t goal, const OccupancyRaster& raster, float orthogonal,
                            float diagonal, float* dist) {
  TileSearch search(raster, orthogonal, diagonal, dist);
  return search.run(goal);
}

#pragma GCC diagnostic pop
#pragma GCC pop_options

bool tile_search_available() {
  return __builtin_cpu_supports("avx2");
}

#else  // no x86 vector code here: compute_cost_to_go uses its cell bucket queue

bool tile_search_available() {
  return false;
}

TileSearchStats tile_search(std::size_t, const OccupancyRaster&, float, float, float*) {
  return {};
}

#endif

}  // namespace autonomy::grid::detail
