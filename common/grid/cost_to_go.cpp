#include "common/grid/cost_to_go.hpp"

#include "common/grid/tile_relaxation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <queue>
#include <utility>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace autonomy::grid {

// Why the bucket queue is exact.
// Let W = res / kBucketsPerRes and bucket(x) = floor(x / W) (computed in double). Every step costs
// at least float(res) >= W * kBucketsPerRes, so for a cell u with label d a relaxation produces
// c = float(d + step) >= d + res - ulp(d)/2, and bucket(c) >= bucket(d) + 1 as long as
// ulp(d) is small against res (d < 2^20 res leaves a margin of > 3 buckets). Hence:
//   - expanding bucket k only pushes into buckets > k, so a bucket never grows while it is read;
//   - when bucket k comes up, every cell whose final label lies in it got that label from a cell
//     in an earlier bucket, which was already expanded: its label is final. Each reachable cell is
//     expanded once, and labels satisfy label(v) = min over neighbours u of float(label(u) +
//     step(u, v)), the same fixed point a textbook float Dijkstra reaches, so the two agree bit
//     for bit (that equation has one solution when every float addition strictly increases).
// A cell may sit in several buckets (it was improved after being pushed); its later copies are
// skipped because expansion clears its move mask. Only buckets [k, k + max_step / W + 2] can hold
// cells, so a small power-of-two ring of reusable vectors is enough.
namespace {

constexpr double kBucketsPerRes = 4.0;  // measured: 2, 4 and 8 are within a few percent
constexpr std::size_t kPrefetchAhead =
    16;  // measured: 8..32 alike; without, 20-30 % slower at 4000^2
constexpr std::size_t kMaxRing = std::size_t{1}
                                 << 12;  // beyond: the heap (ring headers, empty scans)

// Byte j of kUnpack[b] is bit j of b: turns 8 raster bits into 8 bytes of 0/1.
constexpr std::array<std::uint64_t, 256> make_unpack_table() {
  std::array<std::uint64_t, 256> t{};
  for (unsigned b = 0; b < 256; ++b) {
    std::uint64_t v = 0;
    for (unsigned j = 0; j < 8; ++j) v |= static_cast<std::uint64_t>((b >> j) & 1u) << (8 * j);
    t[b] = v;
  }
  return t;
}
constexpr auto kUnpack = make_unpack_table();

// free_row[1 + c] = 1 when cell (c, row) is free; free_row[0] and free_row[width + 1] are 0.
void unpack_free_row(const OccupancyRaster& raster, int row, std::vector<std::uint8_t>& free_row) {
  const auto w = static_cast<std::size_t>(raster.width());
  if (row < 0 || row >= raster.height()) {
    std::fill(free_row.begin(), free_row.end(), 0);
    return;
  }
  const std::uint64_t* words = raster.row_words(row);
  std::uint8_t* out = free_row.data() + 1;
  for (std::size_t k = 0; k < raster.words_per_row(); ++k) {
    const std::uint64_t free_bits = ~words[k];
    for (unsigned b = 0; b < 8; ++b) {
      const std::uint64_t bytes = kUnpack[(free_bits >> (8 * b)) & 0xffu];
      std::memcpy(out + 64 * k + 8 * b, &bytes, 8);
    }
  }
  free_row[0] = 0;
  free_row[w + 1] = 0;  // the padding bits past the width unpacked as "free"
}

// Bit m of mask[i] is set when move kMoves[m] from cell i is allowed (corner rule included);
// blocked cells get 0. A branch-free loop over three padded byte rows that the compiler vectorises.
void build_move_masks(const OccupancyRaster& raster, std::uint8_t* mask,
                      std::vector<std::uint8_t> (&rows)[3]) {
  const int w = raster.width();
  const std::size_t row_bytes = 64 * raster.words_per_row() + 2;
  for (auto& r : rows) r.assign(row_bytes, 0);
  unpack_free_row(raster, -1, rows[0]);
  unpack_free_row(raster, 0, rows[1]);
  for (int row = 0; row < raster.height(); ++row) {
    unpack_free_row(raster, row + 1, rows[(row + 2) % 3]);
    const std::uint8_t* dn = rows[row % 3].data() + 1;
    const std::uint8_t* cur = rows[(row + 1) % 3].data() + 1;
    const std::uint8_t* up = rows[(row + 2) % 3].data() + 1;
    std::uint8_t* out = mask + static_cast<std::size_t>(row) * static_cast<std::size_t>(w);
    for (int c = 0; c < w; ++c) {
      const unsigned e = cur[c + 1], n = up[c], wst = cur[c - 1], s = dn[c];
      const unsigned m = e | (n << 1) | (wst << 2) | (s << 3) | ((up[c + 1] & e & n) << 4) |
                         ((up[c - 1] & wst & n) << 5) | ((dn[c - 1] & wst & s) << 6) |
                         ((dn[c + 1] & e & s) << 7);
      out[c] = static_cast<std::uint8_t>(m & (0u - cur[c]));
    }
  }
}

// The search walks a wave front across the whole field, touching three rows per cell: on a
// 4000 x 4000 map most of those accesses miss the TLB with 4 KiB pages. Asking for transparent
// huge pages before the arrays are first written (Linux "madvise" THP mode) measured about 20 %
// less CPU time there (the kernel may spend a one-off 100-300 ms compacting memory on a busy
// machine). Only a hint: nothing depends on it being honoured; small arrays are left alone.
void advise_huge_pages(void* p, std::size_t bytes) {
#ifdef __linux__
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  if (bytes < 2 * kHuge) return;
  const auto begin = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHuge - 1);
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

struct StepCosts {
  float orthogonal;
  float diagonal;
};

StepCosts step_costs(double res) {
  return {static_cast<float>(res), static_cast<float>(res * std::sqrt(2.0))};
}

template <typename Real>
Real layer_extra(const std::vector<CostLayer>& layers, std::size_t i) {
  Real extra = 0;
  for (const auto& l : layers)
    extra = extra + static_cast<Real>(l.gain) * static_cast<Real>(l.values[i]);
  return extra;
}

// A ring slot: entries [0, n) of `v`. Kept apart from v.size() so that a push can be written
// unconditionally and counted only when it is real (see distance_search).
struct Bucket {
  std::vector<std::uint32_t> v;  // storage; v.size() is the capacity in use
  std::uint32_t* data = nullptr;
  std::size_t n = 0;
  std::size_t cap = 0;

  void make_room(std::size_t k) {
    if (n + k > cap) grow(n + k);
  }
  void grow(std::size_t need) {
    v.resize(std::max<std::size_t>(2 * v.size(), need + 32));
    data = v.data();
    cap = v.size();
  }
};

std::size_t ring_size_for(float max_step, double per_bucket) {
  std::size_t ring_size = 4;
  while (static_cast<double>(ring_size) < std::ceil(max_step * per_bucket) + 3.0) ring_size *= 2;
  return ring_size;
}

std::uint64_t bucket_of(float c, double per_bucket, std::uint64_t k) {
  // Through int64: a double -> uint64 conversion costs a compare and a branch on x86-64.
  // (Any monotone rounding of c * per_bucket keeps the argument above; double keeps it simple.)
  const auto b =
      static_cast<std::uint64_t>(static_cast<std::int64_t>(static_cast<double>(c) * per_bucket));
  return b > k ? b : k + 1;  // b <= k only beyond 2^20 res, where float steps are unreliable anyway
}

void finish_ring_stats(const std::vector<Bucket>& ring, FieldStats& stats) {
  stats.buckets = ring.size();
  for (const auto& b : ring) stats.work_bytes += b.v.capacity() * sizeof(std::uint32_t);
  stats.work_bytes += ring.capacity() * sizeof(Bucket);
}

// Relaxes moves first_bit .. first_bit + 3 of cell i (all with candidate c) and appends the
// improved cells to b, without a data-dependent branch: a move that is not allowed is redirected
// to cell i itself, whose label never improves; the label is written as a min; the index is always
// stored but only counted when it improved.
inline std::size_t relax4(std::uint32_t i, unsigned m, unsigned first_bit, float c,
                          const std::ptrdiff_t* offsets, float* dist, Bucket& b) {
  b.make_room(4);
  std::uint32_t* out = b.data + b.n;
  std::size_t count = 0;
  for (unsigned bit = first_bit; bit < first_bit + 4; ++bit) {
    // Arithmetic select: written as ?: the compiler emits a branch on the mask bit, which
    // mispredicts about every other cell.
    const std::ptrdiff_t keep = -static_cast<std::ptrdiff_t>((m >> bit) & 1u);
    const auto j =
        static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(i) + (offsets[bit] & keep));
    const float old = dist[j];
    const bool better = c < old;
    dist[j] = better ? c : old;
    out[count] = j;
    count += better;
  }
  b.n += count;
  return count;
}

// The search without layers. All four orthogonal neighbours get the same candidate d + orth and
// all four diagonal ones d + diag, so each expansion computes two candidates and two target
// buckets, then relaxes the eight neighbours without a single unpredictable branch: a move that
// is not allowed is redirected to the cell itself (whose label d never improves), the label is
// written as a min, and the cell index is always stored but only counted when it improved.
void distance_search(std::size_t goal, int width, StepCosts steps, double res, std::uint8_t* mask,
                     float* dist, FieldStats& stats) {
  const double per_bucket = kBucketsPerRes / res;
  const std::size_t ring_size = ring_size_for(steps.diagonal, per_bucket);
  const std::size_t ring_mask = ring_size - 1;
  std::vector<Bucket> ring(ring_size);

  const std::ptrdiff_t w = width;
  const std::ptrdiff_t offsets[8] = {1, w, -1, -w, w + 1, w - 1, -w - 1, -w + 1};

  dist[goal] = 0.0f;
  ring[0].make_room(1);
  ring[0].data[ring[0].n++] = static_cast<std::uint32_t>(goal);
  std::size_t pushes = 1;
  std::size_t popped = 0;
  std::size_t expanded = 0;
  for (std::uint64_t k = 0; popped != pushes; ++k) {
    Bucket& bucket = ring[k & ring_mask];
    const std::size_t n = bucket.n;  // expanding bucket k never pushes into it (see above)
    for (std::size_t t = 0; t < n; ++t) {
      if (t + kPrefetchAhead < n) {
        // The worklist is known ahead: fetch the three rows a later expansion will touch.
        // Addresses are formed as integers (a row above row 0 is never dereferenced).
        const std::uint32_t p = bucket.data[t + kPrefetchAhead];
        const auto at = reinterpret_cast<std::uintptr_t>(dist + p);
        const auto row = static_cast<std::uintptr_t>(w) * sizeof(float);
        __builtin_prefetch(mask + p, 1);
        __builtin_prefetch(reinterpret_cast<const void*>(at - row), 1);
        __builtin_prefetch(reinterpret_cast<const void*>(at), 1);
        __builtin_prefetch(reinterpret_cast<const void*>(at + row), 1);
      }
      const std::uint32_t i = bucket.data[t];
      const unsigned m = mask[i];
      if (m == 0) continue;  // expanded already (a stale copy), or a free cell with no moves
      mask[i] = 0;
      ++expanded;
      const float d = dist[i];
      // The four orthogonal moves share one candidate and one bucket, so do the four diagonals.
      // The groups are relaxed one after the other, so they may even share a bucket.
      const float c_orth = d + steps.orthogonal;
      const float c_diag = d + steps.diagonal;
      pushes += relax4(i, m, 0, c_orth, offsets, dist,
                       ring[bucket_of(c_orth, per_bucket, k) & ring_mask]);
      pushes += relax4(i, m, 4, c_diag, offsets, dist,
                       ring[bucket_of(c_diag, per_bucket, k) & ring_mask]);
    }
    popped += n;
    bucket.n = 0;
  }
  stats.pushes = pushes;
  stats.expanded = expanded;
  finish_ring_stats(ring, stats);
}

// The search with layers: every neighbour has its own candidate and bucket.
void layered_search(std::size_t goal, int width, StepCosts steps, float max_step, double res,
                    const std::vector<CostLayer>& layers, std::uint8_t* mask, float* dist,
                    FieldStats& stats) {
  const double per_bucket = kBucketsPerRes / res;
  const std::size_t ring_size = ring_size_for(max_step, per_bucket);
  const std::size_t ring_mask = ring_size - 1;
  std::vector<Bucket> ring(ring_size);

  const std::ptrdiff_t w = width;
  const std::ptrdiff_t offsets[8] = {1, w, -1, -w, w + 1, w - 1, -w - 1, -w + 1};
  const float base[8] = {steps.orthogonal, steps.orthogonal, steps.orthogonal, steps.orthogonal,
                         steps.diagonal,   steps.diagonal,   steps.diagonal,   steps.diagonal};

  dist[goal] = 0.0f;
  ring[0].make_room(1);
  ring[0].data[ring[0].n++] = static_cast<std::uint32_t>(goal);
  std::size_t live = 1;
  std::size_t pushes = 1;
  std::size_t expanded = 0;
  for (std::uint64_t k = 0; live != 0; ++k) {
    Bucket& bucket = ring[k & ring_mask];
    const std::size_t n = bucket.n;
    for (std::size_t t = 0; t < n; ++t) {
      const std::uint32_t i = bucket.data[t];
      unsigned m = mask[i];
      if (m == 0) continue;
      mask[i] = 0;
      ++expanded;
      const float d = dist[i];
      while (m != 0) {
        const unsigned bit = static_cast<unsigned>(__builtin_ctz(m));
        m &= m - 1;
        const std::size_t j =
            static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + offsets[bit]);
        const float c = d + (base[bit] + layer_extra<float>(layers, j));
        if (c < dist[j]) {
          dist[j] = c;
          Bucket& b = ring[bucket_of(c, per_bucket, k) & ring_mask];
          b.make_room(1);
          b.data[b.n++] = static_cast<std::uint32_t>(j);
          ++live;
          ++pushes;
        }
      }
    }
    live -= n;
    bucket.n = 0;
  }
  stats.pushes = pushes;
  stats.expanded = expanded;
  finish_ring_stats(ring, stats);
}

// Exact fallback for layers whose costs dwarf the resolution (the ring would be too long): a binary
// heap with lazy deletion over the same masks. Slower, same labels.
void heap_search(std::size_t goal, int width, StepCosts steps, const std::vector<CostLayer>& layers,
                 std::uint8_t* mask, float* dist, FieldStats& stats) {
  const std::ptrdiff_t w = width;
  const std::ptrdiff_t offsets[8] = {1, w, -1, -w, w + 1, w - 1, -w - 1, -w + 1};
  using Entry = std::pair<float, std::uint32_t>;
  std::vector<Entry> heap;
  const auto later = std::greater<Entry>();
  dist[goal] = 0.0f;
  heap.push_back({0.0f, static_cast<std::uint32_t>(goal)});
  std::size_t pushes = 1;
  std::size_t expanded = 0;
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const auto [d, i] = heap.back();
    heap.pop_back();
    unsigned m = mask[i];
    if (m == 0) continue;
    mask[i] = 0;
    ++expanded;
    while (m != 0) {
      const unsigned bit = static_cast<unsigned>(__builtin_ctz(m));
      m &= m - 1;
      const std::size_t j = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + offsets[bit]);
      const float step =
          (bit < 4 ? steps.orthogonal : steps.diagonal) + layer_extra<float>(layers, j);
      const float c = d + step;
      if (c < dist[j]) {
        dist[j] = c;
        heap.push_back({c, static_cast<std::uint32_t>(j)});
        std::push_heap(heap.begin(), heap.end(), later);
        ++pushes;
      }
    }
  }
  stats.pushes = pushes;
  stats.expanded = expanded;
  stats.heap_fallback = true;
  stats.work_bytes += heap.capacity() * sizeof(Entry);
}

// Checks the layers; on success sets max_extra to the largest extra cost any cell can add.
std::string check_layers(const OccupancyRaster& raster, const std::vector<CostLayer>& layers,
                         float& max_extra) {
  max_extra = 0.0f;
  if (layers.empty()) return {};
  for (std::size_t k = 0; k < layers.size(); ++k) {
    const auto& l = layers[k];
    if (l.values == nullptr || l.size != raster.cell_count()) {
      return "cost layer " + std::to_string(k) + " has " + std::to_string(l.size) + " values for " +
             std::to_string(raster.cell_count()) + " cells";
    }
    if (!std::isfinite(l.gain) || l.gain < 0.0f) {
      return "cost layer " + std::to_string(k) + " has a negative or non-finite gain";
    }
    for (std::size_t i = 0; i < l.size; ++i) {
      if (!(l.values[i] >= 0.0f) || !std::isfinite(l.values[i])) {
        return "cost layer " + std::to_string(k) + " has a negative or non-finite value at index " +
               std::to_string(i) + " (obstacles belong in the raster)";
      }
    }
  }
  // The per-cell sum is monotone in each term, so its maximum is bounded by the sum of maxima.
  for (std::size_t i = 0; i < raster.cell_count(); ++i) {
    max_extra = std::max(max_extra, layer_extra<float>(layers, i));
  }
  if (!std::isfinite(max_extra)) return "cost layers overflow float";
  return {};
}

}  // namespace

CostField::CostField(int width, int height, double resolution_m, Cell goal,
                     std::vector<float> costs)
    : width_(width),
      height_(height),
      resolution_m_(resolution_m),
      goal_(goal),
      costs_(std::move(costs)) {
  assert(costs_.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
}

std::optional<Step> CostField::downhill_step(Cell c) const {
  const float here = cost(c);
  if (!(here < kUnreachable) || here == 0.0f) return std::nullopt;
  std::optional<Step> best;
  float best_cost = here;
  for (const auto& m : kMoves) {
    const float v = cost({c.col + m.dc, c.row + m.dr});
    if (!(v < best_cost)) continue;
    const bool diagonal = m.dc != 0 && m.dr != 0;
    if (diagonal && (!reachable({c.col + m.dc, c.row}) || !reachable({c.col, c.row + m.dr})))
      continue;
    best_cost = v;
    best = m;
  }
  return best;
}

geometry::Vec2 CostField::advice(Cell c) const {
  const auto s = downhill_step(c);
  if (!s) return geometry::Vec2::Zero();
  return geometry::Vec2(s->dc, s->dr).normalized();
}

const char* to_string(FieldStatus s) {
  switch (s) {
    case FieldStatus::kOk:
      return "ok";
    case FieldStatus::kGoalOutside:
      return "goal outside the map";
    case FieldStatus::kGoalBlocked:
      return "goal on a blocked cell";
    case FieldStatus::kBadLayer:
      return "bad cost layer";
    case FieldStatus::kTooLarge:
      return "map too large";
  }
  return "?";
}

FieldResult compute_cost_to_go(const OccupancyRaster& raster, Cell goal,
                               const std::vector<CostLayer>& layers) {
  FieldResult result;
  const std::size_t n = raster.cell_count();
  result.stats.cells = n;
  std::vector<float> dist;
  dist.reserve(n);
  advise_huge_pages(dist.data(), n * sizeof(float));
  dist.assign(n, kUnreachable);
  result.stats.work_bytes = dist.capacity() * sizeof(float);

  float max_extra = 0.0f;
  if (!raster.contains(goal)) {
    result.status = FieldStatus::kGoalOutside;
    result.reason = "goal cell (" + std::to_string(goal.col) + ", " + std::to_string(goal.row) +
                    ") is outside the " + std::to_string(raster.width()) + " x " +
                    std::to_string(raster.height()) + " map";
  } else if (raster.blocked(goal)) {
    result.status = FieldStatus::kGoalBlocked;
    result.reason =
        "goal cell (" + std::to_string(goal.col) + ", " + std::to_string(goal.row) + ") is blocked";
  } else if (n > std::numeric_limits<std::uint32_t>::max()) {
    result.status = FieldStatus::kTooLarge;
    result.reason = std::to_string(n) + " cells exceed the 2^32 - 1 the search can index";
  } else if (auto why = check_layers(raster, layers, max_extra); !why.empty()) {
    result.status = FieldStatus::kBadLayer;
    result.reason = std::move(why);
  } else if (layers.empty() && detail::tile_search_available()) {
    // No move masks here: the tile search reads the raster's bits for the tiles it reaches.
    const StepCosts steps = step_costs(raster.resolution_m());
    const std::size_t g = raster.index(goal);
    dist[g] = 0.0f;
    const auto t = detail::tile_search(g, raster, steps.orthogonal, steps.diagonal, dist.data());
    result.stats.expanded = t.reachable;
    result.stats.pushes = t.tile_runs;
    result.stats.tiles = t.tiles;
    result.stats.tile_runs = t.tile_runs;
    result.stats.tile_sweeps = t.passes;
    result.stats.buckets = t.buckets;
    result.stats.work_bytes += t.work_bytes;
    result.stats.reachable = std::max<std::size_t>(result.stats.expanded, 1);
  } else {
    std::vector<std::uint8_t> mask;
    mask.reserve(n);
    advise_huge_pages(mask.data(), n);
    mask.resize(n);
    {
      std::vector<std::uint8_t> rows[3];
      build_move_masks(raster, mask.data(), rows);
      for (const auto& r : rows) result.stats.work_bytes += r.capacity();
    }
    result.stats.work_bytes += mask.capacity();

    const double res = raster.resolution_m();
    const StepCosts steps = step_costs(res);
    const float max_step = steps.diagonal + max_extra;
    const std::size_t g = raster.index(goal);
    // The ring costs about 200 bytes per bucket once used; keep it under ~1.5 bytes per cell.
    const double ring_limit =
        static_cast<double>(std::min(kMaxRing, std::max<std::size_t>(64, n / 128)));
    if (static_cast<double>(ring_size_for(max_step, kBucketsPerRes / res)) > ring_limit) {
      heap_search(g, raster.width(), steps, layers, mask.data(), dist.data(), result.stats);
    } else if (layers.empty()) {
      distance_search(g, raster.width(), steps, res, mask.data(), dist.data(), result.stats);
    } else {
      layered_search(g, raster.width(), steps, max_step, res, layers, mask.data(), dist.data(),
                     result.stats);
    }
    result.stats.reachable =
        std::max<std::size_t>(result.stats.expanded, 1);  // a goal with no moves
  }
  result.field =
      CostField(raster.width(), raster.height(), raster.resolution_m(), goal, std::move(dist));
  return result;
}

template <typename Real>
std::vector<Real> reference_dijkstra(const OccupancyRaster& raster, Cell goal,
                                     const std::vector<CostLayer>& layers) {
  constexpr Real kInf = std::numeric_limits<Real>::infinity();
  std::vector<Real> cost(raster.cell_count(), kInf);
  if (!raster.contains(goal) || raster.blocked(goal)) return cost;
  const double res = raster.resolution_m();
  Real orthogonal, diagonal;
  if constexpr (std::is_same_v<Real, float>) {
    const StepCosts s = step_costs(res);
    orthogonal = s.orthogonal;
    diagonal = s.diagonal;
  } else {
    orthogonal = res;
    diagonal = res * std::sqrt(2.0);
  }
  const auto is_free = [&raster](int col, int row) { return !raster.blocked({col, row}); };

  using Entry = std::pair<Real, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const std::size_t start = raster.index(goal);
  cost[start] = 0;
  open.push({Real(0), start});
  const auto w = static_cast<std::size_t>(raster.width());
  while (!open.empty()) {
    const auto [d, index] = open.top();
    open.pop();
    if (d > cost[index]) continue;
    const int col = static_cast<int>(index % w);
    const int row = static_cast<int>(index / w);
    for (const auto& m : kMoves) {
      const int nc = col + m.dc;
      const int nr = row + m.dr;
      if (!is_free(nc, nr)) continue;
      const bool diag = m.dc != 0 && m.dr != 0;
      if (diag && (!is_free(nc, row) || !is_free(col, nr))) continue;
      const std::size_t to = raster.index({nc, nr});
      Real step = diag ? diagonal : orthogonal;
      if (!layers.empty()) step = step + layer_extra<Real>(layers, to);
      const Real candidate = d + step;
      if (candidate < cost[to]) {
        cost[to] = candidate;
        open.push({candidate, to});
      }
    }
  }
  return cost;
}

template std::vector<float> reference_dijkstra<float>(const OccupancyRaster&, Cell,
                                                      const std::vector<CostLayer>&);
template std::vector<double> reference_dijkstra<double>(const OccupancyRaster&, Cell,
                                                        const std::vector<CostLayer>&);

}  // namespace autonomy::grid
