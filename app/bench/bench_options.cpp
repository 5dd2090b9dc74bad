#include "app/bench/bench_options.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "core/util/error.h"

namespace sandstorm::bench {
namespace {

const char* kUsage = R"(sandstorm-bench: GPU particle benchmark (headless EGL)

  sandstorm-bench [--quick] [--json FILE] [--frames N] [--warmup N] [--size WxH]
                  [--sections verify,ceilings,update,render,walls,sort] [--verify-particles N]
                  [--particles 1e4,1e5,...] [--backends tf-gs,compute]
                  [--fields texture,equation] [--renderers billboards,points,splat,splat-atomic]
                  [--billboard-limit N] [--walls 1,2,4,8] [--wall-particles N]
                  [--wall-sims per-wall,shared] [--wall-renderers billboards,splat]
                  [--wall-trails 0,16] [--wall-shadows 0,1] [--sort-keys 1e6,1e7]
                  [--update-obstacles 0,1,2] [--update-molecules 0,4]
                  [--solver-grids 128x128x64] [--solver-iterations 40]
                  [--wall-backend compute] [--particle-size M] [--memory-gib G]
                  [--integrator euler|rk2|rk4] [--update-items 1|2|4|8] [--gpu-warmup S]
                  [--wall-warmup S]

A fixed scene (a tornado, particles in steady state at each count) timed over
fixed frames. Sections:
  verify    the compute and transform-feedback backends on this GPU: the same
            records, bit for bit, through births, deaths and compaction
  ceilings  buffer-copy bandwidth, a bare transform-feedback pass, a bare point draw
  update    the particle update per backend and field type, without and with
            obstacles (--update-obstacles: 0 none, 1 a sphere the flow goes around,
            the Mali sample's, 2 the sphere and a box, both in the cloud), of particles or of molecules of n members
            (--update-molecules 0,4: 0 particles, 2..8 molecules of that complexity
            holding as many particles, their rate against the particles')
  render    scene, particles and composite of one view per renderer
  walls     whole frames of 1..8 views, each wall simulating or one shared simulation,
            with trails of each --wall-trails length (render.trail_length; 0 none),
            without and with shadows (--wall-shadows: render.shadows; the update
            stage then includes the shadow map's pass); each configuration's
            untimed frames last --warmup frames and --wall-warmup seconds (1)
  sort      GpuRadixSort (render.order = sorted) of --sort-keys random keys:
            ms, and its memory traffic against the copy ceiling
  solver    the live flow solver's step on the GPU (GpuFluidSolver) on each of
            --solver-grids (cells), with wind and a rotor: ms a step, cells/s
Prints a table (each stage as a ratio to its ceiling) and writes JSON.
--quick: tiny sizes and few frames (seconds on llvmpipe; structure, not speed).
)";

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// A list of switches, "0,1": each 0 (`zero`) or 1 (`one`), at least one.
std::vector<int> zeroOrOne(const std::string& option, const std::string& text, const char* zero,
                           const char* one) {
  std::vector<int> out;
  for (const std::string& t : split(text)) {
    if (t != "0" && t != "1")
      throw Error(concat(option, ": ", t, ": expected 0 (", zero, ") or 1 (", one, ")"));
    out.push_back(t == "1");
  }
  if (out.empty()) throw Error(concat(option, ": expected 0,1, 0 or 1"));
  return out;
}

double number(const std::string& text, const std::string& option) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0')
    throw Error(concat(option, ": '", text, "' is not a number"));
  return v;
}

std::size_t count(const std::string& text, const std::string& option) {
  const double v = number(text, option);
  if (!(v >= 1.0)) throw Error(concat(option, ": ", text, " must be at least 1"));
  return std::size_t(v + 0.5);
}

void checkChoices(const std::vector<std::string>& values, const std::vector<std::string>& known,
                  const std::string& option) {
  for (const std::string& v : values) {
    bool ok = false;
    for (const std::string& k : known)
      ok = ok || v == k;
    if (!ok) {
      std::string list;
      for (const std::string& k : known)
        list += (list.empty() ? "" : ", ") + k;
      throw Error(concat(option, ": unknown '", v, "'; expected some of ", list));
    }
  }
}

}  // namespace

BenchOptions parseBenchOptions(int argc, char** argv) {
  BenchOptions o;
  std::vector<std::string> args(argv + 1, argv + argc);
  // --quick first, so options after it may still override its sizes.
  for (const std::string& a : args)
    if (a == "--quick") {
      o.quick = true;
      o.warmup = 1;
      o.frames = 3;
      o.size = {160, 90};
      o.particles = {1000, 4000};
      o.billboardLimit = 4000;
      o.walls = {1, 2};
      o.wallParticles = 2000;
      o.particleSize = 0.2f;
      o.verifyParticles = 3000;
      o.sortKeys = {5000};
      o.solverGrids = {{16, 16, 8}};
      o.gpuWarmupSeconds = 0.0;
      o.wallWarmupSeconds = 0.0;
    }
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--quick") continue;
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    }
    if (i + 1 >= args.size()) throw Error(concat(a, ": expected a value (see --help)"));
    const std::string v = args[++i];
    if (a == "--json") {
      o.json = v;
    } else if (a == "--frames") {
      o.frames = int(count(v, a));
    } else if (a == "--warmup") {
      o.warmup = int(number(v, a));
    } else if (a == "--size") {
      const auto x = v.find('x');
      if (x == std::string::npos) throw Error(concat(a, ": expected WxH, got '", v, "'"));
      o.size = {int(count(v.substr(0, x), a)), int(count(v.substr(x + 1), a))};
    } else if (a == "--solver-grids") {
      o.solverGrids.clear();
      for (const std::string& g : split(v)) {
        const auto x = g.find('x'), y = g.find('x', x == std::string::npos ? x : x + 1);
        if (x == std::string::npos || y == std::string::npos)
          throw Error(concat(a, ": expected grids as XxYxZ cells, got '", g, "'"));
        const glm::ivec3 d(int(count(g.substr(0, x), a)), int(count(g.substr(x + 1, y - x - 1), a)),
                           int(count(g.substr(y + 1), a)));
        if (glm::any(glm::lessThan(d, glm::ivec3(2))) ||
            glm::any(glm::greaterThan(d, glm::ivec3(1024))))
          throw Error(concat(a, ": ", g, ": expected 2..1024 cells an axis"));
        o.solverGrids.push_back(d);
      }
      if (o.solverGrids.empty()) throw Error(concat(a, ": expected grids, e.g. 128x128x64"));
    } else if (a == "--solver-iterations") {
      o.solverIterations = int(count(v, a));
      if (o.solverIterations < 1 || o.solverIterations > 500)
        throw Error(concat(a, ": ", v, ": expected 1..500 iterations"));
    } else if (a == "--sections") {
      o.sections = split(v);
      checkChoices(o.sections,
                   {"verify", "ceilings", "update", "render", "walls", "sort", "solver"}, a);
    } else if (a == "--particles") {
      o.particles.clear();
      for (const std::string& p : split(v))
        o.particles.push_back(count(p, a));
    } else if (a == "--backends") {
      o.backends = split(v);
      checkChoices(o.backends, {"tf-gs", "compute"}, a);
    } else if (a == "--fields") {
      o.fields = split(v);
      checkChoices(o.fields, {"texture", "equation"}, a);
    } else if (a == "--renderers") {
      o.renderers = split(v);
      checkChoices(o.renderers, {"billboards", "points", "splat", "splat-atomic"}, a);
    } else if (a == "--verify-particles") {
      o.verifyParticles = count(v, a);
    } else if (a == "--billboard-limit") {
      o.billboardLimit = count(v, a);
    } else if (a == "--walls") {
      o.walls.clear();
      for (const std::string& w : split(v))
        o.walls.push_back(int(count(w, a)));
    } else if (a == "--wall-particles") {
      o.wallParticles = count(v, a);
    } else if (a == "--wall-sims") {
      o.wallSims = split(v);
      checkChoices(o.wallSims, {"per-wall", "shared"}, a);
    } else if (a == "--wall-renderers") {
      o.wallRenderers = split(v);
      checkChoices(o.wallRenderers, {"billboards", "points", "splat", "splat-atomic"}, a);
    } else if (a == "--sort-keys") {
      o.sortKeys.clear();
      for (const std::string& k : split(v))
        o.sortKeys.push_back(count(k, a));
    } else if (a == "--wall-trails") {
      o.wallTrails.clear();
      for (const std::string& t : split(v)) {
        const double k = number(t, a);
        if (!(k >= 0.0 && k <= 64.0) || k != double(int(k)))
          throw Error(concat(a, ": ", t, ": expected a trail length of 0 to 64 positions"));
        o.wallTrails.push_back(int(k));
      }
      if (o.wallTrails.empty()) throw Error(concat(a, ": expected lengths, e.g. 0,16"));
    } else if (a == "--wall-shadows") {
      o.wallShadows = zeroOrOne(a, v, "off", "on");
    } else if (a == "--update-molecules") {
      o.updateMolecules.clear();
      for (const std::string& t : split(v)) {
        const double k = number(t, a);
        if (!(k == 0.0 || (k >= 2.0 && k <= 8.0)) || k != double(int(k)))
          throw Error(concat(a, ": ", t, ": expected 0 (particles) or a complexity of 2 to 8"));
        o.updateMolecules.push_back(int(k));
      }
      if (o.updateMolecules.empty()) throw Error(concat(a, ": expected complexities, e.g. 0,4"));
    } else if (a == "--update-obstacles") {
      o.updateObstacles.clear();
      for (const std::string& t : split(v)) {
        if (t != "0" && t != "1" && t != "2")
          throw Error(concat(a, ": ", t,
                             ": expected 0 (none), 1 (a sphere: the Mali sample's) or 2 (a sphere "
                             "and a box)"));
        o.updateObstacles.push_back(t[0] - '0');
      }
      if (o.updateObstacles.empty()) throw Error(concat(a, ": expected 0, 1 or 2"));
    } else if (a == "--wall-backend") {
      o.wallBackend = v;
      checkChoices({v}, {"tf-gs", "compute"}, a);
    } else if (a == "--particle-size") {
      o.particleSize = float(number(v, a));
    } else if (a == "--gpu-warmup") {
      o.gpuWarmupSeconds = number(v, a);
      if (!(o.gpuWarmupSeconds >= 0.0 && o.gpuWarmupSeconds <= 600.0))
        throw Error(concat(a, ": ", v, ": expected 0..600 seconds"));
    } else if (a == "--wall-warmup") {
      o.wallWarmupSeconds = number(v, a);
      if (!(o.wallWarmupSeconds >= 0.0 && o.wallWarmupSeconds <= 600.0))
        throw Error(concat(a, ": ", v, ": expected 0..600 seconds"));
    } else if (a == "--update-items") {
      o.updateItems = int(count(v, a));
      if (o.updateItems != 1 && o.updateItems != 2 && o.updateItems != 4 && o.updateItems != 8)
        throw Error(concat(a, ": ", v, ": expected 1, 2, 4 or 8 records an invocation"));
    } else if (a == "--integrator") {
      o.integrator = v;
      checkChoices({v}, {"euler", "rk2", "rk4"}, a);
    } else if (a == "--memory-gib") {
      o.memoryGiB = number(v, a);
    } else {
      throw Error(concat("unknown option '", a, "' (see --help)"));
    }
  }
  return o;
}

}  // namespace sandstorm::bench
