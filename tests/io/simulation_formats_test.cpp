// Files simulations write, made with the formats' own libraries and writers
// (the Exodus II library, VTK's writers, the NetCDF library, hand-written
// OpenFOAM dictionaries as OpenFOAM writes them): every one loads with the
// analytic field's values, over its blocks and its time steps.
#include <gtest/gtest.h>

#include <hdf5.h>
#include <vtk_cgns.h>
#include VTK_CGNS(cgnslib.h)
#include <netcdf.h>
#include <vtkCellData.h>
#include <vtkDataSetTriangleFilter.h>
#include <vtkEnSightWriter.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtk_exodusII.h>

#include <cstring>
#include <thread>

#include <cmath>

#include "core/io/field_loader.h"
#include "core/io/field_sequence.h"
#include "tests/io/io_test_util.h"
#include "tests/io/openfoam_case.h"

namespace sandstorm {
namespace {

using test::asymmetric;

constexpr double kExact = 1e-5;

std::string replaceFirst(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The flow at time t: the asymmetric field, growing with time.
glm::dvec3 flowAt(const glm::dvec3& p, double t) {
  return asymmetric(p) * (1.0 + t);
}

// Two element blocks of hexahedra over [0, 2] x [0, 1] x [0, 1] (x < 1, x > 1),
// n cells per metre, nodal vel_x/vel_y/vel_z and an element "pressure" at
// times 0, 0.5 and 1, written by the Exodus II library. With `rank` 0 or 1:
// only that block and its nodes, as rank `rank` of a decomposed run writes
// them (`mode` EX_NETCDF4 for the HDF5-based layout).
void writeExodus(const std::filesystem::path& path, int n, int rank = -1, int mode = 0) {
  int cpu = 8, io = 8;
  const int id = ex_create(path.c_str(), EX_CLOBBER | mode, &cpu, &io);
  ASSERT_GE(id, 0);
  const int firstBlock = rank < 0 ? 0 : rank, blocks = rank < 0 ? 2 : 1;
  const int i0 = firstBlock * n, nx = blocks * n + 1, ny = n + 1, nz = n + 1;
  const int nodes = nx * ny * nz, cells = blocks * n * n * n;
  ASSERT_EQ(ex_put_init(id, "two blocks", 3, nodes, cells, blocks, 0, 0), 0);
  std::vector<double> x, y, z;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = i0; i < i0 + nx; ++i) {
        x.push_back(double(i) / n);
        y.push_back(double(j) / n);
        z.push_back(double(k) / n);
      }
  ASSERT_EQ(ex_put_coord(id, x.data(), y.data(), z.data()), 0);
  auto node = [&](int i, int j, int k) { return 1 + (i - i0) + nx * (j + ny * k); };
  for (int block = firstBlock; block < firstBlock + blocks; ++block) {
    const int blockId = 10 + block;
    ASSERT_EQ(ex_put_block(id, EX_ELEM_BLOCK, blockId, "HEX8", n * n * n, 8, 0, 0, 0), 0);
    std::vector<int> connect;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = block * n; i < (block + 1) * n; ++i)
          for (const int c : {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k),
                              node(i, j + 1, k), node(i, j, k + 1), node(i + 1, j, k + 1),
                              node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)})
            connect.push_back(c);
    ASSERT_EQ(ex_put_conn(id, EX_ELEM_BLOCK, blockId, connect.data(), nullptr, nullptr), 0);
  }
  char* nodal[] = {const_cast<char*>("vel_x"), const_cast<char*>("vel_y"),
                   const_cast<char*>("vel_z")};
  ASSERT_EQ(ex_put_variable_param(id, EX_NODAL, 3), 0);
  ASSERT_EQ(ex_put_variable_names(id, EX_NODAL, 3, nodal), 0);
  char* element[] = {const_cast<char*>("pressure")};
  ASSERT_EQ(ex_put_variable_param(id, EX_ELEM_BLOCK, 1), 0);
  ASSERT_EQ(ex_put_variable_names(id, EX_ELEM_BLOCK, 1, element), 0);
  const double times[] = {0.0, 0.5, 1.0};
  for (int step = 1; step <= 3; ++step) {
    const double t = times[step - 1];
    ASSERT_EQ(ex_put_time(id, step, &t), 0);
    for (int c = 0; c < 3; ++c) {
      std::vector<double> v(static_cast<std::size_t>(nodes));
      for (int p = 0; p < nodes; ++p)
        v[std::size_t(p)] = flowAt({x[std::size_t(p)], y[std::size_t(p)], z[std::size_t(p)]}, t)[c];
      ASSERT_EQ(ex_put_var(id, step, EX_NODAL, c + 1, 1, nodes, v.data()), 0);
    }
    for (int block = firstBlock; block < firstBlock + blocks; ++block) {
      const std::vector<double> pressure(std::size_t(n * n * n), 100.0 * (block + 1) + t);
      ASSERT_EQ(ex_put_var(id, step, EX_ELEM_BLOCK, 1, 10 + block, n * n * n, pressure.data()), 0);
    }
  }
  ASSERT_EQ(ex_close(id), 0);
}

void expectFlow(const VectorField& f, double t, double tolerance) {
  for (int k = 0; k < f.dims().z; ++k)
    for (int j = 0; j < f.dims().y; ++j)
      for (int i = 0; i < f.dims().x; ++i) {
        const glm::dvec3 p(f.pointPosition(i, j, k));
        ASSERT_TRUE(f.valid(i, j, k));
        ASSERT_LE(glm::length(glm::dvec3(f.at(i, j, k)) - flowAt(p, t)), tolerance * (1 + t))
            << "at " << p.x << " " << p.y << " " << p.z << ", t = " << t;
      }
}

TEST(SimulationFormats, ExodusBlocksMergeAndItsTimeStepsPlay) {
  const auto dir = test::scratch();
  const auto path = dir / "flow.e";
  writeExodus(path, 4);
  LoadReport report;
  LoadOptions options;
  options.resolution = {17, 9, 9};
  const VectorField first = loadField(path, options, &report);
  EXPECT_EQ(report.format, "Exodus II file (.e)");
  EXPECT_EQ(report.arrayName, "vel_");  // vel_x, vel_y, vel_z joined by VTK's reader
  EXPECT_EQ(report.blocks.size(), 2u);
  EXPECT_EQ(report.cells, std::uint64_t(2 * 64));
  ASSERT_EQ(report.times, (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(first.bounds().max, glm::vec3(2.0f, 1.0f, 1.0f));
  expectFlow(first, 0.0, kExact);
  // The element variable, moved to the points: the blocks' means meet at x = 1.
  const VectorField::Scalars* pressure = first.findScalars("pressure");
  ASSERT_NE(pressure, nullptr);
  EXPECT_NEAR(first.sampleScalars(*pressure, {0.25f, 0.5f, 0.5f}), 100.0, 1e-4);
  EXPECT_NEAR(first.sampleScalars(*pressure, {1.75f, 0.5f, 0.5f}), 200.0, 1e-4);

  options.timeStep = 2;
  options.arrayName = "vel";  // as the file names its components
  expectFlow(loadField(path, options), 1.0, kExact);
  options.arrayName.clear();
  options.timeStep = 3;
  test::expectError([&] { loadField(path, options); },
                    {path.string(), "3 time steps", "asked for step 3"});

  options.timeStep = 0;
  const FieldSequence sequence = FieldSequence::fromFile(path, options);
  ASSERT_EQ(sequence.size(), 3u);
  EXPECT_EQ(sequence.time(1), 0.5);
  expectFlow(sequence.frame(1), 0.5, kExact);
  // By default: the hexahedra's size, 0.25 m.
  EXPECT_EQ(loadField(path).dims(), glm::ivec3(9, 5, 5));
}

// A run on two ranks wrote a file each ("flow.e.2.0", "flow.e.2.1"): either
// opens the whole run, as the one file of the same mesh does, in both of
// Exodus's layouts; a rank's file missing is named.
TEST(SimulationFormats, ADecomposedExodusRunOpensWholeFromAnyRanksFile) {
  const auto dir = test::scratch();
  writeExodus(dir / "flow.e", 4);
  LoadOptions options;
  options.resolution = {17, 9, 9};
  const VectorField whole = loadField(dir / "flow.e", options);
  for (const int mode : {0, EX_NETCDF4}) {
    SCOPED_TRACE(mode == 0 ? "classic" : "netcdf-4");
    const std::string base = mode == 0 ? "flow.e" : "flow4.exo";
    writeExodus(dir / (base + ".2.0"), 4, 0, mode);
    writeExodus(dir / (base + ".2.1"), 4, 1, mode);
    for (const char* rank : {".2.0", ".2.1"}) {
      LoadReport report;
      const VectorField f = loadField(dir / (base + rank), options, &report);
      EXPECT_EQ(report.format, "Exodus II file (.e)");
      EXPECT_EQ(report.cells, std::uint64_t(2 * 64));
      EXPECT_EQ(report.blocks.size(), 2u);
      ASSERT_EQ(report.times, (std::vector<double>{0.0, 0.5, 1.0}));
      ASSERT_EQ(f.dims(), whole.dims());
      EXPECT_EQ(f.bounds().min, whole.bounds().min);
      EXPECT_EQ(f.bounds().max, whole.bounds().max);
      EXPECT_EQ(f.invalidCount(), std::size_t(0));
      expectFlow(f, 0.0, kExact);
      for (std::size_t p = 0; p < f.pointCount(); ++p)
        ASSERT_LE(glm::length(f.values()[p] - whole.values()[p]), 1e-6f) << "point " << p;
    }
    LoadOptions last = options;
    last.timeStep = 2;
    expectFlow(loadField(dir / (base + ".2.1"), last), 1.0, kExact);
  }
  std::filesystem::remove(dir / "flow.e.2.1");
  test::expectError([&] { loadField(dir / "flow.e.2.0", options); },
                    {"flow.e.2.0", "rank 1's file flow.e.2.1 is missing"});
}

// A series' reader threads read an Exodus file's steps at once: the NetCDF
// library underneath takes one of them at a time (netcdf_lock.h), and every
// step comes out right.
TEST(SimulationFormats, ExodusStepsReadOnSeveralThreadsAtOnce) {
  const auto dir = test::scratch();
  const auto path = dir / "flow.e";
  writeExodus(path, 3);
  std::vector<std::string> errors(8);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < errors.size(); ++t)
    threads.emplace_back([&, t] {
      try {
        LoadOptions options;
        options.resolution = {7, 4, 4};
        options.timeStep = t % 3;
        const VectorField f = loadField(path, options);
        const double time = 0.5 * double(t % 3);
        for (std::size_t p = 0; p < f.pointCount(); ++p) {
          const glm::dvec3 expected =
              flowAt(glm::dvec3(f.pointPosition(int(p % 7), int(p / 7 % 4), int(p / 28))), time);
          if (glm::length(glm::dvec3(f.values()[p]) - expected) > kExact * 2.0)
            throw Error(concat("step ", t % 3, ": point ", p, " is off"));
        }
      } catch (const std::exception& e) {
        errors[t] = e.what();
      }
    });
  for (std::thread& t : threads)
    t.join();
  for (std::size_t t = 0; t < errors.size(); ++t)
    EXPECT_EQ(errors[t], "") << "thread " << t;
}

TEST(SimulationFormats, ExodusFilesThatClaimMoreThanTheyHoldAreRefused) {
  const auto dir = test::scratch();
  const auto path = dir / "flow.e";
  writeExodus(path, 2);
  const std::string whole = test::readAll(path);
  const auto cut = dir / "cut.e";
  test::writeText(cut, whole.substr(0, whole.size() - 100));
  test::expectError([&] { loadField(cut); }, {cut.string(), "claims bytes", "truncated"});
  test::writeText(cut, whole.substr(0, 40));
  test::expectError([&] { loadField(cut); },
                    {cut.string(), "the file ends inside", "NetCDF header"});
  LoadOptions small;
  small.memoryBudget = 1000;
  test::expectError([&] { loadField(path, small); },
                    {path.string(), "memory budget (field.memory_budget) of 1000"});
}

// Two element blocks with one id: VTK's reader read past its tables on such a
// file (a segmentation fault, found by fuzz_field_e); it is refused first.
TEST(SimulationFormats, ExodusBlocksSharingAnIdAreRefused) {
  const auto path = test::scratch() / "shared_id.e";
  writeExodus(path, 2);
  int id = -1, var = -1;
  ASSERT_EQ(nc_open(path.c_str(), NC_WRITE, &id), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(id, "eb_prop1", &var), NC_NOERR);
  const int ids[] = {10, 10};
  ASSERT_EQ(nc_put_var_int(id, var, ids), NC_NOERR);
  ASSERT_EQ(nc_close(id), NC_NOERR);
  test::expectError([&] { loadField(path); },
                    {path.string(), "element blocks 1 and 2 share the id 10", "eb_prop1"});
}

// VTK's reader sizes its name buffers by the file's maximum_name_length (a
// 5.5 GB allocation for one a fuzzer wrote): past NetCDF's 256 it is refused.
TEST(SimulationFormats, AnExodusMaximumNameLengthBeyondNetcdfsIsRefused) {
  const auto path = test::scratch() / "long_names.e";
  writeExodus(path, 2);
  int id = -1;
  ASSERT_EQ(nc_open(path.c_str(), NC_WRITE, &id), NC_NOERR);
  ASSERT_EQ(nc_redef(id), NC_NOERR);
  const int huge = 687865888;
  ASSERT_EQ(nc_put_att_int(id, NC_GLOBAL, "maximum_name_length", NC_INT, 1, &huge), NC_NOERR);
  ASSERT_EQ(nc_close(id), NC_NOERR);
  test::expectError([&] { loadField(path); },
                    {path.string(), "maximum_name_length is", "at most 256 characters"});
}

// An OpenFOAM case's cell values at the points: each mesh point takes the mean
// of the cells around it, exact for a linear flow where those cells lie
// symmetrically about it (inside the box), within the flow's stretch (3)
// times a cell's half diagonal on the box's faces.
void expectFoamFlow(const VectorField& f, int n, double t) {
  const double h = 1.0 / n, reach = 0.5 * std::sqrt(3.0) * h;
  ASSERT_EQ(f.dims(), glm::ivec3(n + 1));
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const glm::dvec3 p(f.pointPosition(i, j, k));
        const bool inside = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        const double error = glm::length(glm::dvec3(f.at(i, j, k)) - flowAt(p, t));
        ASSERT_LE(error, (inside ? kExact : 3.0 * reach + kExact) * (1 + t))
            << "at " << p.x << " " << p.y << " " << p.z;
      }
}

TEST(SimulationFormats, OpenFoamCasesAsciiBinaryAndDecomposed) {
  const auto dir = test::scratch();
  for (const bool binary : {false, true})
    for (const bool decomposed : {false, true}) {
      SCOPED_TRACE(concat(binary ? "binary" : "ascii", decomposed ? ", decomposed" : ""));
      test::FoamCase c;
      c.binary = binary;
      c.decomposed = decomposed;
      c.flow = flowAt;
      const auto folder = dir / concat(binary ? "binary" : "ascii", decomposed ? "-dec" : "");
      test::writeFoamCase(c, folder);
      LoadOptions options;
      options.resolution = glm::ivec3(c.n + 1);
      LoadReport report;
      const VectorField f = loadField(folder, options, &report);
      EXPECT_EQ(report.format, "OpenFOAM case");
      EXPECT_EQ(report.arrayName, "U");
      EXPECT_EQ(report.cells, std::uint64_t(c.n * c.n * c.n));
      ASSERT_EQ(report.times, c.times);
      EXPECT_EQ(f.invalidCount(), 0u);
      expectFoamFlow(f, c.n, 0.0);
      // The .foam file and controlDict name the same case; a later time folder.
      options.timeStep = 2;
      expectFoamFlow(loadField(folder / "case.foam", options), c.n, 1.0);
      expectFoamFlow(loadField(folder / "system" / "controlDict", options), c.n, 1.0);
    }
}

TEST(SimulationFormats, OpenFoamListsThatClaimMoreThanTheyHoldAreRefused) {
  const auto dir = test::scratch();
  for (const bool binary : {false, true}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    test::FoamCase c;
    c.binary = binary;
    c.n = 2;
    c.flow = flowAt;
    const auto folder = dir / (binary ? "binary" : "ascii");
    test::writeFoamCase(c, folder);
    EXPECT_NO_THROW(loadField(folder));
    const auto points = folder / "constant" / "polyMesh" / "points";
    const std::string good = test::readAll(points);
    std::string bad = good;
    bad.replace(bad.find("27\n("), 4, "2700000000\n(");
    test::writeText(points, bad);
    test::expectError([&] { loadField(folder); }, {points.string(), "2700000000 elements"});
    bad = good;
    bad.replace(bad.find("27\n("), 4, "28\n(");
    test::writeText(points, bad);
    test::expectError([&] { loadField(folder); }, {points.string(), "28 elements"});
    test::writeText(points, good.substr(0, good.size() - 40));
    test::expectError([&] { loadField(folder); }, {points.string()});
    test::writeText(points, good);
  }
  test::expectError([&] { loadField(dir); }, {dir.string(), "not an OpenFOAM case"});
}

// A flow linear in metres east, north and up of 10 E, 44.5 N, time t.
glm::dvec3 netcdfFlow(double lon, double lat, double z, double t) {
  const double radians = 3.14159265358979323846 / 180.0, r = 6371000.0;
  const double x = lon * radians * r * std::cos(44.5 * radians);
  const double y = (lat - 44.5) * radians * r;
  return glm::dvec3(x / 10000.0 - 80.0, 2.0 * y / 10000.0, 3.0 * z / 100.0 + 0.5) * (1.0 + t);
}

// A mesh of tetrahedra over [0, 1]^3 carrying the flow at time t.
vtkSmartPointer<vtkUnstructuredGrid> tetraBox(double t) {
  vtkNew<vtkImageData> box;
  box->SetDimensions(5, 5, 5);
  box->SetSpacing(0.25, 0.25, 0.25);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputData(box);
  tets->Update();
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  mesh->DeepCopy(tets->GetOutput());
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p) {
    double x[3];
    mesh->GetPoint(p, x);
    const glm::dvec3 f = flowAt({x[0], x[1], x[2]}, t);
    v->SetTuple3(p, f.x, f.y, f.z);
  }
  mesh->GetPointData()->AddArray(v);
  vtkNew<vtkIntArray> block;  // the writer's parts
  block->SetName("BlockId");
  block->SetNumberOfTuples(mesh->GetNumberOfCells());
  block->Fill(1);
  mesh->GetCellData()->AddArray(block);
  return mesh;
}

TEST(SimulationFormats, EnSightGoldBinaryTransientCases) {
  const auto dir = test::scratch();
  vtkSmartPointer<vtkEnSightWriter> writer;
  for (int step = 0; step < 3; ++step) {
    writer = vtkSmartPointer<vtkEnSightWriter>::New();
    writer->SetInputData(tetraBox(0.5 * step));
    writer->SetPath(dir.c_str());
    writer->SetBaseName("flow");
    writer->SetNumberOfBlocks(1);
    writer->SetTimeStep(step);
    writer->SetTransientGeometry(1);
    writer->Write();
  }
  // The case file as the writer's WriteCaseFile writes it (which leaves its
  // file unflushed until the process ends), with times 0, 0.5, 1.
  const auto path = dir / "flow.0.case";
  test::writeText(path,
                  "FORMAT\ntype: ensight gold\n\n\nGEOMETRY\nmodel: 1 flow.0.*****.geo\n\n"
                  "VARIABLE\nvector per node: 1 velocity_n flow.0.*****_n.velocity\n\nTIME\n"
                  "time set: 1\nnumber of steps: 3\nfilename start number: 00000\n"
                  "filename increment: 00001\ntime values: \n0 0.5 1\n");

  LoadOptions options;
  options.resolution = {5, 5, 5};
  LoadReport report;
  const VectorField f = loadField(path, options, &report);
  EXPECT_EQ(report.format, "EnSight Gold case (.case)");
  EXPECT_EQ(report.arrayName, "velocity_n");  // VTK's writer adds its _n
  ASSERT_EQ(report.times, (std::vector<double>{0.0, 0.5, 1.0}));
  expectFlow(f, 0.0, kExact);
  const FieldSequence sequence = FieldSequence::fromFile(path, options);
  ASSERT_EQ(sequence.size(), 3u);
  expectFlow(sequence.frame(2), 1.0, kExact);

  // A count beyond the file, a wildcard file missing, a file outside the case.
  const auto geo = dir / "flow.0.00001.geo";
  const std::string good = test::readAll(geo);
  test::writeText(geo, good.substr(0, good.size() - 64));
  options.timeStep = 1;
  test::expectError([&] { loadField(path, options); }, {geo.string(), "part 1", "truncated"});
  std::filesystem::remove(geo);
  test::expectError([&] { loadField(path, options); }, {geo.string(), "no such file"});
  test::writeText(path, "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: ../flow.0.00000.geo\n");
  test::expectError([&] { loadField(path); }, {"outside the case's folder"});
  test::writeText(path, "FORMAT\ntype: ensight\nGEOMETRY\nmodel: flow.0.00000.geo\n");
  test::expectError([&] { loadField(path); }, {path.string(), "EnSight 6 is not read"});
  // Keys VTK's reader would loop on for ever (a fuzz find), refused before it reads.
  test::writeText(path,
                  "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: flow.0.00000.geo\n"
                  "Xmodel: vector per node: 1 velocity flow.vel\n");
  test::expectError([&] { loadField(path); },
                    {path.string() + ":5", "'xmodel' in the GEOMETRY section; expected model"});
  test::writeText(path, "FORMAT\ntype: ensight gold\nXtype: foo\nGEOMETRY\nmodel: flow.geo\n");
  test::expectError([&] { loadField(path); },
                    {path.string() + ":3", "'xtype' in the FORMAT section; expected type"});
  // A zero byte in the type line: VTK's reader read the case as EnSight 6 and
  // crashed on the Gold files (a fuzz find); control characters are refused.
  test::writeText(path,
                  std::string("FORMAT\ntype: \x01\0 ensight gold\nGEOMETRY\nmodel: f.geo\n", 51));
  test::expectError([&] { loadField(path); },
                    {path.string() + ":2", "a control character (byte 1); a case file is text"});
  test::writeText(path, "FORMAT\ntype: ensight gold extra\nGEOMETRY\nmodel: f.geo\n");
  test::expectError([&] { loadField(path); }, {path.string(), "not an EnSight Gold case"});
}

// EnSight Gold ascii as its format guide lays it out: a value a line, an
// element a line; a hexahedron, its node ids given, and a per-node vector.
TEST(SimulationFormats, EnSightGoldAscii) {
  const auto dir = test::scratch();
  std::string geo =
      "one hexahedron\nascii\nnode id given\nelement id given\npart\n1\nbox\n"
      "coordinates\n8\n";
  for (int i = 1; i <= 8; ++i)
    geo += std::to_string(i) + "\n";
  const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                            {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::string vec = "velocity\npart\n1\ncoordinates\n";
  for (int a = 0; a < 3; ++a) {
    for (const auto& c : corner)
      geo += concat(2.0 * c[a], "\n");
    for (const auto& c : corner)
      vec += concat(flowAt(2.0 * glm::dvec3(c[0], c[1], c[2]), 0.0)[a], "\n");
  }
  geo += "hexa8\n1\n1\n1 2 3 4 5 6 7 8\n";
  test::writeText(dir / "box.geo", geo);
  test::writeText(dir / "box.vel", vec);
  const auto path = dir / "box.case";
  test::writeText(path,
                  "FORMAT\ntype: ensight gold\n\nGEOMETRY\nmodel: box.geo\n\nVARIABLE\n"
                  "vector per node: velocity box.vel\n");
  LoadOptions options;
  options.resolution = {5, 5, 5};
  const VectorField f = loadField(path, options);
  EXPECT_EQ(f.bounds().max, glm::vec3(2.0f));
  expectFlow(f, 0.0, kExact);
  test::writeText(dir / "box.geo", replaceFirst(geo, "hexa8\n1\n", "hexa8\n1000000\n"));
  test::expectError([&] { loadField(path); }, {"box.geo", "part 1's hexa8", "the file ends"});
}

// A NetCDF CF file as a weather model writes one, through the NetCDF
// library: u, v, w (by their CF standard names ua, va, wa, or named u, v, w)
// on longitude, latitude (running north to south) and height, two times.
// `components` 2: u and v alone, a horizontal flow.
void writeNetcdf(const std::filesystem::path& path, bool standardNames, const char* levelUnits,
                 int components = 3) {
  int id = -1;
  ASSERT_EQ(nc_create(path.c_str(), NC_CLOBBER, &id), NC_NOERR);
  int time, lev, lat, lon;
  ASSERT_EQ(nc_def_dim(id, "time", NC_UNLIMITED, &time), NC_NOERR);
  ASSERT_EQ(nc_def_dim(id, "lev", 3, &lev), NC_NOERR);
  ASSERT_EQ(nc_def_dim(id, "lat", 5, &lat), NC_NOERR);
  ASSERT_EQ(nc_def_dim(id, "lon", 6, &lon), NC_NOERR);
  auto coordinate = [&](const char* name, int dim, const char* units, const char* standard) {
    int v = -1;
    EXPECT_EQ(nc_def_var(id, name, NC_DOUBLE, 1, &dim, &v), NC_NOERR);
    nc_put_att_text(id, v, "units", std::strlen(units), units);
    nc_put_att_text(id, v, "standard_name", std::strlen(standard), standard);
    return v;
  };
  const int vt = coordinate("time", time, "seconds since 2026-01-01", "time");
  const int vz = coordinate("lev", lev, levelUnits, "height");
  const int vy = coordinate("lat", lat, "degrees_north", "latitude");
  const int vx = coordinate("lon", lon, "degrees_east", "longitude");
  const int dims[4] = {time, lev, lat, lon};
  const char* names[3] = {"u", "v", "w"};
  const char* standard[3] = {"eastward_wind", "northward_wind", "upward_air_velocity"};
  int flow[3];
  for (int c = 0; c < components; ++c) {
    const std::string name = standardNames ? std::string(names[c]) + "a" : names[c];
    ASSERT_EQ(nc_def_var(id, name.c_str(), NC_FLOAT, 4, dims, &flow[c]), NC_NOERR);
    if (standardNames)
      nc_put_att_text(id, flow[c], "standard_name", std::strlen(standard[c]), standard[c]);
    nc_put_att_text(id, flow[c], "units", 3, "m/s");
  }
  ASSERT_EQ(nc_enddef(id), NC_NOERR);
  const double lons[6] = {10.0, 10.1, 10.2, 10.3, 10.4, 10.5};
  const double lats[5] = {45.0, 44.75, 44.5, 44.25, 44.0};
  const double levs[3] = {0.0, 100.0, 200.0};
  ASSERT_EQ(nc_put_var_double(id, vx, lons), NC_NOERR);
  ASSERT_EQ(nc_put_var_double(id, vy, lats), NC_NOERR);
  ASSERT_EQ(nc_put_var_double(id, vz, levs), NC_NOERR);
  for (std::size_t step = 0; step < 2; ++step) {
    const double t = double(step);
    const std::size_t one = 1;
    nc_put_vara_double(id, vt, &step, &one, &t);
    for (int c = 0; c < components; ++c) {
      std::vector<float> values;
      for (double z : levs)
        for (double la : lats)
          for (double lo : lons)
            values.push_back(float(netcdfFlow(lo, la, z, t)[c]));
      const std::size_t start[4] = {step, 0, 0, 0}, count[4] = {1, 3, 5, 6};
      ASSERT_EQ(nc_put_vara_float(id, flow[c], start, count, values.data()), NC_NOERR);
    }
  }
  ASSERT_EQ(nc_close(id), NC_NOERR);
}

TEST(SimulationFormats, NetcdfCfOnLongitudeLatitudeAndHeightInMetres) {
  const auto dir = test::scratch();
  for (const bool standardNames : {false, true}) {
    SCOPED_TRACE(standardNames ? "ua, va, wa by standard_name" : "u, v, w");
    const auto path = dir / (standardNames ? "cf.nc" : "uvw.nc");
    writeNetcdf(path, standardNames, "m");
    LoadReport report;
    const VectorField f = loadField(path, {}, &report);
    EXPECT_EQ(report.format, "NetCDF file (.nc)");
    ASSERT_EQ(report.times, (std::vector<double>{0.0, 1.0}));
    EXPECT_EQ(f.dims(), glm::ivec3(6, 5, 3));
    // x: 0.5 degrees of longitude at 44.5 N; y: a degree of latitude about it.
    const double radians = 3.14159265358979323846 / 180.0, r = 6371000.0;
    EXPECT_NEAR(f.bounds().max.x - f.bounds().min.x, 0.5 * radians * r * std::cos(44.5 * radians),
                1.0);
    EXPECT_NEAR(f.bounds().min.y, -0.5 * radians * r, 1.0);
    EXPECT_NEAR(f.bounds().max.y, 0.5 * radians * r, 1.0);
    EXPECT_FLOAT_EQ(f.bounds().max.z, 200.0f);
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 6; ++i) {
          const glm::dvec3 expected = netcdfFlow(10.0 + 0.1 * i, 44.0 + 0.25 * j, 100.0 * k, 0.0);
          ASSERT_LE(glm::length(glm::dvec3(f.at(i, j, k)) - expected), 1e-4)
              << i << " " << j << " " << k;
        }
    LoadOptions later;
    later.timeStep = 1;
    EXPECT_NEAR(loadField(path, later).at(2, 1, 1).x, netcdfFlow(10.2, 44.25, 100.0, 1.0).x, 1e-4);
  }
  // A horizontal flow alone, u and v (or by their standard names): z 0.
  for (const bool standardNames : {false, true}) {
    SCOPED_TRACE(standardNames ? "ua, va by standard_name" : "u, v");
    const auto path = dir / (standardNames ? "cf2.nc" : "uv.nc");
    writeNetcdf(path, standardNames, "m", 2);
    const VectorField f = loadField(path);
    ASSERT_EQ(f.dims(), glm::ivec3(6, 5, 3));
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 6; ++i) {
          glm::dvec3 expected = netcdfFlow(10.0 + 0.1 * i, 44.0 + 0.25 * j, 100.0 * k, 0.0);
          expected.z = 0.0;
          ASSERT_LE(glm::length(glm::dvec3(f.at(i, j, k)) - expected), 1e-4)
              << i << " " << j << " " << k;
        }
  }
  // A vertical axis in pressure: kept, and said.
  const auto pressure = dir / "pressure.nc";
  writeNetcdf(pressure, false, "hPa");
  LoadReport report;
  const VectorField f = loadField(pressure, {}, &report);
  EXPECT_FLOAT_EQ(f.bounds().max.z, 200.0f);
  bool said = false;
  for (const std::string& note : report.notes)
    said = said || note.find("axis 'lev' (units 'hpa')") != std::string::npos;
  EXPECT_TRUE(said);
}

// VTKHDF (version 1) as its specification lays it out, written with the HDF5
// library: an unstructured grid of one piece, the mesh's tetrahedra.
void writeVtkHdf(const std::filesystem::path& path, vtkUnstructuredGrid* mesh,
                 long long extraPoints = 0) {
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t root = H5Gcreate2(file, "VTKHDF", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const hsize_t two = 2;
  const hid_t versionSpace = H5Screate_simple(1, &two, nullptr);
  const hid_t version =
      H5Acreate2(root, "Version", H5T_NATIVE_INT, versionSpace, H5P_DEFAULT, H5P_DEFAULT);
  const int v[2] = {1, 0};
  H5Awrite(version, H5T_NATIVE_INT, v);
  H5Aclose(version);
  H5Sclose(versionSpace);
  const hid_t text = H5Tcopy(H5T_C_S1);
  H5Tset_size(text, 16);
  H5Tset_strpad(text, H5T_STR_NULLPAD);
  const hid_t scalar = H5Screate(H5S_SCALAR);
  const hid_t type = H5Acreate2(root, "Type", text, scalar, H5P_DEFAULT, H5P_DEFAULT);
  const char typeName[17] = "UnstructuredGrid";  // 16 characters, NULLPAD: no terminator
  H5Awrite(type, text, typeName);
  H5Aclose(type);
  H5Sclose(scalar);
  H5Tclose(text);
  auto dataset = [&](hid_t at, const char* name, hid_t memType, std::vector<hsize_t> dims,
                     const void* data) {
    const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
    const hid_t d = H5Dcreate2(at, name, memType, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
    H5Dclose(d);
    H5Sclose(space);
  };
  const long long points = mesh->GetNumberOfPoints(), cells = mesh->GetNumberOfCells();
  std::vector<double> xyz;
  for (vtkIdType p = 0; p < points; ++p) {
    double x[3];
    mesh->GetPoint(p, x);
    xyz.insert(xyz.end(), x, x + 3);
  }
  std::vector<long long> offsets{0}, connectivity;
  std::vector<unsigned char> types;
  for (vtkIdType c = 0; c < cells; ++c) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    mesh->GetCellPoints(c, n, ids);
    connectivity.insert(connectivity.end(), ids, ids + n);
    offsets.push_back((long long)connectivity.size());
    types.push_back((unsigned char)mesh->GetCellType(c));
  }
  const long long counts[3] = {points + extraPoints, cells, (long long)connectivity.size()};
  dataset(root, "NumberOfPoints", H5T_NATIVE_LLONG, {1}, &counts[0]);
  dataset(root, "NumberOfCells", H5T_NATIVE_LLONG, {1}, &counts[1]);
  dataset(root, "NumberOfConnectivityIds", H5T_NATIVE_LLONG, {1}, &counts[2]);
  dataset(root, "Points", H5T_NATIVE_DOUBLE, {hsize_t(points), 3}, xyz.data());
  dataset(root, "Types", H5T_NATIVE_UCHAR, {hsize_t(cells)}, types.data());
  dataset(root, "Offsets", H5T_NATIVE_LLONG, {hsize_t(cells + 1)}, offsets.data());
  dataset(root, "Connectivity", H5T_NATIVE_LLONG, {connectivity.size()}, connectivity.data());
  const hid_t pointData = H5Gcreate2(root, "PointData", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<float> velocity;
  vtkDataArray* a = mesh->GetPointData()->GetArray("velocity");
  for (vtkIdType p = 0; p < points; ++p)
    for (int c = 0; c < 3; ++c)
      velocity.push_back(float(a->GetComponent(p, c)));
  dataset(pointData, "velocity", H5T_NATIVE_FLOAT, {hsize_t(points), 3}, velocity.data());
  H5Gclose(pointData);
  H5Gclose(root);
  H5Fclose(file);
}

TEST(SimulationFormats, VtkHdfUnstructuredGrids) {
  const auto dir = test::scratch();
  const auto mesh = tetraBox(0.0);
  const auto path = dir / "flow.vtkhdf";
  writeVtkHdf(path, mesh);
  LoadOptions options;
  options.resolution = {5, 5, 5};
  LoadReport report;
  expectFlow(loadField(path, options, &report), 0.0, kExact);
  EXPECT_EQ(report.format, "VTKHDF file (.vtkhdf)");
  EXPECT_EQ(report.cells, std::uint64_t(mesh->GetNumberOfCells()));
  // Counts that the datasets do not hold are refused before VTK reads them.
  writeVtkHdf(path, mesh, 5);
  test::expectError([&] { loadField(path, options); },
                    {path.string(), "dataset Points is not shaped as the counts give"});
}

// CGNS as a CFD code writes it, through the CGNS library (HDF5): a
// structured zone and an unstructured zone of tetrahedra beside it, their
// VelocityX/Y/Z at the vertices.
void writeCgns(const std::filesystem::path& path, vtkUnstructuredGrid* tetrahedra, int layout) {
  ASSERT_EQ(cg_set_file_type(layout), CG_OK);
  int fn = -1, base = -1;
  ASSERT_EQ(cg_open(path.c_str(), CG_MODE_WRITE, &fn), CG_OK) << cg_get_error();
  ASSERT_EQ(cg_base_write(fn, "Base", 3, 3, &base), CG_OK);
  auto velocity = [&](int zone, const std::vector<double>& x, const std::vector<double>& y,
                      const std::vector<double>& z) {
    int solution = -1, field = -1;
    ASSERT_EQ(cg_sol_write(fn, base, zone, "Flow", CGNS_ENUMV(Vertex), &solution), CG_OK);
    const char* names[3] = {"VelocityX", "VelocityY", "VelocityZ"};
    for (int c = 0; c < 3; ++c) {
      std::vector<double> v;
      for (std::size_t i = 0; i < x.size(); ++i)
        v.push_back(flowAt({x[i], y[i], z[i]}, 0.0)[c]);
      ASSERT_EQ(cg_field_write(fn, base, zone, solution, CGNS_ENUMV(RealDouble), names[c], v.data(),
                               &field),
                CG_OK);
    }
  };
  auto coordinates = [&](int zone, const std::vector<double>& x, const std::vector<double>& y,
                         const std::vector<double>& z) {
    int c = -1;
    ASSERT_EQ(cg_coord_write(fn, base, zone, CGNS_ENUMV(RealDouble), "CoordinateX", x.data(), &c),
              CG_OK);
    ASSERT_EQ(cg_coord_write(fn, base, zone, CGNS_ENUMV(RealDouble), "CoordinateY", y.data(), &c),
              CG_OK);
    ASSERT_EQ(cg_coord_write(fn, base, zone, CGNS_ENUMV(RealDouble), "CoordinateZ", z.data(), &c),
              CG_OK);
  };
  // A structured box over x in [1, 2], y and z in [0, 1], i fastest.
  {
    int zone = -1;
    cgsize_t size[9] = {5, 5, 5, 4, 4, 4, 0, 0, 0};
    ASSERT_EQ(cg_zone_write(fn, base, "Block", size, CGNS_ENUMV(Structured), &zone), CG_OK);
    std::vector<double> x, y, z;
    for (int k = 0; k < 5; ++k)
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) {
          x.push_back(1.0 + 0.25 * i);
          y.push_back(0.25 * j);
          z.push_back(0.25 * k);
        }
    coordinates(zone, x, y, z);
    velocity(zone, x, y, z);
  }
  // The tetrahedra over [0, 1]^3.
  {
    int zone = -1, section = -1;
    cgsize_t size[3] = {cgsize_t(tetrahedra->GetNumberOfPoints()),
                        cgsize_t(tetrahedra->GetNumberOfCells()), 0};
    ASSERT_EQ(cg_zone_write(fn, base, "Tetrahedra", size, CGNS_ENUMV(Unstructured), &zone), CG_OK);
    std::vector<double> x, y, z;
    for (vtkIdType p = 0; p < tetrahedra->GetNumberOfPoints(); ++p) {
      double q[3];
      tetrahedra->GetPoint(p, q);
      x.push_back(q[0]);
      y.push_back(q[1]);
      z.push_back(q[2]);
    }
    coordinates(zone, x, y, z);
    std::vector<cgsize_t> connectivity;
    for (vtkIdType c = 0; c < tetrahedra->GetNumberOfCells(); ++c) {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      tetrahedra->GetCellPoints(c, n, ids);
      for (vtkIdType i = 0; i < n; ++i)
        connectivity.push_back(cgsize_t(ids[i] + 1));
    }
    ASSERT_EQ(cg_section_write(fn, base, zone, "Cells", CGNS_ENUMV(TETRA_4), 1,
                               cgsize_t(tetrahedra->GetNumberOfCells()), 0, connectivity.data(),
                               &section),
              CG_OK);
    velocity(zone, x, y, z);
  }
  ASSERT_EQ(cg_close(fn), CG_OK);
}

TEST(SimulationFormats, CgnsStructuredAndUnstructuredZones) {
  const auto dir = test::scratch();
  for (const int layout : {CG_FILE_HDF5, CG_FILE_ADF}) {
    SCOPED_TRACE(layout == CG_FILE_HDF5 ? "HDF5" : "ADF");
    const auto path = dir / (layout == CG_FILE_HDF5 ? "flow.cgns" : "adf.cgns");
    writeCgns(path, tetraBox(0.0), layout);
    LoadOptions options;
    options.resolution = {9, 5, 5};
    LoadReport report;
    const VectorField f = loadField(path, options, &report);
    EXPECT_EQ(report.format, "CGNS file (.cgns)");
    EXPECT_EQ(report.blocks.size(), 2u);
    EXPECT_EQ(f.bounds().max, glm::vec3(2.0f, 1.0f, 1.0f));
    expectFlow(f, 0.0, kExact);
  }
}

}  // namespace
}  // namespace sandstorm
