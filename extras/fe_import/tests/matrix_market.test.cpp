// Tests of the FE model import (extras/fe_import): Matrix Market and node-table files read as they
// are written by FE packages, and every fault named with its file and line. Round trips through
// sparse assembly and the sparse eigensolver are in extras/sparse.
#include <string>

#include "fe_files.hpp"
#include "fmbd/matrix_market.hpp"
#include "grading.hpp"

using namespace fmbd;
using fmbd::testing::small_symmetric;
using fmbd::testing::TempDir;
using fmbd::testing::kSmallSymmetric;

TEST_CASE("read_matrix_market: symmetric and general files with comments and repeated entries", "[fe_import]") {
  TempDir dir;
  CHECK(MatX(read_matrix_market(dir.write("small.mtx", kSmallSymmetric))) == small_symmetric());
  // A general file, CRLF line ends, a repeated entry summed: (2, 2) = 1.5 + 1.0.
  const std::string general =
      "%%MatrixMarket Matrix Coordinate Real General\r\n"
      "%\r\n"
      "3 3 6\r\n"
      "1 1 2\r\n"
      "1 2 -1\r\n"
      "2 1 -1\r\n"
      "2 2 1.5\r\n"
      "3 3 1\r\n"
      "2 2 1.0\r\n";
  CHECK(MatX(read_matrix_market(dir.write("general.mtx", general), MatrixShape::symmetric)) == small_symmetric());
  // A rectangular general matrix is read as it is where no shape is demanded.
  const MatX rect = MatX(read_matrix_market(dir.write("rect.mtx", "%%MatrixMarket matrix coordinate integer general\n"
                                                                     "2 3 2\n1 3 4\n2 1 -2\n")));
  CHECK(rect.rows() == 2);
  CHECK(rect.cols() == 3);
  CHECK(rect(0, 2) == 4.0);
  CHECK(rect(1, 0) == -2.0);
}

TEST_CASE("read_matrix_market: every fault names the file and its line", "[fe_import]") {
  TempDir dir;
  struct Case {
    const char* name;
    const char* text;
    const char* where;  // "name:line:"
    const char* what;
  };
  const Case cases[] = {
      {"empty.mtx", "", "empty.mtx:1:", "empty"},
      {"array.mtx", "%%MatrixMarket matrix array real general\n2 2\n1\n0\n0\n1\n", "array.mtx:1:", "coordinate"},
      {"banner.mtx", "%MatrixMarket matrix coordinate real general\n1 1 1\n1 1 1\n", "banner.mtx:1:", "header"},
      {"complex.mtx", "%%MatrixMarket matrix coordinate complex general\n1 1 1\n1 1 1 0\n", "complex.mtx:1:", "field"},
      {"hermitian.mtx", "%%MatrixMarket matrix coordinate real hermitian\n1 1 1\n1 1 1\n", "hermitian.mtx:1:",
       "symmetry"},
      {"nosize.mtx", "%%MatrixMarket matrix coordinate real general\n% only comments\n", "nosize.mtx:3:", "size line"},
      {"size.mtx", "%%MatrixMarket matrix coordinate real general\n%\n3 x 4\n", "size.mtx:3:", "three integers"},
      {"huge.mtx", "%%MatrixMarket matrix coordinate real general\n300000000 3 1\n1 1 1\n", "huge.mtx:2:",
       "1 .. 10^8"},
      {"count.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 50000000\n1 1 1\n", "count.mtx:2:",
       "holds only 1"},
      {"few.mtx", "%%MatrixMarket matrix coordinate real symmetric\n% c\n3 3 4\n1 1 1\n2 2 1\n3 3 1\n", "few.mtx:3:",
       "holds only 3"},
      {"many.mtx", "%%MatrixMarket matrix coordinate real symmetric\n3 3 2\n1 1 1\n2 2 1\n\n3 3 1\n", "many.mtx:6:",
       "more entries than the 2"},
      {"range.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 3\n1 1 1\n2 2 1\n4 3 1\n", "range.mtx:5:",
       "outside 1 .. 3"},
      {"zero.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 1\n2 0 1\n", "zero.mtx:4:",
       "column index 0"},
      {"text.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 1\n% c\n2 2 abc\n", "text.mtx:5:",
       "'abc' is not a number"},
      {"index.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 1\n2.5 2 1\n", "index.mtx:4:",
       "not an integer"},
      {"nan.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 nan\n2 2 1\n", "nan.mtx:3:", "not finite"},
      {"fields.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 2\n1 1 1\n2 2\n", "fields.mtx:4:",
       "three fields"},
      {"upper.mtx", "%%MatrixMarket matrix coordinate real symmetric\n3 3 3\n1 1 1\n1 2 5\n2 2 1\n", "upper.mtx:4:",
       "above the diagonal"},
      {"square.mtx", "%%MatrixMarket matrix coordinate real symmetric\n\n3 4 1\n1 1 1\n", "square.mtx:3:", "square"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const std::string path = dir.write(c.name, c.text);
    CHECK_THROWS_MENTIONING(read_matrix_market(path), FeFileError, c.where);
    CHECK_THROWS_MENTIONING(read_matrix_market(path), FeFileError, c.what);
  }
  // A general file that is not symmetric, where symmetry is demanded: the line of the entry.
  const std::string asymmetric = dir.write("asym.mtx",
                                           "%%MatrixMarket matrix coordinate real general\n3 3 4\n1 1 2\n"
                                           "2 2 2\n3 1 0.5\n3 3 2\n");
  CHECK_NOTHROW(read_matrix_market(asymmetric));
  CHECK_THROWS_MENTIONING(read_matrix_market(asymmetric, MatrixShape::symmetric), FeFileError, "asym.mtx:5:");
  CHECK_THROWS_MENTIONING(read_matrix_market(asymmetric, MatrixShape::symmetric), FeFileError, "(1, 3) = 0 (no entry)");
  const std::string rectangular =
      dir.write("rectangular.mtx", "%%MatrixMarket matrix coordinate real general\n%\n2 3 1\n1 1 1\n");
  CHECK_THROWS_MENTIONING(read_matrix_market(rectangular, MatrixShape::symmetric), FeFileError, "rectangular.mtx:3:");
  // A file that does not exist.
  try {
    read_matrix_market(dir.path("absent.mtx"));
    FAIL("no exception");
  } catch (const FeFileError& e) {
    CHECK(e.line() == 0);
    CHECK(e.path() == dir.path("absent.mtx"));
    CHECK(std::string(e.what()).find("absent.mtx: cannot open") != std::string::npos);
  }
}

TEST_CASE("load_sparse_fe_model: every fault of a node table or a size mismatch names the file and line", "[fe_import]") {
  TempDir dir;
  const std::string mass = dir.write("m.mtx", kSmallSymmetric);
  const std::string stiffness = dir.write("k.mtx", kSmallSymmetric);
  const std::string good = dir.write("good.txt", "# x y ux uy psi\n0 0 -1 -1 -1\n\n1.5 0  0 1 2  # the free node\n");
  const SparseFeModel model = load_sparse_fe_model(mass, stiffness, good);
  CHECK(model.num_nodes() == 2);
  CHECK(model.dof(1, NodeDof::psi) == 2);
  CHECK(model.table.nodes[1].x() == 1.5);

  struct Case {
    const char* name;
    const char* text;
    const char* where;
    const char* what;
  };
  const Case cases[] = {
      {"outside.txt", "0 0 -1 -1 -1\n# c\n1 0 0 1 3\n", "outside.txt:3:", "DOF number 3 of psi is outside the matrices"},
      {"negative.txt", "0 0 -2 0 1\n", "negative.txt:1:", "outside the matrices"},
      {"twice.txt", "0 0 0 1 -1\n1 0 2 -1 -1\n\n2 0 -1 1 -1\n", "twice.txt:4:",
       "DOF number 1 of u_y is already used by u_y of node 0 (line 1)"},
      {"fields.txt", "0 0 0 1\n", "fields.txt:1:", "five fields"},
      {"coordinate.txt", "# header\n0 zero 0 1 2\n", "coordinate.txt:2:", "'zero' is not a number"},
      {"integer.txt", "0 0 0 1.0 2\n", "integer.txt:1:", "not an integer"},
      {"nodes.txt", "# nothing\n\n", "nodes.txt:", "no nodes"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const std::string path = dir.write(c.name, c.text);
    CHECK_THROWS_MENTIONING(load_sparse_fe_model(mass, stiffness, path), FeFileError, c.where);
    CHECK_THROWS_MENTIONING(load_sparse_fe_model(mass, stiffness, path), FeFileError, c.what);
  }

  // M and K of different sizes: at the size line of the stiffness file, naming the mass file.
  const std::string bigger = dir.write("k4.mtx", "%%MatrixMarket matrix coordinate real symmetric\n% c\n4 4 1\n4 4 1\n");
  CHECK_THROWS_MENTIONING(load_sparse_fe_model(mass, bigger, good), FeFileError, "k4.mtx:3:");
  CHECK_THROWS_MENTIONING(load_sparse_fe_model(mass, bigger, good), FeFileError, "m.mtx:4");
  // A general stiffness file that is not symmetric.
  const std::string general = dir.write("kg.mtx", "%%MatrixMarket matrix coordinate real general\n3 3 4\n1 1 2\n2 1 -1\n"
                                                  "2 2 2\n3 3 1\n");
  CHECK_THROWS_MENTIONING(load_sparse_fe_model(mass, general, good), FeFileError, "kg.mtx:4:");
}

// ---- sparse Craig-Bampton ------------------------------------------------------------------------
