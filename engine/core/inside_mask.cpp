#include "inside_mask.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numbers>
#include <numeric>
#include <thread>

#include <glm/geometric.hpp>

#include "task_scheduler.h"

namespace voxflame::core {

double InsideMask::insideFraction() const {
  if (inside.empty()) return 0.0;
  const auto count = std::accumulate(inside.begin(), inside.end(), std::size_t{0});
  return static_cast<double>(count) / static_cast<double>(inside.size());
}

const char* maskMethodName(MaskMethod method) {
  switch (method) {
    case MaskMethod::WindingNumber:
      return "winding-number";
    case MaskMethod::ExactWindingNumber:
      return "exact-winding-number";
    case MaskMethod::Parity:
      return "parity";
  }
  return "unknown";
}

namespace {

int resolveThreads(int threads) {
  if (threads > 0) return threads;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// Runs work(0) … work(threads - 1) as tasks on the shared scheduler and returns when all are done.
// Each index has its own slot in what the work writes (per-thread lists); several may run one after
// the other on one thread, which is harmless: each drains a shared ChunkQueue, never waits for another.
template <class Work>
void onThreads(int threads, const Work& work) {
  parallelFor(static_cast<std::size_t>(std::max(1, threads)), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) work(static_cast<int>(t));
  });
}

// Hands out [begin, end) chunks of [0, count) to whichever thread asks next, so uneven work
// (dense and empty parts of a mesh) still keeps every thread busy.
class ChunkQueue {
 public:
  ChunkQueue(std::size_t count, std::size_t chunk) : count_(count), chunk_(std::max<std::size_t>(1, chunk)) {}
  bool next(std::size_t& begin, std::size_t& end) {
    begin = next_.fetch_add(chunk_, std::memory_order_relaxed);
    if (begin >= count_) return false;
    end = std::min(count_, begin + chunk_);
    return true;
  }

 private:
  std::size_t count_, chunk_;
  std::atomic<std::size_t> next_{0};
};

// Signed solid angle of triangle (a, b, c), given relative to the viewpoint (Van Oosterom and
// Strackee 1983); positive when the viewpoint sees the triangle's back, i.e. is inside.
double solidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double numerator = glm::dot(a, glm::cross(b, c));
  const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(b, c) * la + glm::dot(c, a) * lb;
  return 2.0 * std::atan2(numerator, denominator);
}

constexpr double kFourPi = 4.0 * std::numbers::pi;

// ---------------------------------------------------------------------------------------------
// Ray crossings along grid columns.
//
// A column of axis a runs along a through the voxel centres (u, v) = (iu + 0.5, iv + 0.5), where
// (u, v, a) is right-handed. Each column is nudged off the centres by a fraction no mesh is
// aligned to, so it (almost) never passes exactly through an edge or a vertex. Edge functions are
// evaluated with the edge's vertices in index order and negated for the other direction, so two
// triangles sharing an edge see exactly opposite values and a column is claimed by at most one
// of them: no crossing is counted twice. Anything missed makes the column's signs not sum to
// zero, and the column is then not trusted.

constexpr int kAxisU[3] = {1, 2, 0};
constexpr int kAxisV[3] = {2, 0, 1};
constexpr double kNudge[3][2] = {{1.37e-4, 2.91e-4}, {3.13e-4, 1.71e-4}, {2.23e-4, 1.19e-4}};

// Column index with the layouts the sweep below reads fastest: x columns by (j, k), y columns by
// (i, k), z columns by (i, j), the first one fastest.
std::size_t columnIndex(int axis, int iu, int iv, const glm::ivec3& n) {
  if (axis == 1) return static_cast<std::size_t>(iv) + static_cast<std::size_t>(n.x) * static_cast<std::size_t>(iu);
  return static_cast<std::size_t>(iu) + static_cast<std::size_t>(n[kAxisU[axis]]) * static_cast<std::size_t>(iv);
}

// Calls emit(column, t, sign) for every column of `axis` that crosses the triangle: t is where
// along the column (voxel units), sign +1 where the column enters the mesh, -1 where it leaves.
template <class Emit>
void rasterizeTriangle(const std::vector<glm::dvec3>& p, const std::array<std::uint32_t, 3>& tri, int axis,
                       const glm::ivec3& n, Emit&& emit) {
  const int u = kAxisU[axis], v = kAxisV[axis];
  const double du = kNudge[axis][0], dv = kNudge[axis][1];
  const glm::dvec3& p0 = p[tri[0]];
  const glm::dvec3& p1 = p[tri[1]];
  const glm::dvec3& p2 = p[tri[2]];
  // Clamped before the conversion so that a grid far smaller than the mesh cannot overflow it.
  auto firstColumn = [](double low, int count) {
    return static_cast<int>(std::clamp(std::ceil(low), 0.0, 1.0 * count));
  };
  auto lastColumn = [](double high, int count) {
    return static_cast<int>(std::clamp(std::floor(high), -1.0, count - 1.0));
  };
  const int iu0 = firstColumn(std::min({p0[u], p1[u], p2[u]}) - 0.5 - du, n[u]);
  const int iu1 = lastColumn(std::max({p0[u], p1[u], p2[u]}) - 0.5 - du, n[u]);
  const int iv0 = firstColumn(std::min({p0[v], p1[v], p2[v]}) - 0.5 - dv, n[v]);
  const int iv1 = lastColumn(std::max({p0[v], p1[v], p2[v]}) - 0.5 - dv, n[v]);
  if (iu0 > iu1 || iv0 > iv1) return;
  // orient(a, b, s) > 0 when s lies left of a → b in the (u, v) plane.
  auto edge = [&](std::uint32_t a, std::uint32_t b, double su, double sv) {
    const bool ordered = a < b;
    const glm::dvec3& from = p[ordered ? a : b];
    const glm::dvec3& to = p[ordered ? b : a];
    const double value = (to[u] - from[u]) * (sv - from[v]) - (to[v] - from[v]) * (su - from[u]);
    return ordered ? value : -value;
  };
  for (int iv = iv0; iv <= iv1; ++iv) {
    const double sv = iv + 0.5 + dv;
    for (int iu = iu0; iu <= iu1; ++iu) {
      const double su = iu + 0.5 + du;
      const double e0 = edge(tri[1], tri[2], su, sv);
      const double e1 = edge(tri[2], tri[0], su, sv);
      const double e2 = edge(tri[0], tri[1], su, sv);
      int sign = 0;
      if (e0 > 0.0 && e1 > 0.0 && e2 > 0.0) {
        sign = -1;  // counter-clockwise seen down the column: the normal points along it, leaving
      } else if (e0 < 0.0 && e1 < 0.0 && e2 < 0.0) {
        sign = 1;
      } else {
        continue;
      }
      const double t = (e0 * p0[axis] + e1 * p1[axis] + e2 * p2[axis]) / (e0 + e1 + e2);
      emit(columnIndex(axis, iu, iv, n), t, sign);
    }
  }
}

// Every column's crossings, sorted along the column: compressed rows, one float per crossing
// holding where it is (always > 0) with the crossing's sign as the float's sign.
struct AxisCrossings {
  std::vector<std::uint32_t> offsets;  // columns + 1
  std::vector<float> crossings;
  std::vector<std::uint8_t> closed;  // 1 when the column's signs sum to zero: it can be trusted
};

void collectCrossings(const std::vector<glm::dvec3>& p, const TriangleMesh& mesh, const glm::ivec3& n, int orientation,
                      int threads, AxisCrossings (&axes)[3]) {
  std::vector<std::uint32_t> cursors[3];
  for (int a = 0; a < 3; ++a) {
    const std::size_t columns = static_cast<std::size_t>(n[kAxisU[a]]) * static_cast<std::size_t>(n[kAxisV[a]]);
    axes[a].offsets.assign(columns + 1, 0);
    cursors[a].assign(columns, 0);
  }
  // Each thread rasterises its share of the triangles once into its own list of (column,
  // crossing) records; the records are then counted and scattered into per-column rows.
  struct Record {
    std::uint32_t column;
    float crossing;
  };
  std::vector<std::array<std::vector<Record>, 3>> records(static_cast<std::size_t>(threads));
  {
    ChunkQueue queue(mesh.triangles.size(), 4096);
    onThreads(threads, [&](int thread) {
      auto& mine = records[static_cast<std::size_t>(thread)];
      std::size_t begin = 0, end = 0;
      while (queue.next(begin, end))
        for (std::size_t t = begin; t < end; ++t)
          for (int a = 0; a < 3; ++a)
            rasterizeTriangle(p, mesh.triangles[t], a, n, [&](std::size_t column, double where, int sign) {
              // Any crossing before the first voxel centre (0.5) acts the same; keep it positive.
              const float position = static_cast<float>(std::clamp(where, 0.25, 1.0e9));
              mine[a].push_back({static_cast<std::uint32_t>(column), sign * orientation > 0 ? position : -position});
            });
    });
  }
  onThreads(threads, [&](int thread) {
    for (int a = 0; a < 3; ++a)
      for (const Record& r : records[static_cast<std::size_t>(thread)][a])
        std::atomic_ref<std::uint32_t>(cursors[a][r.column]).fetch_add(1, std::memory_order_relaxed);
  });
  for (int a = 0; a < 3; ++a) {
    std::uint32_t total = 0;
    for (std::size_t c = 0; c < cursors[a].size(); ++c) {
      axes[a].offsets[c] = total;
      total += cursors[a][c];
      cursors[a][c] = axes[a].offsets[c];
    }
    axes[a].offsets.back() = total;
    axes[a].crossings.resize(total);
  }
  onThreads(threads, [&](int thread) {
    for (int a = 0; a < 3; ++a) {
      for (const Record& r : records[static_cast<std::size_t>(thread)][a]) {
        const std::uint32_t slot =
            std::atomic_ref<std::uint32_t>(cursors[a][r.column]).fetch_add(1, std::memory_order_relaxed);
        axes[a].crossings[slot] = r.crossing;
      }
      std::vector<Record>().swap(records[static_cast<std::size_t>(thread)][a]);
    }
  });
  // Sort each column and check that its signs sum to zero.
  for (int a = 0; a < 3; ++a) {
    AxisCrossings& axis = axes[a];
    const std::size_t columns = axis.offsets.size() - 1;
    axis.closed.assign(columns, 1);
    ChunkQueue queue(columns, 4096);
    onThreads(threads, [&](int) {
      std::size_t begin = 0, end = 0;
      while (queue.next(begin, end))
        for (std::size_t c = begin; c < end; ++c) {
          float* first = axis.crossings.data() + axis.offsets[c];
          float* last = axis.crossings.data() + axis.offsets[c + 1];
          if (first == last) continue;
          std::sort(first, last, [](float x, float y) { return std::fabs(x) < std::fabs(y); });
          int sum = 0;
          for (float* f = first; f != last; ++f) sum += *f > 0.0f ? 1 : -1;
          axis.closed[c] = sum == 0;
        }
    });
  }
}

// A column's crossings read in order while walking its voxels: the running sum of the signs
// passed so far is the integer winding number along that column.
struct ColumnWalk {
  const float* next = nullptr;
  const float* end = nullptr;
  int winding = 0;

  void reset(const AxisCrossings& axis, std::size_t column) {
    next = axis.crossings.data() + axis.offsets[column];
    end = axis.crossings.data() + axis.offsets[column + 1];
    winding = 0;
  }
  void advanceTo(float centre) {
    while (next != end && std::fabs(*next) < centre) winding += *next++ > 0.0f ? 1 : -1;
  }
};

InsideMask voteOverAxes(const TriangleMesh& mesh, const GridGeometry& grid, int threads) {
  const glm::ivec3 n = grid.size;
  std::vector<glm::dvec3> p(mesh.vertices.size());
  for (std::size_t v = 0; v < p.size(); ++v) p[v] = (glm::dvec3(mesh.vertices[v]) - grid.origin) / grid.voxelSize;
  const int orientation = meshOrientation(mesh);
  auto clock = std::chrono::steady_clock::now();
  auto lap = [&clock] {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - clock).count();
    clock = now;
    return seconds;
  };
  AxisCrossings axes[3];
  collectCrossings(p, mesh, n, orientation, threads, axes);

  InsideMask mask;
  mask.geometry = grid;
  mask.crossingSeconds = lap();
  mask.inside.resize(grid.voxelCount());
  const std::size_t planeSize = static_cast<std::size_t>(n.x) * static_cast<std::size_t>(n.y);

  // z crossings regrouped by the slice they first count for (a crossing at t counts for every
  // voxel centre beyond t), so a sweep up the slices carries a plane of z votes and touches a
  // column only where it crosses the surface.
  struct ZEvent {
    std::uint32_t column;
    std::int32_t sign;
  };
  auto firstSlice = [](float position) {
    return static_cast<std::size_t>(std::min(std::floor(std::fabs(position) - 0.5f) + 1.0f, 2.0e9f));
  };
  std::vector<std::uint32_t> sliceStart(static_cast<std::size_t>(n.z) + 1, 0);
  for (const float f : axes[2].crossings) {
    const std::size_t k = firstSlice(f);
    if (k < static_cast<std::size_t>(n.z)) ++sliceStart[k + 1];
  }
  for (std::size_t k = 1; k < sliceStart.size(); ++k) sliceStart[k] += sliceStart[k - 1];
  std::vector<ZEvent> zEvents(sliceStart.back());
  {
    std::vector<std::uint32_t> fill(sliceStart.begin(), sliceStart.end() - 1);
    for (std::size_t c = 0; c < planeSize; ++c)
      for (std::uint32_t e = axes[2].offsets[c]; e < axes[2].offsets[c + 1]; ++e) {
        const float f = axes[2].crossings[e];
        const std::size_t k = firstSlice(f);
        if (k < static_cast<std::size_t>(n.z)) zEvents[fill[k]++] = {static_cast<std::uint32_t>(c), f > 0.0f ? 1 : -1};
      }
  }

  // A vote is 0 (the column is not closed: no vote), 1 (outside) or 2 (inside); the table turns
  // three votes into 0 or 1, or kUndecided when fewer than two agree and none dissent.
  constexpr std::uint8_t kUndecided = 2;
  std::uint8_t decide[27];
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) {
        const int in = (x == 2) + (y == 2) + (z == 2), out = (x == 1) + (y == 1) + (z == 1);
        decide[9 * x + 3 * y + z] = in >= 2 && out == 0 ? 1 : (out >= 2 && in == 0 ? 0 : kUndecided);
      }
  auto vote = [](bool closed, int winding) -> std::uint8_t { return closed ? (winding > 0 ? 2 : 1) : 0; };

  std::vector<std::vector<std::size_t>> undecided(static_cast<std::size_t>(threads));
  const std::size_t slabSlices = std::max<std::size_t>(4, static_cast<std::size_t>(n.z) / (4 * threads));
  ChunkQueue slabs(static_cast<std::size_t>(n.z), slabSlices);
  // Slab by slab along z, voxels in memory order: x columns are walked along each row, y columns
  // along each slice, z votes carried in a plane that fits the cache, so every read and write
  // streams.
  onThreads(threads, [&](int thread) {
    std::vector<std::int32_t> zWinding(planeSize);
    std::vector<std::uint8_t> zVote(planeSize), yVote(static_cast<std::size_t>(n.x));
    std::vector<ColumnWalk> yWalks(static_cast<std::size_t>(n.x));
    auto applySlice = [&](std::size_t k) {
      for (std::uint32_t e = sliceStart[k]; e < sliceStart[k + 1]; ++e) {
        const ZEvent event = zEvents[e];
        zWinding[event.column] += event.sign;
        zVote[event.column] = vote(axes[2].closed[event.column], zWinding[event.column]);
      }
    };
    std::size_t kBegin = 0, kEnd = 0;
    while (slabs.next(kBegin, kEnd)) {
      std::fill(zWinding.begin(), zWinding.end(), 0);
      for (std::size_t c = 0; c < planeSize; ++c) zVote[c] = vote(axes[2].closed[c], 0);
      for (std::size_t k = 0; k < kBegin; ++k) applySlice(k);
      for (std::size_t k = kBegin; k < kEnd; ++k) {
        applySlice(k);
        const int kk = static_cast<int>(k);
        for (int i = 0; i < n.x; ++i) {
          const std::size_t yColumn = columnIndex(1, kk, i, n);
          yWalks[i].reset(axes[1], yColumn);
          yVote[i] = vote(axes[1].closed[yColumn], 0);
        }
        for (int j = 0; j < n.y; ++j) {
          const float cy = static_cast<float>(j) + 0.5f;
          const std::size_t xColumn = columnIndex(0, j, kk, n);
          const bool xClosed = axes[0].closed[xColumn];
          ColumnWalk xWalk;
          xWalk.reset(axes[0], xColumn);
          int xVote = vote(xClosed, 0);
          const std::size_t row = grid.index(0, j, kk);
          const std::uint8_t* zRow = zVote.data() + static_cast<std::size_t>(n.x) * static_cast<std::size_t>(j);
          std::uint8_t* out = mask.inside.data() + row;
          for (int i = 0; i < n.x; ++i) {
            const float cx = static_cast<float>(i) + 0.5f;
            if (xWalk.next != xWalk.end && std::fabs(*xWalk.next) < cx) {
              xWalk.advanceTo(cx);
              xVote = vote(xClosed, xWalk.winding);
            }
            ColumnWalk& yWalk = yWalks[i];
            if (yWalk.next != yWalk.end && std::fabs(*yWalk.next) < cy) {
              yWalk.advanceTo(cy);
              yVote[i] = vote(axes[1].closed[columnIndex(1, kk, i, n)], yWalk.winding);
            }
            const std::uint8_t decision = decide[9 * xVote + 3 * yVote[i] + zRow[i]];
            if (decision == kUndecided) {
              out[i] = 0;
              undecided[static_cast<std::size_t>(thread)].push_back(row + static_cast<std::size_t>(i));
            } else {
              out[i] = decision;
            }
          }
        }
      }
    }
  });

  std::vector<std::size_t> pending;
  for (auto& list : undecided) pending.insert(pending.end(), list.begin(), list.end());
  mask.windingNumberVoxels = pending.size();
  mask.sweepSeconds = lap();
  if (pending.empty()) return mask;
  const WindingNumberTree tree(mesh, threads);
  mask.treeSeconds = lap();
  ChunkQueue queue(pending.size(), 256);
  onThreads(threads, [&](int) {
    std::size_t begin = 0, end = 0;
    while (queue.next(begin, end))
      for (std::size_t e = begin; e < end; ++e) {
        const std::size_t index = pending[e];
        const std::size_t i = index % static_cast<std::size_t>(n.x);
        const std::size_t j = (index / static_cast<std::size_t>(n.x)) % static_cast<std::size_t>(n.y);
        const std::size_t k = index / planeSize;
        const glm::dvec3 centre = grid.voxelCenter(static_cast<int>(i), static_cast<int>(j), static_cast<int>(k));
        mask.inside[index] = orientation * tree(centre) >= 0.5;
      }
  });
  mask.windingNumberSeconds = lap();
  return mask;
}

InsideMask exactWindingNumber(const TriangleMesh& mesh, const GridGeometry& grid, int threads) {
  InsideMask mask;
  mask.geometry = grid;
  mask.inside.assign(grid.voxelCount(), 0);
  const int orientation = meshOrientation(mesh);
  ChunkQueue queue(grid.voxelCount(), 64);
  onThreads(threads, [&](int) {
    std::size_t begin = 0, end = 0;
    while (queue.next(begin, end))
      for (std::size_t index = begin; index < end; ++index) {
        const int i = static_cast<int>(index % static_cast<std::size_t>(grid.size.x));
        const int j =
            static_cast<int>((index / static_cast<std::size_t>(grid.size.x)) % static_cast<std::size_t>(grid.size.y));
        const int k = static_cast<int>(index / (static_cast<std::size_t>(grid.size.x) * grid.size.y));
        mask.inside[index] = orientation * windingNumber(mesh, grid.voxelCenter(i, j, k)) >= 0.5;
      }
  });
  mask.windingNumberVoxels = grid.voxelCount();
  return mask;
}

// The seed's method, kept for comparison: crossings along +z only, filled between alternate ones.
constexpr double kParityNudgeX = 1.3e-4;
constexpr double kParityNudgeY = 2.9e-4;

InsideMask parityAlongZ(const TriangleMesh& mesh, const GridGeometry& grid) {
  InsideMask mask;
  mask.geometry = grid;
  mask.inside.assign(grid.voxelCount(), 0);
  const int nx = grid.size.x;
  const int ny = grid.size.y;
  std::vector<std::vector<float>> crossings(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));

  for (const auto& tri : mesh.triangles) {
    glm::dvec3 p[3];
    for (int c = 0; c < 3; ++c) p[c] = (glm::dvec3(mesh.vertices[tri[c]]) - grid.origin) / grid.voxelSize;
    const double minX = std::min({p[0].x, p[1].x, p[2].x});
    const double maxX = std::max({p[0].x, p[1].x, p[2].x});
    const double minY = std::min({p[0].y, p[1].y, p[2].y});
    const double maxY = std::max({p[0].y, p[1].y, p[2].y});
    const int i0 = std::max(0, static_cast<int>(std::ceil(minX - 0.5 - kParityNudgeX)));
    const int i1 = std::min(nx - 1, static_cast<int>(std::floor(maxX - 0.5 - kParityNudgeX)));
    const int j0 = std::max(0, static_cast<int>(std::ceil(minY - 0.5 - kParityNudgeY)));
    const int j1 = std::min(ny - 1, static_cast<int>(std::floor(maxY - 0.5 - kParityNudgeY)));
    if (i0 > i1 || j0 > j1) continue;
    const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    if (area == 0.0) continue;  // edge-on to the columns: no crossing
    for (int j = j0; j <= j1; ++j) {
      const double y = j + 0.5 + kParityNudgeY;
      for (int i = i0; i <= i1; ++i) {
        const double x = i + 0.5 + kParityNudgeX;
        const double w0 = ((p[1].x - x) * (p[2].y - y) - (p[2].x - x) * (p[1].y - y)) / area;
        const double w1 = ((p[2].x - x) * (p[0].y - y) - (p[0].x - x) * (p[2].y - y)) / area;
        const double w2 = 1.0 - w0 - w1;
        if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
        const double z = w0 * p[0].z + w1 * p[1].z + w2 * p[2].z;
        crossings[static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j].push_back(static_cast<float>(z));
      }
    }
  }

  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      auto& zs = crossings[static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j];
      if (zs.size() < 2) continue;
      std::sort(zs.begin(), zs.end());
      for (std::size_t c = 0; c + 1 < zs.size(); c += 2) {
        const int k0 = std::max(0, static_cast<int>(std::ceil(zs[c] - 0.5)));
        const int k1 = std::min(grid.size.z - 1, static_cast<int>(std::floor(zs[c + 1] - 0.5)));
        for (int k = k0; k <= k1; ++k) mask.inside[grid.index(i, j, k)] = 1;
      }
    }
  }
  return mask;
}

}  // namespace

int meshOrientation(const TriangleMesh& mesh) {
  double volume = 0.0;  // six times the signed enclosed volume
  for (const auto& tri : mesh.triangles)
    volume += glm::dot(glm::dvec3(mesh.vertices[tri[0]]),
                       glm::cross(glm::dvec3(mesh.vertices[tri[1]]), glm::dvec3(mesh.vertices[tri[2]])));
  return volume < 0.0 ? -1 : 1;
}

double windingNumber(const TriangleMesh& mesh, const glm::dvec3& point) {
  double sum = 0.0;
  for (const auto& tri : mesh.triangles)
    sum += solidAngle(glm::dvec3(mesh.vertices[tri[0]]) - point, glm::dvec3(mesh.vertices[tri[1]]) - point,
                      glm::dvec3(mesh.vertices[tri[2]]) - point);
  return sum / kFourPi;
}

// ---------------------------------------------------------------------------------------------
// Fast winding number.

struct WindingNumberTree::Node {
  glm::dvec3 centre{0.0};      // area-weighted centre of its triangles
  glm::dvec3 areaNormal{0.0};  // sum of the triangles' normals times their areas
  double area = 0.0;
  double radius = 0.0;      // every triangle of the node lies within this distance of centre
  std::uint32_t first = 0;  // leaf: first triangle in order_; inner: index of the second child
  std::uint32_t count = 0;  // leaf: number of triangles; 0 for an inner node (first child follows it)
};

namespace {

constexpr std::uint32_t kLeafTriangles = 12;

// Spreads the low 10 bits of x so that two zero bits follow each.
std::uint32_t spreadBits(std::uint32_t x) {
  x &= 0x3ffu;
  x = (x | (x << 16)) & 0x030000ffu;
  x = (x | (x << 8)) & 0x0300f00fu;
  x = (x | (x << 4)) & 0x030c30c3u;
  x = (x | (x << 2)) & 0x09249249u;
  return x;
}

}  // namespace

WindingNumberTree::WindingNumberTree(const TriangleMesh& mesh, int threads) : mesh_(&mesh) {
  threads = resolveThreads(threads);
  const std::size_t count = mesh.triangles.size();
  if (count == 0) return;
  // Triangles ordered along a Morton curve of their centres: consecutive runs are compact
  // clusters, so the tree can split runs in half instead of partitioning at every level.
  const Box box = mesh.bounds();
  const glm::dvec3 scale = 1023.0 / glm::max(box.extent(), glm::dvec3(1e-30));
  std::vector<std::uint64_t> keys(count);
  {
    ChunkQueue queue(count, 16384);
    onThreads(threads, [&](int) {
      std::size_t begin = 0, end = 0;
      while (queue.next(begin, end))
        for (std::size_t t = begin; t < end; ++t) {
          const auto& tri = mesh.triangles[t];
          const glm::dvec3 centre = (glm::dvec3(mesh.vertices[tri[0]]) + glm::dvec3(mesh.vertices[tri[1]]) +
                                     glm::dvec3(mesh.vertices[tri[2]])) /
                                    3.0;
          const glm::dvec3 q = glm::clamp((centre - box.min) * scale, glm::dvec3(0.0), glm::dvec3(1023.0));
          const std::uint32_t code = spreadBits(static_cast<std::uint32_t>(q.x)) |
                                     (spreadBits(static_cast<std::uint32_t>(q.y)) << 1) |
                                     (spreadBits(static_cast<std::uint32_t>(q.z)) << 2);
          keys[t] = (static_cast<std::uint64_t>(code) << 32) | static_cast<std::uint64_t>(t);
        }
    });
  }
  // Least-significant-digit radix sort on the 30-bit code (bits 32..61), 10 bits a pass.
  {
    std::vector<std::uint64_t> scratch(count);
    for (int shift = 32; shift < 62; shift += 10) {
      std::vector<std::uint32_t> histogram(1025, 0);
      for (const std::uint64_t key : keys) ++histogram[((key >> shift) & 1023u) + 1];
      for (std::size_t b = 1; b < histogram.size(); ++b) histogram[b] += histogram[b - 1];
      for (const std::uint64_t key : keys) scratch[histogram[(key >> shift) & 1023u]++] = key;
      keys.swap(scratch);
    }
  }
  order_.resize(count);
  for (std::size_t e = 0; e < count; ++e) order_[e] = static_cast<std::uint32_t>(keys[e] & 0xffffffffu);
  std::vector<std::uint64_t>().swap(keys);
  auto corner = [&](std::uint32_t e, int c) { return glm::dvec3(mesh.vertices[mesh.triangles[order_[e]][c]]); };
  // Depth-first: a node's first child directly follows it, so a query walks memory forward.
  // Each top-level subtree is built by its own thread into its own array, then appended.
  auto build = [&](auto&& self, std::vector<Node>& nodes, std::uint32_t begin, std::uint32_t end) -> std::uint32_t {
    const auto index = static_cast<std::uint32_t>(nodes.size());
    nodes.emplace_back();
    Node node;
    if (end - begin <= kLeafTriangles) {
      node.first = begin;
      node.count = end - begin;
      glm::dvec3 weighted(0.0), plain(0.0);
      for (std::uint32_t e = begin; e < end; ++e) {
        const glm::dvec3 a = corner(e, 0), b = corner(e, 1), c = corner(e, 2);
        const glm::dvec3 normal = 0.5 * glm::cross(b - a, c - a);
        const double area = glm::length(normal);
        const glm::dvec3 centre = (a + b + c) / 3.0;
        node.areaNormal += normal;
        node.area += area;
        weighted += area * centre;
        plain += centre;
      }
      node.centre = node.area > 0.0 ? weighted / node.area : plain / static_cast<double>(end - begin);
      double radius2 = 0.0;
      for (std::uint32_t e = begin; e < end; ++e)
        for (int c = 0; c < 3; ++c) {
          const glm::dvec3 d = corner(e, c) - node.centre;
          radius2 = std::max(radius2, glm::dot(d, d));
        }
      node.radius = std::sqrt(radius2);
    } else {
      const std::uint32_t middle = begin + (end - begin) / 2;
      const std::uint32_t left = self(self, nodes, begin, middle);
      const std::uint32_t right = self(self, nodes, middle, end);
      node = combine(nodes[left], nodes[right], right);
    }
    nodes[index] = node;
    return index;
  };
  const auto total = static_cast<std::uint32_t>(count);
  if (threads < 2 || total <= 2 * kLeafTriangles) {
    nodes_.reserve(2 * count / kLeafTriangles * 2 + 4);
    build(build, nodes_, 0, total);
    return;
  }
  const std::uint32_t middle = total / 2;
  std::vector<Node> leftNodes, rightNodes;
  leftNodes.reserve(2 * count / kLeafTriangles + 4);
  rightNodes.reserve(2 * count / kLeafTriangles + 4);
  // The two halves as two tasks: the left one on this thread, the right one wherever one is free.
  parallelFor(2, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t half = begin; half < end; ++half)
      if (half == 0)
        build(build, leftNodes, 0, middle);
      else
        build(build, rightNodes, middle, total);
  });
  // Root, then the left subtree (offset 1), then the right one: shift the child links.
  const auto rightOffset = static_cast<std::uint32_t>(1 + leftNodes.size());
  nodes_.reserve(1 + leftNodes.size() + rightNodes.size());
  nodes_.push_back(combine(leftNodes[0], rightNodes[0], rightOffset));
  for (Node node : leftNodes) {
    if (node.count == 0) node.first += 1;
    nodes_.push_back(node);
  }
  for (Node node : rightNodes) {
    if (node.count == 0) node.first += rightOffset;
    nodes_.push_back(node);
  }
}

WindingNumberTree::Node WindingNumberTree::combine(const Node& l, const Node& r, std::uint32_t rightIndex) {
  Node node;
  node.first = rightIndex;
  node.count = 0;
  node.areaNormal = l.areaNormal + r.areaNormal;
  node.area = l.area + r.area;
  node.centre = node.area > 0.0 ? (l.area * l.centre + r.area * r.centre) / node.area : 0.5 * (l.centre + r.centre);
  node.radius =
      std::max(glm::length(l.centre - node.centre) + l.radius, glm::length(r.centre - node.centre) + r.radius);
  return node;
}

WindingNumberTree::~WindingNumberTree() = default;

double WindingNumberTree::operator()(const glm::dvec3& point, double accuracy) const {
  if (nodes_.empty()) return 0.0;
  double sum = 0.0;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    const glm::dvec3 toCentre = node.centre - point;
    const double distance2 = glm::dot(toCentre, toCentre);
    const double reach = accuracy * node.radius;
    if (distance2 > reach * reach) {
      // Far away the cluster looks like a dipole: solid angle ≈ (c - p)·N / |c - p|³.
      sum += glm::dot(toCentre, node.areaNormal) / (distance2 * std::sqrt(distance2));
    } else if (node.count > 0) {
      for (std::uint32_t e = node.first; e < node.first + node.count; ++e) {
        const auto& tri = mesh_->triangles[order_[e]];
        sum += solidAngle(glm::dvec3(mesh_->vertices[tri[0]]) - point, glm::dvec3(mesh_->vertices[tri[1]]) - point,
                          glm::dvec3(mesh_->vertices[tri[2]]) - point);
      }
    } else {
      const auto self = static_cast<std::uint32_t>(&node - nodes_.data());
      stack[top++] = node.first;
      stack[top++] = self + 1;
    }
  }
  return sum / kFourPi;
}

InsideMask buildInsideMask(const TriangleMesh& mesh, const GridGeometry& grid, MaskMethod method, int threads) {
  threads = resolveThreads(threads);
  switch (method) {
    case MaskMethod::WindingNumber:
      return voteOverAxes(mesh, grid, threads);
    case MaskMethod::ExactWindingNumber:
      return exactWindingNumber(mesh, grid, threads);
    case MaskMethod::Parity:
      return parityAlongZ(mesh, grid);
  }
  return voteOverAxes(mesh, grid, threads);
}

}  // namespace voxflame::core
