// sandstorm: Sandstorm from Python (pybind11). docs/PYTHON.md shows it in use.
//
//   import sandstorm
//   f = sandstorm.load_field("data/tornado.vti")        # f.values: (nz, ny, nx, 3)
//   with sandstorm.Run("config/desktop.toml", set={"emitter.0.rate": 5000}) as run:
//       run.step(60)
//       p = run.particles()                              # p["position"]: (n, 3)
//       img = run.image()                                # (h, w, 3) uint8
//
// Errors are sandstorm.Error (a RuntimeError) with Sandstorm's own message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>

#include "app/default_config.h"
#include "app/file_scene.h"
#include "app/stepped_run.h"
#include "core/config/config_sets.h"
#include "core/io/field_info.h"
#include "core/io/field_loader.h"
#include "core/io/field_writer.h"
#include "core/io/pvd_file.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace py = pybind11;

namespace sandstorm {
namespace {

// A Python value as the text --set reads: true/false, numbers, x,y,z.
std::string attributeText(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::sequence>(value)) {
    std::string text;
    for (const py::handle item : value.cast<py::sequence>())
      text += (text.empty() ? "" : ",") + py::str(item).cast<std::string>();
    return text;
  }
  return py::str(value).cast<std::string>();
}

template <class T>
py::array_t<T> array(std::vector<py::ssize_t> shape, const T* data) {
  py::array_t<T> a(shape);
  std::copy_n(data, a.size(), a.mutable_data());
  return a;
}

// A field file as numpy arrays.
struct Field {
  py::array_t<float> values;    // (nz, ny, nx, 3)
  py::array_t<bool> valid;      // (nz, ny, nx)
  py::tuple bounds;             // ((x0, y0, z0), (x1, y1, z1))
  std::vector<double> times;    // a series' or file's time steps; empty for one field
  std::string info, arrayName;  // `sandstorm-field info`; the array loaded
  py::dict scalars;             // the file's scalar arrays, (nz, ny, nx) each
};

Field loadFieldFile(const std::string& path, const std::optional<std::string>& arrayName,
                    const std::optional<std::vector<int>>& resolution, std::size_t timeStep) {
  LoadOptions options;
  if (arrayName) options.arrayName = *arrayName;
  if (resolution) {
    if (resolution->size() != 3)
      throw Error(concat("load_field ", path, ": resolution has ", resolution->size(),
                         " numbers; expected three (nx, ny, nz)"));
    options.resolution = {(*resolution)[0], (*resolution)[1], (*resolution)[2]};
  }
  LoadReport report;
  std::vector<double> times;
  std::vector<std::filesystem::path> parts{path};
  // A series: its steps' times, and the step asked for (all its parts).
  if (std::filesystem::path(path).extension() == ".pvd") {
    const std::vector<PvdFrame> frames = readPvd(path);
    for (const PvdFrame& f : frames)
      times.push_back(f.time);
    if (timeStep >= frames.size())
      throw Error(concat(path, ": time_step ", timeStep, " of a series of ", frames.size()));
    parts = frames[timeStep].parts;
  } else {
    options.timeStep = timeStep;
  }
  VectorField f = [&] {
    py::gil_scoped_release release;
    return loadFieldParts(parts, path, options, &report);
  }();
  if (times.empty() && report.times.size() > 1) times = report.times;
  const glm::ivec3 d = f.dims();
  Field out;
  out.values = array<float>({d.z, d.y, d.x, 3}, &f.values()[0].x);
  std::vector<std::uint8_t> valid(f.pointCount(), 1);
  if (f.hasValidity()) std::ranges::copy(f.validity(), valid.begin());
  out.valid = py::array_t<bool>({d.z, d.y, d.x});
  std::ranges::transform(valid, out.valid.mutable_data(), [](std::uint8_t v) { return v != 0; });
  const Box& b = f.bounds();
  out.bounds = py::make_tuple(py::make_tuple(b.min.x, b.min.y, b.min.z),
                              py::make_tuple(b.max.x, b.max.y, b.max.z));
  out.times = times;
  out.info = describeField(path, f, report);
  out.arrayName = report.arrayName;
  for (const VectorField::Scalars& s : f.scalars())
    out.scalars[py::str(s.name)] = array<float>({d.z, d.y, d.x}, s.values.data());
  return out;
}

// numpy in: a field computed in Python, written where Run and every other
// tool can open it.
void saveFieldFile(const std::string& path, const py::array& values, const py::tuple& bounds,
                   const std::string& arrayName) {
  const auto v = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(values);
  if (!v || v.ndim() != 4 || v.shape(3) != 3)
    throw Error(concat("save_field ", path, ": values must be an array of shape (nz, ny, nx, 3)"));
  const glm::ivec3 dims(int(v.shape(2)), int(v.shape(1)), int(v.shape(0)));
  if (py::len(bounds) != 2)
    throw Error(concat("save_field ", path, ": bounds must be ((x0, y0, z0), (x1, y1, z1))"));
  Box box;
  for (int c = 0; c < 3; ++c) {
    const py::sequence lo = bounds[0].cast<py::sequence>(), hi = bounds[1].cast<py::sequence>();
    if (py::len(lo) != 3 || py::len(hi) != 3)
      throw Error(concat("save_field ", path, ": bounds must be ((x0, y0, z0), (x1, y1, z1))"));
    box.min[c] = lo[c].cast<float>();
    box.max[c] = hi[c].cast<float>();
  }
  std::vector<glm::vec3> points(std::size_t(v.size() / 3));
  std::copy_n(v.data(), v.size(), &points[0].x);
  py::gil_scoped_release release;
  saveField(path, VectorField(box, dims, std::move(points)), arrayName);
}

py::list linesToPython(const std::vector<Streamline>& lines) {
  py::list out;
  for (const Streamline& line : lines) {
    const py::ssize_t n = py::ssize_t(line.points.size());
    py::array_t<float> points({n, py::ssize_t(3)}), velocity({n, py::ssize_t(3)}), speed(n), arc(n);
    std::vector<double> along(line.points.size(), 0.0);
    for (std::size_t i = 1; i < line.points.size(); ++i)
      along[i] = along[i - 1] + glm::length(line.points[i].position - line.points[i - 1].position);
    const double seed = line.points.empty() ? 0.0 : along[std::size_t(line.seedIndex)];
    for (py::ssize_t i = 0; i < n; ++i) {
      const StreamlinePoint& p = line.points[std::size_t(i)];
      for (int c = 0; c < 3; ++c) {
        points.mutable_at(i, c) = p.position[c];
        velocity.mutable_at(i, c) = p.velocity[c];
      }
      speed.mutable_at(i) = glm::length(p.velocity);
      arc.mutable_at(i) = float(along[std::size_t(i)] - seed);
    }
    py::dict d;
    d["points"] = points;
    d["velocity"] = velocity;
    d["speed"] = speed;
    d["arc_length"] = arc;
    out.append(d);
  }
  return out;
}

class Run {
 public:
  Run(const std::string& path, const std::optional<py::dict>& sets,
      const std::optional<std::vector<std::string>>& walls, const std::optional<std::string>& array,
      const std::optional<std::string>& config, const std::optional<std::string>& record,
      const std::optional<std::string>& replay, const std::optional<std::string>& movie,
      const std::optional<std::string>& movieWall, const std::optional<std::string>& movieSize,
      const std::string& movieStereo, const std::optional<double>& movieFps,
      const std::optional<int>& movieCrf, bool movieMenu) {
    AppOptions options;
    if (sets)
      for (const auto& [key, value] : *sets)
        options.sets.push_back(py::str(key).cast<std::string>() + "=" + attributeText(value));
    if (walls) options.walls = *walls;
    if (record) options.record = *record;
    if (replay) options.replay = *replay;
    if (movie) {
      options.movie = movieSpecFrom({.path = *movie,
                                     .wall = movieWall.value_or(""),
                                     .stereo = movieStereo,
                                     .size = movieSize,
                                     .fps = movieFps,
                                     .crf = movieCrf,
                                     .menu = movieMenu});
    }
    py::gil_scoped_release release;
    AppConfig appConfig;
    std::optional<FieldSource> field;
    if (path.ends_with(".toml")) {
      if (array)
        throw Error("array= names an array of a field file; " + path + " is a configuration");
      appConfig = loadConfig(path);
      applyConfigSets(appConfig, options.sets);
    } else {  // a field file, opened as `sandstorm FILE` opens it
      appConfig = loadConfig(config ? *config : defaultConfig("desktop.toml").string());
      field = fileSceneField(appConfig, path, array.value_or(""), options.sets);
      openFileScene(appConfig, path, *field->update.field);
    }
    run_ = std::make_unique<SteppedRun>(std::move(appConfig), std::move(options), std::move(field));
  }

  SteppedRun& run() {
    if (!run_ || run_->closed()) throw Error("this run is closed");
    return *run_;
  }

  void step(int n) {
    py::gil_scoped_release release;
    run().step(n);
  }

  void set(const std::string& key, const py::handle& value) {
    const std::string warning = run().set(key, attributeText(value));
    if (!warning.empty()) PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1);
  }

  py::dict particles(std::size_t wall) {
    const std::vector<Particle>& p = run().capture(wall).particles;
    const py::ssize_t n = py::ssize_t(p.size());
    py::array_t<float> position({n, py::ssize_t(3)}), velocity({n, py::ssize_t(3)}), age(n),
        life(n), lifetime(n);
    for (py::ssize_t i = 0; i < n; ++i) {
      const Particle& q = p[std::size_t(i)];
      for (int c = 0; c < 3; ++c) {
        position.mutable_at(i, c) = q.positionLife[c];
        velocity.mutable_at(i, c) = q.velocityKind[c];
      }
      age.mutable_at(i) = q.age();
      life.mutable_at(i) = q.life();
      lifetime.mutable_at(i) = q.lifetime();
    }
    py::dict d;
    d["position"] = position;
    d["velocity"] = velocity;
    d["age"] = age;
    d["life_remaining"] = life;
    d["lifetime"] = lifetime;
    return d;
  }

  py::array_t<std::uint8_t> image(std::size_t wall) {
    const Image& img = run().capture(wall).image;
    py::array_t<std::uint8_t> out(
        {py::ssize_t(img.height), py::ssize_t(img.width), py::ssize_t(3)});
    std::uint8_t* o = out.mutable_data();
    for (std::size_t i = 0, n = std::size_t(img.width) * std::size_t(img.height); i < n; ++i)
      std::copy_n(&img.rgba[i * 4], 3, o + i * 3);
    return out;
  }

  py::list streamlines(std::size_t wall) { return linesToPython(run().streamlines(wall)); }
  py::list trails(std::size_t wall) {
    std::vector<std::size_t> owners;
    return linesToPython(run().trails(wall, owners));
  }

  py::dict stats() {
    SteppedRun& r = run();
    py::dict d;
    d["frames"] = r.frames();
    py::list walls;
    const std::vector<std::string> names = r.wallNames();
    for (std::size_t i = 0; i < names.size(); ++i) {
      const WallStats s = r.stats(i);
      py::dict w;
      w["name"] = names[i];
      w["frame"] = s.frame;
      w["fps"] = s.fps;
      w["frame_ms"] = s.frameMs;
      w["update_ms"] = s.updateMs;
      w["scene_ms"] = s.sceneMs;
      w["particles_ms"] = s.renderMs;
      w["post_ms"] = s.postMs;
      w["live_particles"] = s.liveParticles;
      w["capacity"] = s.capacity;
      walls.append(w);
    }
    d["walls"] = walls;
    return d;
  }

  int close() {
    if (!run_) return exitCode_;
    py::gil_scoped_release release;
    exitCode_ = run_->close();
    run_.reset();
    return exitCode_;
  }

 private:
  std::unique_ptr<SteppedRun> run_;
  int exitCode_ = 0;
};

}  // namespace
}  // namespace sandstorm

PYBIND11_MODULE(sandstorm, m) {
  using namespace sandstorm;
  m.doc() = "Sandstorm: GPU particles carried through vector fields (docs/PYTHON.md)";
  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });
  // Quiet by default in Python: warnings and errors only.
  log::setLevel(log::Level::Warn);
  m.def(
      "set_log_level",
      [](const std::string& name) {
        log::Level level;
        if (!log::parseLevel(name, level))
          throw Error("set_log_level('" + name + "'): expected error, warn, info or debug");
        log::setLevel(level);
      },
      py::arg("level"), "Sandstorm's log on stderr: error, warn (the default here), info or debug");

  py::class_<Field>(m, "Field", "A vector field file read as Sandstorm reads it")
      .def_readonly("values", &Field::values, "(nz, ny, nx, 3) float32, m/s")
      .def_readonly("valid", &Field::valid, "(nz, ny, nx) bool: points inside the file's cells")
      .def_readonly("bounds", &Field::bounds, "((x0, y0, z0), (x1, y1, z1)), metres")
      .def_readonly("times", &Field::times, "the time steps of a series or file, seconds")
      .def_readonly("info", &Field::info, "what `sandstorm-field info` says")
      .def_readonly("array", &Field::arrayName, "the vector array or grid read")
      .def_readonly("scalars", &Field::scalars, "the file's scalar arrays, (nz, ny, nx) each")
      .def("__repr__", [](const Field& f) {
        return concat("<sandstorm.Field ", f.arrayName, " of ", f.values.shape(2), " x ",
                      f.values.shape(1), " x ", f.values.shape(0), " points>");
      });
  m.def("load_field", &loadFieldFile, py::arg("path"), py::arg("array") = py::none(),
        py::arg("resolution") = py::none(), py::arg("time_step") = 0,
        "Reads a field file (every format the application reads): its values, validity "
        "mask, bounds, times and description. resolution=(nx, ny, nz) resamples.");

  m.def("save_field", &saveFieldFile, py::arg("path"), py::arg("values"), py::arg("bounds"),
        py::arg("array") = "velocity",
        "Writes (nz, ny, nx, 3) values over bounds ((x0, y0, z0), (x1, y1, z1)) as a .vti or "
        ".vdb file that Run, load_field and the application open");

  py::class_<Run>(m, "Run", "A run of the application, stepped from Python, headless")
      .def(py::init<const std::string&, const std::optional<py::dict>&,
                    const std::optional<std::vector<std::string>>&,
                    const std::optional<std::string>&, const std::optional<std::string>&,
                    const std::optional<std::string>&, const std::optional<std::string>&,
                    const std::optional<std::string>&, const std::optional<std::string>&,
                    const std::optional<std::string>&, const std::string&,
                    const std::optional<double>&, const std::optional<int>&, bool>(),
           py::arg("path"), py::kw_only(), py::arg("set") = py::none(),
           py::arg("walls") = py::none(), py::arg("array") = py::none(),
           py::arg("config") = py::none(), py::arg("record") = py::none(),
           py::arg("replay") = py::none(), py::arg("movie") = py::none(),
           py::arg("movie_wall") = py::none(), py::arg("movie_size") = py::none(),
           py::arg("movie_stereo") = "left", py::arg("movie_fps") = py::none(),
           py::arg("movie_crf") = py::none(), py::arg("movie_menu") = false,
           "path: a configuration (.toml) or a field file (opened as `sandstorm FILE`). "
           "set: attributes as --set; walls: as --walls; movie...: as --movie...")
      .def("step", &Run::step, py::arg("n") = 1, "Runs n frames; returns when every wall drew")
      .def("set", &Run::set, py::arg("key"), py::arg("value"),
           "Sets an attribute from the next frame on, as --set and the menu do")
      .def("particles", &Run::particles, py::arg("wall") = 0,
           "The wall's particles at the last frame: position, velocity, age, life_remaining, "
           "lifetime")
      .def("image", &Run::image, py::arg("wall") = 0, "The wall's picture, (h, w, 3) uint8")
      .def("streamlines", &Run::streamlines, py::arg("wall") = 0,
           "The streamlines (the [streamlines] rake) as dicts of points and point data")
      .def("trails", &Run::trails, py::arg("wall") = 0,
           "The particles' trails (render.trail_length) as dicts of points and point data")
      .def("stats", &Run::stats, "Frames run and each wall's times and particle count")
      .def("close", &Run::close, "Ends the run, frees its GL contexts; returns its exit code")
      .def_property_readonly("frames", [](Run& r) { return r.run().frames(); })
      .def_property_readonly("walls", [](Run& r) { return r.run().wallNames(); })
      .def("__enter__", [](Run& r) -> Run& { return r; })
      .def("__exit__", [](Run& r, py::args) { r.close(); });
}
