// sandstorm-field: the command line for Sandstorm's vector field files.
//
//   sandstorm-field info FILE [--array NAME]
//   sandstorm-field convert IN OUT [--array NAME] [--dims X Y Z]
//   sandstorm-field resample IN OUT --dims X Y Z [--array NAME]
//   sandstorm-field generate NAME OUT --dims X Y Z --bounds X0 Y0 Z0 X1 Y1 Z1 [--param K=V]...
//   sandstorm-field derive IN OUT --quantity NAME... [--array NAME] [--dims X Y Z]
//
// Reads every format loadField() reads; writes .vti and .vdb. Errors go to
// stderr with exit status 1; bad arguments exit with CLI11's status (non-zero).
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli_numbers.h"
#include "app/cli_unknown_option.h"
#include "core/config/app_config.h"
#include "core/field/analytic_field.h"
#include "core/field/analytic_field_factory.h"
#include "core/field/derived_scalars.h"
#include "core/field/height_map_io.h"
#include "core/io/field_format.h"
#include "core/io/field_info.h"
#include "core/io/field_loader.h"
#include "core/io/field_writer.h"
#include "core/util/error.h"
#include "core/util/output_file.h"

namespace sandstorm {
namespace {

struct Common {
  std::string array;
  std::vector<int> dims;
  double budgetMiB = 0.0;  // 0: the application's automatic field.memory_budget
};

// How a command that writes a field compresses a .vti.
struct Output {
  std::string compression = "zlib";
  CLI::Option* option = nullptr;
};

void addOutput(CLI::App* cmd, Output& o) {
  o.option = cmd->add_option("--compression", o.compression,
                             "a .vti's compression: zlib (smallest), lz4 (faster to read), none "
                             "(read at the disk's speed: a series to stream)")
                 ->check(CLI::IsMember({"zlib", "lz4", "none"}));
}

void write(const std::string& out, const VectorField& f, const std::string& array,
           const Output& o) {
  saveField(out, f, array, vtiCompressionNamed(o.compression, "--compression"));
}

void addCommon(CLI::App* cmd, Common& c, bool dimsRequired) {
  cmd->add_option("--array", c.array,
                  "VTK array or VDB grid to read (default: the only vector one)");
  auto* dims = cmd->add_option("--dims", c.dims, "points per axis of the grid made: X Y Z")
                   ->expected(3)
                   ->check(wholeNumberCheck(1));
  if (dimsRequired) dims->required();
  cmd->add_option("--memory-budget", c.budgetMiB,
                  "largest dense grid accepted, MiB (default: half this machine's memory, as "
                  "field.memory_budget = \"auto\")")
      ->check(positiveNumberCheck());
}

LoadOptions optionsFrom(const Common& c) {
  LoadOptions o;
  o.arrayName = c.array;
  if (c.dims.size() == 3) o.resolution = {c.dims[0], c.dims[1], c.dims[2]};
  o.memoryBudget = c.budgetMiB > 0.0 ? std::size_t(c.budgetMiB * 1024.0 * 1024.0)
                                     : std::size_t(fieldMemoryBudget(FieldSpec{}));
  return o;
}

void info(const std::string& file, const Common& c) {
  LoadReport report;
  const VectorField f = loadField(file, optionsFrom(c), &report);
  std::cout << describeField(file, f, report);
}

// The output's checks, made before the input is read (a large file takes minutes).
void checkOutput(const std::string& out, const Output& o) {
  if (o.option->count() > 0 && formatForExtension(out) != FieldFormat::VtkImageData)
    throw Error(concat("--compression applies to .vti files; ", out,
                       " is written as its format compresses"));
  checkFieldOutput(out);
}

void convert(const std::string& in, const std::string& out, const Common& c, const Output& o) {
  checkOutput(out, o);
  LoadReport report;
  const VectorField f = loadField(in, optionsFrom(c), &report);
  write(out, f, report.arrayName.empty() ? "velocity" : report.arrayName, o);
  const glm::ivec3 d = f.dims();
  std::cerr << "wrote " << out << " (" << d.x << "x" << d.y << "x" << d.z << ")\n";
}

// Adds derived quantities (core/field/derived_scalars.h) to a field's scalar
// arrays and writes it with them (and those it had).
void derive(const std::string& in, const std::string& out, const std::vector<std::string>& names,
            const Common& c, const Output& o) {
  checkOutput(out, o);
  LoadReport report;
  VectorField f = loadField(in, optionsFrom(c), &report);
  for (const std::string& name : names) {
    if (f.findScalars(name))
      throw Error(concat(in, ": already has an array '", name, "'; its arrays: ", f.scalarNames()));
    f.addScalars(name, derivedScalars(f, name).values);
  }
  write(out, f, report.arrayName.empty() ? "velocity" : report.arrayName, o);
  std::cerr << "wrote " << out << " with arrays " << f.scalarNames() << "\n";
}

FieldParams parseParams(const std::vector<std::string>& items) {
  FieldParams params;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw Error(concat("--param '", item, "': expected KEY=VALUE, e.g. --param spin=4"));
    const std::string key = item.substr(0, eq), text = item.substr(eq + 1);
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != text.size())
      throw Error(concat("--param '", item, "': '", text, "' is not a number"));
    params[key] = value;
  }
  return params;
}

std::string fieldList() {
  std::ostringstream os;
  os << "Analytic fields and their parameters (defaults):\n";
  for (const AnalyticFieldSpec& spec : analyticFieldSpecs()) {
    os << "  " << spec.name << ": " << spec.summary << "\n     ";
    for (const auto& [key, value] : spec.defaults)
      os << " " << key << "=" << value;
    os << "\n";
  }
  return os.str();
}

}  // namespace
}  // namespace sandstorm

int main(int argc, char** argv) {
  using namespace sandstorm;
  CLI::App app{"sandstorm-field: inspect, convert, resample and generate vector field files"};
  app.require_subcommand(1);

  Common infoOpts, convertOpts, resampleOpts;
  std::string infoFile, in, out, rin, rout, name, gout;
  auto* infoCmd = app.add_subcommand("info", "describe a field file: grid, bounds, magnitudes");
  infoCmd->add_option("FILE", infoFile, "field file")->required();
  addCommon(infoCmd, infoOpts, false);

  auto* convertCmd = app.add_subcommand("convert", "read any field file, write .vti or .vdb");
  convertCmd->add_option("IN", in, "input file")->required();
  convertCmd->add_option("OUT", out, "output file (.vti or .vdb)")->required();
  addCommon(convertCmd, convertOpts, false);
  Output convertOut, resampleOut, generateOut, deriveOut;
  addOutput(convertCmd, convertOut);

  auto* resampleCmd = app.add_subcommand("resample", "resample a field onto a new grid");
  resampleCmd->add_option("IN", rin, "input file")->required();
  resampleCmd->add_option("OUT", rout, "output file (.vti or .vdb)")->required();
  addCommon(resampleCmd, resampleOpts, true);
  addOutput(resampleCmd, resampleOut);

  std::vector<int> gdims;
  std::vector<double> gbounds;
  std::vector<std::string> gparams;
  auto* generateCmd = app.add_subcommand("generate", "bake an analytic field to a file");
  generateCmd->add_option("NAME", name, "field name (see below)")->required();
  generateCmd->add_option("OUT", gout, "output file (.vti or .vdb)")->required();
  generateCmd->add_option("--dims", gdims, "grid points per axis: X Y Z")
      ->expected(3)
      ->required()
      ->check(wholeNumberCheck(1));
  generateCmd->add_option("--bounds", gbounds, "box in metres: X0 Y0 Z0 X1 Y1 Z1")
      ->expected(6)
      ->required();
  generateCmd->add_option("--param", gparams, "a field parameter KEY=VALUE (repeatable)");
  addOutput(generateCmd, generateOut);
  generateCmd->footer(fieldList());

  Common deriveOpts;
  std::string din, dout;
  std::vector<std::string> dnames;
  auto* deriveCmd = app.add_subcommand(
      "derive", "add derived scalar arrays (vortex cores, divergence) to a field");
  deriveCmd->add_option("IN", din, "input file")->required();
  deriveCmd->add_option("OUT", dout, "output file (.vti or .vdb)")->required();
  std::string quantities;
  for (std::string_view n : derivedScalarNames())
    quantities += (quantities.empty() ? "" : ", ") + std::string(n);
  deriveCmd->add_option("--quantity", dnames, "a quantity to add (repeatable): " + quantities)
      ->required();
  addCommon(deriveCmd, deriveOpts, false);
  addOutput(deriveCmd, deriveOut);

  std::string tout;
  int tsize = 257;
  double textent = 200.0;
  unsigned tseed = 7;
  auto* terrainCmd = app.add_subcommand("terrain", "make a desert dune height map (16-bit PGM)");
  terrainCmd->add_option("OUT", tout, "output file (.pgm)")->required();
  terrainCmd->add_option("--size", tsize, "samples per side")->check(CLI::Range(2, 8193));
  terrainCmd->add_option("--extent", textent, "metres per side (for the dunes' wavelength)")
      ->check(positiveNumberCheck());
  terrainCmd->add_option("--seed", tseed, "noise seed");

  if (const std::string unknown = unknownOption(app, argc, argv); !unknown.empty()) {
    std::cerr << "sandstorm-field: " << unknown << "\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  try {
    if (*infoCmd) info(infoFile, infoOpts);
    if (*convertCmd) convert(in, out, convertOpts, convertOut);
    if (*resampleCmd) convert(rin, rout, resampleOpts, resampleOut);
    if (*deriveCmd) derive(din, dout, dnames, deriveOpts, deriveOut);
    if (*terrainCmd) {
      std::string extension = std::filesystem::path(tout).extension().string();
      for (char& ch : extension)
        ch = char(std::tolower(static_cast<unsigned char>(ch)));
      if (extension != ".pgm")
        throw Error(
            concat(tout, ": a height map is written as a 16-bit PGM; expected a .pgm file"));
      checkOutputFile(tout, "writing");
      const HeightMap dunes = duneTerrain({tsize, tsize}, glm::vec2(float(textent)), tseed);
      writeHeightMapPgm(dunes, tout, 0.0f, 1.0f);
      std::cerr << "wrote " << tout << " (" << tsize << "x" << tsize << " dunes over " << textent
                << " m; heights 0..1, scaled by the config's terrain_min/max)\n";
    }
    if (*generateCmd) {
      checkOutput(gout, generateOut);
      const auto field = makeAnalyticField(name, parseParams(gparams));
      const Box box{{float(gbounds[0]), float(gbounds[1]), float(gbounds[2])},
                    {float(gbounds[3]), float(gbounds[4]), float(gbounds[5])}};
      const VectorField grid = bake(*field, box, {gdims[0], gdims[1], gdims[2]});
      write(gout, grid, "velocity", generateOut);
      std::cerr << "wrote " << gout << " (" << name << ", " << gdims[0] << "x" << gdims[1] << "x"
                << gdims[2] << ")\n";
    }
  } catch (const Error& e) {
    std::cerr << "sandstorm-field: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "sandstorm-field: unexpected failure: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
