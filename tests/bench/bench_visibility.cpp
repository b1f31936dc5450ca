// Speed of the visibility sweep (paper section IV-B) against two floors and a trusted peer.
//
// Input, for n = 64 … 16384 edges: a square room with random star-shaped 12-gon holes on a
// jittered grid (n = 1024: 85 holes), alternately targets and obstacles; the viewpoint in the
// middle of the room, in a cell left free.
//  - Preprocess:  Occluders::build (Algorithm 1 line 1), once per World.
//  - Sweep:       one camera, θ = 45°: S and visibleBy (Algorithm 1 lines 3–17), as the tool
//                 runs it: from 1024 pieces on, culled first (Culling, OcclusionCulling).
//  - Polygon:     the omnidirectional visibility polygon (Algorithm 2 line 6), likewise.
//  - …Whole:      the same, always over the whole scene (the sweep's own growth).
//  - …Culled:     the same, always culled first (what culling costs where it cannot pay).
//  - SortDoubles: std::sort of 2n random doubles, the floor any O(n log n) sweep is held to.
//  - CGAL (when found): Triangular_expansion_visibility_2 and Rotational_sweep_visibility_2
//    queries with the exact kernel Epeck; preprocessing (arrangement, triangulation) excluded.
//    Their polygon area is checked against ours before timing.
// `bench_visibility --epick-check` instead tries the same CGAL queries with the inexact kernel
// Epick, each in a child process, and reports whether they return, throw or crash.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <vector>

#include "geometry/ring.h"
#include "kinematics/world.h"
#include "support/splitmix64.h"
#include "visibility/sweep.h"

#ifdef CAMCOV_BENCH_WITH_CGAL
#include <sys/wait.h>
#include <unistd.h>

#include <CGAL/Arr_naive_point_location.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Rotational_sweep_visibility_2.h>
#include <CGAL/Triangular_expansion_visibility_2.h>
#endif

namespace {

using camcov::geometry::Ring;
using camcov::geometry::Vec2;
namespace vis = camcov::visibility;

constexpr double kCell = 10.0;  // one hole per cell of this side

using Random = camcov::testing::SplitMix64;  // the same scenes on every machine

struct Scene {
  camcov::kinematics::World world;
  Vec2 viewpoint;
};

// A room of ⌈√(holes + 1)⌉² cells; every cell but the middle one may hold a hole.
Scene roomWithHoles(int edges) {
  const int holes = std::max(1, (edges - 4) / 12);
  const int side = static_cast<int>(std::ceil(std::sqrt(holes + 1.0)));
  const double size = side * kCell;
  Scene scene;
  scene.world.boundary = {{0, 0}, {size, 0}, {size, size}, {0, size}};
  const int free = (side / 2) * side + side / 2;
  scene.viewpoint = {(side / 2 + 0.5) * kCell, (side / 2 + 0.5) * kCell};
  Random random{static_cast<std::uint64_t>(edges)};
  std::vector<int> cells;
  for (int c = 0; c < side * side; ++c) {
    if (c != free) cells.push_back(c);
  }
  for (std::size_t i = cells.size(); i > 1; --i) {  // Fisher–Yates: which cells get holes
    std::swap(cells[i - 1],
              cells[static_cast<std::size_t>(random.uniform(0, static_cast<double>(i)))]);
  }
  for (int h = 0; h < holes; ++h) {
    const int c = cells[static_cast<std::size_t>(h)];
    const Vec2 centre{(c % side + 0.5) * kCell + random.uniform(-0.8, 0.8),
                      (c / side + 0.5) * kCell + random.uniform(-0.8, 0.8)};
    Ring hole;
    for (int k = 0; k < 12; ++k) {
      const double angle = (k + random.uniform(0.1, 0.9)) * 2.0 * std::numbers::pi / 12.0;
      hole.push_back(centre + camcov::geometry::unitVector(angle) * random.uniform(1.5, 4.0));
    }
    (h % 2 == 0 ? scene.world.targets : scene.world.obstacles).push_back(hole);
  }
  return scene;
}

const std::vector<int> kSizes{64, 256, 1024, 4096, 16384};

void sizes(benchmark::internal::Benchmark* b) {
  for (const int n : kSizes)
    b->Arg(n);
}

void Preprocess(benchmark::State& state) {
  const Scene scene = roomWithHoles(static_cast<int>(state.range(0)));
  vis::Occluders occluders;
  for (auto _ : state) {
    occluders.build(scene.world);
    benchmark::DoNotOptimize(occluders.pieceCount());
  }
  state.counters["edges"] = occluders.pieceCount();
}
BENCHMARK(Preprocess)->Apply(sizes);

// How a benchmark row sweeps: as the tool does (culling from Culling::fromPieces pieces on),
// always over the whole scene, or always culled first.
enum class Mode { AsTool, Whole, Culled };
vis::Culling culling(Mode mode) {
  switch (mode) {
    case Mode::AsTool:
      break;
    case Mode::Whole:
      return {UINT32_MAX};
    case Mode::Culled:
      return {0};
  }
  return {};
}

// The share of queries culled first, and the chains they left out, per query.
void countCulling(benchmark::State& state, const vis::Sweep& sweep) {
  const vis::CullingCounts& n = sweep.counts();
  const auto queries = static_cast<double>(n.culled + n.whole);
  state.counters["culled"] = static_cast<double>(n.culled) / queries;
  state.counters["leftOut"] = static_cast<double>(n.chainsLeftOut) / queries;
}

template <Mode kMode>
void Sweep(benchmark::State& state) {
  const Scene scene = roomWithHoles(static_cast<int>(state.range(0)));
  const vis::Occluders occluders(scene.world);
  vis::Sweep sweep(culling(kMode));
  std::vector<vis::Segment> segments;
  // Three yaws a few ulps apart in turn: the Sweep keeps a camera's last two sweeps and would
  // answer a repeated pose without sweeping.
  camcov::geometry::Pose camera{scene.viewpoint.x, scene.viewpoint.y, 0.3};
  int turn = 0;
  for (auto _ : state) {
    camera.yaw = 0.3 + 1e-15 * turn;
    turn = (turn + 1) % 3;
    sweep.segments(occluders, {&camera, 1}, std::numbers::pi / 4, segments);
    benchmark::DoNotOptimize(segments.data());
  }
  state.counters["segments"] = static_cast<double>(segments.size());
  state.counters["chains"] = static_cast<double>(occluders.chains().size());
  countCulling(state, sweep);
}
BENCHMARK_TEMPLATE(Sweep, Mode::AsTool)->Name("Sweep")->Apply(sizes);
BENCHMARK_TEMPLATE(Sweep, Mode::Whole)->Name("SweepWhole")->Apply(sizes);
BENCHMARK_TEMPLATE(Sweep, Mode::Culled)->Name("SweepCulled")->Apply(sizes);

template <Mode kMode>
void Polygon(benchmark::State& state) {
  const Scene scene = roomWithHoles(static_cast<int>(state.range(0)));
  const vis::Occluders occluders(scene.world);
  vis::Sweep sweep(culling(kMode));
  Ring polygon;
  for (auto _ : state) {
    sweep.visibilityPolygon(occluders, scene.viewpoint, polygon);
    benchmark::DoNotOptimize(polygon.data());
  }
  state.counters["vertices"] = static_cast<double>(polygon.size());
  state.counters["chains"] = static_cast<double>(occluders.chains().size());
  countCulling(state, sweep);
}
BENCHMARK_TEMPLATE(Polygon, Mode::AsTool)->Name("Polygon")->Apply(sizes);
BENCHMARK_TEMPLATE(Polygon, Mode::Whole)->Name("PolygonWhole")->Apply(sizes);
BENCHMARK_TEMPLATE(Polygon, Mode::Culled)->Name("PolygonCulled")->Apply(sizes);

void SortDoubles(benchmark::State& state) {
  Random random{42};
  std::vector<double> input(2 * static_cast<std::size_t>(state.range(0)));
  for (double& v : input)
    v = random.uniform(0.0, 4.0);
  std::vector<double> work(input.size());
  for (auto _ : state) {
    std::copy(input.begin(), input.end(), work.begin());
    std::sort(work.begin(), work.end());
    benchmark::DoNotOptimize(work.data());
  }
}
BENCHMARK(SortDoubles)->Apply(sizes);

#ifdef CAMCOV_BENCH_WITH_CGAL

template <typename Kernel>
struct CgalScene {
  using Traits = CGAL::Arr_segment_traits_2<Kernel>;
  using Arrangement = CGAL::Arrangement_2<Traits>;
  using Point = typename Kernel::Point_2;

  Arrangement arrangement;
  Point viewpoint;
  typename Arrangement::Face_const_handle face;

  explicit CgalScene(const Scene& scene) : viewpoint(scene.viewpoint.x, scene.viewpoint.y) {
    std::vector<typename Traits::Segment_2> segments;
    auto add = [&segments](const Ring& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
        segments.emplace_back(Point(a.x, a.y), Point(b.x, b.y));
      }
    };
    add(scene.world.boundary);
    for (const Ring& r : scene.world.obstacles)
      add(r);
    for (const Ring& r : scene.world.targets)
      add(r);
    CGAL::insert(arrangement, segments.begin(), segments.end());
    CGAL::Arr_naive_point_location<Arrangement> locator(arrangement);
    const auto location = locator.locate(viewpoint);  // a boost::variant in CGAL 5.5
    face = *boost::get<typename Arrangement::Face_const_handle>(&location);
  }
};

// Area of the bounded face of a visibility output arrangement.
template <typename Arrangement>
double outputArea(const Arrangement& out) {
  double area = 0.0;
  for (auto f = out.faces_begin(); f != out.faces_end(); ++f) {
    if (f->is_unbounded()) continue;
    auto e = f->outer_ccb();
    const auto first = e;
    do {
      const double x0 = CGAL::to_double(e->source()->point().x()),
                   y0 = CGAL::to_double(e->source()->point().y());
      const double x1 = CGAL::to_double(e->target()->point().x()),
                   y1 = CGAL::to_double(e->target()->point().y());
      area += 0.5 * (x0 * y1 - x1 * y0);
    } while (++e != first);
  }
  return area;
}

template <template <typename> class Visibility>
void CgalQuery(benchmark::State& state) {
  using Exact = CgalScene<CGAL::Exact_predicates_exact_constructions_kernel>;
  const Scene scene = roomWithHoles(static_cast<int>(state.range(0)));
  Exact cgal(scene);
  Visibility<typename Exact::Arrangement> visibility(cgal.arrangement);
  typename Exact::Arrangement out;
  // The trusted peer and the sweep must see the same region.
  visibility.compute_visibility(cgal.viewpoint, cgal.face, out);
  Ring polygon;
  vis::Sweep sweep;
  sweep.visibilityPolygon(vis::Occluders(scene.world), scene.viewpoint, polygon);
  const double ours = camcov::geometry::signedArea(polygon), theirs = outputArea(out);
  if (std::abs(ours - theirs) > 1e-9 * theirs) {
    state.SkipWithError("visibility polygon areas differ from CGAL's");
    return;
  }
  for (auto _ : state) {
    visibility.compute_visibility(cgal.viewpoint, cgal.face, out);
    benchmark::DoNotOptimize(out.number_of_vertices());
  }
  state.counters["areaDiff"] = std::abs(ours - theirs);
}

template <typename Arrangement>
using Triangular = CGAL::Triangular_expansion_visibility_2<Arrangement>;
template <typename Arrangement>
using Rotational = CGAL::Rotational_sweep_visibility_2<Arrangement>;

BENCHMARK_TEMPLATE(CgalQuery, Triangular)->Name("CgalTriangularExpansion")->Apply(sizes);
BENCHMARK_TEMPLATE(CgalQuery, Rotational)->Name("CgalRotationalSweep")->Apply(sizes);

// Runs `query` in a child process: "ok", "threw: …" or "crashed (signal n)".
template <typename Query>
void inChild(const char* what, int n, Query query) {
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid == 0) {
    try {
      query();
      std::_Exit(0);
    } catch (const std::exception& e) {
      std::printf("%-22s n=%-6d threw: %.100s\n", what, n, e.what());
      std::fflush(stdout);
      std::_Exit(3);
    }
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) std::printf("%-22s n=%-6d ok\n", what, n);
  if (WIFSIGNALED(status))
    std::printf("%-22s n=%-6d crashed (signal %d)\n", what, n, WTERMSIG(status));
}

void epickCheck() {
  using Inexact = CgalScene<CGAL::Exact_predicates_inexact_constructions_kernel>;
  for (const int n : kSizes) {
    const Scene scene = roomWithHoles(n);
    inChild("Epick arrangement", n, [&] { Inexact cgal(scene); });
    inChild("Epick triangular", n, [&] {
      Inexact cgal(scene);
      Triangular<Inexact::Arrangement> visibility(cgal.arrangement);
      Inexact::Arrangement out;
      visibility.compute_visibility(cgal.viewpoint, cgal.face, out);
    });
    inChild("Epick rotational", n, [&] {
      Inexact cgal(scene);
      Rotational<Inexact::Arrangement> visibility(cgal.arrangement);
      Inexact::Arrangement out;
      visibility.compute_visibility(cgal.viewpoint, cgal.face, out);
    });
  }
}

#endif

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--epick-check") == 0) {
#ifdef CAMCOV_BENCH_WITH_CGAL
    epickCheck();
    return 0;
#else
    std::puts("built without CGAL");
    return 1;
#endif
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
