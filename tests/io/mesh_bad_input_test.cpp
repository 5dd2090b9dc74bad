// Malformed meshes and index files: each refused with the file, the place
// and what was expected, before VTK walks what the file claims.
#include <gtest/gtest.h>

#include <vtkXMLUnstructuredGridWriter.h>

#include "core/io/field_loader.h"
#include "tests/io/io_test_util.h"
#include "tests/io/mesh_test_util.h"

namespace sandstorm {
namespace {

using test::expectError;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the file";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// One tetrahedron, one hexahedron: the legacy text around them.
std::string legacyMesh(const std::string& cells, const std::string& types,
                       const std::string& version = "4.2") {
  std::string points = "POINTS 12 float\n";
  for (int i = 0; i < 12; ++i)
    points += concat(i & 1, " ", (i >> 1) & 1, " ", i >> 2, "\n");
  std::string vectors = "POINT_DATA 12\nVECTORS velocity float\n";
  for (int i = 0; i < 12; ++i)
    vectors += "1 2 3\n";
  return "# vtk DataFile Version " + version + "\nmesh\nASCII\nDATASET UNSTRUCTURED_GRID\n" +
         points + cells + types + vectors;
}

TEST(MeshBadInput, LegacyCellsThatDoNotAddUp) {
  const auto dir = test::scratch();
  const auto path = dir / "mesh.vtk";
  const std::string types = "CELL_TYPES 2\n10\n12\n";
  test::writeText(path, legacyMesh("CELLS 2 14\n4 0 1 2 4\n8 4 5 7 6 8 9 11 10\n", types));
  EXPECT_NO_THROW(loadField(path));

  test::writeText(path, legacyMesh("CELLS 2 14\n4 0 1 2 4\n8 4 5 7 6 8 9 11 12\n", types));
  expectError([&] { loadField(path); }, {path.string(), "CELLS names point 12", "0..11"});
  test::writeText(path, legacyMesh("CELLS 2 15\n4 0 1 2 4\n8 4 5 7 6 8 9 11 10 3\n", types));
  expectError([&] { loadField(path); }, {path.string(), "CELLS", "take 14 of the 15 values"});
  test::writeText(path, legacyMesh("CELLS 2 14\n4 0 1 2 4\n9 4 5 7 6 8 9 11 10\n", types));
  expectError([&] { loadField(path); }, {path.string(), "cell 1 has 9 points"});
  test::writeText(path, legacyMesh("CELLS 2 14\n4 0 1 2 4\n8 4 5 7 6 8 9 11 10\n",
                                   "CELL_TYPES 3\n10\n12\n12\n"));
  expectError([&] { loadField(path); }, {path.string(), "CELL_TYPES 3 but CELLS lists 2 cells"});
  // Types the reader checks once the cells are built: a hexahedron of four
  // points, a type Sandstorm does not sample in.
  test::writeText(path, legacyMesh("CELLS 2 10\n4 0 1 2 4\n4 4 5 7 6\n", types));
  expectError([&] { loadField(path); },
              {path.string(), "cell 1 (vtkHexahedron) has 4 points; expected 8"});
  test::writeText(
      path, legacyMesh("CELLS 2 14\n4 0 1 2 4\n8 4 5 7 6 8 9 11 10\n", "CELL_TYPES 2\n10\n77\n"));
  expectError([&] { loadField(path); }, {path.string(), "cell 1 is of VTK type 77"});
  // 5.1: offsets that run backwards, or past the connectivity.
  const std::string conn = "CONNECTIVITY vtktypeint64\n0 1 2 4 4 5 7 6 8 9 11 10\n";
  test::writeText(path,
                  legacyMesh("CELLS 3 12\nOFFSETS vtktypeint64\n0 4 12\n" + conn, types, "5.1"));
  EXPECT_NO_THROW(loadField(path));
  test::writeText(path,
                  legacyMesh("CELLS 3 12\nOFFSETS vtktypeint64\n0 5 4\n" + conn, types, "5.1"));
  expectError([&] { loadField(path); }, {path.string(), "offset 2 (4) is below the one before"});
  test::writeText(path,
                  legacyMesh("CELLS 3 12\nOFFSETS vtktypeint64\n0 4 13\n" + conn, types, "5.1"));
  expectError([&] { loadField(path); },
              {path.string(), "the last offset is 13 but CONNECTIVITY holds 12"});
  // Ids, offsets and counts that are no whole numbers, or beyond what an
  // integer holds (once undefined behaviour in the conversion: a fuzz find).
  test::writeText(path, legacyMesh("CELLS 3 12\nOFFSETS vtktypeint64\n0 4 12\n"
                                   "CONNECTIVITY vtktypeint64\n0 1 2 4 4 5 7 6 8 9 11 4.4e32\n",
                                   types, "5.1"));
  expectError([&] { loadField(path); }, {path.string(), "CONNECTIVITY", "is not a point index"});
  test::writeText(path,
                  legacyMesh("CELLS 3 12\nOFFSETS vtktypeint64\n0 4.5 12\n" + conn, types, "5.1"));
  expectError([&] { loadField(path); }, {path.string(), "offset 1", "4.5 is not a point index"});
  test::writeText(path, legacyMesh("CELLS 2 14\n4 0 1 2 4\n8 4 5 7 6 8 9 11 -1e300\n", types));
  expectError([&] { loadField(path); }, {path.string(), "CELLS", "is not a point index"});
  test::writeText(path, legacyMesh("CELLS 2 14\n4 0 1 2 4\n7.5 4 5 7 6 8 9 11 10\n", types));
  expectError([&] { loadField(path); }, {path.string(), "cell 1's point count", "7.5"});
  test::writeText(path,
                  "# vtk DataFile Version 4.2\nm\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
                  "0 0 0 1 0 0 0 1 0\nPOLYGONS 1 3\n2 0 1\n");
  expectError([&] { loadField(path); }, {path.string(), "polygon cell 0 has 2 points"});
}

// A .vtu as VTK writes it (ascii), then edited.
std::string asciiVtu(const std::filesystem::path& dir) {
  const auto path = dir / "source.vtu";
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(test::lMesh(1, test::asymmetric));
  w->SetFileName(path.c_str());
  w->SetDataModeToAscii();
  w->Write();
  return test::readAll(path);
}

TEST(MeshBadInput, XmlCellsAndCountsThatDoNotHold) {
  const auto dir = test::scratch();
  const std::string good = asciiVtu(dir);
  const auto path = dir / "mesh.vtu";
  test::writeText(path, good);
  EXPECT_NO_THROW(loadField(path));
  // The mesh: 18 points, 18 tetrahedra (3 hexahedra of 6).
  ASSERT_NE(good.find("NumberOfPoints=\"18\" NumberOfCells=\"18\""), std::string::npos);

  test::writeText(path, replaced(good, "NumberOfPoints=\"18\"", "NumberOfPoints=\"19\""));
  expectError([&] { loadField(path); }, {path.string(), "19 tuples"});
  test::writeText(path, replaced(good, "NumberOfCells=\"18\"", "NumberOfCells=\"900000000000\""));
  expectError([&] { loadField(path); },
              {path.string(), "NumberOfCells 900000000000", "memory budget"});
  test::writeText(path, replaced(good, "NumberOfCells=\"18\"", "NumberOfCells=\"17\""));
  expectError([&] { loadField(path); }, {path.string(), "offsets", "17 tuples"});
  // Connectivity naming a point past the last, or offsets past the connectivity.
  const std::size_t cells = good.find("Name=\"connectivity\"");
  const std::size_t first = good.find('>', cells) + 1;
  std::string wrong = good;
  const std::size_t digit = wrong.find_first_of("0123456789", first);
  wrong.replace(digit, 1, "99");
  test::writeText(path, wrong);
  expectError([&] { loadField(path); }, {path.string(), "names point 99", "0..17"});
  const std::size_t offsets = good.find("Name=\"offsets\"");
  const std::size_t last = good.find("</DataArray>", offsets);
  wrong = good;
  const std::size_t end = wrong.find_last_of("0123456789", last);
  wrong.insert(end + 1, "0");  // 72 -> 720
  test::writeText(path, wrong);
  expectError([&] { loadField(path); }, {path.string()});
  test::writeText(path, replaced(good, "<Points>", "<Pointless>"));
  expectError([&] { loadField(path); }, {path.string()});
}

std::string pvtu(const std::string& pieces, const std::string& pointType = "Float64") {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\">\n"
         "<PUnstructuredGrid GhostLevel=\"0\">\n<PPointData Vectors=\"velocity\">"
         "<PDataArray type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\"/></PPointData>\n"
         "<PPoints><PDataArray type=\"" +
         pointType + "\" NumberOfComponents=\"3\"/></PPoints>\n" + pieces +
         "</PUnstructuredGrid>\n</VTKFile>\n";
}

std::string vtm(const std::string& blocks) {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\">\n"
         "<vtkMultiBlockDataSet>\n" +
         blocks + "</vtkMultiBlockDataSet>\n</VTKFile>\n";
}

TEST(MeshBadInput, IndexFilesNamingWhatTheyShouldNot) {
  const auto dir = test::scratch();
  std::filesystem::create_directories(dir / "case" / "pieces");
  test::writeText(dir / "case" / "pieces" / "a.vtu", asciiVtu(dir));
  test::writeText(dir / "outside.vtu", asciiVtu(dir));
  const auto index = dir / "case" / "run.pvtu";

  test::writeText(index, pvtu("<Piece Source=\"pieces/a.vtu\"/>\n"));
  EXPECT_NO_THROW(loadField(index));
  // Declared otherwise than the piece holds them (VTK's reader crashes on it).
  test::writeText(index, pvtu("<Piece Source=\"pieces/a.vtu\"/>\n", "Float32"));
  expectError([&] { loadField(index); }, {index.string(), "Piece 1", "Points array is Float64 x 3",
                                          "the index declares Float32 x 3"});
  test::writeText(index,
                  pvtu("<Piece Source=\"pieces/a.vtu\"/>\n<Piece Source=\"pieces/b.vtu\"/>\n"));
  expectError([&] { loadField(index); },
              {index.string(), "Piece 2", "pieces/b.vtu", "no such file"});
  test::writeText(index, pvtu("<Piece Source=\"../outside.vtu\"/>\n"));
  expectError([&] { loadField(index); }, {index.string(), "Piece 1", "outside the folder"});
  test::writeText(index, pvtu("<Piece Source=\"" + (dir / "outside.vtu").string() + "\"/>\n"));
  expectError([&] { loadField(index); }, {index.string(), "outside the folder"});
  test::writeText(index, pvtu("<Piece Source=\"run.pvtu\"/>\n"));
  expectError([&] { loadField(index); }, {index.string(), "names the index itself"});
  test::writeText(index, pvtu("<Piece/>\n"));
  expectError([&] { loadField(index); }, {index.string(), "Piece 1 names no file"});
  test::writeText(dir / "case" / "pieces" / "i.vti", "<VTKFile type=\"ImageData\"></VTKFile>");
  test::writeText(index, pvtu("<Piece Source=\"pieces/i.vti\"/>\n"));
  expectError([&] { loadField(index); }, {index.string(), "Piece 1", "is a VTK XML image data file",
                                          "each a VTK XML "
                                          "unstructured grid"});

  const auto a = dir / "case" / "a.vtm";
  test::writeText(a, vtm("<Block index=\"0\" name=\"fluid\">\n<DataSet index=\"0\" "
                         "file=\"pieces/a.vtu\"/>\n</Block>\n"));
  EXPECT_NO_THROW(loadField(a));
  test::writeText(a, vtm("<DataSet index=\"0\" name=\"inner\" file=\"b.vtm\"/>\n"));
  test::writeText(dir / "case" / "b.vtm", vtm("<DataSet index=\"0\" file=\"pieces/a.vtu\"/>\n"));
  expectError([&] { loadField(a); }, {a.string(), "block 'inner'", "VTK reads no index inside"});
  test::writeText(a, vtm("<DataSet index=\"0\" name=\"wall\" file=\"pieces/notes.txt\"/>\n"));
  test::writeText(dir / "case" / "pieces" / "notes.txt", "a note");
  expectError([&] { loadField(a); }, {a.string(), "block 'wall'", "file of unknown format"});
  test::writeText(a, vtm(""));
  expectError([&] { loadField(a); }, {a.string(), "names no block file"});
}

}  // namespace
}  // namespace sandstorm
