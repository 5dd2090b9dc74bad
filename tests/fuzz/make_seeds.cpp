// make_seeds: writes the fuzzers' seed corpora into DIR/<target>/, from the
// project's own writers (the .vti and .vdb writers, the DTrack writer, the
// session log and packet codecs, the height-map writer), VTK's writers for
// the VTK formats Sandstorm only reads, the bundled configurations and
// sample data, and small hand-made engine files. Run by scripts/fuzz.
#include <nanovdb/util/GridBuilder.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkEnSightWriter.h>
#include <vtkExodusIIWriter.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkRectilinearGrid.h>
#include <vtkStructuredGrid.h>
#include <vtkStructuredPointsWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLStructuredGridWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <netcdf.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/field/analytic_field_factory.h"
#include "core/field/height_map_io.h"
#include "core/io/field_writer.h"
#include "core/sim/frame_packet_codec.h"
#include "core/sim/session_log.h"
#include "core/tracking/dtrack_writer.h"
#include "core/tracking/tracker_script.h"
#include "tests/io/openfoam_case.h"

namespace fs = std::filesystem;
using namespace sandstorm;

namespace {

void text(const fs::path& path, const std::string& content) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << content;
}

// OpenVDB writes a random UUID into every file's header (36 characters at
// byte 21); a fixed one keeps the seed corpus, and so a --ci fuzz run, the
// same on every machine.
void fixVdbUuid(const fs::path& path) {
  std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
  f.seekp(21);
  f.write("00000000-0000-4000-8000-000000000000", 36);
}

vtkNew<vtkFloatArray> velocity(int n) {
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(n);
  for (int i = 0; i < 3 * n; ++i)
    v->SetValue(i, 0.5f * float(i % 7) - 1.0f);
  return v;
}

template <class Writer, class Data>
void xml(Data* data, const fs::path& path, int mode, bool zlib) {
  vtkNew<Writer> w;
  w->SetInputData(data);
  w->SetFileName(path.c_str());
  w->SetDataMode(mode);
  if (zlib)
    w->SetCompressorTypeToZLib();
  else
    w->SetCompressorTypeToNone();
  w->Write();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: make_seeds OUT_DIR SOURCE_DIR\n");
    return 2;
  }
  const fs::path out = argv[1], source = argv[2];
  for (const char* t :
       {"fuzz_field_vtk",   "fuzz_field_vti",      "fuzz_field_vtr",   "fuzz_field_vts",
        "fuzz_field_vtu",   "fuzz_field_vtp",      "fuzz_field_index", "fuzz_field_e",
        "fuzz_field_nc",    "fuzz_openfoam",       "fuzz_ensight",     "fuzz_field_vdb",
        "fuzz_field_fga",   "fuzz_field_vf",       "fuzz_height_map",  "fuzz_config",
        "fuzz_session_log", "fuzz_cluster_packet", "fuzz_dtrack",      "fuzz_pvx",
        "fuzz_tracker_path"})
    fs::create_directories(out / t);

  // Image data in every encoding VTK writes, and the legacy format.
  vtkNew<vtkImageData> image;
  image->SetDimensions(3, 2, 2);
  image->GetPointData()->SetVectors(velocity(12));
  for (int mode = 0; mode < 3; ++mode)
    for (bool zlib : {false, true})
      xml<vtkXMLImageDataWriter>(
          image.Get(),
          out / "fuzz_field_vti" / ("mode" + std::to_string(mode) + (zlib ? "z" : "") + ".vti"),
          mode, zlib);
  for (bool binary : {false, true}) {
    vtkNew<vtkStructuredPointsWriter> w;
    w->SetInputData(image);
    w->SetFileName((out / "fuzz_field_vtk" / (binary ? "binary.vtk" : "ascii.vtk")).c_str());
    if (binary) w->SetFileTypeToBinary();
    w->Write();
  }
  vtkNew<vtkRectilinearGrid> rect;
  rect->SetDimensions(3, 2, 2);
  for (int a = 0; a < 3; ++a) {
    vtkNew<vtkFloatArray> c;
    const int n = a == 0 ? 3 : 2;
    c->SetNumberOfTuples(n);
    for (int i = 0; i < n; ++i)
      c->SetValue(i, float(i * i));
    (a == 0   ? rect->SetXCoordinates(c)
     : a == 1 ? rect->SetYCoordinates(c)
              : rect->SetZCoordinates(c));
  }
  rect->GetPointData()->SetVectors(velocity(12));
  xml<vtkXMLRectilinearGridWriter>(rect.Get(), out / "fuzz_field_vtr" / "ascii.vtr", 0, false);
  xml<vtkXMLRectilinearGridWriter>(rect.Get(), out / "fuzz_field_vtr" / "appended.vtr", 2, true);
  vtkNew<vtkStructuredGrid> grid;
  grid->SetDimensions(2, 2, 2);
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 8; ++i)
    points->InsertNextPoint(i & 1, ((i >> 1) & 1) + 0.2 * (i & 1), (i >> 2) & 1);
  grid->SetPoints(points);
  grid->GetPointData()->SetVectors(velocity(8));
  xml<vtkXMLStructuredGridWriter>(grid.Get(), out / "fuzz_field_vts" / "ascii.vts", 0, false);
  xml<vtkXMLStructuredGridWriter>(grid.Get(), out / "fuzz_field_vts" / "binary.vts", 1, false);

  // Meshes: two tetrahedra and a hexahedron carrying vectors and a cell
  // scalar, as unstructured grids (XML in each mode, legacy 4.2 and 5.1 in
  // ASCII and binary) and polydata.
  vtkNew<vtkUnstructuredGrid> mesh;
  {
    vtkNew<vtkPoints> p;
    for (int i = 0; i < 12; ++i)
      p->InsertNextPoint(i & 1, (i >> 1) & 1, i >> 2);
    mesh->SetPoints(p);
    const vtkIdType t1[4] = {0, 1, 2, 4}, t2[4] = {1, 3, 2, 7}, h[8] = {4, 5, 7, 6, 8, 9, 11, 10};
    mesh->InsertNextCell(VTK_TETRA, 4, t1);
    mesh->InsertNextCell(VTK_TETRA, 4, t2);
    mesh->InsertNextCell(VTK_HEXAHEDRON, 8, h);
    mesh->GetPointData()->SetVectors(velocity(12));
    vtkNew<vtkFloatArray> pressure;
    pressure->SetName("pressure");
    pressure->SetNumberOfTuples(3);
    pressure->Fill(2.0f);
    mesh->GetCellData()->AddArray(pressure);
  }
  for (int mode = 0; mode < 3; ++mode)
    xml<vtkXMLUnstructuredGridWriter>(
        mesh.Get(), out / "fuzz_field_vtu" / ("mode" + std::to_string(mode) + ".vtu"), mode,
        mode == 2);
  for (int version : {42, 51})
    for (bool binary : {false, true}) {
      vtkNew<vtkUnstructuredGridWriter> w;
      w->SetInputData(mesh);
      w->SetFileVersion(version);
      w->SetFileName((out / "fuzz_field_vtk" /
                      ("mesh" + std::to_string(version) + (binary ? "b" : "a") + ".vtk"))
                         .c_str());
      if (binary) w->SetFileTypeToBinary();
      w->Write();
    }
  vtkNew<vtkPolyData> sheet;
  {
    vtkNew<vtkPoints> p;
    for (int i = 0; i < 6; ++i)
      p->InsertNextPoint(i % 3, i / 3, 0.5);
    vtkNew<vtkCellArray> polys, lines, verts;
    const vtkIdType tri[3] = {0, 1, 4}, quad[4] = {1, 2, 5, 4}, line[2] = {0, 3}, vert[1] = {3};
    polys->InsertNextCell(3, tri);
    polys->InsertNextCell(4, quad);
    lines->InsertNextCell(2, line);
    verts->InsertNextCell(1, vert);
    sheet->SetPoints(p);
    sheet->SetPolys(polys);
    sheet->SetLines(lines);
    sheet->SetVerts(verts);
    sheet->GetPointData()->SetVectors(velocity(6));
  }
  xml<vtkXMLPolyDataWriter>(sheet.Get(), out / "fuzz_field_vtp" / "ascii.vtp", 0, false);
  xml<vtkXMLPolyDataWriter>(sheet.Get(), out / "fuzz_field_vtp" / "appended.vtp", 2, true);
  {
    vtkNew<vtkPolyDataWriter> w;
    w->SetInputData(sheet);
    w->SetFileName((out / "fuzz_field_vtk" / "sheet.vtk").c_str());
    w->Write();
  }
  {
    vtkNew<vtkExodusIIWriter> w;  // 64-bit-offset NetCDF, as Exodus writes it
    w->SetInputData(mesh);
    w->SetFileName((out / "fuzz_field_e" / "mesh.e").c_str());
    w->Write();
  }
  // OpenFOAM cases of two cells, ascii and binary, as fuzz_openfoam.cpp takes them.
  for (const bool binary : {false, true}) {
    test::FoamCase c;
    c.n = 2;
    c.binary = binary;
    c.times = {0.0, 1.0};
    c.flow = [](const glm::dvec3& p, double t) { return p * (1.0 + t); };
    const fs::path folder = out / "openfoam-case";
    fs::remove_all(folder);
    test::writeFoamCase(c, folder);
    std::string joined;
    for (const char* name :
         {"system/controlDict", "constant/polyMesh/points", "constant/polyMesh/faces",
          "constant/polyMesh/owner", "constant/polyMesh/neighbour", "constant/polyMesh/boundary",
          "0/U", "1/U"}) {
      std::ifstream in(folder / name, std::ios::binary);
      joined += std::string("//@ ") + name + "\n" +
                std::string(std::istreambuf_iterator<char>(in), {}) + "\n";
    }
    text(out / "fuzz_openfoam" / (binary ? "binary" : "ascii"), joined);
    fs::remove_all(folder);
  }
  // An EnSight Gold case (VTK's writer: C binary) and one in ascii, as
  // fuzz_ensight.cpp takes them.
  {
    const fs::path folder = out / "ensight-case";
    fs::remove_all(folder);
    fs::create_directories(folder);
    vtkNew<vtkIntArray> block;
    block->SetName("BlockId");
    block->SetNumberOfTuples(mesh->GetNumberOfCells());
    block->Fill(1);
    mesh->GetCellData()->AddArray(block);
    vtkNew<vtkEnSightWriter> w;
    w->SetInputData(mesh);
    w->SetPath(folder.c_str());
    w->SetBaseName("flow");
    w->SetNumberOfBlocks(1);
    w->Write();
    mesh->GetCellData()->RemoveArray("BlockId");
    auto file = [&](const char* name) {
      std::ifstream in(folder / name, std::ios::binary);
      return std::string(std::istreambuf_iterator<char>(in), {});
    };
    text(out / "fuzz_ensight" / "binary",
         "//@ flow.case\nFORMAT\ntype: ensight gold\nGEOMETRY\nmodel: flow.geo\nVARIABLE\n"
         "vector per node: velocity flow.vel\n\n//@ flow.geo\n" +
             file("flow.0.00000.geo") + "\n//@ flow.vel\n" + file("flow.0.00000_n.velocity") +
             "\n");
    text(out / "fuzz_ensight" / "ascii",
         "//@ flow.case\nFORMAT\ntype: ensight gold\nGEOMETRY\nmodel: 1 flow.*****.geo\n"
         "VARIABLE\nvector per node: 1 velocity flow.*****.vel\nTIME\ntime set: 1\n"
         "number of steps: 1\nfilename start number: 1\nfilename increment: 1\ntime values: 0\n"
         "//@ flow.00001.geo\nmesh\nascii\nnode id off\nelement id off\npart\n1\nbox\n"
         "coordinates\n4\n0\n1\n0\n0\n0\n0\n1\n0\n0\n0\n0\n1\ntetra4\n1\n1 2 3 4\n"
         "//@ flow.00001.vel\nvelocity\npart\n1\ncoordinates\n1\n2\n3\n4\n1\n2\n3\n4\n1\n"
         "2\n3\n4\n");
    fs::remove_all(folder);
  }
  // A NetCDF CF field: u, v, w on longitude, latitude and height, two times,
  // in the classic and 64-bit-offset formats.
  for (const int mode : {0, NC_64BIT_OFFSET}) {
    int id = -1, dims[4], vars[7];
    const fs::path nc = out / "fuzz_field_nc" / (mode ? "offset64.nc" : "classic.nc");
    nc_create(nc.c_str(), NC_CLOBBER | mode, &id);
    const char* names[4] = {"time", "lev", "lat", "lon"};
    const std::size_t sizes[4] = {NC_UNLIMITED, 2, 2, 3};
    for (int d = 0; d < 4; ++d)
      nc_def_dim(id, names[d], sizes[d], &dims[d]);
    const char* units[4] = {"seconds", "m", "degrees_north", "degrees_east"};
    for (int d = 0; d < 4; ++d) {
      nc_def_var(id, names[d], NC_DOUBLE, 1, &dims[d], &vars[d]);
      nc_put_att_text(id, vars[d], "units", std::strlen(units[d]), units[d]);
    }
    const char* flow[3] = {"u", "v", "w"};
    for (int c = 0; c < 3; ++c)
      nc_def_var(id, flow[c], NC_FLOAT, 4, dims, &vars[4 + c]);
    nc_enddef(id);
    const double lev[2] = {0, 10}, lat[2] = {44, 45}, lon[3] = {10, 11, 12};
    nc_put_var_double(id, vars[1], lev);
    nc_put_var_double(id, vars[2], lat);
    nc_put_var_double(id, vars[3], lon);
    for (std::size_t step = 0; step < 2; ++step) {
      const double t = double(step);
      const std::size_t one = 1, start[4] = {step, 0, 0, 0}, count[4] = {1, 2, 2, 3};
      nc_put_vara_double(id, vars[0], &step, &one, &t);
      const std::vector<float> values(12, 1.5f + float(step));
      for (int c = 0; c < 3; ++c)
        nc_put_vara_float(id, vars[4 + c], start, count, values.data());
    }
    nc_close(id);
  }
  // Index files with the one piece or block they name, "p0" (fuzz_field_index.cpp).
  const auto index = [&](const std::string& name, const std::string& head, const fs::path& piece) {
    std::ifstream in(piece, std::ios::binary);
    text(out / "fuzz_field_index" / name,
         head + "\n#---\n" + std::string(std::istreambuf_iterator<char>(in), {}));
  };
  index("pvtu",
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\">\n"
        "<PUnstructuredGrid GhostLevel=\"0\">\n<PPointData Vectors=\"velocity\">\n"
        "<PDataArray type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\"/>\n"
        "</PPointData>\n<PPoints><PDataArray type=\"Float32\" NumberOfComponents=\"3\"/>"
        "</PPoints>\n<Piece Source=\"p0\"/>\n</PUnstructuredGrid>\n</VTKFile>",
        out / "fuzz_field_vtu" / "mode0.vtu");
  index("pvti",
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"PImageData\" version=\"0.1\">\n"
        "<PImageData WholeExtent=\"0 2 0 1 0 1\" GhostLevel=\"0\" Origin=\"0 0 0\" "
        "Spacing=\"1 1 1\">\n<PPointData><PDataArray type=\"Float32\" Name=\"velocity\" "
        "NumberOfComponents=\"3\"/></PPointData>\n<Piece Extent=\"0 2 0 1 0 1\" "
        "Source=\"p0\"/>\n</PImageData>\n</VTKFile>",
        out / "fuzz_field_vti" / "mode0.vti");
  index("vtm",
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\">\n"
        "<vtkMultiBlockDataSet>\n<DataSet index=\"0\" name=\"fluid\" file=\"p0\"/>\n"
        "<Block index=\"1\"><DataSet index=\"0\" file=\"p0\"/></Block>\n"
        "</vtkMultiBlockDataSet>\n</VTKFile>",
        out / "fuzz_field_vtu" / "mode2.vtu");
  index("pvd",
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\">\n<Collection>\n"
        "<DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"p0\"/>\n"
        "<DataSet timestep=\"0.5\" group=\"\" part=\"1\" file=\"p0\"/>\n"
        "<DataSet timestep=\"0.5\" group=\"\" part=\"0\" file=\"p1\"/>\n"
        "</Collection>\n</VTKFile>",
        out / "fuzz_field_vtu" / "mode0.vtu");

  // The project's own writers.
  const auto tornado = makeAnalyticField("tornado", {});
  const VectorField small = bake(*tornado, Box{{-1, -1, 0}, {1, 1, 1}}, {4, 3, 2});
  saveField(out / "fuzz_field_vti" / "sandstorm.vti", small);
  saveField(out / "fuzz_field_vdb" / "sandstorm.vdb", small);
  fixVdbUuid(out / "fuzz_field_vdb" / "sandstorm.vdb");
  fs::copy_file(source / "data" / "downwash.vdb", out / "fuzz_field_vdb" / "downwash.vdb",
                fs::copy_options::overwrite_existing);
  writeHeightMapPgm(HeightMap({-1, -1}, {1, 1}, {3, 2}, {0, 0.5f, 1, 0.25f, 0.75f, 0.1f}),
                    out / "fuzz_height_map" / "small.pgm", 0.0f, 1.0f);
  text(out / "fuzz_field_fga" / "small.fga",
       "2,1,1,\n-100,-50,0,\n100,50,100,\n1,2,3,\n-4,5.5,6e-1,\n");
  std::string vf = "VF_V";
  for (std::uint16_t d : {2, 1, 1})
    vf.append(reinterpret_cast<const char*>(&d), 2);
  for (float f : {1.0f, 2.0f, 3.0f, -1.0f, 0.5f, 0.25f})
    vf.append(reinterpret_cast<const char*>(&f), 4);
  text(out / "fuzz_field_vf" / "small.vf", vf);

  // Configurations, the bundled ones and one with an include.
  for (const auto& e : fs::directory_iterator(source / "config"))
    if (e.path().extension() == ".toml")
      fs::copy_file(e.path(), out / "fuzz_config" / e.path().filename(),
                    fs::copy_options::overwrite_existing);
  text(out / "fuzz_config" / "include.toml",
       "include = \"part.toml\"\n[[wall]]\nname = \"w\"\nlower_left = [0, 0, 0]\n"
       "lower_right = [1, 0, 0]\nupper_left = [0, 0, 1]\n#---\n[sim]\nmaximum = 500\n");
  fs::copy_file(source / "config" / "cave4.pvx", out / "fuzz_pvx" / "cave4.pvx",
                fs::copy_options::overwrite_existing);

  // A session log with every kind of line, a packet of every member, datagrams.
  TrackingSample s;
  s.active = s.headTracked = true;
  s.trackerFrame = 42;
  s.head.position = {0.1f, 0.2f, 1.7f};
  s.wand.present = s.wand.tracked = true;
  s.wand.buttons = 3;
  Emitter e;
  text(out / "fuzz_session_log" / "session.log",
       "# log\n0 set render.size 0.2\n1 add-emitter " +
           formatChange(StateChange::addEmitter(e)).substr(12) +
           "\n2 remove-emitter 0\n3 reset\n4 " + formatTracking(s) + "\n5 " +
           formatNavigation(Navigation{}) + "\n");
  FramePacket p;
  p.frame = 7;
  p.changes = {StateChange::set("sim.maximum", 100), StateChange::addEmitter(e)};
  p.emission = {3, 4};
  p.tracking = s;
  p.fieldUpdate = std::make_shared<const FieldUpdate>();
  const std::vector<std::byte> packet = encodePacket(p, {1, 2});
  text(out / "fuzz_cluster_packet" / "packet.bin",
       std::string(reinterpret_cast<const char*>(packet.data()), packet.size()));
  const std::vector<std::byte> field = encodeField(small);
  text(out / "fuzz_cluster_packet" / "field.bin",
       std::string(reinterpret_cast<const char*>(field.data()), field.size()));
  // A sparse grid's words, as they travel to ranks (NanoVDB's own builder).
  nanovdb::GridBuilder<nanovdb::Vec3f> builder(nanovdb::Vec3f(0.0f));
  auto voxels = builder.getAccessor();
  for (int i = 0; i < 10; ++i)
    voxels.setValue(nanovdb::Coord(i, 2 * i, 700 - i), nanovdb::Vec3f(float(i), 1.0f, -2.0f));
  const auto sparse = builder.getHandle<>(0.5, nanovdb::Vec3d(1.0, 2.0, 3.0), "v");
  text(out / "fuzz_cluster_packet" / "sparse.bin",
       std::string(reinterpret_cast<const char*>(sparse.data()), sparse.size()));
  const TrackerScript walk = TrackerScript::builtIn();
  text(out / "fuzz_dtrack" / "frame.txt", writeDTrack(walk.at(2.0, 17)));
  text(out / "fuzz_dtrack" / "old.txt", writeDTrack(walk.at(3.0, 18), FlystickFormat::V1));
  text(out / "fuzz_tracker_path" / "path.toml",
       "loop = true\nhead_body = 1\n[[key]]\ntime = 0.0\nhead = [0, 0, 1.7]\nbuttons = 1\n"
       "[[key]]\ntime = 1.0\nwand = [0.2, 0.3, 1.1]\nwand_pitch_deg = 20.0\n"
       "joystick = [0.5, -0.5]\nwand_visible = false\n");
  std::printf("make_seeds: wrote the seed corpora to %s\n", out.c_str());
  return 0;
}
