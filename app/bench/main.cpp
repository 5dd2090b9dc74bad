// sandstorm-bench: the particle system's stages timed on the GPU against the
// hardware's own ceilings, measured in the same run (see --help and
// docs/PERFORMANCE.md). Headless: an EGL context, no window, no files read.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "app/bench/bench_options.h"
#include "app/bench/bench_report.h"
#include "app/bench/bench_scene.h"
#include "contexts/bench/bench_view.h"
#include "contexts/bench/ceilings.h"
#include "contexts/bench/gpu_info.h"
#include "contexts/bench/sort_bench.h"
#include "contexts/particles/particle_system.h"
#include "contexts/platform/egl_context.h"
#include "contexts/render/view_targets.h"
#include "contexts/solver/gpu_fluid_solver.h"
#include "core/util/error.h"

namespace sandstorm::bench {
namespace {

constexpr double kRecordBytes = 32.0;  // position + life, velocity + kind

class Bench {
 public:
  Bench(const BenchOptions& options, Report& report, std::size_t memory)
      : o_(options), report_(report), memory_(memory) {}

  void run() {
    const auto has = [&](const char* s) {
      for (const std::string& x : o_.sections)
        if (x == s) return true;
      return false;
    };
    plan(has("ceilings"), has("update"), has("render"), has("walls"));
    if (has("sort")) total_ += int(o_.sortKeys.size());
    if (has("solver")) total_ += int(o_.solverGrids.size());
    if (has("verify")) {
      ++total_;
      for (const std::string& field : o_.fields)
        verify(field);
    }
    warmUpGpu();
    copyBandwidth();
    if (has("ceilings"))
      for (std::size_t n : o_.particles) {
        bareTf(n);
        bareCompute(n);
        barePoints(n);
      }
    if (has("update"))
      for (std::size_t n : o_.particles)
        for (const std::string& backend : o_.backends)
          for (const std::string& field : o_.fields)
            for (int obstacles : o_.updateObstacles)
              for (int molecules : o_.updateMolecules)
                update(n, backend, field, obstacles, molecules);
    if (has("render"))
      for (std::size_t n : o_.particles)
        for (const std::string& renderer : o_.renderers)
          if (renderer != "billboards" || n <= o_.billboardLimit) render(n, renderer);
    if (has("sort"))
      for (std::size_t n : o_.sortKeys)
        sort(n);
    if (has("solver"))
      for (const glm::ivec3& grid : o_.solverGrids)
        solver(grid);
    if (has("walls"))
      for (int w : o_.walls)
        for (const std::string& sim : o_.wallSims)
          for (const std::string& renderer : o_.wallRenderers)
            for (int trails : o_.wallTrails)
              for (int shadows : o_.wallShadows)
                walls(w, sim, renderer, trails, shadows != 0);
  }

 private:
  void plan(bool ceilings, bool update, bool render, bool walls) {
    total_ = 1;
    bool tf = false;
    for (const std::string& b : o_.backends)
      tf = tf || b == "tf-gs";
    if (ceilings || (update && tf)) total_ += int(o_.particles.size());  // bare transform feedback
    if (ceilings || render) total_ += int(o_.particles.size());          // bare point draw
    if (ceilings || update) total_ += int(o_.particles.size());          // bare compute update
    if (update)
      total_ += int(o_.particles.size() * o_.backends.size() * o_.fields.size() *
                    o_.updateObstacles.size() * o_.updateMolecules.size());
    if (render)
      for (std::size_t n : o_.particles)
        for (const std::string& r : o_.renderers)
          total_ += (r != "billboards" || n <= o_.billboardLimit) ? 1 : 0;
    if (walls)
      total_ += int(o_.walls.size() * o_.wallSims.size() * o_.wallRenderers.size() *
                    o_.wallTrails.size() * o_.wallShadows.size());
  }

  // A GPU just started (or idle) runs its first seconds slow: on a fresh H100
  // the second and third stages of an update sweep measured 4-5x their later
  // time (docs/PERFORMANCE.md). Keep it busy first.
  void warmUpGpu() {
    if (o_.gpuWarmupSeconds <= 0.0) return;
    progress(concat("warming the GPU up for ", o_.gpuWarmupSeconds, " s"));
    const auto until =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(o_.gpuWarmupSeconds);
    while (std::chrono::steady_clock::now() < until)
      bench::shaderCopyBandwidth(std::size_t{256} << 20, 5);
  }

  void progress(const std::string& what) {
    writeJson(report_, o_.json);  // what is measured so far survives a run cut short
    ++done_;
    std::fprintf(stderr, "[%d/%d] %s\n", done_, total_, what.c_str());
    std::fflush(stderr);
  }

  bool fits(double bytes, const std::string& what) {
    if (bytes <= double(memory_)) return true;
    std::fprintf(stderr, "  skipped %s: needs %.1f GiB, the budget is %.1f GiB\n", what.c_str(),
                 bytes / 1073741824.0, double(memory_) / 1073741824.0);
    return false;
  }

  // Runs `body` and reports an Error (out of memory, say) without ending the run.
  void guarded(const std::string& what, const std::function<void()>& body) {
    try {
      body();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "  %s failed: %s\n", what.c_str(), e.what());
    }
  }

  // Both backends through the same packets on this GPU: identical records?
  void verify(const std::string& field) {
    const std::size_t n = o_.verifyParticles;
    progress(concat("verify: compute against tf-gs, ", field, " field, ", n,
                    " particles with turnover"));
    if (!fits(8 * n * 16.0, "verify")) return;
    guarded("verify", [&] {
      const SceneChoice c{.particles = n,
                          .field = field,
                          .particleSize = o_.particleSize,
                          .integrator = o_.integrator,
                          .turnover = true};
      const auto fieldUpdate = benchField(field);
      auto tf = makeSystem(c, "tf-gs");
      auto compute = makeSystem(c, "compute");
      std::size_t compared = 0, identical = 0, frames = 0, countsEqual = 0;
      float worst = 0.0f;
      for (int f = 0; f < 40; ++f) {
        const FramePacket packet = benchPacket(std::uint32_t(f), c, fieldUpdate);
        tf->advance(packet);
        compute->advance(packet);
        if (f % 8 != 7) continue;
        const std::vector<Particle> a = tf->update().readBack(), b = compute->update().readBack();
        ++frames;
        countsEqual += a.size() == b.size() ? 1 : 0;
        for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
          ++compared;
          const bool same =
              a[i].positionLife == b[i].positionLife && a[i].velocityKind == b[i].velocityKind;
          identical += same ? 1 : 0;
          worst = std::max(worst, glm::length(a[i].position() - b[i].position()));
        }
      }
      Row row{.section = "verify",
              .stage = "agreement",
              .backend = "compute",
              .field = field,
              .particles = n};
      row.ceiling = "tf-gs";
      row.ratio = compared ? double(identical) / double(compared) : 0.0;
      row.note = concat(identical, " of ", compared, " records identical over ", frames,
                        " frames (", countsEqual, " with equal counts), max |dx| ", worst, " m");
      report_.rows.push_back(row);
    });
  }

  void copyBandwidth() {
    std::size_t bytes = o_.quick ? (16u << 20) : (std::size_t(1) << 30);
    bytes = std::min(bytes, memory_ / 3);
    progress(concat("ceiling: buffer copy of ", bytes >> 20,
                    " MiB (glCopyNamedBufferSubData and a compute shader)"));
    report_.copyBytesPerS = bench::copyBandwidth(bytes, o_.frames);
    report_.shaderCopyBytesPerS = bench::shaderCopyBandwidth(bytes, o_.frames);
    for (const auto& [stage, rate] :
         {std::pair{"copy", report_.copyBytesPerS}, {"copy-shader", report_.shaderCopyBytesPerS}}) {
      Row row{.section = "ceilings", .stage = stage};
      row.ms = rate > 0 ? 2.0 * double(bytes) / rate * 1e3 : 0;
      row.bytesPerS = rate;
      report_.rows.push_back(row);
    }
  }

  // A ceiling over n records (two vec4 in, two out), measured once per n by
  // `pass` (its GPU ms): the time, and a row against the copy bandwidth.
  template <class Pass>
  double bareRecords(std::size_t n, std::map<std::size_t, double>& measured, const char* what,
                     const char* stage, Pass pass) {
    if (auto it = measured.find(n); it != measured.end()) return it->second;
    progress(concat("ceiling: ", what, ", ", n, " records"));
    double ms = 0;
    if (fits(4 * n * 16.0, what)) guarded(what, [&] { ms = pass(); });
    measured[n] = ms;
    if (ms > 0) {
      Row row{.section = "ceilings", .stage = stage, .particles = n};
      row.ms = ms;
      row.particlesPerS = double(n) / (ms * 1e-3);
      row.bytesPerS = 2 * kRecordBytes * double(n) / (ms * 1e-3);
      row.ceiling = report_.bandwidthName();
      row.ratio = ratio(row.bytesPerS, report_.bandwidth());
      report_.rows.push_back(row);
    }
    return ms;
  }

  double bareCompute(std::size_t n) {
    return bareRecords(n, bareComputeMs_, "bare compute update", "bare-compute",
                       [&] { return BareComputeUpdate(n, o_.updateItems).passMs(o_.frames); });
  }

  double bareTf(std::size_t n) {
    return bareRecords(n, bareTfMs_, "bare transform feedback", "bare-tf",
                       [&] { return BareTransformFeedback(n).passMs(o_.frames); });
  }

  double barePoints(std::size_t n) {
    if (auto it = barePointsMs_.find(n); it != barePointsMs_.end()) return it->second;
    progress(concat("ceiling: bare point draw, ", n, " points"));
    double ms = 0;
    if (fits(2 * n * 16.0, "bare point draw"))
      guarded("bare point draw", [&] {
        BarePointDraw draw(n, o_.size);
        ms = draw.drawMs(o_.frames);
      });
    barePointsMs_[n] = ms;
    if (ms > 0) {
      Row row{.section = "ceilings",
              .stage = "bare-points",
              .particles = n,
              .width = o_.size.x,
              .height = o_.size.y};
      row.ms = ms;
      row.particlesPerS = double(n) / (ms * 1e-3);
      row.bytesPerS = kRecordBytes * double(n) / (ms * 1e-3);
      report_.rows.push_back(row);
    }
    return ms;
  }

  static double ratio(double rate, double ceiling) { return ceiling > 0 ? rate / ceiling : 0.0; }

  std::unique_ptr<ParticleSystem> makeSystem(const SceneChoice& c, const std::string& backend) {
    GpuTuning tuning;
    tuning.updateItems = o_.updateItems;
    if (c.renderer == "splat-atomic") tuning.splat = GpuTuning::Splat::Atomic;
    auto system = std::make_unique<ParticleSystem>(
        benchState(c), ParticleSystem::Options{.capacity = c.particles,
                                               .capacityLimit = c.particles,
                                               .backend = backend,
                                               .tuning = tuning});
    system->setTerrain(terrain_);
    return system;
  }

  // `molecules` > 0: the n particles are molecules of that many members
  // (MoleculeUpdate, compute whatever the backend), their rate compared with
  // the particles' of the same run.
  void update(std::size_t n, const std::string& backend, const std::string& field, int obstacles,
              int molecules = 0) {
    progress(concat("update: ", backend, ", ", field, " field, ", n, " particles",
                    obstacles == 1   ? ", a sphere"
                    : obstacles == 2 ? ", a sphere and a box"
                                     : "",
                    molecules > 0 ? concat(", molecules of ", molecules) : ""));
    if (!fits(4 * n * 16.0, "update")) return;
    guarded("update", [&] {
      const SceneChoice c{.particles = n,
                          .field = field,
                          .particleSize = o_.particleSize,
                          .integrator = o_.integrator,
                          .obstacles = obstacles,
                          .molecules = molecules};
      const auto fieldUpdate = benchField(field);
      auto system = makeSystem(c, backend);
      GpuStopwatch watch;
      const int frames = 1 + o_.warmup + o_.frames;
      for (int f = 0; f < frames; ++f) {
        const bool timed = f >= frames - o_.frames;
        if (timed) watch.begin();
        system->advance(benchPacket(std::uint32_t(f), c, fieldUpdate));
        if (timed) watch.end();
      }
      const double ms = median(watch.intervalsMs());
      const std::size_t live =
          molecules > 0 ? system->readBackMolecules().size() : system->update().liveCount();
      Row row{.section = "update",
              .stage = "update",
              .backend = backend,
              .field = field,
              .particles = live,
              .obstacles = obstacles,
              .molecules = molecules};
      row.ms = ms;
      row.particlesPerS = double(live) / (ms * 1e-3);
      row.bytesPerS = 2 * kRecordBytes * double(live) / (ms * 1e-3);
      if (molecules > 0) {
        // Against the particles' update of the same count, field and obstacles in this run.
        for (const Row& r : report_.rows)
          if (r.section == "update" && r.molecules == 0 && r.backend == backend &&
              r.field == field && r.obstacles == obstacles && r.particlesPerS > 0 &&
              std::abs(double(r.particles) - double(live)) <= 0.01 * double(live)) {
            row.ceiling = "particles";
            row.ratio = row.particlesPerS / r.particlesPerS;
            row.note = concat(row.ratio, " of the particles' rate (molecules of ", molecules, ")");
          }
      } else if (backend == "compute") {
        row.ceiling = report_.bandwidthName();
        row.ratio = ratio(row.bytesPerS, report_.bandwidth());
        const double bare = bareCompute(n);
        if (bare > 0)
          row.note = concat(row.ratio, " of ", row.ceiling, "; ", bare / ms, " of bare-compute");
      } else {
        const double bare = bareTf(n);
        row.ceiling = "bare-tf";
        row.ratio = bare > 0 && ms > 0 ? bare / ms : 0;
      }
      report_.rows.push_back(row);
    });
  }

  void render(std::size_t n, const std::string& renderer) {
    const double bare = barePoints(n);
    progress(concat("render: ", renderer, ", ", n, " particles, one ", o_.size.x, "x", o_.size.y,
                    " view"));
    if (!fits(4 * n * 16.0, "render")) return;
    guarded("render", [&] {
      const SceneChoice c{.particles = n,
                          .renderer = renderer,
                          .particleSize = o_.particleSize,
                          .integrator = o_.integrator};
      const auto fieldUpdate = benchField("texture");
      auto system = makeSystem(c, o_.wallBackend);
      BenchView view;
      view.scene().setTerrain(terrain_);
      OutputTarget out;
      out.resize(o_.size);
      StageWatches watches;
      const View camera = benchView(0, 1, o_.size);
      const int frames = 1 + o_.warmup + o_.frames;
      for (int f = 0; f < frames; ++f) {
        system->advance(benchPacket(std::uint32_t(f), c, fieldUpdate));
        if (f == frames - o_.frames) {
          watches.scene.clear();
          watches.particles.clear();
          watches.post.clear();
        }
        view.render(*system, camera, o_.size, out.framebuffer(), watches);
      }
      const std::size_t live = system->update().liveCount();
      const double pixels = double(o_.size.x) * double(o_.size.y);
      auto row = [&](const char* stage, GpuStopwatch& watch) {
        Row r{.section = "render",
              .stage = stage,
              .backend = o_.wallBackend,
              .field = "texture",
              .renderer = renderer,
              .particles = live,
              .walls = 1,
              .width = o_.size.x,
              .height = o_.size.y};
        r.ms = median(watch.intervalsMs());
        return r;
      };
      report_.rows.push_back(row("scene", watches.scene));
      Row particles = row("particles", watches.particles);
      particles.particlesPerS = double(live) / (particles.ms * 1e-3);
      particles.bytesPerS = kRecordBytes * double(live) / (particles.ms * 1e-3);
      particles.ceiling = "bare-points";
      particles.ratio = bare > 0 ? bare / particles.ms : 0;
      report_.rows.push_back(particles);
      Row post = row("post", watches.post);
      post.bytesPerS = 24.0 * pixels / (post.ms * 1e-3);  // reads 4 + 8 + 8 bytes a pixel, writes 4
      post.ceiling = report_.bandwidthName();
      post.ratio = ratio(post.bytesPerS, report_.bandwidth());
      report_.rows.push_back(post);
    });
  }

  // GpuRadixSort of n keys: ms, and its traffic against the copy ceiling.
  void sort(std::size_t n) {
    progress(concat("sort: ", n, " keys with values (GpuRadixSort)"));
    if (!fits(4.0 * 4.0 * double(n), "sort")) return;
    guarded("sort", [&] {
      Row r{.section = "sort", .stage = "sort", .particles = n};
      r.ms = sortMs(n, o_.frames);
      r.particlesPerS = r.ms > 0 ? double(n) / (r.ms * 1e-3) : 0;
      r.bytesPerS = r.ms > 0 ? kSortBytesPerKey * double(n) / (r.ms * 1e-3) : 0;
      r.ceiling = report_.bandwidthName();
      r.ratio = report_.bandwidth() > 0 ? r.bytesPerS / report_.bandwidth() : 0;
      report_.rows.push_back(r);
    });
  }

  // The live flow solver's GPU step on a grid of `cells`: a wind blowing in
  // and a rotor pushing down in a 40 x 40 x 20 m box, from rest.
  void solver(glm::ivec3 cells) {
    const std::size_t n = std::size_t(cells.x) * std::size_t(cells.y) * std::size_t(cells.z);
    progress(concat("solver: a step on ", cells.x, "x", cells.y, "x", cells.z, " cells, ",
                    o_.solverIterations, " pressure iterations"));
    if (!fits(double(n) * 64.0, "solver")) return;
    guarded("solver", [&] {
      GpuFluidSolver fluid(Box{{-20.0f, -20.0f, 0.0f}, {20.0f, 20.0f, 20.0f}}, cells);
      FluidSettings s;
      s.wind = {2.0f, 0.0f, 0.0f};
      s.iterations = o_.solverIterations;
      FluidForces rotor{
          .rotorCentre = {0.0f, 0.0f, 10.0f}, .rotorRadius = 6.0f, .rotorPressure = 200.0f};
      GpuStopwatch watch;
      const int frames = o_.warmup + o_.frames;
      for (int f = 0; f < frames; ++f) {
        const bool timed = f >= o_.warmup;
        if (timed) watch.begin();
        fluid.step(1.0f / 60.0f, s, rotor);
        if (timed) watch.end();
      }
      const double ms = median(watch.intervalsMs());
      Row r{.section = "solver", .stage = "step", .particles = n};
      r.ms = ms;
      r.particlesPerS = ms > 0 ? double(n) / (ms * 1e-3) : 0;
      r.note = concat(cells.x, "x", cells.y, "x", cells.z, ": ", ms > 0 ? 1e3 / ms : 0.0,
                      " steps/s (cells/s in Mpart/s), max |div| ", fluid.maxDivergence(), " /s");
      report_.rows.push_back(r);
    });
  }

  void walls(int count, const std::string& sim, const std::string& renderer, int trails,
             bool shadows) {
    const std::size_t n = o_.wallParticles;
    progress(concat("walls: ", count, " views of ", o_.size.x, "x", o_.size.y, ", ", sim,
                    " simulation, ", renderer, ", ", n, " particles",
                    trails > 0 ? concat(", trails of ", trails) : std::string(),
                    shadows ? ", shadows" : ""));
    const int systems = sim == "shared" ? 1 : count;
    if (!fits(4 * n * 16.0 * systems, "walls")) return;
    guarded("walls", [&] {
      const SceneChoice c{.particles = n,
                          .renderer = renderer,
                          .particleSize = o_.particleSize,
                          .integrator = o_.integrator,
                          .trailLength = trails,
                          .shadows = shadows};
      const auto fieldUpdate = benchField("texture");
      std::vector<std::unique_ptr<ParticleSystem>> sims;
      for (int s = 0; s < systems; ++s)
        sims.push_back(makeSystem(c, o_.wallBackend));
      std::vector<std::unique_ptr<BenchView>> views;
      std::vector<View> cameras;
      for (int w = 0; w < count; ++w) {
        views.push_back(std::make_unique<BenchView>());
        views.back()->scene().setTerrain(terrain_);
        cameras.push_back(benchView(w, count, o_.size));
      }
      OutputTarget out;
      out.resize(o_.size);
      GpuStopwatch updates;
      StageWatches watches;
      std::vector<double> wallMs;
      // Untimed frames: --warmup of them and --wall-warmup seconds; then the timed ones.
      std::uint32_t f = 0;
      auto drawFrame = [&] {
        const FramePacket packet = benchPacket(f++, c, fieldUpdate);
        for (auto& system : sims) {
          updates.begin();
          system->advance(packet);
          updates.end();
        }
        for (int w = 0; w < count; ++w)
          views[std::size_t(w)]->render(*sims[std::size_t(sim == "shared" ? 0 : w)],
                                        cameras[std::size_t(w)], o_.size, out.framebuffer(),
                                        watches);
      };
      const auto warmStart = std::chrono::steady_clock::now();
      auto warming = [&] {
        return f < std::uint32_t(1 + o_.warmup) ||
               std::chrono::duration<double>(std::chrono::steady_clock::now() - warmStart).count() <
                   o_.wallWarmupSeconds;
      };
      while (warming()) {
        drawFrame();
        finishGpu();
      }
      updates.clear();
      watches.scene.clear();
      watches.particles.clear();
      watches.post.clear();
      for (int i = 0; i < o_.frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        drawFrame();
        finishGpu();
        wallMs.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
      }
      // Per frame: the sum of its intervals (systems updates, `count` of each view stage).
      auto perFrame = [&](GpuStopwatch& watch, int perFrameCount) {
        const std::vector<double> all = watch.intervalsMs();
        std::vector<double> sums(std::size_t(o_.frames), 0.0);
        for (std::size_t i = 0; i < all.size(); ++i)
          sums[i / std::size_t(perFrameCount)] += all[i];
        return sums;
      };
      const std::vector<double> u = perFrame(updates, systems), s = perFrame(watches.scene, count),
                                p = perFrame(watches.particles, count),
                                q = perFrame(watches.post, count);
      std::vector<double> total(u.size()), viewsMs(u.size());
      for (std::size_t i = 0; i < u.size(); ++i) {
        viewsMs[i] = s[i] + p[i] + q[i];
        total[i] = u[i] + viewsMs[i];
      }
      const std::size_t live = sims[0]->update().liveCount();
      auto row = [&](const char* stage, const std::vector<double>& ms) {
        Row r{.section = "walls",
              .stage = stage,
              .backend = o_.wallBackend,
              .field = "texture",
              .renderer = renderer,
              .sim = sim,
              .particles = live,
              .walls = count,
              .trails = trails,
              .shadows = shadows,
              .width = o_.size.x,
              .height = o_.size.y};
        r.ms = median(ms);
        r.particlesPerS =
            double(live) * (std::string(stage) == "update" ? systems : count) / (r.ms * 1e-3);
        return r;
      };
      report_.rows.push_back(row("update", u));
      report_.rows.push_back(row("views", viewsMs));
      Row frame = row("frame", total);
      frame.wallMs = median(wallMs);
      frame.ceiling = "60 fps";
      frame.ratio = frame.ms > 0 ? (1000.0 / frame.ms) / 60.0 : 0;
      report_.rows.push_back(frame);
    });
  }

  const BenchOptions& o_;
  Report& report_;
  std::size_t memory_;
  int total_ = 0, done_ = 0;
  std::map<std::size_t, double> bareTfMs_, barePointsMs_, bareComputeMs_;
  std::shared_ptr<const HeightMap> terrain_ = std::make_shared<HeightMap>(HeightMap::flat(0.0f));
};

// The targets, from the rows (largest particle count measured for each).
void printTargets(const Report& r) {
  auto largest = [&](const std::function<bool(const Row&)>& match) {
    const Row* best = nullptr;
    for (const Row& row : r.rows)
      if (match(row) && (!best || row.particles >= best->particles)) best = &row;
    return best;
  };
  std::printf("\nTargets (largest N measured):\n");
  for (const Row& row : r.rows)
    if (row.section == "verify")
      std::printf("  compute = tf-gs on this GPU (%s field): %s\n", row.field.c_str(),
                  row.note.c_str());
  if (const Row* c = largest([](const Row& x) {
        return x.section == "update" && x.molecules == 0 && x.backend == "compute" &&
               x.field == "texture" && x.obstacles == 0;
      }))
    std::printf(
        "  compute update, %zu particles: %.1f GB/s = %.2f of %s bandwidth %.1f GB/s (target >= "
        "0.60); "
        "glCopyNamedBufferSubData %.1f GB/s\n",
        c->particles, c->bytesPerS * 1e-9, c->ratio, r.bandwidthName().c_str(),
        r.bandwidth() * 1e-9, r.copyBytesPerS * 1e-9);
  if (const Row* t = largest([](const Row& x) {
        return x.section == "update" && x.molecules == 0 && x.backend == "tf-gs" &&
               x.field == "texture" && x.obstacles == 0;
      }))
    std::printf(
        "  tf-gs update, %zu particles: %.3f ms = %.2f of the bare transform-feedback pass's speed "
        "(target >= 0.80)\n",
        t->particles, t->ms, t->ratio);
  for (const char* backend : {"compute", "tf-gs"}) {
    const auto updateRow = [&](int obstacles) {
      return largest([&](const Row& x) {
        return x.section == "update" && x.molecules == 0 && x.backend == backend &&
               x.field == "texture" && x.obstacles == obstacles;
      });
    };
    const Row* plain = updateRow(0);
    for (int count : {1, 2}) {
      const Row* with = updateRow(count);
      if (plain && with && plain->particles == with->particles && plain->ms > 0)
        std::printf(
            "  %s update with %s, %zu particles: %.3f ms against %.3f ms = %.2fx (target <= "
            "1.15x)\n",
            backend, count == 1 ? "a sphere" : "a sphere and a box", with->particles, with->ms,
            plain->ms, with->ms / plain->ms);
    }
  }
  for (const Row& row : r.rows)
    if (row.section == "update" && row.molecules > 0 && row.ceiling == "particles")
      std::printf(
          "  %s update of molecules of %d, %zu particles%s: %.1f Mparticles/s = %.2f of the "
          "particles' rate%s\n",
          row.backend.c_str(), row.molecules, row.particles,
          row.obstacles > 0 ? ", with obstacles" : "", row.particlesPerS * 1e-6, row.ratio,
          row.molecules == 4 && row.obstacles == 0 ? " (target >= 0.25)" : "");
  for (const Row& row : r.rows)
    if (row.section == "solver" && row.ms > 0)
      std::printf(
          "  solver step, %zu cells: %.3f ms = %.0f steps/s (target >= 120 at 128x128x64), "
          "%.0f Mcells/s\n",
          row.particles, row.ms, 1e3 / row.ms, row.particlesPerS * 1e-6);
  const Row* b = largest([](const Row& x) {
    return x.section == "render" && x.stage == "particles" && x.renderer == "billboards";
  });
  if (b) {
    const Row* s = nullptr;
    for (const Row& row : r.rows)
      if (row.section == "render" && row.stage == "particles" && row.renderer == "splat" &&
          row.particles == b->particles)
        s = &row;
    if (s)
      std::printf(
          "  splat vs billboards, %zu particles: %.1f vs %.1f Mparticles/s = %.1fx (target >= "
          "10x)\n",
          b->particles, s->particlesPerS * 1e-6, b->particlesPerS * 1e-6,
          s->particlesPerS / b->particlesPerS);
  }
  for (const Row& row : r.rows)
    if (row.section == "walls" && row.stage == "frame")
      std::printf(
          "  %d views, %s simulation, %s, %zu particles, trails %d, shadows %s: %.2f ms GPU (%.1f "
          "fps), %.2f ms wall clock\n",
          row.walls, row.sim.c_str(), row.renderer.c_str(), row.particles, row.trails,
          row.shadows ? "on" : "off", row.ms, 1000.0 / row.ms, row.wallMs);
}

}  // namespace
}  // namespace sandstorm::bench

int main(int argc, char** argv) {
  using namespace sandstorm;
  using namespace sandstorm::bench;
  try {
    const BenchOptions options = parseBenchOptions(argc, argv);
    EglContext context;
    context.makeCurrent();
    Report report;
    report.device = context.description() + " | " + glRenderer();
    for (int i = 0; i < argc; ++i) {
      if (i) report.command += ' ';
      report.command += argv[i];
    }
    std::size_t memory = std::size_t(-1) / 2;
    if (options.memoryGiB > 0)
      memory = std::size_t(options.memoryGiB * 1073741824.0);
    else if (const auto gpu = gpuMemoryBytes())
      memory = *gpu / 10 * 8;  // leave room for the driver, textures and the ceilings' buffers
    std::fprintf(stderr, "sandstorm-bench on %s\n", report.device.c_str());
    Bench(options, report, memory).run();
    printTable(report);
    printTargets(report);
    writeJson(report, options.json);
    std::printf("\nwrote %s\n", options.json.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sandstorm-bench: %s\n", e.what());
    return 1;
  }
}
